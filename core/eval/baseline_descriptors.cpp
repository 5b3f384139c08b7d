// The descriptor methods of the quality harness, on the same cleaned, posed mesh as the ARG.
#include "eval/baseline_descriptors.hpp"

#include <cmath>

#include "features/depth_buffer_descriptor.hpp"
#include "features/panorama_descriptor.hpp"
#include "features/shape_distributions.hpp"
#include "features/surface_detail.hpp"
#include "features/vessel_profile.hpp"
#include "mesh/clean_mesh.hpp"
#include "mesh/normalize_pose.hpp"

namespace arg {

namespace {

std::vector<float> d2(const Mesh& m) {
  return d2_histogram(m, 64, 32768);
}
std::vector<float> cords(const Mesh& m) {
  return cords_histogram(m, 64);
}
std::vector<float> panorama(const Mesh& m) {
  return panorama_descriptor(m);
}
std::vector<float> depth(const Mesh& m) {
  return depth_buffer_descriptor(depth_images(m, 64), 8);
}
std::vector<float> profile(const Mesh& m) {
  return profile_vector(vessel_profile(m));
}
std::vector<float> symmetry(const Mesh& m) {
  return {float(vessel_profile(m).symmetry)};
}
std::vector<float> detail(const Mesh& m) {
  return surface_detail(m);
}

}  // namespace

const std::vector<DescriptorMethod>& descriptor_methods() {
  static const std::vector<DescriptorMethod> methods = {
      {"d2", "Osada et al.: 64 bins of distances between 32768 random surface point pairs", d2,
       l1_distance},
      {"cords", "Paquet and Rioux: 64 bins of triangle-centre distances to the centre of mass",
       cords, l1_distance},
      {"depth", "Vranic: Fourier magnitudes of six 64x64 depth images in the PCA frame", depth,
       l1_distance},
      {"panorama",
       "Papadakis et al.: Fourier magnitudes of cylindrical views about the axes of two frames",
       panorama, panorama_distance},
      {"profile",
       "the vessel profile: area, mean radius and its spread in 24 height bins along the most "
       "rotationally symmetric principal axis",
       profile, profile_distance},
      {"symmetry",
       "the vessel profile's symmetry score alone: how little the radius about the most "
       "rotationally symmetric principal axis varies with direction",
       symmetry, l1_distance},
      {"detail",
       "surface detail: how far 4 and 32 Taubin steps move each vertex, area-weighted "
       "histograms over log10 of the distance",
       detail, l1_distance},
  };
  return methods;
}

const DescriptorMethod* find_descriptor_method(std::string_view name) {
  for (const DescriptorMethod& m : descriptor_methods())
    if (name == m.name) return &m;
  return nullptr;
}

Mesh posed_for_descriptors(const Mesh& input) {
  Mesh mesh = clean_mesh(input);
  return apply_pose(mesh, surface_pose(mesh));
}

double l1_distance(const std::vector<float>& a, const std::vector<float>& b) {
  double s = 0;
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k) s += std::fabs(double(a[k]) - b[k]);
  return s;
}

}  // namespace arg
