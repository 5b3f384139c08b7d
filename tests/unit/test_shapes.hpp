// Small analytic meshes for unit tests: sphere, torus, capped cylinder, two-holed torus.
#pragma once

#include <cmath>
#include <vector>

#include "mesh/mesh.hpp"

namespace arg::test {

// Closed mesh from a (rows x cols) grid of points, periodic in the column direction; the first
// and last rows are collapsed to poles when `poles` is set, otherwise periodic in rows too.
template <class Point>
Mesh grid_mesh(int rows, int cols, bool poles, Point point) {
  Mesh m;
  std::vector<Eigen::RowVector3d> V;
  std::vector<Eigen::RowVector3i> F;
  if (poles) {
    V.push_back(point(0, 0));
    for (int i = 1; i < rows - 1; ++i)
      for (int j = 0; j < cols; ++j) V.push_back(point(i, j));
    V.push_back(point(rows - 1, 0));
    auto id = [&](int i, int j) { return 1 + (i - 1) * cols + ((j % cols) + cols) % cols; };
    const int south = int(V.size()) - 1;
    for (int j = 0; j < cols; ++j) F.push_back({0, id(1, j + 1), id(1, j)});
    for (int i = 1; i < rows - 2; ++i)
      for (int j = 0; j < cols; ++j) {
        F.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
        F.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
      }
    for (int j = 0; j < cols; ++j) F.push_back({south, id(rows - 2, j), id(rows - 2, j + 1)});
  } else {
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j) V.push_back(point(i, j));
    auto id = [&](int i, int j) {
      return ((i % rows) + rows) % rows * cols + ((j % cols) + cols) % cols;
    };
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j) {
        F.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
        F.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
      }
  }
  m.V.resize(Eigen::Index(V.size()), 3);
  for (std::size_t i = 0; i < V.size(); ++i) m.V.row(Eigen::Index(i)) = V[i];
  m.F.resize(Eigen::Index(F.size()), 3);
  for (std::size_t i = 0; i < F.size(); ++i) m.F.row(Eigen::Index(i)) = F[i];
  return m;
}

inline Mesh sphere(int rows = 40, int cols = 60, double rx = 1, double ry = 1, double rz = 1) {
  return grid_mesh(rows, cols, true, [&](int i, int j) {
    double t = M_PI * i / (rows - 1), p = 2 * M_PI * j / cols;
    return Eigen::RowVector3d(rx * std::sin(t) * std::cos(p), ry * std::sin(t) * std::sin(p),
                              rz * std::cos(t));
  });
}

inline Mesh torus(double R = 2, double r = 0.6, int rows = 80, int cols = 30) {
  return grid_mesh(rows, cols, false, [&](int i, int j) {
    double u = 2 * M_PI * i / rows, v = 2 * M_PI * j / cols;
    return Eigen::RowVector3d((R + r * std::cos(v)) * std::cos(u),
                              (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
  });
}

// A long capsule along z: a cylinder of half-length h with hemispherical ends.
inline Mesh capsule(double h = 3, double radius = 0.5, int rows = 90, int cols = 32) {
  return grid_mesh(rows, cols, true, [&](int i, int j) {
    // arc length parameter along the profile: cap, side, cap
    double cap = M_PI / 2 * radius, total = 2 * cap + 2 * h;
    double s = total * i / (rows - 1), z, rad;
    if (s < cap) {
      double a = s / radius;
      z = h + radius * std::cos(a), rad = radius * std::sin(a);
    } else if (s < cap + 2 * h) {
      z = h - (s - cap), rad = radius;
    } else {
      double a = (s - cap - 2 * h) / radius;
      z = -h - radius * std::sin(a), rad = radius * std::cos(a);
    }
    double p = 2 * M_PI * j / cols;
    return Eigen::RowVector3d(rad * std::cos(p), rad * std::sin(p), z);
  });
}

inline Mesh transformed(const Mesh& m, const Eigen::Matrix3d& R, const Eigen::Vector3d& t,
                        double s) {
  Mesh out = m;
  for (Eigen::Index i = 0; i < m.V.rows(); ++i)
    out.V.row(i) = (s * (R * m.V.row(i).transpose()) + t).transpose();
  return out;
}

// The unit square in the z = 0 plane as two triangles: an open sheet of large faces.
inline Mesh unit_square() {
  Mesh square;
  square.V.resize(4, 3);
  square.V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  square.F.resize(2, 3);
  square.F << 0, 1, 2, 0, 2, 3;
  return square;
}

// The same surface as a soup: every triangle with corners of its own.
inline Mesh unwelded(const Mesh& m) {
  Mesh soup;
  soup.V.resize(3 * m.F.rows(), 3);
  soup.F.resize(m.F.rows(), 3);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int c = 0; c < 3; ++c) {
      soup.V.row(3 * f + c) = m.V.row(m.F(f, c));
      soup.F(f, c) = int(3 * f + c);
    }
  return soup;
}

}  // namespace arg::test
