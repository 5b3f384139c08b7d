// SIM(M, N) from the matched groups, in a canonical order so that it is exactly symmetric.
#include "match/similarity.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <optional>
#include <stdexcept>

#include "features/laplace_spectrum.hpp"
#include "features/panorama_descriptor.hpp"
#include "match/match_prep.hpp"
#include "match/mpair.hpp"
#include "match/node_similarity.hpp"
#include "match/packed_graph.hpp"
#include "match/term_weights.hpp"

namespace arg {

namespace {

// The first keys of compare_graphs, which a head (match/packed_graph.hpp) has too: counts,
// then the global descriptor.
struct HeadKey {
  std::size_t nodes, adjacency;
  int levels;
  const std::array<float, kGlobalDims>& global;
};
HeadKey head_key(const ArgGraph& g) {
  return {g.nodes.size(), g.adjacency.size(), g.levels(), g.global};
}
HeadKey head_key(const PackedGraph& g) {
  return {g.prep.keys.size(), g.adjacency, g.head.levels(), g.head.global};
}
int compare_heads(const HeadKey& a, const HeadKey& b) {
  if (a.nodes != b.nodes) return a.nodes < b.nodes ? -1 : 1;
  if (a.levels != b.levels) return a.levels < b.levels ? -1 : 1;
  if (a.adjacency != b.adjacency) return a.adjacency < b.adjacency ? -1 : 1;
  return std::memcmp(a.global.data(), b.global.data(), sizeof(float) * a.global.size());
}

// Total order on graphs by content, so that (A, B) and (B, A) are matched the same way;
// 0 only for graphs equal in every node, link and descriptor value.
int compare_graphs(const ArgGraph& a, const ArgGraph& b) {
  static_assert(sizeof(ArgNode) ==
                    2 * 2 + 4 * 5 + 4 * 8 + 4 * (kCordBins + 2 * kCurvatureBins + 3 * kColourBins),
                "ArgNode must have no padding: it is compared with memcmp");
  // A head (no node records) is ordered by packed_similarity alone.
  if (a.nodes.empty() || b.nodes.empty())
    throw std::logic_error("a graph without node records came to compare_graphs");
  if (int c = compare_heads(head_key(a), head_key(b))) return c;
  if (int c = std::memcmp(a.nodes.data(), b.nodes.data(), sizeof(ArgNode) * a.nodes.size()))
    return c;
  // Equal node records imply equal section sizes; an empty section may have no storage at all.
  if (!a.children.empty())
    if (int c = std::memcmp(a.children.data(), b.children.data(), 4 * a.children.size())) return c;
  if (!a.adjacency.empty())
    if (int c = std::memcmp(a.adjacency.data(), b.adjacency.data(), 4 * a.adjacency.size()))
      return c;
  for (std::vector<float> ArgGraph::*section : {&ArgGraph::panorama, &ArgGraph::spectrum}) {
    const std::vector<float>& x = a.*section;
    const std::vector<float>& y = b.*section;
    if (x.size() != y.size()) return x.size() < y.size() ? -1 : 1;
    if (!x.empty())
      if (int c = std::memcmp(x.data(), y.data(), sizeof(float) * x.size())) return c;
  }
  return 0;
}

int index_in_level(const ArgGraph& g, int node) {
  return node - int(g.level_begin[g.nodes[std::size_t(node)].level]);
}

double similarity_ordered(const ArgGraph& x, const MatchPrep* px, const ArgGraph& y,
                          const MatchPrep* py, const Weights& w, std::vector<MatchPair>* matches,
                          bool swapped) {
  std::vector<MatchGroup> groups;
  std::vector<double> group_sim;
  double self_x = 0;
  const double numerator = match_graphs(x, px, y, py, w, matches ? &groups : nullptr,
                                        matches ? &group_sim : nullptr, &self_x);
  if (matches) {
    matches->clear();
    for (std::size_t k = 0; k < groups.size(); ++k)
      for (int m : groups[k].x)
        for (int n : groups[k].y) {
          MatchPair p;
          p.level = groups[k].level;
          p.a_node = index_in_level(x, m);
          p.b_node = index_in_level(y, n);
          if (swapped) std::swap(p.a_node, p.b_node);
          p.group = int(k);
          p.loss = groups[k].loss;
          p.sim = group_sim[k];
          matches->push_back(p);
        }
    std::stable_sort(matches->begin(), matches->end(), [](const MatchPair& p, const MatchPair& q) {
      return p.level != q.level ? p.level < q.level : p.a_node < q.a_node;
    });
  }
  const MatchPrep::Sums* sums_y = prep_shape_fits(py, y) ? py->sums(w.lambda_4 != 0) : nullptr;
  const double denominator = 0.5 * (self_x + (sums_y ? sums_y->total : self_mass(y, w)));
  if (!(denominator > 0)) return 0.0;
  return std::clamp(1.0 - numerator / denominator, 0.0, 1.0);
}

// graph_similarity with compare_graphs(a, b) given as `order` (computed when not given).
double graph_similarity_in(const ArgGraph& a, const ArgGraph& b, const Weights& weights,
                           std::vector<MatchPair>* matches, const MatchPrep* prep_a,
                           const MatchPrep* prep_b, std::optional<int> order) {
  // Colour is compared only when both models have some; otherwise it weighs nothing.
  Weights w = weights;
  if (!(a.summary.has_colour && b.summary.has_colour)) w.lambda_4 = 0;
  if (!prep_fits(prep_a, a, weights)) prep_a = nullptr;
  if (!prep_fits(prep_b, b, weights)) prep_b = nullptr;
  // A head has no node records to list pairs of (compare_graphs refuses to order one).
  if ((a.nodes.empty() || b.nodes.empty()) && matches)
    throw std::logic_error("a graph without node records came to list matched pairs");
  if (!order) order = compare_graphs(a, b);
  if (*order == 0 && !matches) return 0.0;  // identical graphs: self-identity holds exactly
  const double s = *order > 0 ? similarity_ordered(b, prep_b, a, prep_a, w, matches, true)
                              : similarity_ordered(a, prep_a, b, prep_b, w, matches, false);
  return *order == 0 ? 0.0 : s;
}

SimilarityParts parts_in(const ArgGraph& a, const ArgGraph& b, const Weights& w,
                         std::vector<MatchPair>* matches, const MatchPrep* prep_a,
                         const MatchPrep* prep_b, std::optional<int> order) {
  SimilarityParts p;
  const TermWeights t =
      term_weights(w, a.summary.flags | b.summary.flags, !a.panorama.empty() && !b.panorama.empty(),
                   !a.spectrum.empty() && !b.spectrum.empty());
  p.w_graph = t.graph, p.w_panorama = t.panorama, p.w_spectrum = t.spectrum;
  if (t.panorama > 0) p.panorama = panorama_distance(a.panorama, b.panorama);
  if (t.spectrum > 0) p.spectrum = spectrum_distance(a.spectrum, b.spectrum);
  if (t.graph > 0 || matches)
    p.graph = graph_similarity_in(a, b, w, matches, prep_a, prep_b, order);
  const TermShares shares = term_shares(t, p.graph, p.panorama, p.spectrum);
  p.share_graph = shares.graph, p.share_panorama = shares.panorama;
  p.share_spectrum = shares.spectrum;
  // mix_terms' sum, in its order: the shares a reader is shown add up to SIM to the bit.
  p.sim = std::clamp(shares.graph + shares.panorama + shares.spectrum, 0.0, 1.0);
  return p;
}

}  // namespace

double graph_similarity(const ArgGraph& a, const ArgGraph& b, const Weights& weights,
                        std::vector<MatchPair>* matches, const MatchPrep* prep_a,
                        const MatchPrep* prep_b) {
  return graph_similarity_in(a, b, weights, matches, prep_a, prep_b, std::nullopt);
}

SimilarityParts similarity_parts(const ArgGraph& a, const ArgGraph& b, const Weights& w,
                                 std::vector<MatchPair>* matches, const MatchPrep* prep_a,
                                 const MatchPrep* prep_b) {
  return parts_in(a, b, w, matches, prep_a, prep_b, std::nullopt);
}

double arg_similarity(const ArgGraph& a, const ArgGraph& b, const Weights& weights,
                      std::vector<MatchPair>* matches, const MatchPrep* prep_a,
                      const MatchPrep* prep_b) {
  if (matches) return similarity_parts(a, b, weights, matches, prep_a, prep_b).sim;
  const int order = compare_graphs(a, b);
  if (order == 0) return 0.0;  // identical: self-identity exactly
  return parts_in(a, b, weights, nullptr, prep_a, prep_b, order).sim;
}

bool packs_rows(const ArgGraph& a, const MatchPrep* prep_a, const Weights& weights) {
  // What matching a head allows (mpair.cpp): sim keys on both sides, no node groups, no colour
  // (a head has none).
  return !a.nodes.empty() && !weights.groups && prep_fits(prep_a, a, weights) &&
         !prep_a->sim_keys.empty();
}

bool packed_similarity(const ArgGraph& a, const MatchPrep* prep_a, PackedGraph& b,
                       const Weights& weights, double& sim) {
  if (!packs_rows(a, prep_a, weights) || !prep_fits(&b.prep, b.head, weights)) return false;
  const int order = compare_heads(head_key(a), head_key(b));
  if (order == 0) return false;          // the node records would decide
  if (order > 0) order_packed_graph(b);  // b is matched first: its order is read
  sim = parts_in(a, b.head, weights, nullptr, prep_a, &b.prep, order).sim;
  return true;
}

}  // namespace arg
