// PSB retrieval measures on tiny hand-made rankings with known answers, and the label CSV.
#include <gtest/gtest.h>

#include <stdexcept>

#include "common/errors.hpp"
#include "eval/label_file.hpp"
#include "eval/retrieval_metrics.hpp"

using namespace arg;

namespace {

// Distances that make every query rank the others in the order given by `rank_of`.
std::vector<double> from_rankings(const std::vector<std::vector<int>>& ranking) {
  const std::size_t n = ranking.size();
  std::vector<double> d(n * n, 0.0);
  for (std::size_t q = 0; q < n; ++q)
    for (std::size_t k = 0; k < ranking[q].size(); ++k)
      d[q * n + std::size_t(ranking[q][k])] = double(k + 1);
  return d;
}

}  // namespace

TEST(RetrievalMetrics, PerfectRankingScoresOneEverywhere) {
  // Two classes of three: {0,1,2} and {3,4,5}; each query lists its class first.
  std::vector<int> label = {0, 0, 0, 1, 1, 1};
  auto d = from_rankings({{1, 2, 3, 4, 5},
                          {0, 2, 3, 4, 5},
                          {0, 1, 3, 4, 5},
                          {4, 5, 0, 1, 2},
                          {3, 5, 0, 1, 2},
                          {3, 4, 0, 1, 2}});
  RetrievalScores s = retrieval_scores(d, label, 2);
  EXPECT_DOUBLE_EQ(s.nn, 1.0);
  EXPECT_DOUBLE_EQ(s.ft, 1.0);
  EXPECT_DOUBLE_EQ(s.st, 1.0);
  EXPECT_DOUBLE_EQ(s.dcg, 1.0);
  EXPECT_DOUBLE_EQ(s.map, 1.0);
  // E over the first 32 of only 5 results: P = 2/32, R = 1, E = 2PR/(P+R) = 4/34.
  EXPECT_NEAR(s.e, 2.0 * (2.0 / 32) / (2.0 / 32 + 1.0), 1e-12);
  for (double p : s.precision_at_recall) EXPECT_DOUBLE_EQ(p, 1.0);
}

TEST(RetrievalMetrics, KnownValuesOfOneImperfectQuery) {
  // Class {0,1,2} and singletons 3, 4 (which have nothing to find and are not counted).
  // Query 0 ranks 3, 1, 4, 2: hits at ranks 2 and 4.
  std::vector<int> label = {0, 0, 0, 1, 2};
  auto d = from_rankings({{3, 1, 4, 2}, {0, 2, 3, 4}, {0, 1, 3, 4}, {0, 1, 2, 4}, {0, 1, 2, 3}});
  RetrievalScores s = retrieval_scores(d, label, 3);
  // Queries 1 and 2 are perfect. Query 0 (C - 1 = 2 to find): NN 0; FT 1/2 (one hit in the
  // first 2); ST 1 (both hits in the first 4); DCG (1/log2 2 + 1/log2 4) / (1 + 1/log2 2)
  // = 0.75; AP (1/2 + 2/4) / 2 = 0.5.
  EXPECT_NEAR(s.nn, 2.0 / 3, 1e-12);
  EXPECT_NEAR(s.ft, 2.5 / 3, 1e-12);
  EXPECT_NEAR(s.st, 1.0, 1e-12);
  EXPECT_NEAR(s.dcg, (1.0 + 1.0 + 0.75) / 3, 1e-12);
  EXPECT_NEAR(s.map, (1.0 + 1.0 + 0.5) / 3, 1e-12);
  EXPECT_NEAR(s.ft_per_class[0], 2.5 / 3, 1e-12);
}

TEST(RetrievalMetrics, AFailedModelIsAMissAndRanksLast) {
  std::vector<int> label = {0, 0, 1, 1};
  auto d = from_rankings({{1, 2, 3}, {0, 2, 3}, {3, 0, 1}, {2, 0, 1}});
  RetrievalScores s = retrieval_scores(d, label, 2, {true, false, true, true});
  // Query 1 failed (zero); query 0 finds only the failed 1, ranked last: NN 0; 2 and 3 fine.
  EXPECT_NEAR(s.nn, 0.5, 1e-12);
}

