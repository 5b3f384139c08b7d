// Red-green refinement: near faces into four, their neighbours closed up so no T-junction forms.
#include "eval/refine_faces.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <vector>

#include "mesh/coincident_vertices.hpp"

namespace arg {

Mesh refine_faces(const Mesh& mesh, double max_edge, const NearFace& near, Eigen::Index max_faces) {
  std::vector<Eigen::RowVector3d> points(std::size_t(mesh.V.rows()));
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) points[std::size_t(v)] = mesh.V.row(v);
  const std::vector<int> first = first_at_same_position(mesh);
  std::vector<std::array<int, 3>> faces(std::size_t(mesh.F.rows()));
  std::vector<Eigen::Index> source(faces.size());  // the input face each face lies in
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    for (int c = 0; c < 3; ++c) faces[std::size_t(f)][std::size_t(c)] = mesh.F(f, c);
    source[std::size_t(f)] = f;
  }
  auto key = [&](int a, int b) {
    const int p = a < int(first.size()) ? first[std::size_t(a)] : a;
    const int q = b < int(first.size()) ? first[std::size_t(b)] : b;
    return std::make_pair(std::min(p, q), std::max(p, q));  // minmax would return references
  };
  for (int pass = 0; pass < 64; ++pass) {
    // The edges to split this pass (every edge of a face to cut into four), each with its
    // midpoint's index.
    std::map<std::pair<int, int>, int> midpoint;
    for (const auto& f : faces) {
      const Eigen::RowVector3d& a = points[std::size_t(f[0])];
      const Eigen::RowVector3d& b = points[std::size_t(f[1])];
      const Eigen::RowVector3d& c = points[std::size_t(f[2])];
      const double longest = std::max({(a - b).norm(), (b - c).norm(), (c - a).norm()});
      if (longest > max_edge && near(a, b, c))
        for (int k = 0; k < 3; ++k)
          midpoint.emplace(key(f[std::size_t(k)], f[std::size_t((k + 1) % 3)]), -1);
    }
    if (midpoint.empty()) break;
    for (auto& [edge, id] : midpoint) {
      id = int(points.size());
      points.push_back(0.5 * (points[std::size_t(edge.first)] + points[std::size_t(edge.second)]));
    }
    std::vector<std::array<int, 3>> next;
    std::vector<Eigen::Index> next_source;
    auto add = [&](int a, int b, int c, Eigen::Index s) {
      next.push_back({a, b, c});
      next_source.push_back(s);
    };
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const auto& t = faces[f];
      int m[3];
      int splits = 0;
      for (int c = 0; c < 3; ++c) {
        const auto it = midpoint.find(key(t[std::size_t(c)], t[std::size_t((c + 1) % 3)]));
        m[c] = it == midpoint.end() ? -1 : it->second;
        splits += m[c] >= 0;
      }
      const Eigen::Index s = source[f];
      if (splits == 0) {
        add(t[0], t[1], t[2], s);
      } else if (splits == 3) {
        add(t[0], m[0], m[2], s), add(m[0], t[1], m[1], s), add(m[2], m[1], t[2], s);
        add(m[0], m[1], m[2], s);
      } else {
        // Rotate so that edge 0 (corners 0, 1) is split, and edge 1 too when two are.
        int r = 0;
        while (!(m[r] >= 0 && (splits == 1 || m[(r + 1) % 3] >= 0))) ++r;
        const int a = t[std::size_t(r)], b = t[std::size_t((r + 1) % 3)],
                  c = t[std::size_t((r + 2) % 3)];
        const int ab = m[r];
        if (splits == 1) {
          add(a, ab, c, s), add(ab, b, c, s);
        } else {
          const int bc = m[(r + 1) % 3];
          add(ab, b, bc, s);
          // The quadrilateral a, ab, bc, c along its shorter diagonal.
          const auto& P = points;
          if ((P[std::size_t(a)] - P[std::size_t(bc)]).norm() <=
              (P[std::size_t(ab)] - P[std::size_t(c)]).norm())
            add(a, ab, bc, s), add(a, bc, c, s);
          else
            add(a, ab, c, s), add(ab, bc, c, s);
        }
      }
    }
    if (Eigen::Index(next.size()) > max_faces) {  // the pass is not taken
      points.resize(points.size() - midpoint.size());
      break;
    }
    faces = std::move(next);
    source = std::move(next_source);
  }
  Mesh out;
  out.V.resize(Eigen::Index(points.size()), 3);
  for (std::size_t v = 0; v < points.size(); ++v) out.V.row(Eigen::Index(v)) = points[v];
  out.F.resize(Eigen::Index(faces.size()), 3);
  if (mesh.has_colour()) out.C.resize(Eigen::Index(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (int c = 0; c < 3; ++c) out.F(Eigen::Index(f), c) = faces[f][std::size_t(c)];
    if (mesh.has_colour()) out.C.row(Eigen::Index(f)) = mesh.C.row(source[f]);
  }
  return out;
}

}  // namespace arg
