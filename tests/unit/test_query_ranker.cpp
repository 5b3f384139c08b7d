// A query ranked against stored values straight from their bytes: SIM to the bit, as <~>.
#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "graph/serialize.hpp"
#include "match/similarity.hpp"
#include "search/query_ranker.hpp"
#include "test_stored_graphs.hpp"

namespace arg {
namespace {

TEST(QueryRanker, GivesSimToTheBitForEveryRow) {
  const std::vector<ArgGraph>& g = test::stored_graphs();
  for (std::size_t q = 0; q < g.size(); ++q) {
    QueryRanker ranker(serialize_arg(g[q]));
    for (std::size_t r = 0; r < g.size(); ++r)
      EXPECT_EQ(ranker.sim(serialize_arg(g[r])), arg_similarity(g[r], g[q]))
          << "row " << r << " against query " << q;
  }
}

TEST(QueryRanker, KeepsTheQuerysSketch) {
  const ArgGraph& q = test::stored_graphs()[2];
  const QueryRanker ranker(serialize_arg(q));
  const ShapeSketch s = shape_sketch(q);
  EXPECT_EQ(write_shape_sketch(ranker.sketch()), write_shape_sketch(s));
}

TEST(QueryRanker, RefusesBadQueriesAndRows) {
  const std::vector<ArgGraph>& g = test::stored_graphs();
  std::string bytes = serialize_arg(g[0]);
  bytes[40] ^= 1;  // the digest no longer matches
  EXPECT_THROW(QueryRanker{bytes}, InputError);
  QueryRanker ranker(serialize_arg(g[1]));
  EXPECT_THROW(ranker.sim(bytes.substr(0, 30)), InputError);
  // A row built by another builder cannot be compared.
  ArgGraph other = g[3];
  other.builder_version += 100;
  EXPECT_THROW(ranker.sim(serialize_arg(other)), Incomparable);
}

}  // namespace
}  // namespace arg
