// Shortest-path graph over mesh edges plus Steiner points on long edges and component links.
#include "mu/surface_graph.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "mesh/connected_components.hpp"

namespace arg {

SurfaceGraph surface_graph(const Mesh& mesh, const MeshEdges& E, double max_edge,
                           const StopRequested& stop) {
  const int nv = int(mesh.V.rows());
  // Steiner points per edge, numbered after the mesh vertices.
  std::vector<int> steiner_begin(std::size_t(E.count()) + 1, nv);
  std::vector<Eigen::Vector3d> points;
  for (int e = 0; e < E.count(); ++e) {
    poll_interrupt(std::size_t(e), stop);
    Eigen::Vector3d a = mesh.V.row(E.v0[e]).transpose(), b = mesh.V.row(E.v1[e]).transpose();
    double len = (b - a).norm();
    int s = max_edge > 0 ? std::min(8, int(std::ceil(len / max_edge)) - 1) : 0;
    steiner_begin[e + 1] = steiner_begin[e] + std::max(s, 0);
    for (int k = 1; k <= s; ++k) points.push_back(a + (b - a) * (double(k) / (s + 1)));
  }
  const int nodes = nv + int(points.size());
  auto position = [&](int p) -> Eigen::Vector3d {
    return p < nv ? Eigen::Vector3d(mesh.V.row(p).transpose()) : points[std::size_t(p - nv)];
  };

  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(std::size_t(E.count()) * 2 + points.size() * 4);
  // Along each edge: v0, its Steiner points in order, v1.
  for (int e = 0; e < E.count(); ++e) {
    poll_interrupt(std::size_t(e), stop);
    int prev = E.v0[e];
    for (int p = steiner_begin[e]; p < steiner_begin[e + 1]; ++p)
      pairs.emplace_back(prev, p), prev = p;
    pairs.emplace_back(prev, E.v1[e]);
  }
  // Across each face: every point on one side to every point on the other two sides. Only
  // faces with Steiner points add anything new (corner-to-corner pairs are the mesh edges).
  std::vector<std::array<int, 3>> face_edge(std::size_t(mesh.F.rows()), {-1, -1, -1});
  for (int e = 0; e < E.count(); ++e) {
    poll_interrupt(std::size_t(e), stop);
    for (int k = E.face_begin[e]; k < E.face_begin[e + 1]; ++k)
      face_edge[E.face_of[k]][E.corner_of[k]] = e;
  }
  std::vector<int> side[3];
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    poll_interrupt(std::size_t(f), stop);
    bool any = false;
    for (int c = 0; c < 3; ++c) {
      int e = face_edge[f][c];
      any |= steiner_begin[e + 1] > steiner_begin[e];
    }
    if (!any) continue;
    for (int c = 0; c < 3; ++c) {
      int e = face_edge[f][c];
      side[c].assign(1, mesh.F(f, c));  // the side's first corner
      for (int p = steiner_begin[e]; p < steiner_begin[e + 1]; ++p) side[c].push_back(p);
    }
    // Side c runs from corner c to corner c+1; the opposite corner of side c is corner c+2.
    for (int c = 0; c < 3; ++c)
      for (std::size_t i = 1; i < side[c].size(); ++i) {
        int p = side[c][i];
        pairs.emplace_back(p, mesh.F(f, (c + 2) % 3));
        for (int d = c + 1; d < 3; ++d)
          for (std::size_t j = 1; j < side[d].size(); ++j) pairs.emplace_back(p, side[d][j]);
      }
  }
  // Links between connected components, so mu is defined on multi-part objects.
  std::vector<int> component;
  int components = vertex_components(mesh, component);
  check_interrupt(stop);
  for (auto [a, b] : component_links(mesh, component, components)) pairs.emplace_back(a, b);

  SurfaceGraph g;
  g.mesh_vertices = nv;
  g.offset.assign(std::size_t(nodes) + 1, 0);
  check_interrupt(stop);
  for (auto [a, b] : pairs) ++g.offset[a + 1], ++g.offset[b + 1];
  for (int i = 0; i < nodes; ++i) g.offset[i + 1] += g.offset[i];
  g.target.resize(std::size_t(g.offset[nodes]));
  g.length.resize(g.target.size());
  std::vector<int> cursor(g.offset.begin(), g.offset.end() - 1);
  check_interrupt(stop);
  std::size_t done = 0;
  for (auto [a, b] : pairs) {
    poll_interrupt(done++, stop);
    float len = float((position(a) - position(b)).norm());
    g.target[cursor[a]] = b, g.length[cursor[a]++] = len;
    g.target[cursor[b]] = a, g.length[cursor[b]++] = len;
  }
  g.steiner = std::move(points);
  return g;
}

}  // namespace arg
