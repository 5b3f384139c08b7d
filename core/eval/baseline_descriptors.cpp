// D2 and cords baselines on the same cleaned, pose-normalised mesh the ARG uses.
#include "eval/baseline_descriptors.hpp"

#include <cmath>

#include "features/shape_distributions.hpp"
#include "mesh/clean_mesh.hpp"
#include "mesh/normalize_pose.hpp"

namespace arg {

std::vector<float> baseline_descriptor(const Mesh& input, BaselineKind kind) {
  Mesh mesh = clean_mesh(input);
  mesh = apply_pose(mesh, surface_pose(mesh));
  return kind == BaselineKind::D2 ? d2_histogram(mesh, 64, 32768) : cords_histogram(mesh, 64);
}

double l1_distance(const std::vector<float>& a, const std::vector<float>& b) {
  double s = 0;
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k) s += std::fabs(double(a[k]) - b[k]);
  return s;
}

}  // namespace arg
