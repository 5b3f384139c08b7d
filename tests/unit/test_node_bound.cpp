// The node bound: how many nodes a level of a graph may hold, and which level passes it.
#include <gtest/gtest.h>

#include "graph/node_bound.hpp"

namespace arg {
namespace {

// A graph head of `levels` levels whose level r holds counts[r] nodes (no node records needed).
ArgGraph with_level_counts(int levels, const std::vector<std::uint32_t>& counts) {
  ArgGraph g;
  g.options.levels = levels;
  g.level_begin.assign(std::size_t(levels) + 2, 0);
  for (std::size_t r = 0; r < counts.size(); ++r)
    g.level_begin[r + 1] = g.level_begin[r] + counts[r];
  return g;
}

TEST(NodeBound, ShrinksWithMoreLevels) {
  EXPECT_EQ(max_nodes_per_level(5), 640u);
  EXPECT_EQ(max_nodes_per_level(7), 480u);
  EXPECT_GT(max_nodes_per_level(7), 1u << 7) << "room for the pool on the finest level";
  EXPECT_LE(max_nodes_per_level(1) * 2, kMaxGraphNodes);
}

TEST(NodeBound, NamesTheFirstLevelOverIt) {
  EXPECT_EQ(level_over_node_bound(with_level_counts(2, {1, 2, 4})), -1);
  EXPECT_EQ(level_over_node_bound(with_level_counts(2, {1, 1280, 1280})), -1) << "at the bound";
  EXPECT_EQ(level_over_node_bound(with_level_counts(2, {1, 1281, 2000})), 1);
  EXPECT_EQ(level_over_node_bound(with_level_counts(2, {1, 2, 1281})), 2);
}

}  // namespace
}  // namespace arg
