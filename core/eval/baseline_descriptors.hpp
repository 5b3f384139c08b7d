// Whole-shape descriptors that argtool eval measures beside the ARG, each with its distance.
#pragma once

#include <string_view>
#include <vector>

#include "mesh/mesh.hpp"

namespace arg {

struct DescriptorMethod {
  const char* name;
  const char* help;
  // From the cleaned mesh in the aligned, centred, scaled frame of apply_pose.
  std::vector<float> (*compute)(const Mesh& posed);
  double (*distance)(const std::vector<float>&, const std::vector<float>&);
};

// d2 (Osada et al.), cords (Paquet and Rioux), depth (Vranic's depth buffer), ..., profile.
const std::vector<DescriptorMethod>& descriptor_methods();

// nullptr when no method has that name.
const DescriptorMethod* find_descriptor_method(std::string_view name);

// The mesh every descriptor method reads: cleaned, centred, aligned and scaled.
Mesh posed_for_descriptors(const Mesh& mesh);

// L1 distance between two vectors of the same size.
double l1_distance(const std::vector<float>& a, const std::vector<float>& b);

}  // namespace arg
