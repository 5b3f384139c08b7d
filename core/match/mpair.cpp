// The coarse-to-fine matching with branch labels, Tung's rule and node groups.
#include "match/mpair.hpp"

#include <algorithm>
#include <numeric>

#include "match/node_similarity.hpp"

namespace arg {

namespace {

// Matching state of one graph.
struct Side {
  const ArgGraph& g;
  std::vector<int> group;  // per node: match group, -1 when unmatched
  std::vector<int> label;  // per node: branch label at its level, 0 when none

  explicit Side(const ArgGraph& graph)
      : g(graph), group(graph.nodes.size(), -1), label(graph.nodes.size(), 0) {}

  // Neighbours of node i whose interval is interval(i) + step (step = +1 or -1).
  template <class F>
  void for_neighbours(int i, int step, F&& f) const {
    const ArgNode& n = g.nodes[std::size_t(i)];
    for (std::uint32_t k = 0; k < n.adj_count; ++k) {
      int j = int(g.adjacency[n.adj_begin + k]);
      if (int(g.nodes[std::size_t(j)].interval) - int(n.interval) == step) f(j);
    }
  }
  int count_neighbours(int i, int step) const {
    int c = 0;
    for_neighbours(i, step, [&](int) { ++c; });
    return c;
  }
  int only_neighbour(int i, int step) const {
    int last = -1;
    for_neighbours(i, step, [&](int j) { last = j; });
    return last;
  }

  // Labels the branch through i: neighbours up and down while the chain does not fork.
  void label_branch(int i, int value) {
    label[std::size_t(i)] = value;
    for (int step : {+1, -1}) {
      int cur = i;
      while (count_neighbours(cur, step) == 1) {
        int next = only_neighbour(cur, step);
        if (count_neighbours(next, -step) != 1 || label[std::size_t(next)] != 0) break;
        label[std::size_t(next)] = value;
        cur = next;
      }
    }
  }

