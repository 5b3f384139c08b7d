// Shortest paths for kLanes sources at once: Gauss-Seidel sweeps, forward and backward in turn
// over a few node orders, of rows of kLanes distances updated together (one vector min per arc
// instead of a bucket-queue step per source and arc). Distances in whole units of the
// quantised lengths are integers and the sweeps stop only at the fixpoint, where every row is
// the least over its arcs: that is the shortest distance, so the result is the bucket queue's
// to the bit, whatever the orders or the number of sweeps.
#include "mu/lane_steps.hpp"

#include <algorithm>

#include "common/radix_sort.hpp"

namespace arg {

namespace {

using Lanes = std::int32_t __attribute__((vector_size(4 * kLanes)));

bool differ(const Lanes& a, const Lanes& b) {
  // Eight 64-bit words rather than sixteen lanes: the compiler keeps this in a few instructions.
  using Words = std::uint64_t __attribute__((vector_size(4 * kLanes)));
  const Words w = reinterpret_cast<Words>(a) ^ reinterpret_cast<Words>(b);
  std::uint64_t any = 0;
  for (int k = 0; k < kLanes / 2; ++k) any |= w[k];
  return any != 0;
}

// Nodes by key, ties by node: one radix sort of key << 32 | node.
std::vector<int> sorted_nodes(const std::vector<std::uint32_t>& key, const StopRequested& stop) {
  std::vector<std::uint64_t> records(key.size()), scratch;
  for (std::size_t v = 0; v < key.size(); ++v)
    records[v] = std::uint64_t(key[v]) << 32 | std::uint64_t(v);
  radix_sort_by_key(
      records, [](std::uint64_t r) { return r; }, scratch, stop);
  std::vector<int> order(key.size());
  for (std::size_t i = 0; i < key.size(); ++i) order[i] = int(std::uint32_t(records[i]));
  return order;
}

}  // namespace

LaneGraph lane_graph(const SurfaceGraph& g, const BucketScratch& q,
                     const std::vector<std::vector<std::uint32_t>>& keys,
                     const StopRequested& stop) {
  const int n = g.nodes();
  LaneGraph out;
  const std::vector<int> layout = sorted_nodes(keys.at(0), stop);
  out.rank.assign(std::size_t(n), 0);
  for (int i = 0; i < n; ++i) out.rank[std::size_t(layout[std::size_t(i)])] = i;
  out.offset.assign(std::size_t(n) + 1, 0);
  out.arc.resize(q.arc.size());
  std::size_t next = 0;
  for (int i = 0; i < n; ++i) {
    poll_interrupt(std::size_t(i), stop);
    const int v = layout[std::size_t(i)];
    for (int k = g.offset[std::size_t(v)]; k < g.offset[std::size_t(v) + 1]; ++k) {
      const std::uint64_t a = q.arc[std::size_t(k)];
      out.arc[next++] = std::uint64_t(std::uint32_t(out.rank[std::uint32_t(a)])) | (a >> 32 << 32);
    }
    out.offset[std::size_t(i) + 1] = int(next);
  }
  std::uint64_t total = 0;
  for (std::uint64_t a : out.arc) total += a >> 32;
  out.fits = total < std::uint64_t(kLaneFar);
  for (std::size_t o = 1; o < keys.size(); ++o) {
    std::vector<int> order = sorted_nodes(keys[o], stop);
    for (int& v : order) v = out.rank[std::size_t(v)];
    out.orders.push_back(std::move(order));
  }
  return out;
}

// The sweeps are the build's hottest loop: compiled for AVX-512 and AVX2 besides the baseline,
// the processor choosing at load time (integers: every variant gives the same bits).
__attribute__((target_clones("avx512f", "avx2", "default"))) void shortest_steps_lanes(
    const LaneGraph& g, const int* sources, int count, LaneRows& s, const StopRequested& stop) {
  const int n = g.rows();
  s.values.resize(std::size_t(n) * kLanes + kLanes);
  const auto address = reinterpret_cast<std::uintptr_t>(s.values.data());
  s.first = ((64 - address % 64) % 64) / sizeof(std::int32_t);
  s.dirty.assign(std::size_t(n), 0);
  Lanes* const row = reinterpret_cast<Lanes*>(s.values.data() + s.first);
  const int* const offset = g.offset.data();
  const std::uint64_t* const arc = g.arc.data();
  std::uint8_t* const dirty = s.dirty.data();
  Lanes far;
  for (int l = 0; l < kLanes; ++l) far[l] = kLaneFar;
  for (int p = 0; p < n; ++p) row[p] = far;
  auto mark_neighbours = [&](int p) {
    for (int k = offset[p]; k < offset[p + 1]; ++k) dirty[std::uint32_t(arc[k])] = 1;
  };
  for (int l = 0; l < count; ++l) {
    const int p = g.rank[std::size_t(sources[l])];
    row[p][l] = 0;
    mark_neighbours(p);
  }
  // A row is pulled only if a neighbour changed since its last pull: no other can improve.
  // A sweep that changes nothing has reached the fixpoint.
  const int orders = int(g.orders.size()) + 1;
  int sweep = 0;
  for (bool changed = true; changed; ++sweep) {
    check_interrupt(stop);
    changed = false;
    const int which = (sweep / 2) % orders;
    const int* const order = which == 0 ? nullptr : g.orders[std::size_t(which - 1)].data();
    const bool forward = sweep % 2 == 0;
    for (int i = 0; i < n; ++i) {
      const int j = forward ? i : n - 1 - i;
      const int p = order ? order[j] : j;
      if (!dirty[p]) continue;
      dirty[p] = 0;
      Lanes best = row[p];
      const int end = offset[p + 1];
      for (int k = offset[p]; k < end; ++k) {
        const std::uint64_t a = arc[k];
        const Lanes through = row[std::uint32_t(a)] + std::int32_t(a >> 32);
        best = through < best ? through : best;
      }
      if (differ(best, row[p])) {
        row[p] = best;
        mark_neighbours(p);
        changed = true;
      }
    }
  }
  s.sweeps = sweep;
}

}  // namespace arg
