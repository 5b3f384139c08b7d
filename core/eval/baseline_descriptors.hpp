// The descriptors of the baseline methods the paper compares with: D2 and cords histograms.
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace arg {

enum class BaselineKind { D2, Cords };

// Cleans and pose-normalises the mesh, then: D2 (Osada et al.: 64 bins of the distances
// between 32768 area-weighted random point pairs, fixed seed) or cords (Paquet and Rioux:
// 64 bins of the area-weighted distances of triangle centres to the centre of mass).
std::vector<float> baseline_descriptor(const Mesh& mesh, BaselineKind kind);

// L1 distance between two histograms of the same size.
double l1_distance(const std::vector<float>& a, const std::vector<float>& b);

}  // namespace arg
