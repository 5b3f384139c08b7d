// Splitting one polygon of a mesh into triangles: a fan when convex, ear clipping otherwise.
#include "io/triangulate_polygon.hpp"

#include <cmath>

namespace arg::io {

namespace {

void fan(std::size_t n, std::vector<std::array<std::size_t, 3>>& triangles) {
  for (std::size_t k = 1; k + 1 < n; ++k) triangles.push_back({0, k, k + 1});
}

double cross2(const double* a, const double* b, const double* c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

bool inside(const double* p, const double* a, const double* b, const double* c) {
  // Closed triangle test; the triangle a, b, c is counter-clockwise.
  return cross2(a, b, p) >= 0 && cross2(b, c, p) >= 0 && cross2(c, a, p) >= 0;
}

}  // namespace

void triangulate_polygon(const double* xyz, const int* corners, std::size_t n,
                         std::vector<std::array<std::size_t, 3>>& triangles,
                         std::size_t& work_budget, std::size_t max_ear_clipping) {
  if (n < 3) return;
  if (n == 3) {
    triangles.push_back({0, 1, 2});
    return;
  }
  if (n > max_ear_clipping) {
    fan(n, triangles);
    return;
  }
  // Newell's normal, then project onto the plane of its two smaller axes.
  double normal[3] = {0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    const double* a = xyz + 3 * static_cast<std::size_t>(corners[i]);
    const double* b = xyz + 3 * static_cast<std::size_t>(corners[(i + 1) % n]);
    normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
    normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
    normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::fabs(normal[k]) > std::fabs(normal[axis])) axis = k;
  }
  if (!(std::fabs(normal[axis]) > 0)) {
    fan(n, triangles);
    return;
  }
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  // Counter-clockwise seen from the normal's side.
  const double flip = normal[axis] > 0 ? 1.0 : -1.0;
  std::vector<double> p(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const double* a = xyz + 3 * static_cast<std::size_t>(corners[i]);
    p[2 * i] = a[u];
    p[2 * i + 1] = flip * a[v];
  }
  bool convex = true;
  for (std::size_t i = 0; i < n && convex; ++i) {
    convex = cross2(&p[2 * i], &p[2 * ((i + 1) % n)], &p[2 * ((i + 2) % n)]) >= 0;
  }
  if (convex) {
    fan(n, triangles);
    return;
  }
  std::vector<std::size_t> left(n);
  for (std::size_t i = 0; i < n; ++i) left[i] = i;
  std::size_t start = 0;  // resume the search for an ear where the last one was cut
  while (left.size() > 3) {
    bool clipped = false;
    const std::size_t m = left.size();
    for (std::size_t step = 0; step < m && !clipped; ++step) {
      if (work_budget < m) break;
      work_budget -= m;
      const std::size_t i = (start + step) % m;
      const std::size_t ia = left[(i + m - 1) % m], ib = left[i], ic = left[(i + 1) % m];
      const double *a = &p[2 * ia], *b = &p[2 * ib], *c = &p[2 * ic];
      if (cross2(a, b, c) <= 0) continue;  // reflex or flat corner
      bool ear = true;
      for (std::size_t j = 0; j < m && ear; ++j) {
        const std::size_t k = left[j];
        if (k == ia || k == ib || k == ic) continue;
        ear = !inside(&p[2 * k], a, b, c);
      }
      if (!ear) continue;
      triangles.push_back({ia, ib, ic});
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(i));
      start = i == 0 ? 0 : i - 1;
      clipped = true;
    }
    if (!clipped) break;  // self-intersecting outline or budget spent: fan the rest
  }
  for (std::size_t k = 1; k + 1 < left.size(); ++k) {
    triangles.push_back({left[0], left[k], left[k + 1]});
  }
}

}  // namespace arg::io
