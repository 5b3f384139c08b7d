// Format 3's codecs: linear, per-total and square-root byte codes with their inverses.
#include "graph/quantise.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace arg {

namespace {

// Rounds a code already scaled to [0, top]; NaN and negatives go to 0.
unsigned rounded(double scaled, unsigned top) {
  if (!(scaled > 0)) return 0;
  return scaled >= top ? top : unsigned(std::lround(scaled));
}

}  // namespace

std::uint16_t quantise_unit16(float x) {
  return std::uint16_t(rounded(double(x) * 65535.0, 65535));
}

std::uint8_t quantise_byte(float x, float lo, float hi) {
  return std::uint8_t(rounded((double(x) - lo) / (double(hi) - lo) * 255.0, 255));
}

void quantise_bins(const float* bins, std::size_t count, float total, std::uint8_t* out) {
  // Largest remainders: the codes add up to the rounded sum of the bins, 255 when the bins add
  // up to the total, so a histogram read back still sums to its node's area (SIM of a graph
  // with itself stays 0).
  double sum = 0;
  for (std::size_t k = 0; k < count; ++k) sum += bins[k] > 0 ? double(bins[k]) : 0.0;
  if (!(total > 0) || !(sum > 0)) {
    std::fill(out, out + count, std::uint8_t(0));
    return;
  }
  const unsigned target = rounded(sum / total * 255.0, 255);
  double fraction[64];
  unsigned given = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const double x = bins[k] > 0 ? std::min(double(bins[k]) / sum * target, 255.0) : 0.0;
    out[k] = std::uint8_t(std::floor(x));
    fraction[k] = x - out[k];
    given += out[k];
  }
  for (; given < target; ++given) {
    std::size_t best = 0;
    for (std::size_t k = 1; k < count; ++k)
      if (fraction[k] > fraction[best]) best = k;
    ++out[best];
    fraction[best] = -1;
  }
}

float quantise_sqrt_block(const float* x, std::size_t count, std::uint8_t* out) {
  float scale = 0;
  for (std::size_t k = 0; k < count; ++k) scale = std::max(scale, x[k]);
  if (!(scale >= kMinBlockScale)) scale = 0;
  for (std::size_t k = 0; k < count; ++k)
    out[k] = scale > 0 ? std::uint8_t(rounded(std::sqrt(double(x[k]) / scale) * 255.0, 255)) : 0;
  return scale;
}

const std::array<float, 256>& code_squares() {
  static const std::array<float, 256> squares = [] {
    std::array<float, 256> t{};
    for (int k = 0; k < 256; ++k) t[std::size_t(k)] = float((k / 255.0) * (k / 255.0));
    return t;
  }();
  return squares;
}

}  // namespace arg