TEST(RetrievalMetrics, QueriesFromOutsideRankEveryModelOfTheSet) {
  // Set: class 0 = {0, 1, 2}, class 1 = {3, 4}. Two part queries: the first (class 0) ranks
  // 0 3 1 4 2, the second (class 1) ranks 3 0 1 2 4.
  const std::vector<int> label = {0, 0, 0, 1, 1};
  const std::vector<double> d = {1, 3, 5, 2, 4,   // query 0: ranks of models 0..4
                                 2, 3, 4, 1, 5};  // query 1
  const RetrievalScores s = query_scores(d, {0, 1}, label, 2);
  // Query 0 (3 relevant, hits at ranks 1, 3, 5): NN 1; FT 2/3 (ranks 1 and 3 of the first 3);
  // AP (1/1 + 2/3 + 3/5) / 3 = 0.7556. Query 1 (2 relevant, hits at ranks 1 and 5): NN 1;
  // FT 1/2; AP (1/1 + 2/5) / 2 = 0.7.
  EXPECT_NEAR(s.nn, 1.0, 1e-12);
  EXPECT_NEAR(s.ft, (2.0 / 3 + 0.5) / 2, 1e-12);
  EXPECT_NEAR(s.map, ((1.0 + 2.0 / 3 + 3.0 / 5) / 3 + (1.0 + 2.0 / 5) / 2) / 2, 1e-12);
}

TEST(RetrievalMetrics, AQueryStandingForAModelLeavesItOut) {
  // The same distances, each query now a part of a model queried where it lies: query 0 is
  // model 0 and query 1 model 4, left out of their rankings and of their classes.
  const std::vector<int> label = {0, 0, 0, 1, 1};
  const std::vector<double> d = {1, 3, 5, 2, 4, 2, 3, 4, 1, 5};
  const RetrievalScores s = query_scores(d, {0, 1}, label, 2, {}, {}, {0, 4});
  // Query 0 ranks 3 1 4 2 (2 relevant, hits at ranks 2 and 4): NN 0, FT 1/2, AP (1/2 + 2/4)
  // / 2 = 0.5. Query 1 ranks 3 0 1 2 (1 relevant, at rank 1): NN 1, FT 1, AP 1.
  EXPECT_NEAR(s.nn, 0.5, 1e-12);
  EXPECT_NEAR(s.ft, 0.75, 1e-12);
  EXPECT_NEAR(s.map, 0.75, 1e-12);
  // -1 stands for no model: the scores of the plain call.
  const RetrievalScores plain = query_scores(d, {0, 1}, label, 2, {}, {}, {-1, -1});
  EXPECT_NEAR(plain.map, query_scores(d, {0, 1}, label, 2).map, 1e-15);
  EXPECT_THROW(query_scores(d, {0, 1}, label, 2, {}, {}, {0}), std::invalid_argument);
  EXPECT_THROW(query_scores(d, {0, 1}, label, 2, {}, {}, {0, 5}), std::invalid_argument);
}

TEST(LabelCsv, ReadsModelsAndClasses) {
  LabelSet set = parse_label_csv(
      "model_id,path,class\n1,Meshes/1.ply,Human\n2,\"Meshes/a,b.ply\",Cup\r\n3,x.off,Human\n");
  ASSERT_EQ(set.models.size(), 3u);
  EXPECT_EQ(set.models[1].path, "Meshes/a,b.ply");
  EXPECT_EQ(set.classes, (std::vector<std::string>{"Human", "Cup"}));
  EXPECT_EQ(set.class_of, (std::vector<int>{0, 1, 0}));
}

TEST(LabelCsv, RejectsMalformedRowsWithTheLineNumber) {
  auto message = [](const char* text) {
    try {
      parse_label_csv(text);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message("id,path,class\n").find("line 1"), std::string::npos);
  EXPECT_NE(message("model_id,path,class\n1,a.off,X\n2,b.off\n").find("line 3"), std::string::npos);
  EXPECT_NE(message("model_id,path,class\n1,a.off,X\n1,b.off,Y\n").find("repeated"),
            std::string::npos);
  EXPECT_NE(message("model_id,path,class\n1,,X\n").find("empty field"), std::string::npos);
  EXPECT_NE(message("").find("empty file"), std::string::npos);
}
