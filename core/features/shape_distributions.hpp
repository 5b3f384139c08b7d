// Whole-shape histograms: Osada's D2 and Paquet-Rioux cords, also the global descriptor.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "graph/arg_graph.hpp"
#include "mesh/mesh.hpp"
#include "mesh/normalize_pose.hpp"

namespace arg {

// `count` points on the surface, uniform by area, from a fixed seed: the same mesh and count give
// the same points on every platform. Empty when the surface has no area.
std::vector<Eigen::Vector3d> surface_samples(const Mesh& mesh, int count, std::uint64_t seed);

// D2: distances between `pairs` random surface point pairs (area-weighted, fixed seed), in
// `bins` bins over [0, max_distance); the histogram sums to 1. Expects unit RMS radius.
std::vector<float> d2_histogram(const Mesh& mesh, int bins = 64, int pairs = 32768,
                                double max_distance = 4.0);

// Cords: area-weighted distances of triangle centres to the centre of mass (the origin), in
// `bins` bins over [0, max_distance); sums to 1.
std::vector<float> cords_histogram(const Mesh& mesh, int bins = 64, double max_distance = 3.0);

struct GraphCounts {
  std::array<int, kMaxLevels + 1> nodes_per_level{};
  int loops = 0;
  int components = 1;
};

// The fixed-size descriptor stored first in every ARG: D2 (16 bins), cords (16 bins) and 16
// shape statistics (PCA ratios, graph size per level, loops, components, compactness).
std::array<float, kGlobalDims> global_descriptor(const Mesh& normalised_mesh, const Pose& pose,
                                                 const GraphCounts& counts, double volume,
                                                 const StopRequested& stop = {});

}  // namespace arg
