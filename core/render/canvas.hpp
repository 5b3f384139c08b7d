// The picture being drawn: an 8-bit RGB Image, colours, blending, copying and shrinking.
#pragma once

#include <cstdint>

#include "io/image.hpp"

namespace arg {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
};

bool operator==(const Rgb& x, const Rgb& y);

// A width x height picture filled with `background`.
Image make_canvas(int width, int height, Rgb background);

// Mixes `colour` into the pixel (x, y) with weight `alpha` in [0, 1]; pixels outside the picture
// are ignored, so shapes may be clipped by the edge.
void blend_pixel(Image& image, int x, int y, Rgb colour, double alpha = 1.0);

Rgb pixel_at(const Image& image, int x, int y);

// Fills the rectangle [x, x + w) x [y, y + h), clipped to the picture.
void fill_rect(Image& image, int x, int y, int w, int h, Rgb colour, double alpha = 1.0);

// Copies `source` with its top-left corner at (x, y) of `target`, clipped.
void blit(Image& target, const Image& source, int x, int y);

// Averages factor x factor blocks: the last step of supersampled drawing. Width and height must
// be multiples of `factor`.
Image downsample(const Image& image, int factor);

// The colour scaled by `k` (clamped), for shading and darker outlines.
Rgb scaled(Rgb colour, double k);

}  // namespace arg
