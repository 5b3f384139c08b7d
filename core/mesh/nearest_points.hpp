// The nearest of a fixed set of points to a query point, found through a uniform grid of cells.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "mesh/mesh.hpp"

namespace arg {

// A uniform grid over `points` (rows), about `per_cell` points a cell on average. Queries
// search rings of cells outwards until no closer point can lie beyond the ring reached.
class NearestPoints {
 public:
  // Keeps a reference to `points`, which must outlive the index (a temporary may not).
  explicit NearestPoints(const Vertices& points, double per_cell = 2.0);
  explicit NearestPoints(Vertices&&, double = 2.0) = delete;

  // The index of the point nearest to `q` (the lowest index among equally near ones; a point
  // with a non-finite coordinate is never nearer than a finite one); -1 when there are no
  // points or q is not finite.
  int nearest(const Eigen::Vector3d& q) const;

 private:
  long long cell_index(long long x, long long y, long long z) const {
    return (z * dims_[1] + y) * dims_[0] + x;
  }

  const Vertices& points_;
  Eigen::Vector3d low_ = Eigen::Vector3d::Zero();
  double cell_ = 1;
  long long dims_[3] = {1, 1, 1};
  std::vector<int> begin_;  // per cell, into order_ (CSR)
  std::vector<int> order_;  // point indices, grouped by cell, increasing within a cell
};

}  // namespace arg
