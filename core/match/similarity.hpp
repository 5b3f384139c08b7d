// Comparing two ARGs: the matched node pairs, SIM and part matching.
#pragma once

#include <cstdint>
#include <vector>

#include "common/limits.hpp"
#include "graph/arg_graph.hpp"
#include "match/weights.hpp"

namespace arg {

struct MatchPrep;
struct PackedGraph;

// One matched pair; a node matched to a group appears in several rows with the same group.
struct MatchPair {
  int level = 0;
  int a_node = 0;  // index within its level in the first argument
  int b_node = 0;  // index within its level in the second argument
  int group = 0;   // rows with the same group form one match
  double loss = 0;
  double sim = 0;  // contribution to the numerator of SIM (shared by the group's rows)
};

// SIM(A, B) in [0, 1]: 0 for identical values, exactly symmetric. The weighted mean of the
// graph's SIM and the whole-shape distances (Weights::graph, panorama, spectrum; the graph's
// weight times graph_on_proxy when either was built on a proxy); a term one of the values
// lacks is left out. Fills `matches` (the graph's node pairs) if given.
// `prep_a` and `prep_b` (optional, match/match_prep.hpp): the graphs' per-graph parts of
// matching, made with these weights, to compare one graph many times for less; the result is
// the same to the bit with or without them (a prep made with other weights is not used).
double arg_similarity(const ArgGraph& a, const ArgGraph& b, const Weights& weights = {},
                      std::vector<MatchPair>* matches = nullptr, const MatchPrep* prep_a = nullptr,
                      const MatchPrep* prep_b = nullptr);

// Whether rows may be compared with `a` as packed graphs: a decoded graph whose prep fits it
// with sim keys, and weights that do not group nodes (groups read node records).
bool packs_rows(const ArgGraph& a, const MatchPrep* prep_a, const Weights& weights);

// arg_similarity(a, b's decoded graph, weights, nullptr, prep_a, b's prep) for a row read by
// read_packed_graph with these weights, the same to the bit, without b's node records. Returns
// false, `sim` untouched, when that needs them: not packs_rows, b not read (its prep unfit), or
// b's counts and global descriptor equal a's (the node records would order the two). Compare b
// decoded then.
// b's prep gets its order when b is matched first (order_packed_graph).
bool packed_similarity(const ArgGraph& a, const MatchPrep* prep_a, PackedGraph& b,
                       const Weights& weights, double& sim);

// The graph's own SIM (Hilaga et al., Tung and Schmitt): 1 - matched sim over self sim, in
// [0, 1], 0 for identical graphs, exactly symmetric. Fills `matches` if given.
double graph_similarity(const ArgGraph& a, const ArgGraph& b, const Weights& weights = {},
                        std::vector<MatchPair>* matches = nullptr,
                        const MatchPrep* prep_a = nullptr, const MatchPrep* prep_b = nullptr);

// The terms of arg_similarity: each distance in [0, 1], the weight it got (0 when left out) and
// its share of SIM (weight x distance over the sum of the weights: term_shares); sim is the
// three shares added graph, panorama, spectrum (clamped to [0, 1], which they never leave).
struct SimilarityParts {
  double graph = 0, panorama = 0, spectrum = 0;
  double w_graph = 0, w_panorama = 0, w_spectrum = 0;
  double share_graph = 0, share_panorama = 0, share_spectrum = 0;
  double sim = 0;
};
SimilarityParts similarity_parts(const ArgGraph& a, const ArgGraph& b, const Weights& weights,
                                 std::vector<MatchPair>* matches = nullptr,
                                 const MatchPrep* prep_a = nullptr,
                                 const MatchPrep* prep_b = nullptr);

struct PartMatch {
  int level = 0;
  int node = 0;      // index within its level in the candidate
  double score = 0;  // SIM of the sub-graphs, 0 = same part
};

// Part matching (paper section 5). Candidates are the nodes of `candidate` at `level` and the
// neighbouring levels whose node similarity to the query node (sim over the larger self-sim,
// with the nodes' own attributes, so relative size counts) reaches `threshold` and whose
// number of neighbours differs by at most one. Each is scored by the mean of the SIM of the
// renormalised sub-graphs below the two nodes and 1 - the node similarity; best (lowest)
// first. `node` is the query node's index within `level`. The weights default to the `part`
// preset, with which parts find their kin better than with the `arg` preset's (weights.hpp).
// Throws InputError when level or node is out of range, Interrupted when `stop` says so (it is
// polled once per candidate node).
std::vector<PartMatch> part_match(const ArgGraph& query, int level, int node,
                                  const ArgGraph& candidate,
                                  const Weights& weights = weights_preset("part"),
                                  double threshold = 0.5, const StopRequested& stop = {});

}  // namespace arg
