// A graph's part of matching, worked out once: packed keys with their branches, neighbour
// lists, children in halves, sim keys, where intervals start, self sims and each level's
// order.
#include "match/match_prep.hpp"

#include <algorithm>
#include <cstring>
#include <utility>

#include "match/child_halves.hpp"
#include "match/mpair.hpp"

namespace arg {

const MatchPrep::Sums* MatchPrep::sums(bool colour_counts) const {
  if (!colour_counts) return &plain;
  return coloured.self.size() == plain.self.size() ? &coloured : nullptr;
}

namespace {

// Where node n's neighbours above start in its adjacency (sorted, those below at lower indices:
// nodes of a level are sorted by interval).
const std::uint32_t* above_begin(const ArgGraph& g, std::size_t i) {
  const ArgNode& n = g.nodes[i];
  const std::uint32_t *adj = g.adjacency.data() + n.adj_begin, *end = adj + n.adj_count;
  while (adj != end && *adj < i) ++adj;
  return adj;
}

}  // namespace

void prepare_nodes(const ArgGraph& g, std::vector<std::array<int, 2>>& only,
                   std::vector<MatchKey>& keys) {
  // One pass: what it reads lies in the first 64 bytes of a node's record.
  only.resize(g.nodes.size());
  keys.resize(g.nodes.size());
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const ArgNode& n = g.nodes[i];
    keys[i] = {n.parent, n.interval, n.a, n.l, n.r, n.theta, n.phi};
    const std::uint32_t *adj = g.adjacency.data() + n.adj_begin, *split = above_begin(g, i);
    only[i] = {only_neighbour(adj, split), only_neighbour(split, adj + n.adj_count)};
  }
}

int prepare_branches(const std::vector<std::array<int, 2>>& only, std::vector<MatchKey>& keys) {
  int count = 0;
  for (std::size_t i = 0; i < only.size(); ++i) {
    // The neighbour below lies in a lower interval of the level, so at a lower index: its
    // branch is known. Evaluated whole and selected (whether a node joins a chain is not
    // predictable): node 0 stands in for a missing neighbour.
    const int below = only[i][0];
    const std::size_t at = std::size_t(std::max(below, 0));
    const bool joins = (below >= 0) & (below < int(i)) & (only[at][1] == int(i));
    const int branch = keys[at].branch;
    keys[i].branch = joins ? branch : count;
    count += !joins;
  }
  return count;
}

void prepare_neighbours(const ArgGraph& g, MatchPrep& out) {
  const std::size_t n = g.nodes.size();
  out.neighbour_begin.resize(n + 1);
  out.neighbour_split.resize(n);
  out.neighbours.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const ArgNode& node = g.nodes[i];
    const std::uint32_t* adj = g.adjacency.data() + node.adj_begin;
    out.neighbour_begin[i] = std::uint32_t(out.neighbours.size());
    out.neighbour_split[i] = std::uint32_t(out.neighbours.size() + (above_begin(g, i) - adj));
    out.neighbours.insert(out.neighbours.end(), adj, adj + node.adj_count);
  }
  out.neighbour_begin[n] = std::uint32_t(out.neighbours.size());
  out.neighbours.push_back(0);  // the spare entry (match_prep.hpp)
}

void prepare_interval_begin(const ArgGraph& g, int r, int* out) {
  fill_interval_begin(
      int(g.level_begin[std::size_t(r)]), int(g.level_begin[std::size_t(r) + 1]), r,
      [&g](int n) { return g.nodes[std::size_t(n)].interval; }, out);
}

void prepare_sums(const ArgGraph& g, const Weights& w, MatchPrep::Sums& out,
                  std::vector<OrderKey>* scratch) {
  fill_self(
      g.nodes.size(), [&](std::size_t m) { return node_self_sim(g.nodes[m], w); }, g.level_begin,
      w.level_ratio, out);
  prepare_order(g.level_begin, g.levels(), out, scratch);
}

namespace {

// Orders doubles as integers: larger self sims first (their bits, made monotonic over the sign
// and complemented), -0 as +0, so that the keys sort as (-self, index) pairs would.
std::uint64_t descending(double x) {
  if (x == 0) x = 0;  // -0 to +0
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const std::uint64_t ascending = (bits >> 63) != 0 ? ~bits : bits | (std::uint64_t(1) << 63);
  return ~ascending;
}
// The same for the float nearest a double: rounding never reverses two doubles' order, so
// these keys order nodes as the doubles do except where two doubles round to one float.
std::uint32_t descending(float x) {
  if (x == 0) x = 0;
  std::uint32_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const std::uint32_t ascending = (bits >> 31) != 0 ? ~bits : bits | (std::uint32_t(1) << 31);
  return ~ascending;
}

// Sorts keys by their upper 32 bits, keeping the order of equal ones, with room for n more at
// `spare`: an LSD radix sort, a byte a pass, passes where every key has the same byte skipped.
// A comparison sort's branches on keys in no order are mostly mispredicted; a radix sort has
// none to mispredict (docs/BENCHMARKS.md, "ARG values", compares the three sorts tried).
void sort_by_upper_half(OrderKey* keys, std::size_t n, OrderKey* spare) {
  if (n <= 32) {  // insertion sort: few enough comparisons
    for (std::size_t i = 1; i < n; ++i) {
      const OrderKey x = keys[i];
      std::size_t j = i;
      for (; j > 0 && keys[j - 1] >> 32 > x >> 32; --j) keys[j] = keys[j - 1];
      keys[j] = x;
    }
    return;
  }
  std::uint32_t count[4][256] = {};  // every byte's histogram in one pass
  for (std::size_t i = 0; i < n; ++i)
    for (int b = 0; b < 4; ++b) ++count[b][(keys[i] >> (32 + 8 * b)) & 0xff];
  OrderKey *from = keys, *to = spare;
  for (int b = 0; b < 4; ++b) {
    const int shift = 32 + 8 * b;
    if (count[b][(from[0] >> shift) & 0xff] == n) continue;  // one byte for all
    std::uint32_t sum = 0;  // where each byte's keys start, summed in a register
    for (std::uint32_t& c : count[b]) {
      const std::uint32_t here = c;
      c = sum;
      sum += here;
    }
    for (std::size_t i = 0; i < n; ++i) to[count[b][(from[i] >> shift) & 0xff]++] = from[i];
    std::swap(from, to);
  }
  if (from != keys) std::copy(from, from + n, keys);
}

}  // namespace

