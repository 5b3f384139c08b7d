// Components by union-find over faces, and nearest-point links between them.
#include "mesh/connected_components.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

namespace arg {

namespace {
int find_root(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}
}  // namespace

int vertex_components(const Mesh& mesh, std::vector<int>& component) {
  const int n = int(mesh.V.rows());
  std::vector<int> parent(static_cast<std::size_t>(n));
  std::iota(parent.begin(), parent.end(), 0);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int c = 1; c < 3; ++c) {
      int a = find_root(parent, mesh.F(f, 0)), b = find_root(parent, mesh.F(f, c));
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  std::vector<int> root_id(std::size_t(n), -1);
  std::vector<double> area;
  std::vector<int> first_vertex;
  component.assign(std::size_t(n), 0);
  for (int v = 0; v < n; ++v) {
    int r = find_root(parent, v);
    if (root_id[r] < 0) {
      root_id[r] = int(area.size());
      area.push_back(0);
      first_vertex.push_back(v);
    }
    component[v] = root_id[r];
  }
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    Eigen::RowVector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)),
                       c = mesh.V.row(mesh.F(f, 2));
    area[component[mesh.F(f, 0)]] += 0.5 * (b - a).cross(c - a).norm();
  }
  const int count = int(area.size());
  std::vector<int> order(static_cast<std::size_t>(count));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return area[x] > area[y]; });
  std::vector<int> rank(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) rank[order[k]] = k;
  for (int& c : component) c = rank[c];
  return count;
}

std::vector<std::pair<int, int>> component_links(const Mesh& mesh,
                                                 const std::vector<int>& component,
                                                 int components) {
  std::vector<std::pair<int, int>> links;
  if (components <= 1) return links;
  const int n = int(mesh.V.rows());
  std::vector<std::vector<int>> members(static_cast<std::size_t>(components));
  for (int v = 0; v < n; ++v) members[component[v]].push_back(v);
  // Prim-like growth from the largest component: repeatedly attach the unlinked component
  // nearest to the linked set. Distances use a subsample of each component's vertices so that
  // many small parts stay affordable; the nearest pair among the samples is exact for them.
  // Fewer samples per part when there are many parts keeps the cost near 10^7 distance checks.
  const std::size_t per_part = std::clamp<std::size_t>(4096 / std::size_t(components), 4, 256);
  auto sample = [&](int c) {
    const auto& m = members[c];
    std::vector<int> s;
    const std::size_t step = std::max<std::size_t>(1, m.size() / per_part);
    for (std::size_t k = 0; k < m.size(); k += step) s.push_back(m[k]);
    return s;
  };
  std::vector<std::vector<int>> samples(static_cast<std::size_t>(components));
  for (int c = 0; c < components; ++c) samples[c] = sample(c);
  std::vector<char> linked(std::size_t(components), 0);
  linked[0] = 1;
  std::vector<double> best(std::size_t(components), std::numeric_limits<double>::infinity());
  std::vector<std::pair<int, int>> best_pair(std::size_t(components), {-1, -1});
  auto relax_from = [&](int source) {
    for (int c = 0; c < components; ++c) {
      if (linked[c]) continue;
      for (int u : samples[c])
        for (int w : samples[source]) {
          double d = (mesh.V.row(u) - mesh.V.row(w)).squaredNorm();
          if (d < best[c]) best[c] = d, best_pair[c] = {u, w};
        }
    }
  };
  relax_from(0);
  for (int step = 1; step < components; ++step) {
    int next = -1;
    for (int c = 0; c < components; ++c)
      if (!linked[c] && (next < 0 || best[c] < best[next])) next = c;
    linked[next] = 1;
    links.push_back(best_pair[next]);
    relax_from(next);
  }
  return links;
}

std::vector<double> component_areas(const Mesh& mesh, const std::vector<int>& component,
                                    std::size_t count) {
  std::vector<double> area(count, 0.0);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    area[std::size_t(component[std::size_t(mesh.F(f, 0))])] +=
        0.5 * (mesh.V.row(mesh.F(f, 1)) - mesh.V.row(mesh.F(f, 0)))
                  .cross(mesh.V.row(mesh.F(f, 2)) - mesh.V.row(mesh.F(f, 0)))
                  .norm();
  return area;
}

}  // namespace arg
