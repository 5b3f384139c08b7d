// Anti-aliased shapes by coverage from the signed distance of each pixel centre to the edge.
// (A cheap, deterministic stand-in for exact area coverage, good to a fraction of a pixel.)
#include "render/draw_shapes.hpp"

#include <algorithm>
#include <cmath>

namespace arg {

namespace {

double coverage(double distance_inside) {
  return std::clamp(distance_inside + 0.5, 0.0, 1.0);
}

// Visits the pixels whose centres lie within the box, clipped to the picture.
template <class Visit>
void for_box(const Image& image, double x0, double y0, double x1, double y1, Visit visit) {
  const int i0 = std::max(0, int(std::floor(x0))),
            i1 = std::min(image.width - 1, int(std::ceil(x1)));
  const int j0 = std::max(0, int(std::floor(y0))),
            j1 = std::min(image.height - 1, int(std::ceil(y1)));
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) visit(i, j, i + 0.5, j + 0.5);
}

}  // namespace

void draw_disc(Image& image, double cx, double cy, double radius, Rgb colour, double alpha) {
  const double reach = radius + 1;
  for_box(image, cx - reach, cy - reach, cx + reach, cy + reach,
          [&](int i, int j, double x, double y) {
            const double d = std::hypot(x - cx, y - cy);
            blend_pixel(image, i, j, colour, alpha * coverage(radius - d));
          });
}

void draw_ring(Image& image, double cx, double cy, double radius, double width, Rgb colour,
               double alpha) {
  const double reach = radius + width / 2 + 1;
  for_box(image, cx - reach, cy - reach, cx + reach, cy + reach,
          [&](int i, int j, double x, double y) {
            const double d = std::fabs(std::hypot(x - cx, y - cy) - radius);
            blend_pixel(image, i, j, colour, alpha * coverage(width / 2 - d));
          });
}

void draw_line(Image& image, double x0, double y0, double x1, double y1, double width, Rgb colour,
               double alpha) {
  const double reach = width / 2 + 1;
  const double dx = x1 - x0, dy = y1 - y0, length2 = dx * dx + dy * dy;
  for_box(image, std::min(x0, x1) - reach, std::min(y0, y1) - reach, std::max(x0, x1) + reach,
          std::max(y0, y1) + reach, [&](int i, int j, double x, double y) {
            const double t =
                length2 > 0 ? std::clamp(((x - x0) * dx + (y - y0) * dy) / length2, 0.0, 1.0) : 0.0;
            const double d = std::hypot(x - (x0 + t * dx), y - (y0 + t * dy));
            blend_pixel(image, i, j, colour, alpha * coverage(width / 2 - d));
          });
}

}  // namespace arg
