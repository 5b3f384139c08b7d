// The part of matching that depends on one graph only, done once for a graph compared many times.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "graph/arg_graph.hpp"
#include "match/node_similarity.hpp"
#include "match/sim_key.hpp"
#include "match/weights.hpp"

namespace arg {

// What the candidate scan of match_graphs reads of a node, packed: a node record is 248 bytes,
// and reading these few fields from records spread over 64 kB was most of a scan's time.
struct MatchKey {
  std::int32_t parent = -1;
  std::uint32_t interval = 0;
  float a = 0, l = 0, r = 0, theta = 0, phi = 0;  // the loss's attributes (node_loss)
  std::int32_t branch = 0;  // its branch (prepare_branches): the nodes a match labels together
};
static_assert(sizeof(MatchKey) == 32, "a key is an eighth of a node record");

// Where level r's entries start in MatchPrep::interval_begin: 2^r + 1 entries a level.
inline std::size_t interval_offset(int r) {
  return (std::size_t(1) << r) - 1 + std::size_t(r);
}

// What match_graphs would otherwise work out from one graph at every comparison: a ranking prepares
// its query once, an evaluation each model once. Holds no pointer into the graph, so it may be kept
// beside it, but it describes the graph as it was when prepared: prepare again after the graph
// changes.
struct MatchPrep {
  // Self sims (sim(m, m)) with one colour weight; lambda_4 counts only when both graphs have
  // colour, so a coloured graph needs both.
  struct Sums {
    std::vector<double> self;  // per node
    double total = 0;          // over every node: the graph's share of SIM's denominator
    // Per level, its nodes by decreasing self sim, ties by index; may be empty (a row's,
    // match/packed_graph.hpp) when the graph is not matched first.
    std::vector<int> order;
  };
  Weights weights;                         // as given to prepare_match (before the colour rule)
  std::vector<std::uint32_t> level_begin;  // the graph's level table, checked on use
  std::vector<MatchKey> keys;              // per node
  int branches = 0;                        // how many (MatchKey::branch)
  // Per node, what its group sims read (match/sim_key.hpp); empty when the graph's histograms
  // are not byte codes (then the sims read its node records).
  std::vector<SimKey> sim_keys;
  // Per level r, where each interval's nodes start (nodes of a level are sorted by interval):
  // interval_begin[interval_offset(r) + k] for k in 0 .. 2^r, the last being the level's end.
  std::vector<int> interval_begin;
  // Per node, for Tung and Schmitt's rule: its neighbours below (in the previous interval),
  // then those above, each in adjacency order: neighbours[neighbour_begin[i],
  // neighbour_split[i]) below, [neighbour_split[i], neighbour_begin[i + 1]) above. Matching
  // finds the groups of their parents when a node first needs them (most never do), so a
  // graph read for one comparison does not list distinct parents for every node. One spare
  // entry follows the lists, so that a list's first entry may be read before its length is
  // looked at (match/packed_graph.cpp selects rather than branches).
  std::vector<std::uint32_t> neighbour_begin, neighbour_split, neighbours;
  // Per node, its children in index order: children[child_begin[i], child_begin[i + 1]), those
  // in the upper half of its interval from child_mid[i] (match/child_halves.hpp); all three
  // empty when a child lies in neither half (the candidate scan then reads whole intervals).
  std::vector<std::uint32_t> child_begin, child_mid, children;
  Sums plain;     // lambda_4 = 0: when either graph has no colour
  Sums coloured;  // the weights' lambda_4: filled when the graph has colour and lambda_4 != 0

  // The sums for the effective lambda_4 (0, or weights.lambda_4 when colour counts), or nullptr
  // when not held.
  const Sums* sums(bool colour_counts) const;
};

// Fills `out` for `g` and `weights` (the weights as passed to arg_similarity).
void prepare_match(const ArgGraph& g, const Weights& weights, MatchPrep& out);

// Whether `prep` was made for a graph of g's shape (node count and level table), and also
// with these weights (a cheap guard that keeps every read in bounds: the caller keeps prep and
// graph together). A graph without node records (a head, match/packed_graph.hpp) fits a prep
// with sim keys of its level table: the prep alone then stands for its nodes.
bool prep_shape_fits(const MatchPrep* prep, const ArgGraph& g);
bool prep_fits(const MatchPrep* prep, const ArgGraph& g, const Weights& weights);

// Its parts one by one (match_graphs' own path when it gets no prep); `w` is the effective
// weights. prepare_nodes fills the only-neighbours and the keys (their branch is
// prepare_branches'); match/child_halves.hpp fills the children.
void prepare_nodes(const ArgGraph& g, std::vector<std::array<int, 2>>& only,
                   std::vector<MatchKey>& keys);
// Numbers the branches: chains of nodes each the only neighbour of the next in its own
// direction (Hilaga's branch, labelled as one by a match). Returns how many; each key's branch
// gets its node's, numbered from 0 in the order of their first nodes.
int prepare_branches(const std::vector<std::array<int, 2>>& only, std::vector<MatchKey>& keys);
void prepare_neighbours(const ArgGraph& g, MatchPrep& out);
// The one neighbour in [begin, end), -1 when there is none or several.
inline int only_neighbour(const std::uint32_t* begin, const std::uint32_t* end) {
  return end - begin == 1 ? int(*begin) : -1;
}
// Level r's part of interval_begin (2^r + 1 entries from `out`).
void prepare_interval_begin(const ArgGraph& g, int r, int* out);
// The same from the level's nodes [b, e), node n's interval being interval_of(n).
template <class IntervalOf>
void fill_interval_begin(int b, int e, int r, IntervalOf&& interval_of, int* out) {
  const int intervals = 1 << r;
  for (int k = 0; k <= intervals; ++k) out[k] = e;
  for (int n = e - 1; n >= b; --n) out[interval_of(n)] = n;
  for (int k = intervals - 1; k >= 0; --k) out[k] = out[k] < out[k + 1] ? out[k] : out[k + 1];
}
// A node's place in its level's order: the float nearest its self sim, then its index, in one
// integer (prepare_order settles self sims that share a float).
using OrderKey = std::uint64_t;
// `keyed` (optional) is scratch space kept by a caller that prepares many graphs.
void prepare_sums(const ArgGraph& g, const Weights& w, MatchPrep::Sums& out,
                  std::vector<OrderKey>* keyed = nullptr);
// Its first half: out.self[m] = self_of(m) for n nodes, and their total summed in node order,
// each times its level's level_scale (levels by `level_begin`, levels + 2 entries). The order
// of matching reads the self sims as they are: the ratio weighs levels, not nodes.
template <class SelfOf>
void fill_self(std::size_t n, SelfOf&& self_of, const std::vector<std::uint32_t>& level_begin,
               double level_ratio, MatchPrep::Sums& out) {
  out.self.resize(n);
  double total = 0;
  int level = 0;
  double scale = 1;
  for (std::size_t m = 0; m < n; ++m) {
    while (std::size_t(level) + 2 < level_begin.size() && m >= level_begin[std::size_t(level) + 1])
      scale = level_scale(level_ratio, ++level);
    total += (out.self[m] = self_of(m)) * scale;
  }
  out.total = total;
}
// Its second half: out.order from out.self, level by level of `level_begin` (levels + 2 entries).
void prepare_order(const std::vector<std::uint32_t>& level_begin, int levels, MatchPrep::Sums& out,
                   std::vector<OrderKey>* keyed = nullptr);

}  // namespace arg
