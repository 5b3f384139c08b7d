// Dijkstra with a binary heap and lazy deletion; ties resolved by node index for determinism.
#include "mu/dijkstra.hpp"

#include <algorithm>
#include <limits>
#include <queue>
#include <utility>

namespace arg {

void shortest_paths(const SurfaceGraph& g, const std::vector<int>& sources,
                    std::vector<float>& distance, std::vector<int>* nearest,
                    const StopRequested& stop) {
  const int n = g.nodes();
  distance.assign(std::size_t(n), std::numeric_limits<float>::infinity());
  if (nearest) nearest->assign(std::size_t(n), -1);
  using Item = std::pair<float, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  for (std::size_t s = 0; s < sources.size(); ++s) {
    int v = sources[s];
    if (distance[v] == 0) continue;
    distance[v] = 0;
    if (nearest) (*nearest)[v] = int(s);
    heap.emplace(0.0f, v);
  }
  std::size_t pops = 0;
  while (!heap.empty()) {
    auto [d, v] = heap.top();
    heap.pop();
    if (d > distance[v]) continue;
    if ((++pops & 8191) == 0) check_interrupt(stop);
    for (int k = g.offset[v]; k < g.offset[v + 1]; ++k) {
      int w = g.target[k];
      float nd = d + g.length[k];
      if (nd < distance[w]) {
        distance[w] = nd;
        if (nearest) (*nearest)[w] = (*nearest)[v];
        heap.emplace(nd, w);
      }
    }
  }
}

}  // namespace arg
