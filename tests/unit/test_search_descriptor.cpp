// The first stage's descriptor: its blocks hold what a value stores, scaled, within a cube.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "features/laplace_spectrum.hpp"
#include "features/panorama_descriptor.hpp"
#include "gen/generate_models.hpp"
#include "graph/serialize.hpp"
#include "pipeline/build_arg.hpp"
#include "search/search_descriptor.hpp"

using namespace arg;

namespace {

// Where each block starts (search_descriptor.hpp).
constexpr int kCountsAt = kSearchCountsAt, kPanoramaAt = kSearchPanoramaAt,
              kEigenAt = kSearchEigenAt, kColourAt = kSearchColourAt;

// Stored values, as arg_global reads them: a coloured cup and a plain human.
const ArgGraph& stored(bool colour) {
  static const ArgGraph cup = deserialize_arg(
                            serialize_arg(build_arg(generate_model("cup", 1, 32, true).mesh))),
                        human = deserialize_arg(
                            serialize_arg(build_arg(generate_model("human", 2, 32, false).mesh)));
  return colour ? cup : human;
}

double taxicab(const std::array<float, kSearchDims>& a, const std::array<float, kSearchDims>& b) {
  double s = 0;
  for (int k = 0; k < kSearchDims; ++k) s += std::fabs(double(a[k]) - b[k]);
  return s;
}

}  // namespace

TEST(SearchDescriptor, FitsACubeAndEndsWithColour) {
  static_assert(kSearchDims <= 100, "contrib/cube holds at most 100 dimensions");
  EXPECT_EQ(kColourAt + 3 * kSearchColourBins, kSearchDims);
}

TEST(SearchDescriptor, PanoramaBlockIsTheFirstFramesLowestFrequencies) {
  const ArgGraph& g = stored(false);
  ASSERT_EQ(g.panorama.size(), std::size_t(kPanoramaSize));
  const auto d = search_descriptor(g);
  int k = kPanoramaAt;
  for (int view = 0; view < kSearchViews; ++view)
    for (int u = 0; u <= kSearchAngular; ++u)
      for (int v = 0; v <= kSearchAxial; ++v, ++k) {
        const float x =
            g.panorama[std::size_t(view * kPanoramaPerView + u * (kPanoramaAxial + 1) + v)];
        EXPECT_FLOAT_EQ(d[std::size_t(k)], 3.0f * x) << "view " << view << " u " << u << " v " << v;
      }
  // The mean of each view (frequency 0, 0) is far from zero: the block is not empty.
  EXPECT_GT(d[std::size_t(kPanoramaAt)], 0.0f);
}

TEST(SearchDescriptor, EigenBlockIsTheLogSpectrumOrOneFillWithoutIt) {
  ArgGraph g = stored(false);
  ASSERT_GE(g.spectrum.size(), std::size_t(kSearchEigen));
  const auto with = search_descriptor(g);
  for (int e = 0; e < kSearchEigen; ++e)
    EXPECT_NEAR(with[std::size_t(kEigenAt + e)], 0.3 * std::log(double(g.spectrum[std::size_t(e)])),
                1e-6);
  // Without a spectrum (a proxy's), every model sits at the same point of the block.
  g.spectrum.clear();
  ArgGraph other = stored(true);
  other.spectrum.clear();
  const auto a = search_descriptor(g), b = search_descriptor(other);
  for (int e = 0; e < kSearchEigen; ++e) {
    EXPECT_EQ(a[std::size_t(kEigenAt + e)], b[std::size_t(kEigenAt + e)]);
    EXPECT_LT(a[std::size_t(kEigenAt + e)], 0.0f);  // the labelled sets' mean log eigenvalue
  }
  // A spectrum that holds a number no log can take counts as missing, not as NaN.
  ArgGraph broken = stored(false);
  broken.spectrum[3] = 0.0f;
  const auto c = search_descriptor(broken);
  for (int e = 0; e < kSearchEigen; ++e)
    EXPECT_EQ(c[std::size_t(kEigenAt + e)], a[std::size_t(kEigenAt + e)]);
  // Nothing else moves.
  for (int k = 0; k < kEigenAt; ++k) EXPECT_EQ(a[std::size_t(k)], with[std::size_t(k)]);
}

TEST(SearchDescriptor, ValuesWithoutPanoramaLeaveZeros) {
  ArgGraph g = stored(false);
  g.panorama.clear();
  const auto d = search_descriptor(g);
  for (int k = kPanoramaAt; k < kEigenAt; ++k) EXPECT_EQ(d[std::size_t(k)], 0.0f);
  // A NaN in an unchecked panorama is left out too: every value stays finite.
  ArgGraph nan = stored(false);
  nan.panorama[0] = std::nanf("");
  const auto e = search_descriptor(nan);
  for (float x : e) EXPECT_TRUE(std::isfinite(x));
  EXPECT_EQ(e[std::size_t(kPanoramaAt)], 0.0f);
}

TEST(SearchDescriptor, ColourMergesPairsOfBins) {
  const ArgGraph& plain = stored(false);
  const auto p = search_descriptor(plain);
  for (int k = kColourAt; k < kSearchDims; ++k) EXPECT_EQ(p[std::size_t(k)], 0.0f);
  const ArgGraph& cup = stored(true);
  ASSERT_TRUE(cup.summary.has_colour);
  const auto c = search_descriptor(cup);
  const Weights w;
  const double levels = cup.levels() + 1.0, scale = w.lambda_4 * levels / 3.0;
  double total = 0;
  for (int b = 0; b < 3 * kSearchColourBins; ++b) {
    const auto& bins = cup.nodes.front().colour;
    EXPECT_NEAR(c[std::size_t(kColourAt + b)],
                scale * (double(bins[std::size_t(2 * b)]) + bins[std::size_t(2 * b + 1)]), 1e-6);
    total += c[std::size_t(kColourAt + b)];
  }
  EXPECT_GT(total, 0.0);
}

TEST(SearchDescriptor, NodeCountsPerIntervalOfEachLevel) {
  const ArgGraph& g = stored(false);
  const auto d = search_descriptor(g);
  for (int r = 0; r < kSearchLevels; ++r) {
    const double count =
        r <= g.levels() ? double(g.level_begin[std::size_t(r) + 1] - g.level_begin[std::size_t(r)])
                        : 0.0;
    EXPECT_NEAR(d[std::size_t(kCountsAt + r)], 2.0 * 0.02 * count / double(1 << r), 1e-6);
  }
}

TEST(SearchDescriptor, TellsModelsApartAndAModelFromNoOther) {
  const auto a = search_descriptor(stored(false)), b = search_descriptor(stored(true));
  EXPECT_EQ(taxicab(a, a), 0.0);
  EXPECT_GT(taxicab(a, b), 0.1);
  // A pose of the same human is nearer to it than the cup is.
  const ArgGraph posed =
      deserialize_arg(serialize_arg(build_arg(generate_model("human", 3, 32, false).mesh)));
  EXPECT_LT(taxicab(a, search_descriptor(posed)), taxicab(a, b));
}
