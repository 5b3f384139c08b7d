// Dijkstra with an indexed 4-ary heap (decrease-key in place, no stale entries).
#include "mu/dijkstra.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace arg {

namespace {

// Min-heap of node ids keyed by their current distance; pos[v] = slot of v or -1.
class QuadHeap {
 public:
  QuadHeap(int n, const std::vector<float>& key)
      : key_(key), pos_(static_cast<std::size_t>(n), -1) {
    heap_.reserve(static_cast<std::size_t>(n));
  }
  bool empty() const { return heap_.empty(); }
  void push_or_decrease(int v) {
    int i = pos_[std::size_t(v)];
    if (i < 0) {
      i = int(heap_.size());
      heap_.push_back(v);
    }
    sift_up(i, v);
  }
  int pop() {
    int top = heap_[0];
    pos_[std::size_t(top)] = -2;  // settled
    int last = heap_.back();
    heap_.pop_back();
    if (!heap_.empty()) sift_down(0, last);
    return top;
  }
  bool settled(int v) const { return pos_[std::size_t(v)] == -2; }

 private:
  bool less(int a, int b) const {
    float ka = key_[std::size_t(a)], kb = key_[std::size_t(b)];
    return ka < kb || (ka == kb && a < b);
  }
  void place(int i, int v) {
    heap_[std::size_t(i)] = v;
    pos_[std::size_t(v)] = i;
  }
  void sift_up(int i, int v) {
    while (i > 0) {
      int parent = (i - 1) >> 2;
      int pv = heap_[std::size_t(parent)];
      if (!less(v, pv)) break;
      place(i, pv);
      i = parent;
    }
    place(i, v);
  }
  void sift_down(int i, int v) {
    const int n = int(heap_.size());
    while (true) {
      int first = 4 * i + 1;
      if (first >= n) break;
      int best = first;
      int end = first + 4 < n ? first + 4 : n;
      for (int c = first + 1; c < end; ++c)
        if (less(heap_[std::size_t(c)], heap_[std::size_t(best)])) best = c;
      if (!less(heap_[std::size_t(best)], v)) break;
      place(i, heap_[std::size_t(best)]);
      i = best;
    }
    place(i, v);
  }

  const std::vector<float>& key_;
  std::vector<int> pos_;
  std::vector<int> heap_;
};

}  // namespace

void shortest_paths(const SurfaceGraph& g, const std::vector<int>& sources,
                    std::vector<float>& distance, std::vector<int>* nearest,
                    const StopRequested& stop) {
  const int n = g.nodes();
  distance.assign(static_cast<std::size_t>(n), std::numeric_limits<float>::infinity());
  if (nearest) nearest->assign(static_cast<std::size_t>(n), -1);
  QuadHeap heap(n, distance);
  for (std::size_t s = 0; s < sources.size(); ++s) {
    int v = sources[s];
    if (distance[std::size_t(v)] == 0) continue;
    distance[std::size_t(v)] = 0;
    if (nearest) (*nearest)[std::size_t(v)] = int(s);
    heap.push_or_decrease(v);
  }
  std::size_t pops = 0;
  while (!heap.empty()) {
    const int v = heap.pop();
    if ((++pops & 8191) == 0) check_interrupt(stop);
    const float d = distance[std::size_t(v)];
    for (int k = g.offset[std::size_t(v)]; k < g.offset[std::size_t(v) + 1]; ++k) {
      const int w = g.target[std::size_t(k)];
      const float nd = d + g.length[std::size_t(k)];
      if (nd < distance[std::size_t(w)]) {
        distance[std::size_t(w)] = nd;
        if (nearest) (*nearest)[std::size_t(w)] = (*nearest)[std::size_t(v)];
        heap.push_or_decrease(w);
      }
    }
  }
}

}  // namespace arg

namespace arg {

void prepare_buckets(const SurfaceGraph& g, BucketScratch& s) {
  double sum = 0, longest = 0;
  for (float len : g.length) sum += len, longest = std::max(longest, double(len));
  const double mean = g.length.empty() ? 1.0 : sum / double(g.length.size());
  // About 32 steps per typical edge; coarser when a very long edge (a link between parts)
  // would need more than 2^16 buckets.
  s.unit = std::max(mean / 32.0, longest / 65535.0);
  if (!(s.unit > 0)) s.unit = 1.0;
  s.arc.resize(g.length.size());
  std::uint32_t max_len = 0;
  for (std::size_t k = 0; k < g.length.size(); ++k) {
    const auto len = std::uint32_t(std::lround(double(g.length[k]) / s.unit));
    s.arc[k] = std::uint64_t(std::uint32_t(g.target[k])) | (std::uint64_t(len) << 32);
    max_len = std::max(max_len, len);
  }
  std::size_t ring = 1;
  while (ring <= max_len) ring <<= 1;
  s.mask = ring - 1;
  s.buckets.assign(ring, {});
  s.empty = true;
}

void shortest_steps(const SurfaceGraph& g, int source, BucketScratch& s,
                    const StopRequested& stop) {
  const std::size_t n = std::size_t(g.nodes());
  s.dist.assign(n, kUnreached);
  // A run that ends normally leaves every bucket empty; one stopped by a cancel does not.
  if (!s.empty)
    for (auto& b : s.buckets) b.size = 0;
  s.empty = false;
  // Locals, not members: the stores into dist[] below could alias the scratch's fields, so the
  // compiler would otherwise reload the mask and the buckets' address at every relaxation.
  std::uint32_t* const dist = s.dist.data();
  const std::uint64_t* const arc = s.arc.data();
  const int* const offset = g.offset.data();
  BucketScratch::Bucket* const buckets = s.buckets.data();
  const std::uint64_t mask = s.mask;
  dist[source] = 0;
  auto push = [](BucketScratch::Bucket& b, int v, bool counted) {
    if (b.size == b.slots.size()) b.slots.resize(std::max<std::size_t>(64, 2 * b.size));
    b.slots[b.size] = v;
    b.size += counted;
  };
  push(buckets[0], source, true);
  std::size_t pending = 1, pops = 0;
  for (std::uint64_t current = 0; pending > 0; ++current) {
    BucketScratch::Bucket& bucket = buckets[current & mask];
    while (bucket.size > 0) {
      const int v = bucket.slots[--bucket.size];
      --pending;
      if (dist[v] != current) continue;  // a stale entry
      if ((++pops & 8191) == 0) check_interrupt(stop);
      const int end = offset[v + 1];
      for (int k = offset[v]; k < end; ++k) {
        const std::uint64_t a = arc[k];
        const auto w = std::uint32_t(a);
        const std::uint64_t nd = current + (a >> 32);
        const std::uint32_t old = dist[w];
        const bool better = nd < old;
        dist[w] = better ? std::uint32_t(nd) : old;
        push(buckets[nd & mask], int(w), better);
        pending += better;
      }
    }
  }
  s.empty = true;
}

void shortest_paths_quantised(const SurfaceGraph& g, int source, std::vector<float>& distance,
                              BucketScratch& s, const StopRequested& stop) {
  shortest_steps(g, source, s, stop);
  const std::size_t n = s.dist.size();
  distance.resize(n);
  for (std::size_t v = 0; v < n; ++v) distance[v] = s.distance(v);
}

}  // namespace arg
