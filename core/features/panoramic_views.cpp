// Rasterising triangles in (angle, height) about each axis, keeping the farthest surface.
#include "features/panoramic_views.hpp"

#include <algorithm>
#include <cmath>

#include "features/triangle_pixels.hpp"

namespace arg {

namespace {

struct Cylinder {
  int axis, u, w;  // the axis and the two coordinates across it
  int width, height;
  double radius;
  std::vector<float>* extent;
  std::vector<float>* facing;
};

void put(const Cylinder& c, int i, int j, const Eigen::Vector3d& p, const Eigen::Vector3d& normal) {
  if (j < 0 || j >= c.height) return;
  i = ((i % c.width) + c.width) % c.width;
  const double rho2 = p[c.u] * p[c.u] + p[c.w] * p[c.w];
  const double rho = std::sqrt(rho2);
  const float value = float(std::min(rho / c.radius, 1.0));
  const std::size_t k = std::size_t(j) * std::size_t(c.width) + std::size_t(i);
  if (value <= (*c.extent)[k]) return;
  (*c.extent)[k] = value;
  const double along = p[c.u] * normal[c.u] + p[c.w] * normal[c.w];
  const double cos2 = rho2 > 0 ? along * along / rho2 : 0;  // |cos|^4 = (cos^2)^2
  (*c.facing)[k] = float(cos2 * cos2);
}

// Pixel coordinates of a point: column centre i at angle (i + 1/2) 2 pi / width - pi.
void pixel_of(const Cylinder& c, const Eigen::Vector3d& p, double& x, double& y) {
  x = (std::atan2(p[c.w], p[c.u]) + M_PI) / (2 * M_PI) * c.width - 0.5;
  y = (p[c.axis] + c.radius) / (2 * c.radius) * c.height - 0.5;
}

// A triangle's corners with their pixel coordinates (computed once per vertex and axis).
struct Corner {
  Eigen::Vector3d p;
  double x, y;
};

Corner corner_at(const Cylinder& c, const Eigen::Vector3d& p) {
  Corner k{p, 0, 0};
  pixel_of(c, p, k.x, k.y);
  return k;
}

void rasterise(const Cylinder& c, const Corner (&k)[3], const Eigen::Vector3d& normal, int depth) {
  double px[3] = {k[0].x, k[1].x, k[2].x}, py[3] = {k[0].y, k[1].y, k[2].y};
  // A triangle across the seam at +-pi: continue its angles past the seam.
  if (std::max({px[0], px[1], px[2]}) - std::min({px[0], px[1], px[2]}) > 0.5 * c.width)
    for (double& x : px)
      if (x < 0.5 * c.width) x += c.width;
  // Angle is not linear across a triangle: split those that span many columns (near the axis).
  if (std::max({px[0], px[1], px[2]}) - std::min({px[0], px[1], px[2]}) > 8 && depth < 6) {
    const Corner m01 = corner_at(c, 0.5 * (k[0].p + k[1].p)),
                 m12 = corner_at(c, 0.5 * (k[1].p + k[2].p)),
                 m20 = corner_at(c, 0.5 * (k[2].p + k[0].p));
    const Corner parts[4][3] = {
        {k[0], m01, m20}, {m01, k[1], m12}, {m20, m12, k[2]}, {m01, m12, m20}};
    for (const auto& part : parts) rasterise(c, part, normal, depth + 1);
    return;
  }
  bool drawn = false;
  for_each_pixel_centre(px, py, INT_MIN, INT_MAX, 0, c.height - 1,
                        [&](int i, int j, double b0, double b1, double b2) {
                          put(c, i, j, b0 * k[0].p + b1 * k[1].p + b2 * k[2].p, normal);
                          drawn = true;
                        });
  // A triangle smaller than a pixel still marks the pixel under its centre (the mean of its
  // corners' pixel coordinates: near enough for so small a triangle, and no arc tangent).
  if (!drawn)
    put(c, int(std::lround((px[0] + px[1] + px[2]) / 3.0)),
        int(std::lround((py[0] + py[1] + py[2]) / 3.0)), (k[0].p + k[1].p + k[2].p) / 3.0, normal);
}

// Averages each orientation sample with the one the extent image's slope gives. The farthest
// surface at (angle t, height h) is r(t, h); its normal lies along e_r - (r_t / r) e_t - r_h
// e_axis, so cos^2 = 1 / (1 + (r_t / r)^2 + r_h^2), from central differences a pixel apart.
// The slope sees the surface at the views' resolution, where the faces' own normals see every
// ripple: under noise of 0.3% of the size they scatter and the plain image darkens, the slope's
// does not (mAP of noisy soups .534 -> .546 at strength 3). A slope steeper than 2 (63 degrees)
// along either direction is taken for a jump in extent, a silhouette or the rim of a hole, not
// a surface: there the faces' normal alone counts.
void blend_slope_facing(const Cylinder& c) {
  const std::vector<float>& extent = *c.extent;
  std::vector<float>& facing = *c.facing;
  const double step_angle = 2 * M_PI / c.width, step_height = 2 * c.radius / c.height;
  auto r_at = [&](int i, int j) {
    i = ((i % c.width) + c.width) % c.width;
    return double(extent[std::size_t(j) * std::size_t(c.width) + std::size_t(i)]) * c.radius;
  };
  for (int j = 0; j < c.height; ++j)
    for (int i = 0; i < c.width; ++i) {
      const double r = r_at(i, j);
      if (!(r > 0)) continue;
      const double slope_angle = (r_at(i + 1, j) - r_at(i - 1, j)) / (2 * step_angle) / r;
      const int below = std::max(0, j - 1), above = std::min(c.height - 1, j + 1);
      const double slope_height =
          above > below ? (r_at(i, above) - r_at(i, below)) / ((above - below) * step_height) : 0;
      if (std::fabs(slope_angle) > 2 || std::fabs(slope_height) > 2) continue;
      const double cos2 = 1.0 / (1.0 + slope_angle * slope_angle + slope_height * slope_height);
      float& f = facing[std::size_t(j) * std::size_t(c.width) + std::size_t(i)];
      f = float(0.5 * (cos2 * cos2 + double(f)));
    }
}

}  // namespace

PanoramicViews panoramic_views(const Mesh& mesh, int height, double radius,
                               const StopRequested& stop) {
  PanoramicViews out;
  out.height = height;
  out.width = 2 * height;
  for (auto& image : out.image) image.assign(std::size_t(out.width) * std::size_t(height), 0.0f);
  if (height <= 0 || !(radius > 0)) return out;
  for (int a = 0; a < 3; ++a) {
    const Cylinder c{a,
                     (a + 1) % 3,
                     (a + 2) % 3,
                     out.width,
                     height,
                     radius,
                     &out.image[std::size_t(2 * a)],
                     &out.image[std::size_t(2 * a + 1)]};
    std::vector<Corner> corners(std::size_t(mesh.V.rows()));
    for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
      poll_interrupt(std::size_t(v), stop);
      corners[std::size_t(v)] = corner_at(c, mesh.V.row(v).transpose());
    }
    for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
      poll_interrupt(std::size_t(f), stop);
      const Corner k[3] = {corners[std::size_t(mesh.F(f, 0))], corners[std::size_t(mesh.F(f, 1))],
                           corners[std::size_t(mesh.F(f, 2))]};
      const Eigen::Vector3d n = (k[1].p - k[0].p).cross(k[2].p - k[0].p);
      const double length = n.norm();
      if (!(length > 0)) continue;
      rasterise(c, k, n / length, 0);
    }
    blend_slope_facing(c);
  }
  return out;
}

}  // namespace arg
