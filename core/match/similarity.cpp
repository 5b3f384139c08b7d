// SIM(M, N) from the matched groups, in a canonical order so that it is exactly symmetric.
#include "match/similarity.hpp"

#include <algorithm>
#include <cstring>

#include "match/mpair.hpp"
#include "match/node_similarity.hpp"

namespace arg {

namespace {

// Total order on graphs by content, so that (A, B) and (B, A) are matched the same way.
int compare_graphs(const ArgGraph& a, const ArgGraph& b) {
  if (a.nodes.size() != b.nodes.size()) return a.nodes.size() < b.nodes.size() ? -1 : 1;
  if (a.levels() != b.levels()) return a.levels() < b.levels() ? -1 : 1;
  auto cmp = [](const void* x, const void* y, std::size_t n) { return std::memcmp(x, y, n); };
  if (int c = cmp(a.global.data(), b.global.data(), sizeof(float) * a.global.size())) return c;
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    const ArgNode& m = a.nodes[i];
    const ArgNode& n = b.nodes[i];
    const float fm[] = {m.a, m.l, m.r, m.theta, m.phi, m.v, float(m.interval), float(m.adj_count)};
    const float fn[] = {n.a, n.l, n.r, n.theta, n.phi, n.v, float(n.interval), float(n.adj_count)};
    for (int k = 0; k < 8; ++k)
      if (fm[k] != fn[k]) return fm[k] < fn[k] ? -1 : 1;
  }
  return 0;
}

// Sum of every node's own sim: the value the numerator reaches when a graph meets itself.
double self_mass(const ArgGraph& g, const Weights& w) {
  double s = 0;
  for (const ArgNode& n : g.nodes) s += node_sim(n, n, w);
  return s;
}

int index_in_level(const ArgGraph& g, int node) {
  return node - int(g.level_begin[g.nodes[std::size_t(node)].level]);
}

double similarity_ordered(const ArgGraph& x, const ArgGraph& y, const Weights& w,
                          std::vector<MatchPair>* matches, bool swapped) {
  std::vector<MatchGroup> groups = match_graphs(x, y, w);
  double numerator = 0;
  int group_id = 0;
  if (matches) matches->clear();
  for (const MatchGroup& g : groups) {
    double sim;
    if (g.x.size() == 1 && g.y.size() == 1) {
      sim = node_sim(x.nodes[std::size_t(g.x[0])], y.nodes[std::size_t(g.y[0])], w);
    } else {
      NodeMass mx, my;
      for (int m : g.x) mx.add(x.nodes[std::size_t(m)]);
      for (int n : g.y) my.add(y.nodes[std::size_t(n)]);
      sim = node_sim(mx, my, w);
    }
    numerator += sim;
    if (matches) {
      for (int m : g.x)
        for (int n : g.y) {
          MatchPair p;
          p.level = g.level;
          p.a_node = index_in_level(x, m);
          p.b_node = index_in_level(y, n);
          if (swapped) std::swap(p.a_node, p.b_node);
          p.group = group_id;
          p.loss = g.loss;
          p.sim = sim;
          matches->push_back(p);
        }
    }
    ++group_id;
  }
  // The self masses are summed in node order, like the numerator of a graph matched with
  // itself (identity groups in node order), so SIM(M, M) is exactly 0.
  const double sx = self_mass(x, w), sy = self_mass(y, w);
  const double denominator = x.nodes.size() == y.nodes.size() && sx == sy ? sx : 0.5 * (sx + sy);
  if (!(denominator > 0)) return 0.0;
  return std::clamp(1.0 - numerator / denominator, 0.0, 1.0);
}

}  // namespace

double arg_similarity(const ArgGraph& a, const ArgGraph& b, const Weights& w,
                      std::vector<MatchPair>* matches) {
  const bool swap = compare_graphs(a, b) > 0;
  double s = swap ? similarity_ordered(b, a, w, matches, true)
                  : similarity_ordered(a, b, w, matches, false);
  if (matches && swap)
    std::stable_sort(matches->begin(), matches->end(), [](const MatchPair& p, const MatchPair& q) {
      return p.level != q.level ? p.level < q.level : p.a_node < q.a_node;
    });
  return s;
}

}  // namespace arg
