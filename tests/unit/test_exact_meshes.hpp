// Meshes whose geodesics, areas, volumes and curvatures are known exactly: plane, tube, cube,
// icosphere.
#pragma once

#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "mesh/mesh.hpp"

namespace arg::test {

inline Mesh mesh_of(const std::vector<Eigen::RowVector3d>& V,
                    const std::vector<Eigen::RowVector3i>& F) {
  Mesh m;
  m.V.resize(Eigen::Index(V.size()), 3);
  for (std::size_t i = 0; i < V.size(); ++i) m.V.row(Eigen::Index(i)) = V[i];
  m.F.resize(Eigen::Index(F.size()), 3);
  for (std::size_t i = 0; i < F.size(); ++i) m.F.row(Eigen::Index(i)) = F[i];
  return m;
}

// The unit square in z = 0 as an n x n grid of squares, each cut along the same diagonal, so
// that edge paths have a worst direction (across the diagonals) where they are sqrt(2) long.
inline Mesh unit_square(int n) {
  std::vector<Eigen::RowVector3d> V;
  std::vector<Eigen::RowVector3i> F;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) V.emplace_back(double(i) / n, double(j) / n, 0.0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int a = i * (n + 1) + j, b = a + n + 1;
      F.emplace_back(a, b, b + 1);
      F.emplace_back(a, b + 1, a + 1);
    }
  return mesh_of(V, F);
}

// An open prism of `cols` sides around z, `rows` rings from z = 0 to z = length, vertex
// (ring i, column j) at index i * cols + j. It unrolls onto a strip of width cols x chord.
inline Mesh open_tube(int rows, int cols, double radius, double length) {
  std::vector<Eigen::RowVector3d> V;
  std::vector<Eigen::RowVector3i> F;
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const double p = 2 * M_PI * j / cols;
      V.emplace_back(radius * std::cos(p), radius * std::sin(p), length * i / (rows - 1));
    }
  for (int i = 0; i + 1 < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const int a = i * cols + j, b = i * cols + (j + 1) % cols;
      F.emplace_back(a, b, b + cols);
      F.emplace_back(a, b + cols, a + cols);
    }
  return mesh_of(V, F);
}

// The closed cube [-1, 1]^3, each face an n x n grid of squares cut in two, outward oriented,
// vertices shared along the edges.
inline Mesh cube(int n) {
  std::vector<Eigen::RowVector3d> V;
  std::vector<Eigen::RowVector3i> F;
  std::map<std::array<int, 3>, int> index;  // lattice point (0..n each) -> vertex
  auto vertex = [&](std::array<int, 3> q) {
    auto [it, added] = index.emplace(q, int(V.size()));
    if (added) V.emplace_back(2.0 * q[0] / n - 1, 2.0 * q[1] / n - 1, 2.0 * q[2] / n - 1);
    return it->second;
  };
  for (int a = 0; a < 3; ++a)
    for (int side : {0, n}) {
      const int b = (a + 1) % 3, c = (a + 2) % 3;  // e_b x e_c = e_a
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          int corner[4];
          const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
          for (int k = 0; k < 4; ++k) {
            std::array<int, 3> q{};
            q[a] = side, q[b] = i + di[k], q[c] = j + dj[k];
            corner[k] = vertex(q);
          }
          if (side == n) {
            F.emplace_back(corner[0], corner[1], corner[2]);
            F.emplace_back(corner[0], corner[2], corner[3]);
          } else {
            F.emplace_back(corner[0], corner[2], corner[1]);
            F.emplace_back(corner[0], corner[3], corner[2]);
          }
        }
    }
  return mesh_of(V, F);
}

// The icosahedron with every triangle split in four `splits` times, vertices on the unit
// sphere: nearly equal triangles, no poles.
inline Mesh icosphere(int splits) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<Eigen::RowVector3d> V = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                       {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                       {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<Eigen::RowVector3i> F = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (auto& v : V) v.normalize();
  for (int s = 0; s < splits; ++s) {
    std::map<std::pair<int, int>, int> middle;
    auto mid = [&](int a, int b) {
      auto [it, added] = middle.emplace(std::minmax(a, b), int(V.size()));
      if (added) V.push_back((V[std::size_t(a)] + V[std::size_t(b)]).normalized());
      return it->second;
    };
    std::vector<Eigen::RowVector3i> finer;
    for (const auto& f : F) {
      const int a = mid(f[0], f[1]), b = mid(f[1], f[2]), c = mid(f[2], f[0]);
      finer.emplace_back(f[0], a, c);
      finer.emplace_back(f[1], b, a);
      finer.emplace_back(f[2], c, b);
      finer.emplace_back(a, b, c);
    }
    F.swap(finer);
  }
  return mesh_of(V, F);
}

inline double surface_area(const Mesh& m) {
  double s = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const Eigen::RowVector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    s += 0.5 * (b - a).cross(c - a).norm();
  }
  return s;
}

inline Mesh scaled(Mesh m, double s) {
  m.V *= s;
  return m;
}

}  // namespace arg::test
