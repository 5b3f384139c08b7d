// The pixel centres a triangle covers, with their barycentric coordinates: the scan both view
// descriptors (depth images, panoramic views) draw their triangles with.
#pragma once

#include <algorithm>
#include <climits>
#include <cmath>

namespace arg {

// Calls visit(i, j, b0, b1, b2) for each pixel centre (i, j), i in [i_lo, i_hi] and j in
// [j_lo, j_hi], inside or on the triangle with pixel coordinates (px, py) (pixel i has its
// centre at x = i); b are its barycentric coordinates. A triangle seen edge-on covers none.
template <class Visit>
void for_each_pixel_centre(const double (&px)[3], const double (&py)[3], int i_lo, int i_hi,
                           int j_lo, int j_hi, Visit&& visit) {
  const double area = (px[1] - px[0]) * (py[2] - py[0]) - (px[2] - px[0]) * (py[1] - py[0]);
  if (area == 0) return;
  const int i0 = std::max(i_lo, int(std::ceil(std::min({px[0], px[1], px[2]})))),
            i1 = std::min(i_hi, int(std::floor(std::max({px[0], px[1], px[2]})))),
            j0 = std::max(j_lo, int(std::ceil(std::min({py[0], py[1], py[2]})))),
            j1 = std::min(j_hi, int(std::floor(std::max({py[0], py[1], py[2]}))));
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const double b0 = ((px[1] - i) * (py[2] - j) - (px[2] - i) * (py[1] - j)) / area,
                   b1 = ((px[2] - i) * (py[0] - j) - (px[0] - i) * (py[2] - j)) / area,
                   b2 = 1.0 - b0 - b1;
      if (b0 < 0 || b1 < 0 || b2 < 0) continue;
      visit(i, j, b0, b1, b2);
    }
}

}  // namespace arg
