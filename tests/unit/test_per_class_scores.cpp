// Per-class NN and FT on a hand-made distance matrix whose every ranking is known.
#include <gtest/gtest.h>

#include "eval/retrieval_metrics.hpp"

using namespace arg;

namespace {

// Distances that make query q rank the others in the order ranking[q] gives.
std::vector<double> from_rankings(const std::vector<std::vector<int>>& ranking) {
  const std::size_t n = ranking.size();
  std::vector<double> d(n * n, 0.0);
  for (std::size_t q = 0; q < n; ++q)
    for (std::size_t k = 0; k < ranking[q].size(); ++k)
      d[q * n + std::size_t(ranking[q][k])] = double(k + 1);
  return d;
}

// Vessels {0,1,2} (2 to find each), animals {3,4,5,6} (3 each) and a lone bust 7 (nothing).
const std::vector<int> kLabel = {0, 0, 0, 1, 1, 1, 1, 2};
const std::vector<std::vector<int>> kRanking = {
    {1, 2, 3, 4, 5, 6, 7},  // NN 1, FT 2/2
    {3, 0, 4, 2, 5, 6, 7},  // NN 0, FT 1/2 (0 in the first two)
    {7, 3, 4, 0, 1, 5, 6},  // NN 0, FT 0
    {4, 5, 6, 0, 1, 2, 7},  // NN 1, FT 3/3
    {0, 3, 5, 6, 1, 2, 7},  // NN 0, FT 2/3 (3 and 5 in the first three)
    {6, 1, 2, 3, 4, 0, 7},  // NN 1, FT 1/3
    {3, 4, 5, 0, 1, 2, 7},  // NN 1, FT 3/3
    {0, 1, 2, 3, 4, 5, 6},  // a class of one: not a query
};

}  // namespace

TEST(PerClassScores, KnownNearestNeighbourAndFirstTierOfEachClass) {
  const RetrievalScores s = retrieval_scores(from_rankings(kRanking), kLabel, 3);
  ASSERT_EQ(s.nn_per_class.size(), 3u);
  EXPECT_EQ(s.queries_per_class, (std::vector<int>{3, 4, 0}));
  EXPECT_NEAR(s.nn_per_class[0], 1.0 / 3, 1e-12);
  EXPECT_NEAR(s.ft_per_class[0], (1.0 + 0.5 + 0.0) / 3, 1e-12);
  EXPECT_NEAR(s.nn_per_class[1], 3.0 / 4, 1e-12);
  EXPECT_NEAR(s.ft_per_class[1], (1.0 + 2.0 / 3 + 1.0 / 3 + 1.0) / 4, 1e-12);
  // The lone bust has nothing to find: no queries, means left at 0.
  EXPECT_EQ(s.nn_per_class[2], 0.0);
  EXPECT_EQ(s.ft_per_class[2], 0.0);
}

TEST(PerClassScores, ClassMeansWeighedByTheirQueriesGiveTheOverallMeans) {
  const RetrievalScores s = retrieval_scores(from_rankings(kRanking), kLabel, 3);
  double nn = 0, ft = 0;
  int queries = 0;
  for (std::size_t c = 0; c < 3; ++c) {
    nn += s.nn_per_class[c] * s.queries_per_class[c];
    ft += s.ft_per_class[c] * s.queries_per_class[c];
    queries += s.queries_per_class[c];
  }
  EXPECT_NEAR(nn / queries, s.nn, 1e-12);
  EXPECT_NEAR(ft / queries, s.ft, 1e-12);
  EXPECT_NEAR(s.nn, 4.0 / 7, 1e-12);
}

TEST(PerClassScores, AFailedModelIsAMissAndRanksLast) {
  // Vessel 2 failed: as a query it finds nothing (still counted), as a result it ranks last, so
  // vessel 0's first two are 1 and 3 (FT 1/2) and animal 5's first three 6, 1, 3 (FT 2/3, was
  // 1/3).
  std::vector<bool> valid(8, true);
  valid[2] = false;
  const RetrievalScores s = retrieval_scores(from_rankings(kRanking), kLabel, 3, valid);
  EXPECT_EQ(s.queries_per_class, (std::vector<int>{3, 4, 0}));
  EXPECT_NEAR(s.nn_per_class[0], 1.0 / 3, 1e-12);
  EXPECT_NEAR(s.ft_per_class[0], (0.5 + 0.5 + 0.0) / 3, 1e-12);
  EXPECT_NEAR(s.nn_per_class[1], 3.0 / 4, 1e-12);
  EXPECT_NEAR(s.ft_per_class[1], (1.0 + 2.0 / 3 + 2.0 / 3 + 1.0) / 4, 1e-12);
}
