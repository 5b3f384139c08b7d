// Regrouping MatchPair rows into matched groups and summing their attributes term by term.
#include "match/similarity_terms.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "match/mpair.hpp"
#include "match/node_similarity.hpp"

namespace arg {

SimilarityTerms similarity_terms(const ArgGraph& a, const ArgGraph& b, const Weights& weights,
                                 const std::vector<MatchPair>& matches) {
  Weights w = weights;
  if (!(a.summary.has_colour && b.summary.has_colour)) w.lambda_4 = 0;
  // Each group's level and its members on each side, as global node indices.
  struct Group {
    int level = 0;
    std::set<int> first, second;
  };
  std::map<int, Group> groups;
  for (const MatchPair& p : matches) {
    if (p.level < 0 || p.level > a.levels() || p.level > b.levels()) continue;
    Group& g = groups[p.group];
    g.level = p.level;
    g.first.insert(int(a.level_begin[std::size_t(p.level)]) + p.a_node);
    g.second.insert(int(b.level_begin[std::size_t(p.level)]) + p.b_node);
  }
  SimilarityTerms t;
  t.weights = w;
  for (const auto& [id, members] : groups) {
    NodeMass m, n;
    for (int i : members.first)
      if (i >= 0 && std::size_t(i) < a.nodes.size()) m.add(a.nodes[std::size_t(i)]);
    for (int i : members.second)
      if (i >= 0 && std::size_t(i) < b.nodes.size()) n.add(b.nodes[std::size_t(i)]);
    const double s = level_scale(w.level_ratio, members.level);
    t.a += s * w.alpha_s * std::min(m.a, n.a);
    t.l += s * w.beta_s * std::min(m.l, n.l);
    if (w.lambda_1 > 0) t.v += s * w.lambda_1 * std::min(m.v, n.v);
    if (w.lambda_2 > 0) t.cords += s * w.lambda_2 * histogram_min(m.cords, n.cords);
    if (w.lambda_3 > 0)
      t.curvature +=
          s * w.lambda_3 * 0.5 *
          (histogram_min(m.curv_mean, n.curv_mean) + histogram_min(m.curv_gauss, n.curv_gauss));
    if (w.lambda_4 > 0) t.colour += s * w.lambda_4 * histogram_min(m.colour, n.colour) / 3.0;
  }
  const double denominator = 0.5 * (self_mass(a, w) + self_mass(b, w));
  if (!(denominator > 0)) {
    SimilarityTerms none;
    none.weights = w;
    return none;
  }
  for (double* x : {&t.a, &t.l, &t.v, &t.cords, &t.curvature, &t.colour}) *x /= denominator;
  return t;
}

}  // namespace arg
