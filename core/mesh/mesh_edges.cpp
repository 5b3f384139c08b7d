// Building the undirected edge table of a triangle mesh by bucketing half-edges.
#include "mesh/mesh_edges.hpp"

#include <algorithm>
#include <memory>
#include <numeric>

#include "common/polled_sort.hpp"

namespace arg {

MeshEdges mesh_edges(const Triangles& F, const StopRequested& stop) {
  struct HalfEdge {
    int b, face;
    std::int8_t corner;
  };
  // Half-edges bucketed by their lower vertex (a counting sort), then each bucket, a handful of
  // entries around one vertex, sorted by (upper vertex, face, corner): the order a sort of all
  // of them by (lower, upper, face, corner) gives, in linear time rather than n log n.
  const Eigen::Index nf = F.rows();
  int nv = 0;
  for (Eigen::Index f = 0; f < nf; ++f) {
    poll_interrupt(std::size_t(f), stop);
    nv = std::max({nv, F(f, 0) + 1, F(f, 1) + 1, F(f, 2) + 1});
  }
  std::vector<int> begin(std::size_t(nv) + 1, 0);
  for (Eigen::Index f = 0; f < nf; ++f) {
    poll_interrupt(std::size_t(f), stop);
    for (int c = 0; c < 3; ++c) ++begin[std::size_t(std::min(F(f, c), F(f, (c + 1) % 3))) + 1];
  }
  for (int v = 0; v < nv; ++v) begin[std::size_t(v) + 1] += begin[std::size_t(v)];
  // Filled in place, not zeroed first: zeroing the half-edges of millions of faces is one pass
  // over memory that polls nothing.
  std::unique_ptr<HalfEdge[]> half(new HalfEdge[std::size_t(nf) * 3]);
  std::vector<int> fill(begin.begin(), begin.end() - 1);
  for (Eigen::Index f = 0; f < nf; ++f) {
    poll_interrupt(std::size_t(f), stop);
    for (int c = 0; c < 3; ++c) {
      const int a = F(f, c), b = F(f, (c + 1) % 3);
      half[std::size_t(fill[std::size_t(std::min(a, b))]++)] = {std::max(a, b), int(f),
                                                                std::int8_t(c)};
    }
  }
  const auto less = [](const HalfEdge& x, const HalfEdge& y) {
    if (x.b != y.b) return x.b < y.b;
    if (x.face != y.face) return x.face < y.face;
    return x.corner < y.corner;
  };
  MeshEdges E;
  E.face_of.reserve(std::size_t(nf) * 3);
  E.corner_of.reserve(std::size_t(nf) * 3);
  for (int a = 0; a < nv; ++a) {
    poll_interrupt(std::size_t(a), stop);
    HalfEdge* const first = half.get() + begin[std::size_t(a)];
    HalfEdge* const last = half.get() + begin[std::size_t(a) + 1];
    // A bucket holds about six entries, arriving nearly in order (by face): insertion sort.
    // The centre of a large fan (a cone's apex, a hostile file) is sorted in n log n.
    if (last - first > 32) {
      polled_sort(first, last, less, stop);
    } else {
      for (HalfEdge* i = first + (first != last); i < last; ++i) {
        const HalfEdge x = *i;
        HalfEdge* j = i;
        for (; j > first && less(x, *(j - 1)); --j) *j = *(j - 1);
        *j = x;
      }
    }
    for (HalfEdge* i = first; i < last; ++i) {
      if (i == first || i->b != (i - 1)->b) {
        E.v0.push_back(a);
        E.v1.push_back(i->b);
        E.face_begin.push_back(int(E.face_of.size()));
      }
      E.face_of.push_back(i->face);
      E.corner_of.push_back(i->corner);
    }
  }
  E.face_begin.push_back(int(E.face_of.size()));
  return E;
}

}  // namespace arg
