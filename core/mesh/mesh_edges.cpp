// Building the undirected edge table of a triangle mesh by sorting half-edges.
#include "mesh/mesh_edges.hpp"

#include <algorithm>
#include <numeric>

#include "common/polled_sort.hpp"

namespace arg {

MeshEdges mesh_edges(const Triangles& F, const StopRequested& stop) {
  struct HalfEdge {
    int a, b, face;
    std::int8_t corner;
  };
  // Filled by push_back, not zeroed first: zeroing the half-edges of millions of faces is one
  // pass over memory that polls nothing.
  std::vector<HalfEdge> half;
  half.reserve(std::size_t(F.rows()) * 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    poll_interrupt(std::size_t(f), stop);
    for (int c = 0; c < 3; ++c) {
      int a = F(f, c), b = F(f, (c + 1) % 3);
      half.push_back({std::min(a, b), std::max(a, b), int(f), std::int8_t(c)});
    }
  }
  polled_sort(
      half.begin(), half.end(),
      [](const HalfEdge& x, const HalfEdge& y) {
        if (x.a != y.a) return x.a < y.a;
        if (x.b != y.b) return x.b < y.b;
        return x.face < y.face;
      },
      stop);
  MeshEdges E;
  E.face_of.reserve(half.size());
  E.corner_of.reserve(half.size());
  for (std::size_t i = 0; i < half.size(); ++i) {
    poll_interrupt(i, stop);
    if (i == 0 || half[i].a != half[i - 1].a || half[i].b != half[i - 1].b) {
      E.v0.push_back(half[i].a);
      E.v1.push_back(half[i].b);
      E.face_begin.push_back(int(E.face_of.size()));
    }
    E.face_of.push_back(half[i].face);
    E.corner_of.push_back(half[i].corner);
  }
  E.face_begin.push_back(int(E.face_of.size()));
  return E;
}

}  // namespace arg
