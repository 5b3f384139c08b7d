// Sampling a texture image at texture coordinates, and the colour of one textured triangle.
#include "io/texture_sampling.hpp"

#include <cmath>

namespace arg::io {

namespace {

// Maps texel coordinate i (possibly outside 0..n-1) into the image.
int wrap(long long i, int n, TextureWrap mode) {
  switch (mode) {
    case TextureWrap::ClampToEdge:
      return static_cast<int>(i < 0 ? 0 : (i >= n ? n - 1 : i));
    case TextureWrap::MirroredRepeat: {
      const long long period = 2LL * n;
      long long m = i % period;
      if (m < 0) m += period;
      return static_cast<int>(m < n ? m : period - 1 - m);
    }
    case TextureWrap::Repeat:
      break;
  }
  long long m = i % n;
  if (m < 0) m += n;
  return static_cast<int>(m);
}

}  // namespace

std::array<float, 3> sample_texture(const Image& image, double s, double t,
                                    const TextureSampler& sampler) {
  if (image.empty() || !std::isfinite(s) || !std::isfinite(t)) return {0, 0, 0};
  // Keep coordinates bounded before converting to integers; a shift by 2^20 whole images changes
  // nothing for the repeating modes, and clamping stays clamping.
  auto bound = [](double c, TextureWrap mode) {
    return mode == TextureWrap::ClampToEdge ? std::fmin(2.0, std::fmax(-1.0, c))
                                            : std::fmod(c, double(1 << 20));
  };
  s = bound(s, sampler.wrap_s);
  t = bound(t, sampler.wrap_t);
  const double row = sampler.v_origin_bottom ? 1.0 - t : t;
  const double x = s * image.width - 0.5, y = row * image.height - 0.5;
  const double x0 = std::floor(x), y0 = std::floor(y);
  const double fx = x - x0, fy = y - y0;
  std::array<float, 3> out{0, 0, 0};
  for (int dy = 0; dy < 2; ++dy) {
    for (int dx = 0; dx < 2; ++dx) {
      const double w = (dx ? fx : 1 - fx) * (dy ? fy : 1 - fy);
      const int px = wrap(static_cast<long long>(x0) + dx, image.width, sampler.wrap_s);
      const int py = wrap(static_cast<long long>(y0) + dy, image.height, sampler.wrap_t);
      const std::uint8_t* texel =
          &image.rgb[3 *
                     (static_cast<std::size_t>(py) * std::size_t(image.width) + std::size_t(px))];
      for (int c = 0; c < 3; ++c) out[c] += static_cast<float>(w * texel[c] / 255.0);
    }
  }
  return out;
}

std::array<float, 3> triangle_texture_colour(const Image& image, const double uv[3][2],
                                             const TextureSampler& sampler) {
  const double cs = (uv[0][0] + uv[1][0] + uv[2][0]) / 3, ct = (uv[0][1] + uv[1][1] + uv[2][1]) / 3;
  std::array<float, 3> sum = sample_texture(image, cs, ct, sampler);
  for (int k = 0; k < 3; ++k) {
    const std::array<float, 3> c = sample_texture(image, uv[k][0], uv[k][1], sampler);
    for (int i = 0; i < 3; ++i) sum[i] += c[i];
  }
  for (float& c : sum) c /= 4;
  return sum;
}

std::array<float, 3> mean_texture_colour(const Image& image) {
  double sum[3] = {0, 0, 0};
  const std::size_t n = image.rgb.size() / 3;
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) sum[c] += image.rgb[3 * i + c];
  }
  if (n == 0) return {0, 0, 0};
  return {float(sum[0] / (255.0 * n)), float(sum[1] / (255.0 * n)), float(sum[2] / (255.0 * n))};
}

}  // namespace arg::io
