// A uniform grid of cells for nearest-point queries (a picture's surface finding its proxy).
#include "mesh/nearest_points.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace arg {

namespace {

// The cell of coordinate x along an axis of `dims` cells from `low`: clamped in floating point
// before the conversion, so a far or non-finite x lands in an end cell, never past one.
long long cell_along(double x, double low, double cell, long long dims) {
  const double at = std::floor((x - low) / cell);
  return at >= double(dims - 1) ? dims - 1 : at > 0 ? (long long)at : 0;
}

}  // namespace

NearestPoints::NearestPoints(const Vertices& points, double per_cell) : points_(points) {
  const Eigen::Index n = points.rows();
  if (n == 0) return;
  low_ = points.colwise().minCoeff().transpose();
  const Eigen::Vector3d extent = points.colwise().maxCoeff().transpose() - low_;
  const double largest = extent.maxCoeff();
  if (!extent.allFinite()) {  // a non-finite coordinate: one cell, searched whole
    begin_ = {0, int(n)};
    order_.resize(std::size_t(n));
    for (Eigen::Index i = 0; i < n; ++i) order_[std::size_t(i)] = int(i);
    return;
  }
  // Cubic cells, about n / per_cell of them over the bounding box, a thin side counted as a
  // thousandth of the largest (points on a plane or a line get cells over their own extent);
  // then as many fewer as it takes to keep the cells under 4 n + 64 in all.
  const double floor_side = largest / 1000.0;
  const double volume = std::max(extent.x(), floor_side) * std::max(extent.y(), floor_side) *
                        std::max(extent.z(), floor_side);
  const double wanted = std::max(1.0, double(n) / std::max(per_cell, 0.5));
  cell_ = std::max(std::cbrt(volume / wanted), floor_side);
  if (!(cell_ > 0) || !std::isfinite(cell_)) cell_ = 1;
  const double most = 4.0 * double(n) + 64.0;
  for (;;) {
    double cells = 1;
    for (int k = 0; k < 3; ++k) {
      const double side = std::floor(extent[k] / cell_) + 1;
      dims_[k] = side < 1002 ? (long long)side : 1002;
      cells *= double(dims_[k]);
    }
    if (cells <= most || !std::isfinite(cell_)) break;
    cell_ *= 1.25;
  }
  const auto cells = std::size_t(dims_[0] * dims_[1] * dims_[2]);
  std::vector<long long> cell_of(static_cast<std::size_t>(n));
  begin_.assign(cells + 1, 0);
  for (Eigen::Index i = 0; i < n; ++i) {
    long long c[3];
    for (int k = 0; k < 3; ++k) c[k] = cell_along(points(i, k), low_[k], cell_, dims_[k]);
    cell_of[std::size_t(i)] = cell_index(c[0], c[1], c[2]);
    ++begin_[std::size_t(cell_of[std::size_t(i)]) + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) begin_[c + 1] += begin_[c];
  order_.resize(std::size_t(n));
  std::vector<int> fill(begin_.begin(), begin_.end() - 1);
  for (Eigen::Index i = 0; i < n; ++i)
    order_[std::size_t(fill[std::size_t(cell_of[std::size_t(i)])]++)] = int(i);
}

int NearestPoints::nearest(const Eigen::Vector3d& q) const {
  if (points_.rows() == 0 || !q.allFinite()) return -1;
  long long c[3];
  for (int k = 0; k < 3; ++k) c[k] = cell_along(q[k], low_[k], cell_, dims_[k]);
  // The query's distance to the grid's box: with q' its nearest point in the box, every point
  // p in the box has |q - p|^2 >= |q - q'|^2 + |q' - p|^2 (the box is convex).
  const Eigen::Vector3d high =
      low_ + cell_ * Eigen::Vector3d(double(dims_[0]), double(dims_[1]), double(dims_[2]));
  const double outside2 = (q.cwiseMax(low_).cwiseMin(high) - q).squaredNorm();
  int best = -1;
  double best_d2 = std::numeric_limits<double>::infinity();
  const long long rings = std::max({dims_[0], dims_[1], dims_[2]});
  for (long long r = 0; r <= rings; ++r) {
    // Every point of ring r or beyond lies at least r - 1 cells from q' (q' may sit at the edge
    // of its cell): stop once the best found is nearer than that.
    const double ring = std::max(0.0, double(r) - 1.0) * cell_;
    if (best >= 0 && best_d2 < ring * ring + outside2) break;
    for (long long z = c[2] - r; z <= c[2] + r; ++z) {
      if (z < 0 || z >= dims_[2]) continue;
      for (long long y = c[1] - r; y <= c[1] + r; ++y) {
        if (y < 0 || y >= dims_[1]) continue;
        const bool face = z == c[2] - r || z == c[2] + r || y == c[1] - r || y == c[1] + r;
        for (long long x = c[0] - r; x <= c[0] + r; x += (face || r == 0) ? 1 : 2 * r) {
          if (x < 0 || x >= dims_[0]) continue;
          const auto cell = std::size_t(cell_index(x, y, z));
          for (int k = begin_[cell]; k < begin_[cell + 1]; ++k) {
            const int i = order_[std::size_t(k)];
            const double d2 = (points_.row(i).transpose() - q).squaredNorm();
            if (d2 < best_d2 || (d2 == best_d2 && i < best)) best_d2 = d2, best = i;
          }
        }
      }
    }
  }
  return best;
}

}  // namespace arg
