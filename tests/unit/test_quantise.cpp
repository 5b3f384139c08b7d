// Format 3's codecs: every code decodes and encodes back to itself; errors stay within a step.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <random>

#include "graph/quantise.hpp"

namespace arg {
namespace {

TEST(Quantise, EveryTwoByteCodeComesBack) {
  for (unsigned q = 0; q <= 65535; ++q)
    ASSERT_EQ(quantise_unit16(unit16_value(std::uint16_t(q))), q) << q;
  EXPECT_EQ(quantise_unit16(-1.0f), 0);
  EXPECT_EQ(quantise_unit16(2.0f), 65535);
  EXPECT_EQ(quantise_unit16(std::nanf("")), 0);
  EXPECT_NEAR(unit16_value(quantise_unit16(0.123456f)), 0.123456f, 0.5 / 65535 + 1e-7);
}

TEST(Quantise, TwoByteCodesDecodeAsTheirQuotient) {
  // unit16_value multiplies by 1/65535: stored values read as they were written, q / 65535.
  for (unsigned q = 0; q <= 65535; ++q) {
    const float got = unit16_value(std::uint16_t(q)), want = float(q / 65535.0);
    ASSERT_EQ(std::memcmp(&got, &want, sizeof got), 0) << q;
  }
}

TEST(Quantise, EveryByteCodeComesBackOnEveryRange) {
  const float pi = 3.14159265359f;
  for (auto [lo, hi] : {std::pair{0.0f, 1.0f}, std::pair{-pi / 2, pi / 2}, std::pair{0.0f, pi},
                        std::pair{0.0f, 4.0f}})
    for (unsigned q = 0; q <= 255; ++q) {
      const float x = byte_value(std::uint8_t(q), lo, hi);
      ASSERT_GE(x, lo);
      ASSERT_LE(x, hi);
      ASSERT_EQ(quantise_byte(x, lo, hi), q) << lo << " " << hi << " " << q;
    }
  EXPECT_EQ(quantise_byte(9.0f, 0, 4), 255) << "clamped";
}

TEST(Quantise, HistogramsKeepTheirTotalAndComeBack) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> uniform(0, 1);
  for (int trial = 0; trial < 2000; ++trial) {
    std::array<float, 8> bins{};
    float total = 0;
    for (float& b : bins) b = uniform(random) < 0.3f ? 0 : uniform(random), total += b;
    const float area = total * (trial % 2 ? 1.0f : 1e-4f);
    for (float& b : bins) b *= area / total;
    std::array<std::uint8_t, 8> q{}, again{};
    quantise_bins(bins.data(), 8, area, q.data());
    unsigned sum = 0;
    for (auto x : q) sum += x;
    ASSERT_EQ(sum, 255u) << "codes of a histogram that sums to its total";
    std::array<float, 8> back{};
    bins_values(q.data(), 8, area, back.data());
    double back_sum = 0;
    for (std::size_t k = 0; k < 8; ++k) {
      back_sum += back[k];
      ASSERT_NEAR(back[k], bins[k], area / 255.0 + 1e-9);
    }
    ASSERT_NEAR(back_sum, area, 1e-6 * area);
    quantise_bins(back.data(), 8, area, again.data());
    ASSERT_EQ(again, q) << "trial " << trial;
  }
  // No total, or no mass: zeros.
  std::array<float, 8> some{0.5f, 0.5f};
  std::array<std::uint8_t, 8> q{};
  quantise_bins(some.data(), 8, 0.0f, q.data());
  EXPECT_EQ(q, (std::array<std::uint8_t, 8>{}));
}

TEST(Quantise, SquareRootBlocksKeepSmallValuesAndComeBack) {
  std::mt19937 random(11);
  std::exponential_distribution<float> tail(200.0f);
  for (int trial = 0; trial < 200; ++trial) {
    std::array<float, 153> x{};
    for (float& v : x) v = std::min(tail(random), 1.0f);
    std::array<std::uint8_t, 153> q{}, again{};
    const float scale = quantise_sqrt_block(x.data(), x.size(), q.data());
    std::array<float, 153> back{};
    sqrt_block_values(q.data(), q.size(), scale, back.data());
    for (std::size_t k = 0; k < x.size(); ++k) {
      // Half a step of the square root: small values get small errors.
      const double step = 2 * std::sqrt(double(x[k]) * scale) / 255 + scale / (255.0 * 255.0);
      ASSERT_NEAR(back[k], x[k], step) << k;
    }
    ASSERT_EQ(quantise_sqrt_block(back.data(), back.size(), again.data()), scale);
    ASSERT_EQ(again, q);
  }
  std::array<float, 4> zeros{};
  std::array<std::uint8_t, 4> q{};
  EXPECT_EQ(quantise_sqrt_block(zeros.data(), 4, q.data()), 0.0f);
}

TEST(Quantise, CanonicalChecksAgreeWithTheirDefinition) {
  // canonical_bins_3x8 sums eight codes at once and canonical_sqrt_block looks for a 255 with
  // memchr: both against the plain definitions, on random and edge codes.
  std::mt19937 random(13);
  std::uniform_int_distribution<int> byte(0, 255), small(0, 40);
  for (int trial = 0; trial < 20000; ++trial) {
    std::array<std::uint8_t, 16> q{};
    for (auto& x : q) x = std::uint8_t(trial % 3 == 0 ? byte(random) : small(random));
    if (trial % 7 == 0) q.fill(trial % 2 ? 255 : 0);
    for (std::size_t count : {std::size_t(8), std::size_t(5), std::size_t(16)}) {
      unsigned sum = 0;
      for (std::size_t k = 0; k < count; ++k) sum += q[k];
      for (std::uint16_t total : {std::uint16_t(0), std::uint16_t(1), std::uint16_t(65535)})
        ASSERT_EQ(canonical_bins(q.data(), count, total), total == 0 ? sum == 0 : sum <= 255)
            << trial << " " << count;
      if (count == 16)
        for (std::uint16_t total : {std::uint16_t(0), std::uint16_t(7)}) {
          std::array<std::uint8_t, 24> three{};  // the first eight codes again after these
          std::copy(q.begin(), q.end(), three.begin());
          std::copy(q.begin(), q.begin() + 8, three.begin() + 16);
          const bool each = canonical_bins(three.data(), 8, total) &&
                            canonical_bins(three.data() + 8, 8, total) &&
                            canonical_bins(three.data() + 16, 8, total);
          ASSERT_EQ(canonical_bins_3x8(three.data(), total), each) << trial;
          std::swap(three[3], three[20]);  // the third histogram its own
          ASSERT_EQ(canonical_bins_3x8(three.data(), total),
                    canonical_bins(three.data(), 8, total) &&
                        canonical_bins(three.data() + 8, 8, total) &&
                        canonical_bins(three.data() + 16, 8, total))
              << trial;
        }
      const std::uint8_t top = *std::max_element(q.begin(), q.begin() + std::ptrdiff_t(count));
      for (float scale : {0.0f, kMinBlockScale, kMinBlockScale / 2, 0.5f, -1.0f, NAN})
        ASSERT_EQ(canonical_sqrt_block(q.data(), count, scale),
                  scale == 0 ? top == 0 : scale >= kMinBlockScale && top == 255)
            << trial << " " << count << " " << scale;
    }
  }
}

}  // namespace
}  // namespace arg
