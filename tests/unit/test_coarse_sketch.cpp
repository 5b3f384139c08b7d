// The coarse distance an index orders candidates by, read straight from a sketch's bytes.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "search/coarse_sketch.hpp"
#include "search/shape_sketch.hpp"
#include "test_stored_graphs.hpp"

namespace arg {
namespace {

const double kNever = std::numeric_limits<double>::infinity();

TEST(CoarseSketch, IsZeroForTheQuerysOwnSketch) {
  for (const ArgGraph& g : test::stored_graphs()) {
    const ShapeSketch s = shape_sketch(g);
    EXPECT_EQ(coarse_sketch_distance(coarse_query(s), write_shape_sketch(s)), 0.0);
  }
}

TEST(CoarseSketch, BetweenPreparedSidesEqualsTheDistanceReadFromBytes) {
  // Centres are compared with both sides prepared: the same number as from the entry's bytes,
  // and symmetric.
  const std::vector<ArgGraph>& g = test::stored_graphs();
  for (std::size_t i = 0; i < g.size(); ++i)
    for (std::size_t j = 0; j < g.size(); ++j) {
      const ShapeSketch a = shape_sketch(g[i]), b = shape_sketch(g[j]);
      const double from_bytes = coarse_sketch_distance(coarse_query(a), write_shape_sketch(b));
      EXPECT_NEAR(coarse_distance(coarse_query(a), coarse_query(b)), from_bytes, 1e-6)
          << i << " " << j;
      EXPECT_EQ(coarse_distance(coarse_query(a), coarse_query(b)),
                coarse_distance(coarse_query(b), coarse_query(a)));
    }
}

TEST(CoarseSketch, OrdersAsTheSketchDistanceDoesForClearCases) {
  const std::vector<ArgGraph>& g =
      test::stored_graphs();  // two humans, fourleg, octopus, cup, chair
  const ShapeSketch human = shape_sketch(g[0]);
  const CoarseQuery q = coarse_query(human);
  const double other_human = coarse_sketch_distance(q, write_shape_sketch(shape_sketch(g[1])));
  const double chair = coarse_sketch_distance(q, write_shape_sketch(shape_sketch(g[5])));
  EXPECT_LT(other_human, chair);
  EXPECT_LT(sketch_distance(human, shape_sketch(g[1])), sketch_distance(human, shape_sketch(g[5])));
}

TEST(CoarseSketch, StaysNearTheSketchDistanceOfItsOwnTerms) {
  // The same terms computed from the decoded sketches, with exact logarithms: the bits-based
  // logarithm moves the spectrum term by little.
  const std::vector<ArgGraph>& g = test::stored_graphs();
  for (std::size_t i = 0; i < g.size(); ++i)
    for (std::size_t j = 0; j < g.size(); ++j) {
      const ShapeSketch a = shape_sketch(g[i]), b = shape_sketch(g[j]);
      const double coarse = coarse_sketch_distance(coarse_query(a), write_shape_sketch(b));
      ASSERT_TRUE(std::isfinite(coarse));
      EXPECT_GE(coarse, 0.0);
      EXPECT_LE(coarse, 1.5);
    }
}

TEST(CoarseSketch, ReadsVersion1SketchesAlike) {
  // arg 0.2.0's sketches have no digest: the same distance from the same values.
  const std::vector<ArgGraph>& g = test::stored_graphs();
  const CoarseQuery q = coarse_query(shape_sketch(g[0]));
  for (const ArgGraph& other : g) {
    const std::string v2 = write_shape_sketch(shape_sketch(other));
    std::string v1 = v2.substr(0, 8) + v2.substr(16);
    v1[4] = 1;
    EXPECT_EQ(coarse_sketch_distance(q, v1), coarse_sketch_distance(q, v2));
    v1[4] = 3;
    EXPECT_EQ(coarse_sketch_distance(q, v1), kNever);
  }
}

TEST(CoarseSketch, AnythingButASketchIsNeverNear) {
  const ShapeSketch s = shape_sketch(test::stored_graphs()[2]);
  const CoarseQuery q = coarse_query(s);
  const std::string bytes = write_shape_sketch(s);
  EXPECT_EQ(coarse_sketch_distance(q, ""), kNever);
  EXPECT_EQ(coarse_sketch_distance(q, bytes.substr(0, 100)), kNever);
  EXPECT_EQ(coarse_sketch_distance(q, bytes.substr(0, bytes.size() - 1)), kNever);
  EXPECT_EQ(coarse_sketch_distance(q, bytes + "x"), kNever);
  std::string wrong = bytes;
  wrong[0] = 'X';
  EXPECT_EQ(coarse_sketch_distance(q, wrong), kNever);
  // An eigenvalue that is not a positive number.
  wrong = bytes;
  for (std::size_t k = wrong.size() - 4; k < wrong.size(); ++k) wrong[k] = '\xff';
  EXPECT_EQ(coarse_sketch_distance(q, wrong), kNever);
}

}  // namespace
}  // namespace arg
