// The eval matrix file: a line per model in label order, rereading to the same scores.
#include <gtest/gtest.h>

#include <cmath>

#include "common/errors.hpp"
#include "eval/distance_matrix_file.hpp"
#include "eval/retrieval_metrics.hpp"

namespace arg {
namespace {

TEST(DistanceMatrixFile, OneLinePerModelAndTheSameScoresWhenReadBack) {
  DistanceMatrix m;
  m.n = 5;
  const double d[25] = {0,   0.1, 0.7, 0.3, 1.0 / 3, 0.1, 0,    0.2,     0.9, 0.5, 0.7,  0.2, 0,
                        0.4, 0.6, 0.3, 0.9, 0.4,     0,   0.25, 1.0 / 3, 0.5, 0.6, 0.25, 0};
  m.distance.assign(d, d + 25);
  m.valid = {true, true, true, false, true};  // model 3 failed to build
  const std::string text = format_distance_matrix(m);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 5);
  const DistanceMatrix back = parse_distance_matrix(text);
  ASSERT_EQ(back.n, 5u);
  EXPECT_EQ(back.valid, m.valid);
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t j = 0; j < 5; ++j)
      if (m.valid[i] && m.valid[j])
        EXPECT_EQ(back.distance[i * 5 + j], m.distance[i * 5 + j]);  // exact, not near
      else
        EXPECT_TRUE(std::isinf(back.distance[i * 5 + j]));
  const std::vector<int> label = {0, 0, 1, 1, 1};
  const RetrievalScores a = retrieval_scores(m.distance, label, 2, m.valid);
  const RetrievalScores b = retrieval_scores(back.distance, label, 2, back.valid);
  EXPECT_EQ(a.nn, b.nn);
  EXPECT_EQ(a.ft, b.ft);
  EXPECT_EQ(a.dcg, b.dcg);
  EXPECT_EQ(a.map, b.map);
}

TEST(DistanceMatrixFile, ABadLineIsNamed) {
  try {
    parse_distance_matrix("0 1\n1 x\n");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos);
  }
  EXPECT_THROW(parse_distance_matrix("0 1\n1\n"), InputError);
  EXPECT_THROW(parse_distance_matrix("0 nan\nnan 0\n"), InputError);
}

TEST(RetrievalMetrics, AFailedModelIsAMissNotDropped) {
  // Two classes of two; model 3 failed. Its query scores zero and still counts.
  const std::vector<int> label = {0, 0, 1, 1};
  std::vector<double> d = {0, 1, 5, 5, 1, 0, 5, 5, 5, 5, 0, 1, 5, 5, 1, 0};
  const RetrievalScores all = retrieval_scores(d, label, 2);
  EXPECT_DOUBLE_EQ(all.nn, 1.0);
  const RetrievalScores one_failed = retrieval_scores(d, label, 2, {true, true, true, false});
  EXPECT_DOUBLE_EQ(one_failed.nn, 0.5);  // queries 2 and 3 find nothing of their class
}

TEST(RetrievalMetrics, OutsideQueriesFindTheirOriginalAndClassmates) {
  // A collection of two classes of two; two queries from outside, one per class.
  const std::vector<int> label = {0, 0, 1, 1};
  const std::vector<int> query_label = {0, 1};
  const std::vector<double> d = {0.1, 0.2, 0.9, 0.8,   // query of class 0: both hits first
                                 0.3, 0.9, 0.1, 0.7};  // query of class 1: hit, miss, hit
  const RetrievalScores s = query_scores(d, query_label, label, 2);
  EXPECT_DOUBLE_EQ(s.nn, 1.0);
  EXPECT_DOUBLE_EQ(s.ft, (1.0 + 0.5) / 2);
  EXPECT_DOUBLE_EQ(s.map, (1.0 + (1.0 + 2.0 / 3) / 2) / 2);
}

}  // namespace
}  // namespace arg
