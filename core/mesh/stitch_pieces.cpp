// Mutual-nearest pairing of rim vertices across pieces, found on a grid of the tolerance's size.
#include "mesh/stitch_pieces.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <map>

#include "mesh/face_subset.hpp"

namespace arg {

Mesh stitch_pieces(const Mesh& mesh, const MeshEdges& edges, const std::vector<int>& component,
                   double tolerance, std::size_t* pairs, const StopRequested& stop) {
  Mesh out = mesh;
  if (pairs) *pairs = 0;
  if (!(tolerance > 0)) return out;
  std::vector<char> on_rim(std::size_t(mesh.V.rows()), 0);
  for (int e = 0; e < edges.count(); ++e)
    if (edges.faces(e) == 1)
      on_rim[std::size_t(edges.v0[e])] = on_rim[std::size_t(edges.v1[e])] = 1;
  using Cell = std::array<long long, 3>;
  auto cell_of = [&](Eigen::Index v) {
    Cell c;
    for (int k = 0; k < 3; ++k) c[std::size_t(k)] = (long long)std::floor(mesh.V(v, k) / tolerance);
    return c;
  };
  // An ordered map keeps the search deterministic and needs no hash of our own; rims are a small
  // share of the vertices.
  std::map<Cell, std::vector<int>> grid;
  std::vector<int> rim;
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    if (on_rim[std::size_t(v)]) {
      rim.push_back(int(v));
      grid[cell_of(v)].push_back(int(v));
    }
  if (rim.empty()) return out;
  const double limit = tolerance * tolerance;
  // The nearest rim vertex of another piece within the tolerance that `eligible` accepts, -1
  // when none; ties go to the lower index.
  auto nearest_across = [&](int v, auto eligible) {
    const Cell c = cell_of(v);
    double best = std::numeric_limits<double>::infinity();
    int found = -1;
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          auto it = grid.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == grid.end()) continue;
          for (int w : it->second) {
            if (component[std::size_t(w)] == component[std::size_t(v)] || !eligible(w)) continue;
            const double d = (mesh.V.row(w) - mesh.V.row(v)).squaredNorm();
            if (d <= limit && (d < best || (d == best && w < found))) best = d, found = w;
          }
        }
    return found;
  };
  std::vector<int> nearest(std::size_t(mesh.V.rows()), -1);
  for (std::size_t k = 0; k < rim.size(); ++k) {
    if ((k & 4095) == 0) check_interrupt(stop);
    nearest[std::size_t(rim[k])] = nearest_across(rim[k], [](int) { return true; });
  }
  std::vector<char> paired(std::size_t(mesh.V.rows()), 0);
  for (int v : rim) {
    const int w = nearest[std::size_t(v)];
    if (w > v && nearest[std::size_t(w)] == v) {
      const Eigen::RowVector3d mid = 0.5 * (mesh.V.row(v) + mesh.V.row(w));
      out.V.row(v) = mid;
      out.V.row(w) = mid;
      paired[std::size_t(v)] = paired[std::size_t(w)] = 1;
      if (pairs) ++*pairs;
    }
  }
  // A rim vertex left over (its nearest chose another) would leave a slit between two joined
  // points: it goes onto the nearest joined point across the gap, collapsing its short rim edge.
  // Only left-over vertices move, onto points that stay: no chains along a seam.
  check_interrupt(stop);
  for (int v : rim) {
    if (paired[std::size_t(v)]) continue;
    const int target = nearest_across(v, [&](int w) { return paired[std::size_t(w)] != 0; });
    if (target >= 0) out.V.row(v) = out.V.row(target);
  }
  return out;
}

Mesh without_nonmanifold_faces(const Mesh& mesh, const MeshEdges& edges) {
  std::vector<char> keep(std::size_t(mesh.F.rows()), 1);
  for (int e = 0; e < edges.count(); ++e)
    if (edges.faces(e) > 2)
      for (int k = edges.face_begin[std::size_t(e)]; k < edges.face_begin[std::size_t(e) + 1]; ++k)
        keep[std::size_t(edges.face_of[std::size_t(k)])] = 0;
  return face_subset(mesh, keep);
}

}  // namespace arg
