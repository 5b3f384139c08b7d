// Pixel-level operations on an RGB Image; every other drawing function goes through these.
#include "render/canvas.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"

namespace arg {

namespace {

std::uint8_t mix(std::uint8_t under, std::uint8_t over, double alpha) {
  return std::uint8_t(std::lround(under + (double(over) - under) * alpha));
}

}  // namespace

bool operator==(const Rgb& x, const Rgb& y) {
  return x.r == y.r && x.g == y.g && x.b == y.b;
}

Image make_canvas(int width, int height, Rgb background) {
  if (width <= 0 || height <= 0) throw InputError("render: picture size must be positive");
  Image image;
  image.width = width;
  image.height = height;
  image.rgb.resize(std::size_t(width) * std::size_t(height) * 3);
  for (std::size_t i = 0; i < image.rgb.size(); i += 3)
    image.rgb[i] = background.r, image.rgb[i + 1] = background.g, image.rgb[i + 2] = background.b;
  return image;
}

void blend_pixel(Image& image, int x, int y, Rgb colour, double alpha) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height || !(alpha > 0)) return;
  alpha = std::min(alpha, 1.0);
  std::uint8_t* p = &image.rgb[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 3];
  p[0] = mix(p[0], colour.r, alpha), p[1] = mix(p[1], colour.g, alpha);
  p[2] = mix(p[2], colour.b, alpha);
}

Rgb pixel_at(const Image& image, int x, int y) {
  const std::uint8_t* p =
      &image.rgb[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 3];
  return {p[0], p[1], p[2]};
}

void fill_rect(Image& image, int x, int y, int w, int h, Rgb colour, double alpha) {
  const int x0 = std::max(x, 0), x1 = std::min(x + w, image.width);
  const int y0 = std::max(y, 0), y1 = std::min(y + h, image.height);
  for (int j = y0; j < y1; ++j)
    for (int i = x0; i < x1; ++i) blend_pixel(image, i, j, colour, alpha);
}

void blit(Image& target, const Image& source, int x, int y) {
  for (int j = 0; j < source.height; ++j) {
    const int ty = y + j;
    if (ty < 0 || ty >= target.height) continue;
    for (int i = 0; i < source.width; ++i) {
      const int tx = x + i;
      if (tx < 0 || tx >= target.width) continue;
      const std::size_t s = (std::size_t(j) * std::size_t(source.width) + std::size_t(i)) * 3;
      const std::size_t t = (std::size_t(ty) * std::size_t(target.width) + std::size_t(tx)) * 3;
      std::copy_n(&source.rgb[s], 3, &target.rgb[t]);
    }
  }
}

Image downsample(const Image& image, int factor) {
  if (factor <= 1) return image;
  if (image.width % factor || image.height % factor)
    throw InputError("render: picture size is not a multiple of the supersampling factor");
  Image out = make_canvas(image.width / factor, image.height / factor, {});
  const int n = factor * factor;
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 3; ++c) {
        int sum = 0;
        for (int j = 0; j < factor; ++j)
          for (int i = 0; i < factor; ++i)
            sum += image.rgb[(std::size_t(y * factor + j) * std::size_t(image.width) +
                              std::size_t(x * factor + i)) *
                                 3 +
                             std::size_t(c)];
        out.rgb[(std::size_t(y) * std::size_t(out.width) + std::size_t(x)) * 3 + std::size_t(c)] =
            std::uint8_t((sum + n / 2) / n);
      }
  return out;
}

Rgb scaled(Rgb colour, double k) {
  auto s = [k](std::uint8_t v) { return std::uint8_t(std::clamp(std::lround(v * k), 0L, 255L)); };
  return {s(colour.r), s(colour.g), s(colour.b)};
}

}  // namespace arg
