// Cells of the sketch index: centres are distinct members, filing and probing by distance.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "common/errors.hpp"
#include "gen/generate_models.hpp"
#include "graph/serialize.hpp"
#include "pipeline/build_arg.hpp"
#include "search/sketch_cells.hpp"

using namespace arg;

namespace {

// Sketches of stored values: three variants each of a human, a cup and a table.
const std::vector<ShapeSketch>& sketches() {
  static const std::vector<ShapeSketch> all = [] {
    std::vector<ShapeSketch> v;
    for (const char* cls : {"human", "cup", "table"})
      for (int variant = 1; variant <= 3; ++variant)
        v.push_back(shape_sketch(deserialize_arg(
            serialize_arg(build_arg(generate_model(cls, variant, 32, false).mesh)))));
    return v;
  }();
  return all;
}

}  // namespace

TEST(SketchCells, CentresAreDistinctMembersAndRepeatWithTheSeed) {
  const auto& s = sketches();
  const std::vector<std::size_t> a = choose_cell_centres(s.data(), s.size(), 4, 7);
  ASSERT_EQ(a.size(), 4u);
  EXPECT_EQ(std::set<std::size_t>(a.begin(), a.end()).size(), 4u);
  for (std::size_t c : a) EXPECT_LT(c, s.size());
  EXPECT_EQ(choose_cell_centres(s.data(), s.size(), 4, 7), a);
  // Asking for more centres than sketches gives each sketch once.
  const std::vector<std::size_t> all = choose_cell_centres(s.data(), s.size(), 50, 7);
  EXPECT_EQ(all.size(), s.size());
  EXPECT_EQ(std::set<std::size_t>(all.begin(), all.end()).size(), s.size());
  EXPECT_TRUE(choose_cell_centres(nullptr, 0, 4, 7).empty());
  EXPECT_TRUE(choose_cell_centres(s.data(), s.size(), 0, 7).empty());
}

TEST(SketchCells, DuplicatesNeverMakeTwoCentres) {
  std::vector<ShapeSketch> same(5, sketches()[0]);
  same.push_back(sketches()[4]);
  const std::vector<std::size_t> c = choose_cell_centres(same.data(), same.size(), 4, 1);
  ASSERT_EQ(c.size(), 2u);  // two distinct sketches, however many are asked for
  EXPECT_NE(c[0] == 5, c[1] == 5);
}

TEST(SketchCells, SeedingSpreadsCentresOverTheClasses) {
  // Three centres among three tight classes: one from each, whatever the seed.
  const auto& s = sketches();
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    std::set<std::size_t> classes;
    for (std::size_t c : choose_cell_centres(s.data(), s.size(), 3, seed)) classes.insert(c / 3);
    EXPECT_EQ(classes.size(), 3u) << "seed " << seed;
  }
}

TEST(SketchCells, FilingAndProbingFollowTheDistance) {
  const auto& s = sketches();
  const std::vector<ShapeSketch> centres = {s[0], s[3], s[6]};
  for (std::size_t c = 0; c < centres.size(); ++c)
    EXPECT_EQ(nearest_cell(centres[c], centres.data(), 3), c);
  for (std::size_t m = 0; m < s.size(); ++m) {
    const std::size_t cell = nearest_cell(s[m], centres.data(), 3);
    for (const ShapeSketch& other : centres)
      EXPECT_LE(sketch_distance(s[m], centres[cell]), sketch_distance(s[m], other));
    const std::vector<std::size_t> probe = cells_to_probe(s[m], centres.data(), 3, 2);
    ASSERT_EQ(probe.size(), 2u);
    EXPECT_EQ(probe[0], cell);
    EXPECT_LE(sketch_distance(s[m], centres[probe[0]]), sketch_distance(s[m], centres[probe[1]]));
    std::vector<std::size_t> every = cells_to_probe(s[m], centres.data(), 3, 10);
    ASSERT_EQ(every.size(), 3u);
    std::sort(every.begin(), every.end());
    EXPECT_EQ(every, (std::vector<std::size_t>{0, 1, 2}));
  }
}

TEST(SketchCells, ManyCentresRankedCoarselyFirstKeepTheNearest) {
  // More centres than kCellsRefined: the coarse pass ranks them all, the sketch distance the
  // nearest few. Each sketch is its own centre here (several copies of each), so the coarse
  // pass must keep the exact one among those it refines.
  const auto& s = sketches();
  std::vector<ShapeSketch> centres;
  while (centres.size() <= kCellsRefined + 8)
    for (const ShapeSketch& x : s) centres.push_back(x);
  const std::vector<CoarseQuery> coarse = coarse_centres(centres.data(), centres.size());
  ASSERT_EQ(coarse.size(), centres.size());
  for (std::size_t m = 0; m < s.size(); ++m) {
    const std::size_t exact = nearest_cell(s[m], centres.data(), centres.size());
    EXPECT_EQ(nearest_cell(s[m], centres.data(), centres.size(), coarse.data()), exact);
    EXPECT_EQ(sketch_distance(s[m], centres[exact]), 0.0);
    const std::vector<std::size_t> fast =
        cells_to_probe(s[m], centres.data(), centres.size(), 4, coarse.data());
    const std::vector<std::size_t> slow = cells_to_probe(s[m], centres.data(), centres.size(), 4);
    EXPECT_EQ(fast, slow);
    // A full order still names every cell once.
    std::vector<std::size_t> every =
        cells_to_probe(s[m], centres.data(), centres.size(), centres.size(), coarse.data());
    std::sort(every.begin(), every.end());
    for (std::size_t c = 0; c < every.size(); ++c) EXPECT_EQ(every[c], c);
  }
}

TEST(SketchCells, CandidatesGrowADecadeAtATime) {
  EXPECT_EQ(default_candidates(-1), 25u);  // a size never measured
  EXPECT_EQ(default_candidates(0), 25u);
  EXPECT_EQ(default_candidates(1000), 25u);
  EXPECT_EQ(default_candidates(100000), 25u);
  EXPECT_EQ(default_candidates(300000), 25u);
  EXPECT_EQ(default_candidates(400000), 50u);
  EXPECT_EQ(default_candidates(1000000), 50u);
  EXPECT_EQ(default_candidates(10000000), 75u);
}

TEST(SketchCells, SeedingStopsWhenAsked) {
  int polls = 0;
  EXPECT_THROW(
      choose_cell_centres(sketches().data(), sketches().size(), 5, 1, [&] { return ++polls > 2; }),
      Interrupted);
}
