// Undirected edges of a triangle mesh with the faces around each one.
#pragma once

#include <cstdint>
#include <vector>

#include "common/limits.hpp"
#include "mesh/mesh.hpp"

namespace arg {

// Edge e joins vertices (v0[e], v1[e]), v0 < v1; its faces are
// face_of[face_begin[e] .. face_begin[e + 1]). Edges are sorted by (v0, v1).
struct MeshEdges {
  std::vector<int> v0, v1;
  std::vector<int> face_begin;
  std::vector<int> face_of;
  std::vector<std::int8_t> corner_of;  // which edge of the face (0: f0-f1, 1: f1-f2, 2: f2-f0)

  int count() const { return int(v0.size()); }
  int faces(int e) const { return face_begin[e + 1] - face_begin[e]; }
};

MeshEdges mesh_edges(const Triangles& F, const StopRequested& stop = {});

}  // namespace arg
