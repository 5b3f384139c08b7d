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

float unit16_value(std::uint16_t q) {
  return float(q / 65535.0);
}

std::uint8_t quantise_byte(float x, float lo, float hi) {
  return std::uint8_t(rounded((double(x) - lo) / (double(hi) - lo) * 255.0, 255));
}

float byte_value(std::uint8_t q, float lo, float hi) {
  return float(lo + (double(hi) - lo) * (q / 255.0));
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

void bins_values(const std::uint8_t* q, std::size_t count, float total, float* out) {
  // One multiplication a bin: this runs on every node of every row a query ranks.
  const float step = total / 255.0f;
  for (std::size_t k = 0; k < count; ++k) out[k] = float(q[k]) * step;
}

float quantise_sqrt_block(const float* x, std::size_t count, std::uint8_t* out) {
  float scale = 0;
  for (std::size_t k = 0; k < count; ++k) scale = std::max(scale, x[k]);
  if (!(scale >= kMinBlockScale)) scale = 0;
  for (std::size_t k = 0; k < count; ++k)
    out[k] = scale > 0 ? std::uint8_t(rounded(std::sqrt(double(x[k]) / scale) * 255.0, 255)) : 0;
  return scale;
}

void sqrt_block_values(const std::uint8_t* q, std::size_t count, float scale, float* out) {
  static const std::array<float, 256> squares = [] {
    std::array<float, 256> t{};
    for (int k = 0; k < 256; ++k) t[std::size_t(k)] = float((k / 255.0) * (k / 255.0));
    return t;
  }();
  for (std::size_t k = 0; k < count; ++k) out[k] = scale * squares[q[k]];
}

bool canonical_bins(const std::uint8_t* q, std::size_t count, std::uint16_t total_code) {
  unsigned sum = 0;
  for (std::size_t k = 0; k < count; ++k) sum += q[k];
  return total_code == 0 ? sum == 0 : sum <= 255;
}

bool canonical_sqrt_block(const std::uint8_t* q, std::size_t count, float scale) {
  const std::uint8_t top = count ? *std::max_element(q, q + count) : 0;
  return scale == 0 ? top == 0 : scale >= kMinBlockScale && top == 255;
}

}  // namespace arg
