// Anti-aliased discs, rings and thick line segments, drawn by coverage of each pixel.
#pragma once

#include "render/canvas.hpp"

namespace arg {

// A filled disc centred at (cx, cy) in continuous pixel coordinates (pixel (i, j) covers
// [i, i + 1) x [j, j + 1)).
void draw_disc(Image& image, double cx, double cy, double radius, Rgb colour, double alpha = 1.0);

// A circle outline of the given stroke width, centred on `radius`.
void draw_ring(Image& image, double cx, double cy, double radius, double width, Rgb colour,
               double alpha = 1.0);

// A segment with round ends.
void draw_line(Image& image, double x0, double y0, double x1, double y1, double width, Rgb colour,
               double alpha = 1.0);

}  // namespace arg
