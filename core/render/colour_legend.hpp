// A vertical colour bar with numbered ticks and a caption, explaining the surface colours.
#pragma once

#include <string_view>

#include "render/canvas.hpp"
#include "render/rasterise_mesh.hpp"

namespace arg {

// Draws the bar of `paint` (0 at the bottom, 1 at the top, its bands as stripes) in the column
// (x, y, w, h): caption on top, then the bar with ticks at the band boundaries and numbers at
// 0, 0.5 and 1 to its right. Text is drawn at `text_scale`.
void draw_colour_legend(Image& image, int x, int y, int w, int h, const SurfacePaint& paint,
                        std::string_view caption, Rgb ink, int text_scale = 1);

}  // namespace arg
