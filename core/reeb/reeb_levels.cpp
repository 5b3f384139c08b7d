// Union-find over pieces for the finest Reeb graph, then merging level by level.
#include "reeb/reeb_levels.hpp"

#include <algorithm>
#include <numeric>

namespace arg {

namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(std::size_t(n)) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the smallest member is the root
  }
};

// Numbers the classes of `uf` over items 0..n-1 by (key of the class, smallest member).
std::vector<int> number_classes(UnionFind& uf, int n, const std::vector<int>& key,
                                std::vector<int>& class_key) {
  std::vector<int> roots;
  for (int i = 0; i < n; ++i)
    if (uf.find(i) == i) roots.push_back(i);  // roots are the smallest members
  std::stable_sort(roots.begin(), roots.end(), [&](int a, int b) { return key[a] < key[b]; });
  std::vector<int> id_of_root(std::size_t(n), -1);
  class_key.resize(roots.size());
  for (std::size_t k = 0; k < roots.size(); ++k) {
    id_of_root[roots[k]] = int(k);
    class_key[k] = key[roots[k]];
  }
  std::vector<int> id(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) id[i] = id_of_root[uf.find(i)];
  return id;
}

void sort_unique(std::vector<std::pair<int, int>>& edges) {
  for (auto& e : edges)
    if (e.first > e.second) std::swap(e.first, e.second);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
}

int cycle_rank(int nodes, const std::vector<std::pair<int, int>>& edges) {
  UnionFind uf(nodes);
  int components = nodes;
  for (auto [a, b] : edges)
    if (uf.find(a) != uf.find(b)) uf.unite(a, b), --components;
  return int(edges.size()) - nodes + components;
}

}  // namespace

ReebGraph reeb_levels(const SlicedSurface& s, const MeshEdges& E, int levels,
                      const StopRequested& stop) {
  const int pieces = int(s.pieces.size());
  auto piece_at = [&](int face, int k) { return s.piece_begin[face] + k - s.first_interval[face]; };

  UnionFind uf(pieces);
  for (int e = 0; e < E.count(); ++e) {
    if ((e & 8191) == 0) check_interrupt(stop);
    double a = s.mu[E.v0[e]], b = s.mu[E.v1[e]];
    int k0 = interval_of(std::min(a, b), s.intervals),
        k1 = interval_of(std::max(a, b), s.intervals);
    const int f0 = E.face_of[E.face_begin[e]];
    for (int k = E.face_begin[e] + 1; k < E.face_begin[e + 1]; ++k)
      for (int j = k0; j <= k1; ++j) uf.unite(piece_at(f0, j), piece_at(E.face_of[k], j));
  }
  check_interrupt(stop);
  std::vector<int> piece_interval(static_cast<std::size_t>(pieces));
  for (int p = 0; p < pieces; ++p) piece_interval[p] = s.pieces[p].interval;

  ReebGraph g;
  g.levels.resize(std::size_t(levels) + 1);
  ReebLevel& finest = g.levels[std::size_t(levels)];
  g.piece_node = number_classes(uf, pieces, piece_interval, finest.interval);
  check_interrupt(stop);
  for (std::size_t f = 0; f + 1 < s.piece_begin.size(); ++f)
    for (int p = s.piece_begin[f]; p + 1 < s.piece_begin[f + 1]; ++p)
      finest.edges.emplace_back(g.piece_node[p], g.piece_node[p + 1]);
  sort_unique(finest.edges);
  g.loops = cycle_rank(int(finest.interval.size()), finest.edges);

  for (int r = levels - 1; r >= 0; --r) {
    ReebLevel& child = g.levels[std::size_t(r) + 1];
    ReebLevel& level = g.levels[std::size_t(r)];
    const int n = int(child.interval.size());
    UnionFind merge(n);
    for (auto [i, j] : child.edges)
      if (child.interval[i] / 2 == child.interval[j] / 2) merge.unite(i, j);
    std::vector<int> half(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) half[i] = child.interval[i] / 2;
    child.parent = number_classes(merge, n, half, level.interval);
    for (auto [i, j] : child.edges)
      if (child.parent[i] != child.parent[j])
        level.edges.emplace_back(child.parent[i], child.parent[j]);
    sort_unique(level.edges);
  }
  g.levels[0].parent.assign(g.levels[0].interval.size(), -1);
  return g;
}

}  // namespace arg
