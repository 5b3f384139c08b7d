// Boundary loops from the edges with one face, each rim followed to the rim leaving its end.
#include "mesh/boundary_loops.hpp"

namespace arg {

BoundaryLoops boundary_loops(const Mesh& mesh, const MeshEdges& edges) {
  BoundaryLoops out;
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
      ++out.skipped;
      continue;
    }
    BoundaryLoop b;
    for (int r : loop) {
      b.vertices.push_back(rims[std::size_t(r)].from);
      b.faces.push_back(rims[std::size_t(r)].face);
    }
    out.loops.push_back(std::move(b));
  }
  return out;
}

}  // namespace arg
