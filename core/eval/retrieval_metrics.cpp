// NN, first and second tier, E-measure, DCG, mAP and the precision-recall curve.
#include "eval/retrieval_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace arg {

namespace {

// Adds one query's measures to `out`: `ranked` lists the results best first, `hit` says which
// are of the query's class and `relevant` how many the collection holds.
void add_query(RetrievalScores& out, const std::vector<int>& ranked, const std::vector<char>& hit,
               int relevant, int c) {
  int found = 0, in_first = 0, in_second = 0, in_32 = 0;
  double dcg = 0, ap = 0;
  std::vector<double> precision_at_hit;
  for (std::size_t rank = 1; rank <= ranked.size(); ++rank) {
    if (!hit[std::size_t(ranked[rank - 1])]) continue;
    ++found;
    if (int(rank) <= relevant) ++in_first;
    if (int(rank) <= 2 * relevant) ++in_second;
    if (rank <= 32) ++in_32;
    dcg += rank == 1 ? 1.0 : 1.0 / std::log2(double(rank));
    double precision = double(found) / double(rank);
    ap += precision;
    precision_at_hit.push_back(precision);
  }
  double ideal = 1.0;
  for (int k = 2; k <= relevant; ++k) ideal += 1.0 / std::log2(double(k));
  const double nn = !ranked.empty() && hit[std::size_t(ranked[0])] ? 1.0 : 0.0;
  out.nn += nn;
  out.nn_per_class[std::size_t(c)] += nn;
  const double ft = double(in_first) / relevant;
  out.ft += ft;
  out.ft_per_class[std::size_t(c)] += ft;
  out.st += double(in_second) / relevant;
  const double p32 = in_32 / 32.0, r32 = double(in_32) / relevant;
  out.e += p32 + r32 > 0 ? 2.0 * p32 * r32 / (p32 + r32) : 0.0;
  out.dcg += dcg / ideal;
  out.map += ap / relevant;
  // Interpolated precision: the best precision at any recall at least r.
  for (int k = 0; k < kRecallPoints; ++k) {
    const double recall = double(k + 1) / kRecallPoints;
    const std::size_t needed = std::size_t(std::ceil(recall * relevant - 1e-9));
    double best = 0;
    for (std::size_t h = needed == 0 ? 0 : needed - 1; h < precision_at_hit.size(); ++h)
      best = std::max(best, precision_at_hit[h]);
    out.precision_at_recall[std::size_t(k)] += best;
  }
}

void finish(RetrievalScores& out, int counted) {
  if (counted > 0) {
    for (double* x : {&out.nn, &out.ft, &out.st, &out.e, &out.dcg, &out.map}) *x /= counted;
    for (double& p : out.precision_at_recall) p /= counted;
  }
  for (std::size_t c = 0; c < out.ft_per_class.size(); ++c)
    if (const int q = out.queries_per_class[c]; q > 0) {
      out.ft_per_class[c] /= q;
      out.nn_per_class[c] /= q;
    }
}

// Ranks the models of one distance row by (distance, index), invalid models last.
void rank_row(const double* row, int n, int skip, const std::vector<bool>& valid,
              std::vector<int>& order) {
  order.clear();
  for (int j = 0; j < n; ++j)
    if (j != skip) order.push_back(j);
  auto key = [&](int j) { return valid[std::size_t(j)] ? row[j] : HUGE_VAL; };
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const double da = key(a), db = key(b);
    return da != db ? da < db : a < b;
  });
}

// Scores a row of `distance` (n entries, one per model of the set) per query. A query that is
// one of the set's models (query q is model `self[q]`; self empty: none is) is left out of its
// own ranking and of the count of models its class holds.
RetrievalScores score_rows(const std::vector<double>& distance, const std::vector<int>& query_label,
                           const std::vector<int>& label, int classes,
                           const std::vector<bool>& query_valid_in,
                           const std::vector<bool>& valid_in, const std::vector<int>& self_of) {
  const int q_count = int(query_label.size()), n = int(label.size());
  const std::vector<bool> valid =
      valid_in.empty() ? std::vector<bool>(std::size_t(n), true) : valid_in;
  const std::vector<bool> query_valid =
      query_valid_in.empty() ? std::vector<bool>(std::size_t(q_count), true) : query_valid_in;
  std::vector<int> class_size(std::size_t(classes), 0);
  for (int c : label) ++class_size[std::size_t(c)];
  RetrievalScores out;
  out.precision_at_recall.assign(kRecallPoints, 0.0);
  out.ft_per_class.assign(std::size_t(classes), 0.0);
  out.nn_per_class.assign(std::size_t(classes), 0.0);
  out.queries_per_class.assign(std::size_t(classes), 0);
  std::vector<int> order;
  int counted = 0;
  for (int q = 0; q < q_count; ++q) {
    const int c = query_label[std::size_t(q)];
    const int self = self_of.empty() ? -1 : self_of[std::size_t(q)];
    const int relevant =
        c >= 0 && c < classes ? class_size[std::size_t(c)] - (self >= 0 ? 1 : 0) : 0;
    if (relevant <= 0) continue;  // a class of one has nothing to find
    ++counted;
    ++out.queries_per_class[std::size_t(c)];
    if (!query_valid[std::size_t(q)]) continue;
    rank_row(distance.data() + std::size_t(q) * std::size_t(n), n, self, valid, order);
    std::vector<char> hit(static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j) hit[std::size_t(j)] = label[std::size_t(j)] == c && j != self;
    add_query(out, order, hit, relevant, c);
  }
  finish(out, counted);
  return out;
}

}  // namespace

RetrievalScores retrieval_scores(const std::vector<double>& distance, const std::vector<int>& label,
                                 int classes, const std::vector<bool>& valid) {
  std::vector<int> self(label.size());
  std::iota(self.begin(), self.end(), 0);
  return score_rows(distance, label, label, classes, valid, valid, self);
}

RetrievalScores query_scores(const std::vector<double>& distance,
                             const std::vector<int>& query_label, const std::vector<int>& label,
                             int classes, const std::vector<bool>& query_valid,
                             const std::vector<bool>& valid, const std::vector<int>& query_self) {
  if (!query_self.empty() && query_self.size() != query_label.size())
    throw std::invalid_argument("query_scores: one query_self entry per query");
  for (int m : query_self)
    if (m < -1 || m >= int(label.size()))
      throw std::invalid_argument("query_scores: query_self " + std::to_string(m) +
                                  " is no model of the set");
  return score_rows(distance, query_label, label, classes, query_valid, valid, query_self);
}

}  // namespace arg
