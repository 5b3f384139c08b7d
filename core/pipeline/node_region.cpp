// Cutting one node's triangles out of the surface its graph was built on.
#include "pipeline/node_region.hpp"

#include <string>
#include <vector>

#include "common/errors.hpp"

namespace arg {

int face_node(const NodePositions& p, int level, int face) {
  const Mesh& m = p.mesh;
  if (face < 0 || face >= int(m.F.rows()) || p.mu.size() != std::size_t(m.V.rows())) return -1;
  const double mu = (p.mu[std::size_t(m.F(face, 0))] + p.mu[std::size_t(m.F(face, 1))] +
                     p.mu[std::size_t(m.F(face, 2))]) /
                    3;
  return node_at(p, level, face, mu);
}

Mesh node_region(const NodePositions& p, int level, int node) {
  if (level < 0 || level >= int(p.levels.size()))
    throw InputError("node region: level " + std::to_string(level) + " not in [0, " +
                     std::to_string(int(p.levels.size()) - 1) + "]");
  const int count = int(p.levels[std::size_t(level)].area.size());
  if (node < 0 || node >= count)
    throw InputError("node region: node " + std::to_string(node) + " not in [0, " +
                     std::to_string(count - 1) + "] at level " + std::to_string(level));
  const Mesh& m = p.mesh;
  const bool colour = m.has_colour();
  std::vector<int> faces, new_index(std::size_t(m.V.rows()), -1);
  int vertices = 0;
  for (int f = 0; f < int(m.F.rows()); ++f) {
    if (face_node(p, level, f) != node) continue;
    faces.push_back(f);
    for (int c = 0; c < 3; ++c)
      if (int& v = new_index[std::size_t(m.F(f, c))]; v < 0) v = vertices++;
  }
  if (faces.empty())
    throw InputError("node region: node " + std::to_string(node) + " of level " +
                     std::to_string(level) + " owns no triangle");
  Mesh out;
  out.V.resize(vertices, 3);
  for (int v = 0; v < int(m.V.rows()); ++v)
    if (const int k = new_index[std::size_t(v)]; k >= 0) out.V.row(k) = m.V.row(v);
  out.F.resize(long(faces.size()), 3);
  if (colour) out.C.resize(long(faces.size()), 3);
  for (std::size_t i = 0; i < faces.size(); ++i) {
    for (int c = 0; c < 3; ++c) out.F(long(i), c) = new_index[std::size_t(m.F(faces[i], c))];
    if (colour) out.C.row(long(i)) = m.C.row(faces[i]);
  }
  return out;
}

}  // namespace arg
