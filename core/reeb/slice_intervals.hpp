// Exact cutting of a triangle mesh at the boundaries of R equal intervals of mu.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "common/limits.hpp"
#include "mesh/mesh.hpp"

namespace arg {

// The part of one triangle whose mu lies in one interval (a convex polygon), with the sums the
// node attributes need.
struct Piece {
  int triangle = 0;
  int interval = 0;
  double area = 0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double volume6 = 0;  // 6 x signed volume of the cone from the origin over the piece
  double mu_min = 0, mu_max = 0;
  // The cut segment on the upper interval boundary (shared with the next piece of the same
  // triangle), reversed so that it runs along the cap closing this piece's region:
  // q1 x q0, the length-weighted midpoint and the length.
  Eigen::Vector3d cap_cross = Eigen::Vector3d::Zero();
  Eigen::Vector3d cap_moment = Eigen::Vector3d::Zero();
  double cap_length = 0;
};

struct SlicedSurface {
  int intervals = 1;
  std::vector<double> mu;           // per vertex, nudged off interior boundaries
  std::vector<int> first_interval;  // per triangle
  std::vector<int> piece_begin;     // per triangle + 1: its pieces, one per interval in order
  std::vector<Piece> pieces;
};

// Interval index of a mu value in [0, 1] with `intervals` equal intervals.
inline int interval_of(double mu, int intervals) {
  int k = int(mu * intervals);
  return k < 0 ? 0 : (k >= intervals ? intervals - 1 : k);
}

// Cuts every triangle at the interval boundaries its mu range crosses. Vertices whose mu falls
// exactly on an interior boundary are moved up by one ulp first, so every piece has positive
// area and pieces of neighbouring triangles meet along segments, not single points.
SlicedSurface slice_intervals(const Mesh& mesh, const std::vector<double>& mu, int intervals,
                              const StopRequested& stop = {});

}  // namespace arg
