// Boundary loops from the edges with one face, walked in their faces' direction, then fans.
#include "mesh/fill_holes.hpp"

#include <vector>

#include "mesh/mesh_edges.hpp"

namespace arg {

Mesh fill_holes(const Mesh& mesh, FillReport* report) {
  FillReport local;
  FillReport& rep = report ? *report : local;
  rep = FillReport{};
  const MeshEdges edges = mesh_edges(mesh.F);
  // Each boundary edge as its face runs along it (from -> to), and the face.
  struct Rim {
    int from, to, face;
  };
  std::vector<Rim> rims;
  std::vector<int> leaving(std::size_t(mesh.V.rows()), -1);  // the rim leaving a vertex
  std::vector<char> pinched(std::size_t(mesh.V.rows()), 0);  // more than one rim leaves it
  for (int e = 0; e < edges.count(); ++e) {
    if (edges.faces(e) != 1) continue;
    const int f = edges.face_of[std::size_t(edges.face_begin[std::size_t(e)])];
    const int k = edges.corner_of[std::size_t(edges.face_begin[std::size_t(e)])];
    const Rim r{mesh.F(f, k), mesh.F(f, (k + 1) % 3), f};
    if (leaving[std::size_t(r.from)] >= 0) pinched[std::size_t(r.from)] = 1;
    leaving[std::size_t(r.from)] = int(rims.size());
    rims.push_back(r);
  }
  if (rims.empty()) return mesh;

  std::vector<Eigen::RowVector3d> new_vertices;
  std::vector<Eigen::RowVector3i> new_faces;
  std::vector<Eigen::RowVector3f> new_colours;
  std::vector<char> done(rims.size(), 0);
  std::vector<int> loop;
  for (std::size_t start = 0; start < rims.size(); ++start) {
    if (done[start]) continue;
    // Walk from rim to rim until the loop closes, or give up at a pinched vertex.
    loop.clear();
    bool simple = true;
    for (int r = int(start);;) {
      done[std::size_t(r)] = 1;
      loop.push_back(r);
      const int v = rims[std::size_t(r)].to;
      if (pinched[std::size_t(v)] || pinched[std::size_t(rims[std::size_t(r)].from)])
        simple = false;
      const int next = leaving[std::size_t(v)];
      if (next < 0) {  // cannot happen on a manifold mesh: a rim always continues
        simple = false;
        break;
      }
      if (next == int(start)) break;
      if (done[std::size_t(next)]) {
        simple = false;
        break;
      }
      r = next;
    }
    if (!simple || loop.size() < 3) {
      ++rep.skipped_loops;
      continue;
    }
    ++rep.loops;
    Eigen::RowVector3f colour(0, 0, 0);
    if (mesh.has_colour())
      for (int r : loop) colour += mesh.C.row(rims[std::size_t(r)].face);
    colour /= float(loop.size());
    // The new faces run against the rim (to -> from), as the face across it would.
    if (loop.size() == 3) {
      new_faces.emplace_back(rims[std::size_t(loop[0])].to, rims[std::size_t(loop[0])].from,
                             rims[std::size_t(loop[2])].from);
      new_colours.push_back(colour);
      continue;
    }
    Eigen::RowVector3d centre(0, 0, 0);
    for (int r : loop) centre += mesh.V.row(rims[std::size_t(r)].from);
    centre /= double(loop.size());
    const int c = int(mesh.V.rows() + Eigen::Index(new_vertices.size()));
    new_vertices.push_back(centre);
    for (int r : loop) {
      new_faces.emplace_back(rims[std::size_t(r)].to, rims[std::size_t(r)].from, c);
      new_colours.push_back(colour);
    }
  }
  if (new_faces.empty()) return mesh;

  Mesh out;
  out.V.resize(mesh.V.rows() + Eigen::Index(new_vertices.size()), 3);
  out.V.topRows(mesh.V.rows()) = mesh.V;
  for (std::size_t k = 0; k < new_vertices.size(); ++k)
    out.V.row(mesh.V.rows() + Eigen::Index(k)) = new_vertices[k];
  out.F.resize(mesh.F.rows() + Eigen::Index(new_faces.size()), 3);
  out.F.topRows(mesh.F.rows()) = mesh.F;
  for (std::size_t k = 0; k < new_faces.size(); ++k)
    out.F.row(mesh.F.rows() + Eigen::Index(k)) = new_faces[k];
  if (mesh.has_colour()) {
    out.C.resize(out.F.rows(), 3);
    out.C.topRows(mesh.C.rows()) = mesh.C;
    for (std::size_t k = 0; k < new_colours.size(); ++k)
      out.C.row(mesh.F.rows() + Eigen::Index(k)) = new_colours[k];
  }
  rep.added_faces = new_faces.size();
  return out;
}

}  // namespace arg
