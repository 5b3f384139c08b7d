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
  std::vector<std::uint32_t> below_begin, below, above_begin, above, fill;
  std::vector<std::array<int, 2>> only;
  std::vector<OrderKey> keyed;
};

// The calling thread's buffers, looked up once a call (see thread_scratch in mpair.cpp).
[[gnu::noinline]] PackedBuffers& thread_buffers() {
  thread_local PackedBuffers b;
  return b;
}

// Each node's neighbours below (in the previous interval) and above, in the order of a decoded
// graph's adjacency (graph/compact_nodes.cpp's link_read_graph): each list sorted.
void neighbour_lists(std::size_t n, const CompactRecords& r, PackedBuffers& b) {
  b.below_begin.assign(n + 1, 0);
  b.above_begin.assign(n + 1, 0);
  for (auto [lo, hi] : r.pairs) ++b.below_begin[hi + 1], ++b.above_begin[lo + 1];
  for (std::size_t i = 0; i < n; ++i)
    b.below_begin[i + 1] += b.below_begin[i], b.above_begin[i + 1] += b.above_begin[i];
  // Pairs come by lower end: node i's upper ends are the pairs from above_begin[i], in order.
  b.below.resize(r.pairs.size());
  b.above.resize(r.pairs.size());
  b.fill.assign(b.below_begin.begin(), b.below_begin.end() - 1);
  for (std::size_t k = 0; k < r.pairs.size(); ++k) {
    const auto [lo, hi] = r.pairs[k];
    b.below[b.fill[hi]++] = lo;
    b.above[k] = hi;
  }
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
  neighbour_lists(n, r, b);
  p.weights = weights;
  p.keys.resize(n);
  p.sim_keys.resize(n);
  b.only.resize(n);
  p.parent_begin.resize(n + 1);
  p.parent_split.resize(n);
  p.parents.clear();
  const unsigned char* rec = r.records;
  for (std::size_t i = 0; i < n; ++i, rec += kCompactNodeSize) {
    const CompactScalars s = compact_scalars(rec);
    p.keys[i] = {r.parent[i], r.interval[i], s.a, s.l, s.r, s.theta, s.phi};
    SimKey& k = p.sim_keys[i];
    k.a = s.a, k.l = s.l, k.v = s.v, k.step = code_step(s.a);
    std::memcpy(k.code.data(), rec + kCompactCodesAt, kSimKeyCodes);
    // As prepare_nodes and prepare_neighbour_parents find them in the decoded adjacency.
    const std::uint32_t* below = b.below.data() + b.below_begin[i];
    const std::uint32_t* below_end = b.below.data() + b.below_begin[i + 1];
    const std::uint32_t* above = b.above.data() + b.above_begin[i];
    const std::uint32_t* above_end = b.above.data() + b.above_begin[i + 1];
    b.only[i] = {only_neighbour(below, below_end), only_neighbour(above, above_end)};
    add_neighbour_parents(
        i, below, below_end, above, above_end, [&r](std::uint32_t j) { return r.parent[j]; }, p);
  }
  p.parent_begin[n] = std::uint32_t(p.parents.size());
  p.branches = prepare_branches(b.only, p.keys);
  // The lists of match/child_halves.cpp (which checks, for any graph, what the reader checked
  // here): children in index order, so a parent's lower half first (nodes of a level are sorted
  // by interval, and each lies in a half of its parent's interval).
  p.child_begin.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (r.parent[i] >= 0) ++p.child_begin[std::size_t(r.parent[i]) + 1];
  for (std::size_t i = 0; i < n; ++i) p.child_begin[i + 1] += p.child_begin[i];
  p.children.resize(p.child_begin[n]);
  p.child_mid.assign(p.child_begin.begin() + 1, p.child_begin.end());
  b.fill.assign(p.child_begin.begin(), p.child_begin.end() - 1);
  for (std::size_t i = 0; i < n; ++i) {
    if (r.parent[i] < 0) continue;
    const std::size_t parent = std::size_t(r.parent[i]);
    const std::uint32_t at = b.fill[parent]++;
    p.children[at] = std::uint32_t(i);
    if ((r.interval[i] & 1) != 0 && p.child_mid[parent] == p.child_begin[parent + 1])
      p.child_mid[parent] = at;
  }
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
      p.plain);
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
