// Combinatorial and geometric facts about a mesh that tests check: closed, oriented, manifold.
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

#include "mesh/mesh.hpp"

namespace arg::test {

// What the tests need to know about a mesh's combinatorics and geometry.
struct Inspection {
  long vertices = 0, edges = 0, faces = 0;
  bool every_edge_has_two_triangles = true;
  bool every_directed_edge_once = true;  // consistent orientation
  bool every_fan_is_one_cycle = true;    // manifold at the vertices
  bool every_vertex_used = true;
  int components = 0;
  double smallest_area = 0;
  double signed_volume = 0;
  long euler() const { return vertices - edges + faces; }
};

inline Inspection inspect(const Mesh& m) {
  Inspection r;
  r.vertices = static_cast<long>(m.V.rows());
  r.faces = static_cast<long>(m.F.rows());
  std::vector<std::pair<int, int>> directed, undirected;
  for (Eigen::Index t = 0; t < m.F.rows(); ++t)
    for (int c = 0; c < 3; ++c) {
      const int a = m.F(t, c), b = m.F(t, (c + 1) % 3);
      directed.emplace_back(a, b);
      undirected.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(directed.begin(), directed.end());
  r.every_directed_edge_once =
      std::adjacent_find(directed.begin(), directed.end()) == directed.end();
  std::sort(undirected.begin(), undirected.end());
  for (std::size_t i = 0; i < undirected.size();) {
    std::size_t j = i;
    while (j < undirected.size() && undirected[j] == undirected[i]) ++j;
    if (j - i != 2) r.every_edge_has_two_triangles = false;
    ++r.edges;
    i = j;
  }

  // Around each vertex, each triangle maps the corner after it to the corner before it; the
  // fan is a single disc when following that map visits every triangle once.
  std::vector<std::vector<std::pair<int, int>>> fan(static_cast<std::size_t>(r.vertices));
  for (Eigen::Index t = 0; t < m.F.rows(); ++t)
    for (int c = 0; c < 3; ++c)
      fan[m.F(t, c)].emplace_back(m.F(t, (c + 1) % 3), m.F(t, (c + 2) % 3));
  for (auto& links : fan) {
    if (links.empty()) {
      r.every_vertex_used = false;
      continue;
    }
    std::map<int, int> next(links.begin(), links.end());
    if (next.size() != links.size()) {
      r.every_fan_is_one_cycle = false;
      continue;
    }
    int at = links.front().first;
    std::size_t steps = 0;
    do {
      const auto it = next.find(at);
      if (it == next.end()) break;
      at = it->second;
      ++steps;
    } while (at != links.front().first && steps <= links.size());
    if (steps != links.size() || at != links.front().first) r.every_fan_is_one_cycle = false;
  }

  std::vector<int> parent(static_cast<std::size_t>(r.vertices));
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& [a, b] : undirected) parent[find(a)] = find(b);
  for (int v = 0; v < r.vertices; ++v) r.components += find(v) == v;

  r.smallest_area = INFINITY;
  for (Eigen::Index t = 0; t < m.F.rows(); ++t) {
    const Eigen::Vector3d a = m.V.row(m.F(t, 0)), b = m.V.row(m.F(t, 1)), c = m.V.row(m.F(t, 2));
    r.smallest_area = std::min(r.smallest_area, 0.5 * (b - a).cross(c - a).norm());
    r.signed_volume += a.dot(b.cross(c)) / 6.0;
  }
  return r;
}

}  // namespace arg::test
