// Retrieval quality measures of the Princeton Shape Benchmark over a full distance matrix.
#pragma once

#include <string>
#include <vector>

namespace arg {

inline constexpr int kRecallPoints = 20;  // precision-recall curve at recall 0.05, 0.10, .. 1

struct RetrievalScores {
  double nn = 0, ft = 0, st = 0, e = 0, dcg = 0, map = 0;  // means over queries, in [0, 1]
  std::vector<double> precision_at_recall;  // kRecallPoints values (interpolated precision)
  // Per class, so that a change which helps one kind of shape and hurts another shows: the mean
  // first tier and nearest neighbour of the class's queries, and how many queries that mean is
  // over (0 for a class of one, which has nothing to find: its means stay 0).
  std::vector<double> ft_per_class, nn_per_class;
  std::vector<int> queries_per_class;
};

// `distance` is row-major n x n (row = query); smaller is closer. `label` gives each model's
// class index in [0, classes). A model with `valid` false is a miss as a query (all zeros)
// and ranks last as a result. Each query ranks the n - 1 other models by (distance, index).
// NN: the first result is of the query's class. FT / ST: share of the class (size C, minus
// the query) found in the first C - 1 / 2(C - 1) results. E: F-measure of the first 32
// results. DCG: sum of 1/log2(rank) over relevant results (rank 1 counts 1), divided by its
// ideal value. mAP: mean over relevant results of the precision at their rank.
RetrievalScores retrieval_scores(const std::vector<double>& distance, const std::vector<int>& label,
                                 int classes, const std::vector<bool>& valid = {});

// Queries from outside the collection (the robustness benchmark: transformed copies against the
// clean set). `distance` is row-major q x n; each query ranks all n models by (distance,
// index); its relevant models are those of its class in the collection (class size C, the
// query's own original among them), so FT counts hits in the first C results, ST in 2C, and
// DCG and mAP are taken over the C relevant models. An invalid query is a miss; an invalid
// model ranks last. `query_self`, when given (one entry per query), names a model of the set
// each query stands for (-1: none), as a part of a model queried where it lies: that model is
// left out of the query's ranking and of its class, as in retrieval_scores. Throws
// std::invalid_argument on a size or index that does not fit.
RetrievalScores query_scores(const std::vector<double>& distance,
                             const std::vector<int>& query_label, const std::vector<int>& label,
                             int classes, const std::vector<bool>& query_valid = {},
                             const std::vector<bool>& valid = {},
                             const std::vector<int>& query_self = {});

}  // namespace arg
