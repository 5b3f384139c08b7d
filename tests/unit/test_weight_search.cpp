// Tests of the weight searches: one weight over a list of values, others held.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "eval/weight_search.hpp"

namespace arg {
namespace {

TEST(SearchOneWeight, TakesTheBestValueAndHoldsTheOthers) {
  const Weights start = weights_preset("arg");
  int calls = 0;
  const Weights best = search_one_weight(start, "lambda_4", {0, 0.5f, 1, 2}, [&](const Weights& w) {
    ++calls;
    return -std::abs(double(w.lambda_4) - 0.9);
  });
  EXPECT_EQ(calls, 4);
  EXPECT_FLOAT_EQ(best.lambda_4, 1.0f);
  Weights expected = start;
  expected.lambda_4 = 1.0f;
  EXPECT_TRUE(best == expected);  // nothing else moved
}

TEST(SearchOneWeight, TiesGoToTheFirstValueListed) {
  const Weights start = weights_preset("arg");
  const Weights best =
      search_one_weight(start, "lambda_3", {0, 1, 2}, [](const Weights&) { return 0.5; });
  EXPECT_FLOAT_EQ(best.lambda_3, 0.0f);
}

TEST(SearchOneWeight, MixingWeightsLandOnTheirGrid) {
  const Weights start = weights_preset("arg");
  const Weights best =
      search_one_weight(start, "spectrum", {0.33f}, [](const Weights&) { return 1.0; });
  EXPECT_FLOAT_EQ(best.spectrum, mixing_weight(mixing_steps(0.33f)));
  EXPECT_NE(best.spectrum, 0.33f);
}

TEST(SearchOneWeight, SkipsWeightsThatLeaveNoTerm) {
  Weights start = weights_preset("arg");
  start.panorama = start.spectrum = 0;
  // graph 0 with the others 0 leaves SIM nothing: skipped, so 1 wins though it scores lower.
  const Weights best = search_one_weight(start, "graph", {0, 1},
                                         [](const Weights& w) { return w.graph == 0 ? 1.0 : 0.0; });
  EXPECT_FLOAT_EQ(best.graph, 1.0f);
}

TEST(SearchOneWeight, RefusesAnUnknownNameNoValuesOrANegativeValue) {
  const Weights start = weights_preset("arg");
  const auto any = [](const Weights&) { return 0.0; };
  EXPECT_THROW(search_one_weight(start, "lambda_9", {1}, any), std::invalid_argument);
  EXPECT_THROW(search_one_weight(start, "lambda_4", {}, any), std::invalid_argument);
  EXPECT_THROW(search_one_weight(start, "lambda_4", {-1}, any), std::invalid_argument);
}

}  // namespace
}  // namespace arg
