// Child halves: each node's children in index order split at its interval's halves, and the
// candidate scan over them finds what a scan of the whole interval finds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "match/child_halves.hpp"
#include "match/match_prep.hpp"
#include "match/similarity.hpp"
#include "match/weights.hpp"
#include "test_stored_graphs.hpp"

using namespace arg;
using test::stored_graphs;

namespace {

bool same_bits(double x, double y) {
  return std::memcmp(&x, &y, sizeof x) == 0;
}

std::vector<MatchKey> keys_of(const ArgGraph& g) {
  std::vector<std::array<int, 2>> only;
  std::vector<MatchKey> keys;
  prepare_nodes(g, only, keys);
  return keys;
}

}  // namespace

TEST(ChildHalves, ListEachNodesChildrenInIndexOrderLowerHalfFirst) {
  for (const ArgGraph& g : stored_graphs()) {
    std::vector<std::uint32_t> begin, mid, children;
    ASSERT_TRUE(prepare_child_halves(g, keys_of(g), begin, mid, children));
    ASSERT_EQ(begin.size(), g.nodes.size() + 1);
    std::size_t total = 0;
    for (std::size_t i = 0; i < g.nodes.size(); ++i) {
      std::vector<std::uint32_t> expected;
      for (std::size_t c = 0; c < g.nodes.size(); ++c)
        if (g.nodes[c].parent == int(i)) expected.push_back(std::uint32_t(c));
      EXPECT_EQ(
          std::vector<std::uint32_t>(children.begin() + begin[i], children.begin() + begin[i + 1]),
          expected)
          << i;
      total += expected.size();
      for (std::uint32_t c = begin[i]; c < begin[i + 1]; ++c)
        EXPECT_EQ(g.nodes[children[c]].interval, 2 * g.nodes[i].interval + (c >= mid[i] ? 1u : 0u));
    }
    EXPECT_EQ(children.size(), total);
  }
}

TEST(ChildHalves, ListsInAnyOrderAreSortedAndBadOnesRefused) {
  const ArgGraph& g = stored_graphs()[3];
  std::vector<std::uint32_t> begin, mid, children, begin2, mid2, children2;
  ASSERT_TRUE(prepare_child_halves(g, keys_of(g), begin, mid, children));
  ArgGraph backwards = g;
  for (const ArgNode& n : backwards.nodes)
    std::reverse(backwards.children.begin() + n.child_begin,
                 backwards.children.begin() + n.child_begin + n.child_count);
  ASSERT_TRUE(prepare_child_halves(backwards, keys_of(backwards), begin2, mid2, children2));
  EXPECT_EQ(children2, children);
  EXPECT_EQ(mid2, mid);
  // A child in neither half of its parent's interval, a child naming no node, a list past the
  // end: no lists (the matcher scans whole intervals).
  ArgGraph moved = g, unnamed = g, past = g;
  const std::size_t child = g.level_begin[2];
  moved.nodes[child].interval ^= 2;
  EXPECT_FALSE(prepare_child_halves(moved, keys_of(moved), begin2, mid2, children2));
  EXPECT_TRUE(begin2.empty() && mid2.empty() && children2.empty());
  unnamed.children[0] = std::uint32_t(g.nodes.size());
  EXPECT_FALSE(prepare_child_halves(unnamed, keys_of(unnamed), begin2, mid2, children2));
  past.nodes.back().child_begin = std::uint32_t(g.children.size());
  past.nodes.back().child_count = 1;
  EXPECT_FALSE(prepare_child_halves(past, keys_of(past), begin2, mid2, children2));
}

TEST(ChildHalves, TheChildrenScanFindsWhatTheIntervalScanFinds) {
  // A MatchPrep without its lists makes match_graphs scan whole intervals on both sides.
  Weights no_tung = weights_preset("arg");
  no_tung.tung_rule = false;
  for (const Weights& w : {weights_preset("arg"), weights_preset("graph"), no_tung}) {
    std::vector<MatchPrep> with(stored_graphs().size()), without(stored_graphs().size());
    for (std::size_t i = 0; i < with.size(); ++i) {
      prepare_match(stored_graphs()[i], w, with[i]);
      ASSERT_FALSE(with[i].child_begin.empty());
      without[i] = with[i];
      without[i].child_begin.clear(), without[i].child_mid.clear(), without[i].children.clear();
    }
    for (std::size_t i = 0; i < with.size(); ++i)
      for (std::size_t j = 0; j < with.size(); ++j) {
        if (i == j) continue;
        const ArgGraph &a = stored_graphs()[i], &b = stored_graphs()[j];
        std::vector<MatchPair> scanned, listed;
        const double s0 = arg_similarity(a, b, w, &scanned, &without[i], &without[j]);
        const double s1 = arg_similarity(a, b, w, &listed, &with[i], &with[j]);
        EXPECT_TRUE(same_bits(s0, s1)) << i << " " << j;
        ASSERT_EQ(scanned.size(), listed.size()) << i << " " << j;
        for (std::size_t k = 0; k < scanned.size(); ++k) {
          EXPECT_EQ(scanned[k].a_node, listed[k].a_node);
          EXPECT_EQ(scanned[k].b_node, listed[k].b_node);
          EXPECT_TRUE(same_bits(scanned[k].sim, listed[k].sim));
        }
        // The unprepared path makes its own lists: the same again.
        EXPECT_TRUE(same_bits(arg_similarity(a, b, w), s0));
      }
  }
}