  int parent_group(int i) const {
    int p = g.nodes[std::size_t(i)].parent;
    return p < 0 ? -2 : group[std::size_t(p)];  // -2: a root, whose "parent" always matches
  }
};

// Tung and Schmitt's rule on one side (step): matched parents of the neighbours must agree.
bool neighbours_agree(const Side& X, const Side& Y, int m, int n, int step) {
  int mx[16], ny[16];
  int cx = 0, cy = 0;
  X.for_neighbours(m, step, [&](int j) {
    int gp = X.parent_group(j);
    if (gp >= 0 && cx < 16) mx[cx++] = gp;
  });
  if (cx == 0) return true;
  Y.for_neighbours(n, step, [&](int j) {
    int gp = Y.parent_group(j);
    if (gp >= 0 && cy < 16) ny[cy++] = gp;
  });
  if (cy == 0) return true;
  for (int a = 0; a < cx; ++a)
    for (int b = 0; b < cy; ++b)
      if (mx[a] == ny[b]) return true;
  return false;
}

bool candidate(const Side& X, const Side& Y, int m, int n, const Weights& w) {
  const ArgNode& a = X.g.nodes[std::size_t(m)];
  const ArgNode& b = Y.g.nodes[std::size_t(n)];
  if (a.interval != b.interval || Y.group[std::size_t(n)] >= 0) return false;
  int pa = X.parent_group(m), pb = Y.parent_group(n);
  if (pa == -1 || pa != pb) return false;
  if (X.label[std::size_t(m)] != Y.label[std::size_t(n)]) return false;
  if (w.tung_rule && !(neighbours_agree(X, Y, m, n, +1) && neighbours_agree(X, Y, m, n, -1)))
    return false;
  return true;
}

// Unmatched nodes of `side` whose parent is matched join a group of the same interval and
// parent; the group is chosen by the least loss against its first node on the other side.
void extend_groups(Side& side, const Side& other, std::vector<MatchGroup>& groups, int begin,
                   int end, bool is_x, const Weights& w) {
  for (int u = begin; u < end; ++u) {
    if (side.group[std::size_t(u)] >= 0 || side.parent_group(u) < 0) continue;
    const ArgNode& nu = side.g.nodes[std::size_t(u)];
    int best = -1;
    double best_loss = 0;
    for (int v = begin; v < end; ++v) {
      int gid = side.group[std::size_t(v)];
      if (gid < 0 || v == u) continue;
      const ArgNode& nv = side.g.nodes[std::size_t(v)];
      if (nv.interval != nu.interval || nv.parent != nu.parent) continue;
      const MatchGroup& grp = groups[std::size_t(gid)];
      int partner = is_x ? grp.y.front() : grp.x.front();
      double loss = node_loss(nu, other.g.nodes[std::size_t(partner)], side.g.levels(), w);
      if (best < 0 || loss < best_loss) best = gid, best_loss = loss;
    }
    if (best < 0) continue;
    // Only groups founded at this level are extended (v ranges over this level).
    (is_x ? groups[std::size_t(best)].x : groups[std::size_t(best)].y).push_back(u);
  }
}

}  // namespace

std::vector<MatchGroup> match_graphs(const ArgGraph& gx, const ArgGraph& gy, const Weights& w) {
  Side X(gx), Y(gy);
  std::vector<MatchGroup> groups;
  const int levels = std::min(gx.levels(), gy.levels());
  std::vector<int> order;
  std::vector<double> self;
  int next_label = 1;
  for (int r = 0; r <= levels; ++r) {
    const int xb = int(gx.level_begin[std::size_t(r)]),
              xe = int(gx.level_begin[std::size_t(r) + 1]);
    const int yb = int(gy.level_begin[std::size_t(r)]),
              ye = int(gy.level_begin[std::size_t(r) + 1]);
    const std::size_t level_first_group = groups.size();
    order.resize(std::size_t(xe - xb));
    std::iota(order.begin(), order.end(), xb);
    self.resize(gx.nodes.size());
    for (int m = xb; m < xe; ++m)
      self[std::size_t(m)] = node_sim(gx.nodes[std::size_t(m)], gx.nodes[std::size_t(m)], w);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return self[std::size_t(a)] > self[std::size_t(b)]; });
    for (int m : order) {
      const ArgNode& nm = gx.nodes[std::size_t(m)];
      if (X.parent_group(m) == -1) continue;  // parent unmatched: the subtree stays unmatched
      int best = -1;
      double best_loss = 0, best_sim = 0;
      // Y's nodes of one level are sorted by interval: scan only nm's interval.
      auto first =
          std::lower_bound(gy.nodes.begin() + yb, gy.nodes.begin() + ye, nm.interval,
                           [](const ArgNode& n, std::uint16_t k) { return n.interval < k; });
      for (int n = int(first - gy.nodes.begin());
           n < ye && gy.nodes[std::size_t(n)].interval == nm.interval; ++n) {
        if (!candidate(X, Y, m, n, w)) continue;
        double loss = node_loss(nm, gy.nodes[std::size_t(n)], gx.levels(), w);
        double sim = node_sim(nm, gy.nodes[std::size_t(n)], w);
        if (best < 0 || loss < best_loss || (loss == best_loss && sim > best_sim))
          best = n, best_loss = loss, best_sim = sim;
      }
      if (best < 0) continue;
      const int gid = int(groups.size());
      groups.push_back({r, {m}, {best}, best_loss});
      X.group[std::size_t(m)] = gid;
      Y.group[std::size_t(best)] = gid;
      if (X.label[std::size_t(m)] == 0) {
        X.label_branch(m, next_label);
        Y.label_branch(best, next_label);
        ++next_label;
      }
    }
    extend_groups(X, Y, groups, xb, xe, true, w);
    extend_groups(Y, X, groups, yb, ye, false, w);
    for (std::size_t k = level_first_group; k < groups.size(); ++k) {
      for (int m : groups[k].x) X.group[std::size_t(m)] = int(k);
      for (int n : groups[k].y) Y.group[std::size_t(n)] = int(k);
    }
  }
  // Canonical order: by level, then smallest x node.
  for (auto& g : groups) std::sort(g.x.begin(), g.x.end()), std::sort(g.y.begin(), g.y.end());
  std::sort(groups.begin(), groups.end(), [](const MatchGroup& a, const MatchGroup& b) {
    return a.level != b.level ? a.level < b.level : a.x.front() < b.x.front();
  });
  return groups;
}

}  // namespace arg
