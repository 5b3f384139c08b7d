// MPAIR: coarse-to-fine topological matching of two multiresolution Reeb graphs.
#pragma once

#include <vector>

#include "graph/arg_graph.hpp"
#include "match/node_similarity.hpp"
#include "match/weights.hpp"

namespace arg {

// Nodes of X matched with nodes of Y as one unit (usually one node each; a node may match a
// group of nodes of the same interval and parent). Node indices are global.
struct MatchGroup {
  int level = 0;
  std::vector<int> x, y;
  double loss = 0;  // loss of the pair that founded the group
};

// Matches X and Y level by level from the coarsest. At each level, nodes of X are taken in
// decreasing order of their own sim (their weight in SIM; ties by index); each takes, among
// the unmatched nodes of Y that are candidates, the one of least loss (ties: larger sim, then
// smaller index). (m, n) is a candidate when
//   - both lie in the same mu interval;
//   - their parents were matched to each other at the previous level (level 0: always);
//   - they carry the same branch label: a match labels the branch through each of its nodes
//     (walking to neighbours up and down until a fork) with a fresh label, so that a branch is
//     matched to one branch only (Hilaga et al.);
//   - with weights.tung_rule: on each side (up, down), when parents of neighbours of m and of
//     n are matched, at least one such parent of m is matched to one of n (Tung and Schmitt).
// With weights.groups (Hilaga's node groups), each still unmatched node whose parent is
// matched then joins the group of a matched node of the same interval and parent, when there
// is one (least loss first). Off in the `arg` preset: on SHREC 2007 it joined unrelated
// branches (an arm to a leg) and lowered the first tier (0.659 without, 0.650 with).
// Returns the sum of the groups' sims (summed attributes of the members on each side), the
// numerator of SIM. When given, `groups` receives the groups in the order they were founded
// (level by level) and `group_sim` each group's sim.
// `self_x` (optional) receives the sum of sim(m, m) over X's nodes, computed on the way.
double match_graphs(const ArgGraph& x, const ArgGraph& y, const Weights& weights,
                    std::vector<MatchGroup>* groups = nullptr,
                    std::vector<double>* group_sim = nullptr, double* self_x = nullptr);

struct MatchPrep;

// The same, with the per-graph parts from each graph's MatchPrep (match/match_prep.hpp) where
// given (nullptr: worked out here). `weights` are the effective ones (lambda_4 = 0 unless both
// graphs have colour); each prep must have been made for its graph as it is now, with these
// weights before that rule (arg_similarity checks this with prep_fits; only the graph's shape
// is checked here, which keeps every read in bounds).
double match_graphs(const ArgGraph& x, const MatchPrep* px, const ArgGraph& y, const MatchPrep* py,
                    const Weights& weights, std::vector<MatchGroup>* groups = nullptr,
                    std::vector<double>* group_sim = nullptr, double* self_x = nullptr);

// sim(m, m) without the histogram loops: every histogram of a node sums to its area (colour:
// each of its three channels, counted a third each).
inline double node_self_sim(float a, float l, float v, const Weights& w) {
  return (w.alpha_s + w.lambda_2 + w.lambda_3 + w.lambda_4) * double(a) + w.beta_s * double(l) +
         w.lambda_1 * double(v);
}
inline double node_self_sim(const ArgNode& n, const Weights& w) {
  return node_self_sim(n.a, n.l, n.v, w);
}

// Sum of every node's own sim, each level's by its level_scale: what SIM's numerator would
// reach if the graph met itself (its share of the denominator).
inline double self_mass(const ArgGraph& g, const Weights& w) {
  double s = 0;
  for (const ArgNode& n : g.nodes) s += node_self_sim(n, w) * level_scale(w.level_ratio, n.level);
  return s;
}

}  // namespace arg
