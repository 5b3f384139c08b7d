// Fans over the boundary loops of an open manifold mesh.
#include "mesh/fill_holes.hpp"

#include <vector>

#include "mesh/append_faces.hpp"
#include "mesh/boundary_loops.hpp"
#include "mesh/mesh_edges.hpp"

namespace arg {

Mesh fill_holes(const Mesh& mesh, FillReport* report) {
  FillReport local;
  FillReport& rep = report ? *report : local;
  rep = FillReport{};
  const BoundaryLoops found = boundary_loops(mesh, mesh_edges(mesh.F));
  rep.skipped_loops = found.skipped;
  std::vector<Eigen::RowVector3d> new_vertices;
  std::vector<Eigen::RowVector3i> new_faces;
  std::vector<Eigen::RowVector3f> new_colours;
  for (const BoundaryLoop& loop : found.loops) {
    ++rep.loops;
    const std::size_t n = loop.vertices.size();
    Eigen::RowVector3f colour(0, 0, 0);
    if (mesh.has_colour())
      for (int f : loop.faces) colour += mesh.C.row(f);
    colour /= float(n);
    // The new faces run against the rim (to -> from), as the face across it would.
    if (n == 3) {
      new_faces.emplace_back(loop.vertices[1], loop.vertices[0], loop.vertices[2]);
      new_colours.push_back(colour);
      continue;
    }
    Eigen::RowVector3d centre(0, 0, 0);
    for (int v : loop.vertices) centre += mesh.V.row(v);
    centre /= double(n);
    const int c = int(mesh.V.rows() + Eigen::Index(new_vertices.size()));
    new_vertices.push_back(centre);
    for (std::size_t i = 0; i < n; ++i) {
      new_faces.emplace_back(loop.vertices[(i + 1) % n], loop.vertices[i], c);
      new_colours.push_back(colour);
    }
  }
  if (new_faces.empty()) return mesh;

  rep.added_faces = new_faces.size();
  return append_faces(mesh, new_vertices, new_faces, new_colours);
}

}  // namespace arg
