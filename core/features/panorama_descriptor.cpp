// Separable DFT of each panoramic view at the kept frequencies, in two frames.
#include "features/panorama_descriptor.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/normal_pose.hpp"

namespace arg {

std::vector<float> panorama_features(const PanoramicViews& views, int angular, int axial) {
  const int h = views.height, w = views.width;
  std::vector<float> out;
  if (h <= 0 || w <= 0) return out;
  out.reserve(views.image.size() * std::size_t((angular + 1) * (axial + 1)));
  // Tables of cos and sin of 2 pi k / n, so the sums below are plain multiply-adds.
  auto table = [](int n) {
    std::vector<double> cs(2 * std::size_t(n));
    for (int k = 0; k < n; ++k)
      cs[2 * std::size_t(k)] = std::cos(2.0 * M_PI * k / n),
             cs[2 * std::size_t(k) + 1] = std::sin(2.0 * M_PI * k / n);
    return cs;
  };
  const std::vector<double> around = table(w), along = table(h);
  // G(u, y) = sum_x f(x, y) e^{-2 pi i u x / w}, as (re, im) per u and y.
  std::vector<double> re(std::size_t((angular + 1) * h)), im(re.size());
  const double norm = 1.0 / (double(w) * h);
  for (const auto& image : views.image) {
    std::fill(re.begin(), re.end(), 0.0);
    std::fill(im.begin(), im.end(), 0.0);
    for (int y = 0; y < h; ++y) {
      const float* row = image.data() + std::size_t(y) * std::size_t(w);
      for (int x = 0; x < w; ++x) {
        if (row[x] == 0) continue;
        const double f = row[x];
        for (int u = 0, k = 0; u <= angular; ++u, k = (k + x) % w) {
          re[std::size_t(u * h + y)] += f * around[2 * std::size_t(k)];
          im[std::size_t(u * h + y)] -= f * around[2 * std::size_t(k) + 1];
        }
      }
    }
    // F(u, +-v) = sum_y G(u, y) e^{-+2 pi i v y / h}; keep the mean of the two magnitudes.
    for (int u = 0; u <= angular; ++u)
      for (int v = 0; v <= axial; ++v) {
        double up_re = 0, up_im = 0, down_re = 0, down_im = 0;
        for (int y = 0, k = 0; y < h; ++y, k = (k + v) % h) {
          const double gr = re[std::size_t(u * h + y)], gi = im[std::size_t(u * h + y)];
          const double c = along[2 * std::size_t(k)], s = along[2 * std::size_t(k) + 1];
          up_re += gr * c + gi * s, up_im += gi * c - gr * s;
          down_re += gr * c - gi * s, down_im += gi * c + gr * s;
        }
        out.push_back(
            float(0.5 * (std::hypot(up_re, up_im) + std::hypot(down_re, down_im)) * norm));
      }
  }
  return out;
}

std::vector<float> panorama_wavelet_features(const PanoramicViews& views, int levels) {
  std::vector<float> out;
  std::vector<double> a, next, band;
  auto add_stats = [&](const std::vector<double>& coefficients) {
    double sum = 0, squares = 0;
    for (double c : coefficients) sum += std::fabs(c), squares += c * c;
    const double n = double(std::max<std::size_t>(coefficients.size(), 1));
    const double mean = sum / n;
    out.push_back(float(mean));
    out.push_back(float(std::sqrt(std::max(squares / n - mean * mean, 0.0))));
  };
  for (const auto& image : views.image) {
    int h = views.height, w = views.width;
    a.assign(image.begin(), image.end());
    for (int level = 0; level < levels && h >= 2 && w >= 2; ++level) {
      const int h2 = h / 2, w2 = w / 2;
      next.assign(std::size_t(h2) * std::size_t(w2), 0.0);
      // Detail bands: along the axis, around it, and both (averages and half-differences).
      for (int kind = 0; kind < 3; ++kind) {
        band.assign(next.size(), 0.0);
        for (int y = 0; y < h2; ++y)
          for (int x = 0; x < w2; ++x) {
            const double p = a[std::size_t(2 * y) * std::size_t(w) + std::size_t(2 * x)],
                         q = a[std::size_t(2 * y) * std::size_t(w) + std::size_t(2 * x + 1)],
                         r = a[std::size_t(2 * y + 1) * std::size_t(w) + std::size_t(2 * x)],
                         t = a[std::size_t(2 * y + 1) * std::size_t(w) + std::size_t(2 * x + 1)];
            const std::size_t k = std::size_t(y) * std::size_t(w2) + std::size_t(x);
            band[k] = kind == 0   ? 0.25 * (p + q - r - t)
                      : kind == 1 ? 0.25 * (p - q + r - t)
                                  : 0.25 * (p - q - r + t);
            if (kind == 0) next[k] = 0.25 * (p + q + r + t);
          }
        add_stats(band);
      }
      a.swap(next);
      h = h2, w = w2;
    }
    add_stats(a);
  }
  return out;
}

std::vector<float> panorama_descriptor(const Mesh& posed, const StopRequested& stop) {
  std::vector<float> out;
  const Mesh turned = apply_pose(posed, normal_pose(posed, stop));
  check_interrupt(stop);
  for (const Mesh* frame : {&posed, &turned}) {
    const PanoramicViews views = panoramic_views(*frame, kPanoramaHeight, kPanoramaRadius, stop);
    const std::vector<float> fourier = panorama_features(views, kPanoramaAngular, kPanoramaAxial);
    const std::vector<float> wavelet = panorama_wavelet_features(views, kPanoramaLevels);
    out.insert(out.end(), fourier.begin(), fourier.end());
    out.insert(out.end(), wavelet.begin(), wavelet.end());
  }
  return out;
}

double panorama_distance(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != std::size_t(kPanoramaSize) || b.size() != a.size()) return 1.0;
  return panorama_distance(a.data(), b.data());
}

double panorama_distance(const float* a, const float* b) {
  double best = 1.0;
  for (std::size_t f = 0; f < 2; ++f) {
    const std::size_t begin = f * kPanoramaPerFrame, wavelet = begin + kPanoramaFourier,
                      end = begin + kPanoramaPerFrame;
    // Four running sums, added up at the end: independent sums let the compiler use vector
    // instructions (one sum is a chain of dependent additions).
    auto four_lanes = [](std::size_t from, std::size_t to, auto&& term) {
      double part[4] = {0, 0, 0, 0};
      std::size_t k = from;
      for (; k + 4 <= to; k += 4)
        for (std::size_t q = 0; q < 4; ++q) part[q] += term(k + q);
      for (; k < to; ++k) part[0] += term(k);
      return (part[0] + part[1]) + (part[2] + part[3]);
    };
    const double l1 = four_lanes(
        begin, wavelet, [&](std::size_t k) { return std::fabs(double(a[k]) - double(b[k])); });
    // Smooth views have near-zero detail statistics, whose plain Canberra ratio |x - y| / (x +
    // y) would only measure rounding noise: 0.01 in the denominator damps them (it also scores
    // better on all three benchmark sets than 0.001 or nothing).
    const double canberra = four_lanes(wavelet, end, [&](std::size_t k) {
      const double x = a[k], y = b[k];
      return std::fabs(x - y) / (x + y + 0.01);  // both are >= 0
    });
    best = std::min(best, 0.5 * (std::min(1.0, l1 / 6.0) + canberra / kPanoramaWavelet));
  }
  return best;
}

}  // namespace arg