void prepare_order(const std::vector<std::uint32_t>& level_begin, int levels, MatchPrep::Sums& out,
                   std::vector<OrderKey>* scratch) {
  // The keys are (the float of a self sim, the index), sorted by float stably: nodes whose self
  // sims share a float come by index, and are then put in the doubles' order, which makes the
  // order exactly (-self, index)'s.
  const std::size_t n = out.self.size();
  std::vector<OrderKey> own;
  std::vector<OrderKey>& keyed = scratch ? *scratch : own;
  keyed.resize(2 * n);  // the second half: the sort's spare room
  for (std::size_t m = 0; m < n; ++m)
    keyed[m] = OrderKey(descending(float(out.self[m]))) << 32 | std::uint32_t(m);
  out.order.resize(n);
  for (int r = 0; r <= levels; ++r) {
    const std::size_t b = level_begin[std::size_t(r)], e = level_begin[std::size_t(r) + 1];
    sort_by_upper_half(keyed.data() + b, e - b, keyed.data() + n + b);
    for (std::size_t k = b; k < e; ++k) out.order[k] = int(std::uint32_t(keyed[k]));
    for (std::size_t k = b; k + 1 < e;) {
      std::size_t run = k + 1;
      while (run < e && keyed[run] >> 32 == keyed[k] >> 32) ++run;
      if (run - k > 1)
        std::sort(out.order.begin() + std::ptrdiff_t(k), out.order.begin() + std::ptrdiff_t(run),
                  [&out](int x, int y) {
                    const std::uint64_t kx = descending(out.self[std::size_t(x)]),
                                        ky = descending(out.self[std::size_t(y)]);
                    return kx != ky ? kx < ky : x < y;
                  });
      k = run;
    }
  }
}

void prepare_match(const ArgGraph& g, const Weights& weights, MatchPrep& out) {
  out.weights = weights;
  out.level_begin = g.level_begin;
  std::vector<std::array<int, 2>> only;
  prepare_nodes(g, only, out.keys);
  out.branches = prepare_branches(only, out.keys);
  prepare_neighbours(g, out);
  prepare_child_halves(g, out.keys, out.child_begin, out.child_mid, out.children);
  make_sim_keys(g, out.sim_keys);
  out.interval_begin.resize(interval_offset(g.levels() + 1));
  for (int r = 0; r <= g.levels(); ++r)
    prepare_interval_begin(g, r, out.interval_begin.data() + interval_offset(r));
  Weights plain = weights;
  plain.lambda_4 = 0;
  prepare_sums(g, plain, out.plain);
  if (g.summary.has_colour && weights.lambda_4 != 0) {
    prepare_sums(g, weights, out.coloured);
  } else {
    out.coloured.self.clear();
    out.coloured.order.clear();
    out.coloured.total = 0;
  }
}

bool prep_shape_fits(const MatchPrep* prep, const ArgGraph& g) {
  if (!prep) return false;
  // A head (no node records, match/packed_graph.hpp) is matched on its prep's keys alone.
  const bool head = g.nodes.empty();
  const std::size_t n = head ? prep->keys.size() : g.nodes.size();
  if (head && (n == 0 || prep->sim_keys.size() != n || g.level_begin.size() < 2 ||
               g.level_begin.back() != n))
    return false;
  return prep->level_begin == g.level_begin && prep->neighbour_split.size() == n &&
         prep->neighbour_begin.size() == n + 1 &&
         prep->neighbour_begin[n] + 1 == prep->neighbours.size() && prep->keys.size() == n &&
         (prep->child_begin.empty() ||
          (prep->child_begin.size() == n + 1 && prep->child_mid.size() == n &&
           prep->child_begin[n] == prep->children.size())) &&
         (prep->sim_keys.empty() || prep->sim_keys.size() == n) && prep->plain.self.size() == n &&
         (prep->plain.order.size() == n || prep->plain.order.empty()) &&
         prep->interval_begin.size() == interval_offset(g.levels() + 1);
}

bool prep_fits(const MatchPrep* prep, const ArgGraph& g, const Weights& weights) {
  return prep_shape_fits(prep, g) && prep->weights == weights;
}

}  // namespace arg
