// Meshes cut into pieces, and their pieces, for the hole, stitch and bridge tests.
#pragma once

#include <vector>

#include "mesh/clean_mesh.hpp"
#include "mesh/connected_components.hpp"
#include "mesh/mesh.hpp"
#include "test_shapes.hpp"

namespace arg::test {

struct Pieces {
  Mesh mesh;
  std::vector<int> component;  // vertex_components' numbering
  int count = 0;
};

inline Pieces cleaned(const Mesh& m, CleanReport* report = nullptr) {
  Pieces p;
  p.mesh = clean_mesh(m, report);
  p.count = vertex_components(p.mesh, p.component);
  return p;
}

// The capsule (z in [-3.5, 3.5], radius 0.5) without the faces whose centre lies in [lo, hi]
// along z; the vertices of the faces above the cut move by `shift`.
inline Mesh capsule_cut(double lo, double hi, const Eigen::RowVector3d& shift = {0, 0, 0}) {
  const Mesh whole = capsule();
  Mesh cut = whole;
  Eigen::Index kept = 0;
  for (Eigen::Index f = 0; f < whole.F.rows(); ++f) {
    double z = 0;
    for (int c = 0; c < 3; ++c) z += whole.V(whole.F(f, c), 2) / 3;
    if (z < lo || z > hi) cut.F.row(kept++) = whole.F.row(f);
  }
  cut.F.conservativeResize(kept, 3);
  std::vector<char> above(std::size_t(cut.V.rows()), 0);
  for (Eigen::Index f = 0; f < cut.F.rows(); ++f)
    if (cut.V(cut.F(f, 0), 2) + cut.V(cut.F(f, 1), 2) + cut.V(cut.F(f, 2), 2) > 3 * hi)
      for (int c = 0; c < 3; ++c) above[std::size_t(cut.F(f, c))] = 1;
  for (Eigen::Index v = 0; v < cut.V.rows(); ++v)
    if (above[std::size_t(v)]) cut.V.row(v) += shift;
  return cut;
}

inline double signed_volume(const Mesh& m) {
  double v = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    v += m.V.row(m.F(f, 0)).dot(m.V.row(m.F(f, 1)).cross(m.V.row(m.F(f, 2)))) / 6.0;
  return v;
}

}  // namespace arg::test
