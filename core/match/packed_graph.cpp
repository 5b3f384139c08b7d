// Reading a row's keys, sim keys, links and self sims straight from format 3's records.
#include "match/packed_graph.hpp"

#include <array>
#include <cstring>
#include <vector>

#include "graph/compact_nodes.hpp"
#include "graph/quantise.hpp"
#include "graph/serialize.hpp"
#include "match/mpair.hpp"
#include "match/sim_key.hpp"

namespace arg {

namespace {

// Buffers of one reader, reused row after row.
struct PackedBuffers {
  CompactRecords records;
  std::vector<std::uint32_t> below, fill;
  std::vector<std::array<int, 2>> only;
  std::vector<OrderKey> keyed;
};

// The calling thread's buffers, looked up once a call (see thread_scratch in mpair.cpp).
[[gnu::noinline]] PackedBuffers& thread_buffers() {
  thread_local PackedBuffers b;
  return b;
}

// Each node's neighbours below (in the previous interval), then above, in the order of a
// decoded graph's adjacency (graph/compact_nodes.cpp's link_read_graph): each list sorted.
void neighbour_lists(std::size_t n, const CompactRecords& r, PackedBuffers& b, MatchPrep& p) {
  std::vector<std::uint32_t>& below = b.below;  // per node, how many below
  below.assign(n, 0);
  p.neighbour_begin.assign(n + 1, 0);
  for (auto [lo, hi] : r.pairs)
    ++below[hi], ++p.neighbour_begin[lo + 1], ++p.neighbour_begin[hi + 1];
  p.neighbour_split.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    p.neighbour_begin[i + 1] += p.neighbour_begin[i];
    p.neighbour_split[i] = p.neighbour_begin[i] + below[i];
  }
  p.neighbours.resize(2 * r.pairs.size() + 1);  // and the spare entry
  p.neighbours.back() = 0;
  // Pairs come by lower end, then upper end: each list fills in increasing order.
  b.fill.assign(p.neighbour_begin.begin(), p.neighbour_begin.end() - 1);
  std::uint32_t* above = below.data();  // reused: where each node's list above goes on
  for (std::size_t i = 0; i < n; ++i) above[i] = p.neighbour_split[i];
  for (auto [lo, hi] : r.pairs) {
    p.neighbours[b.fill[hi]++] = lo;
    p.neighbours[above[lo]++] = hi;
  }
}

// The one neighbour below and above node i, -1 where there is none or several: selects rather
// than branches (which neighbour counts a node has is not predictable).
std::array<int, 2> only_neighbours(const MatchPrep& p, std::size_t i) {
  const std::uint32_t b = p.neighbour_begin[i], split = p.neighbour_split[i],
                      e = p.neighbour_begin[i + 1];
  const int below = int(p.neighbours[b]), above = int(p.neighbours[split]);
  // (x + 1) * one - 1: x when `one`, else -1, in arithmetic (GCC kept branches for ?:).
  return {(below + 1) * int(split - b == 1) - 1, (above + 1) * int(e - split == 1) - 1};
}

}  // namespace

bool read_packed_graph(std::string_view bytes, const Weights& weights, PackedGraph& out) {
  PackedBuffers& b = thread_buffers();
  CompactRecords& r = b.records;
  MatchPrep& p = out.prep;
  p.level_begin.clear();  // unfit until the end
  if (!read_compact_value(bytes, out.head, r)) return false;
  const ArgGraph& g = out.head;
  const std::size_t n = r.parent.size();
  out.adjacency = 2 * r.pairs.size();
  neighbour_lists(n, r, b, p);
  p.weights = weights;
  p.keys.resize(n);
  p.sim_keys.resize(n);
  b.only.resize(n);
  const unsigned char* rec = r.records;
  for (std::size_t i = 0; i < n; ++i, rec += kCompactNodeSize) {
    const CompactScalars s = compact_scalars(rec);
    p.keys[i] = {r.parent[i], r.interval[i], s.a, s.l, s.r, s.theta, s.phi};
    SimKey& k = p.sim_keys[i];
    k.a = s.a, k.l = s.l, k.v = s.v, k.step = code_step(s.a);
    std::memcpy(k.code.data(), rec + kCompactCodesAt, kSimKeyCodes);
    // As prepare_nodes finds them in the decoded adjacency.
    b.only[i] = only_neighbours(p, i);
  }
  p.branches = prepare_branches(b.only, p.keys);
  // The lists of match/child_halves.cpp (which checks, for any graph, what the reader checked
  // here): children in index order, so a parent's lower half first (nodes of a level are sorted
  // by interval, and each lies in a half of its parent's interval).
  p.child_begin.assign(n + 1, 0);
  p.child_mid.assign(n, 0);  // first each node's children in the lower half of its interval
  for (std::size_t i = 0; i < n; ++i)
    if (r.parent[i] >= 0) {
      const std::size_t parent = std::size_t(r.parent[i]);
      ++p.child_begin[parent + 1];
      p.child_mid[parent] += (r.interval[i] & 1) == 0;
    }
  for (std::size_t i = 0; i < n; ++i) {
    p.child_begin[i + 1] += p.child_begin[i];
    p.child_mid[i] += p.child_begin[i];  // the lower half's children come first
  }
  p.children.resize(p.child_begin[n]);
  b.fill.assign(p.child_begin.begin(), p.child_begin.end() - 1);
  for (std::size_t i = 0; i < n; ++i)
    if (r.parent[i] >= 0) p.children[b.fill[std::size_t(r.parent[i])]++] = std::uint32_t(i);
  p.interval_begin.resize(interval_offset(g.levels() + 1));
  for (int level = 0; level <= g.levels(); ++level)
    fill_interval_begin(
        int(g.level_begin[std::size_t(level)]), int(g.level_begin[std::size_t(level) + 1]), level,
        [&r](int i) { return r.interval[std::size_t(i)]; },
        p.interval_begin.data() + interval_offset(level));
  // No colour: the plain sums are the only ones.
  Weights plain = weights;
  plain.lambda_4 = 0;
  fill_self(
      n,
      [&](std::size_t i) {
        const SimKey& k = p.sim_keys[i];
        return node_self_sim(k.a, k.l, k.v, plain);
      },
      g.level_begin, plain.level_ratio, p.plain);
  p.plain.order.clear();  // only when the row comes first (order_packed_graph)
  p.coloured.self.clear();
  p.coloured.order.clear();
  p.coloured.total = 0;
  p.level_begin = g.level_begin;
  r.records = nullptr;  // it pointed into `bytes`
  return true;
}

void order_packed_graph(PackedGraph& g) {
  if (g.prep.plain.order.size() != g.prep.plain.self.size())
    prepare_order(g.head.level_begin, g.head.levels(), g.prep.plain, &thread_buffers().keyed);
}

}  // namespace arg
