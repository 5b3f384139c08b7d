// Separable DFT of the depth images, evaluated only at the kept low frequencies.
#include "features/depth_buffer_descriptor.hpp"

#include <cmath>
#include <complex>

namespace arg {

std::vector<float> depth_buffer_descriptor(const DepthImages& images, int band) {
  const int n = images.resolution;
  std::vector<float> out;
  if (n <= 0) return out;
  const int width = 2 * band + 1;  // u in [-band, band]
  std::vector<std::complex<double>> twiddle(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) twiddle[std::size_t(k)] = std::polar(1.0, -2.0 * M_PI * k / n);
  auto root = [&](long long k) { return twiddle[std::size_t(((k % n) + n) % n)]; };
  std::vector<std::complex<double>> rows(static_cast<std::size_t>(width * n));
  for (const auto& image : images.view) {
    // G(u, y) = sum_x f(x, y) e^{-2 pi i u x / N}
    for (int y = 0; y < n; ++y)
      for (int u = -band; u <= band; ++u) {
        std::complex<double> s = 0;
        for (int x = 0; x < n; ++x) {
          const float f = image[std::size_t(y) * std::size_t(n) + std::size_t(x)];
          if (f != 0) s += double(f) * root(static_cast<long long>(u) * x);
        }
        rows[std::size_t(u + band) * std::size_t(n) + std::size_t(y)] = s;
      }
    const double norm = 1.0 / (double(n) * n);
    for (int v = 0; v <= band; ++v)
      for (int u = -band; u <= band; ++u) {
        if (std::abs(u) + v > band || (v == 0 && u < 0)) continue;
        std::complex<double> s = 0;
        for (int y = 0; y < n; ++y)
          s += rows[std::size_t(u + band) * std::size_t(n) + std::size_t(y)] *
               root(static_cast<long long>(v) * y);
        out.push_back(float(std::abs(s) * norm));
      }
  }
  return out;
}

}  // namespace arg
