// MatchPrep: comparing with a graph's prepared parts gives the same bits as without them.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "match/match_prep.hpp"
#include "match/similarity.hpp"
#include "match/weights.hpp"
#include "pipeline/build_arg.hpp"
#include "test_shapes.hpp"
#include "test_stored_graphs.hpp"

using namespace arg;

namespace {

// Built graphs of a few shapes, and one of them again with colour histograms (its curvature's
// mass spread over the channels), so that the colour rule is exercised on both sides.
const std::vector<ArgGraph>& graphs() {
  static const std::vector<ArgGraph> all = [] {
    std::vector<ArgGraph> g;
    g.push_back(build_arg(test::torus()));
    g.push_back(build_arg(test::capsule()));
    g.push_back(build_arg(test::capsule(2, 0.7)));
    g.push_back(build_arg(test::sphere(40, 60, 2, 1, 0.7)));
    for (int k = 0; k < 2; ++k) {
      ArgGraph coloured = g[std::size_t(k + 1)];
      coloured.summary.has_colour = 1;
      for (ArgNode& n : coloured.nodes)
        for (std::size_t c = 0; c < n.colour.size(); ++c)
          n.colour[c] = n.curv_mean[c % n.curv_mean.size()] * float(1 + c % 3) / 2.0f;
      g.push_back(coloured);
    }
    return g;
  }();
  return all;
}

bool same_pairs(const std::vector<MatchPair>& x, const std::vector<MatchPair>& y) {
  if (x.size() != y.size()) return false;
  for (std::size_t k = 0; k < x.size(); ++k)
    if (x[k].level != y[k].level || x[k].a_node != y[k].a_node || x[k].b_node != y[k].b_node ||
        x[k].group != y[k].group || x[k].loss != y[k].loss || x[k].sim != y[k].sim)
      return false;
  return true;
}

}  // namespace

TEST(MatchPrep, GivesTheSameBitsAsComparingWithout) {
  for (const char* preset : {"arg", "mrg", "colour", "shape"}) {
    const Weights w = weights_preset(preset);
    std::vector<MatchPrep> preps(graphs().size());
    for (std::size_t i = 0; i < graphs().size(); ++i) prepare_match(graphs()[i], w, preps[i]);
    for (std::size_t i = 0; i < graphs().size(); ++i)
      for (std::size_t j = 0; j < graphs().size(); ++j) {
        const ArgGraph &a = graphs()[i], &b = graphs()[j];
        std::vector<MatchPair> plain, prepared;
        const double s0 = arg_similarity(a, b, w, &plain);
        const double s1 = arg_similarity(a, b, w, &prepared, &preps[i], &preps[j]);
        EXPECT_EQ(s0, s1) << preset << " " << i << " " << j;
        EXPECT_TRUE(same_pairs(plain, prepared)) << preset << " " << i << " " << j;
        // One side prepared only, and without the pairs (the ranking's path).
        EXPECT_EQ(arg_similarity(a, b, w, nullptr, &preps[i], nullptr), s0);
        EXPECT_EQ(arg_similarity(a, b, w, nullptr, nullptr, &preps[j]), s0);
      }
  }
}

TEST(MatchPrep, ColouredGraphsHoldBothSumsAndPlainOnesOnlyOne) {
  const Weights w = weights_preset("arg");
  MatchPrep plain, coloured;
  prepare_match(graphs()[1], w, plain);
  prepare_match(graphs()[4], w, coloured);
  EXPECT_NE(plain.sums(false), nullptr);
  EXPECT_EQ(plain.sums(true), nullptr);
  ASSERT_NE(coloured.sums(true), nullptr);
  // Colour adds lambda_4 x area to every node's own sim.
  EXPECT_GT(coloured.sums(true)->total, coloured.sums(false)->total);
  for (const MatchPrep* p : {&plain, &coloured})
    for (int r = 0; r <= graphs()[1].levels(); ++r) {
      const auto& order = p->sums(false)->order;
      const auto& self = p->sums(false)->self;
      for (std::uint32_t k = graphs()[1].level_begin[std::size_t(r)] + 1;
           k < graphs()[1].level_begin[std::size_t(r) + 1]; ++k)
        EXPECT_GE(self[std::size_t(order[k - 1])], self[std::size_t(order[k])]);
    }
}

TEST(MatchPrep, APrepForOtherWeightsOrAnotherGraphIsNotUsed) {
  const Weights arg_w = weights_preset("arg"), mrg_w = weights_preset("mrg");
  MatchPrep wrong_weights, wrong_graph;
  prepare_match(graphs()[0], mrg_w, wrong_weights);
  prepare_match(graphs()[3], arg_w, wrong_graph);
  EXPECT_FALSE(prep_fits(&wrong_weights, graphs()[0], arg_w));
  EXPECT_TRUE(prep_fits(&wrong_weights, graphs()[0], mrg_w));
  ASSERT_NE(graphs()[0].nodes.size(), graphs()[3].nodes.size());
  EXPECT_FALSE(prep_fits(&wrong_graph, graphs()[0], arg_w));
  EXPECT_FALSE(prep_fits(nullptr, graphs()[0], arg_w));
  // Same node count and levels, another layout of the levels: its order and keys would point
  // into the wrong levels, so it must not fit either.
  MatchPrep own;
  prepare_match(graphs()[0], arg_w, own);
  ArgGraph moved = graphs()[0];
  ASSERT_GT(moved.level_begin[2], moved.level_begin[1] + 1);
  ++moved.level_begin[1];
  EXPECT_TRUE(prep_shape_fits(&own, graphs()[0]));
  EXPECT_FALSE(prep_shape_fits(&own, moved));
  const double s0 = arg_similarity(graphs()[0], graphs()[1], arg_w);
  EXPECT_EQ(arg_similarity(graphs()[0], graphs()[1], arg_w, nullptr, &wrong_weights, nullptr), s0);
  EXPECT_EQ(arg_similarity(graphs()[0], graphs()[1], arg_w, nullptr, &wrong_graph, nullptr), s0);
}

namespace {

// The branch labels the matcher used to walk at every match: from node i, to the only
// neighbour up (and down) while that neighbour's only neighbour back is the node walked from.
std::vector<int> walked_branches(const std::vector<std::array<int, 2>>& only) {
  std::vector<int> label(only.size(), 0);
  int next = 1;
  for (std::size_t i = 0; i < only.size(); ++i) {
    if (label[i] != 0) continue;
    label[i] = next;
    for (int up : {1, 0}) {
      int cur = int(i);
      for (int to; (to = only[std::size_t(cur)][std::size_t(up)]) >= 0; cur = to) {
        if (only[std::size_t(to)][std::size_t(1 - up)] != cur || label[std::size_t(to)] != 0) break;
        label[std::size_t(to)] = next;
      }
    }
    ++next;
  }
  return label;
}

}  // namespace

TEST(MatchPrep, BranchesAreTheChainsTheMatcherUsedToWalk) {
  int forks = 0;
  for (const ArgGraph& g : test::stored_graphs()) {
    std::vector<std::array<int, 2>> only;
    std::vector<MatchKey> keys;
    prepare_nodes(g, only, keys);
    const int count = prepare_branches(only, keys);
    const std::vector<int> walked = walked_branches(only);
    // The same partition of the nodes: one walked label per branch and one branch per label.
    std::map<int, int> label_of, branch_of;
    for (std::size_t i = 0; i < keys.size(); ++i) {
      ASSERT_GE(keys[i].branch, 0);
      ASSERT_LT(keys[i].branch, count);
      EXPECT_EQ(label_of.emplace(keys[i].branch, walked[i]).first->second, walked[i]) << i;
      EXPECT_EQ(branch_of.emplace(walked[i], keys[i].branch).first->second, keys[i].branch) << i;
    }
    EXPECT_EQ(int(label_of.size()), count);
    for (const auto& o : only) forks += o[0] < 0 || o[1] < 0;
  }
  EXPECT_GT(forks, 0);  // the models do fork and end: chains are not whole levels
}

TEST(MatchPrep, LevelOrderIsBySelfSimThenIndex) {
  // prepare_order sorts integer keys; the order must be that of (-self, index) pairs, ties,
  // both zeros, negative sims (weights given in code) and extremes included.
  MatchPrep::Sums sums;
  const double tiny = std::numeric_limits<double>::denorm_min(),
               inf = std::numeric_limits<double>::infinity();
  sums.self = {0.5,   -0.0, 0.0,  2.0, 0.5,  -1.5,  1e-300, -1e-300,
               1e300, 0.5,  -1.5, 3.0, tiny, -tiny, inf,    -inf};
  const std::vector<std::uint32_t> level_begin = {0, 1, 5, 16};
  prepare_order(level_begin, 2, sums);  // levels 0 to 2
  std::vector<int> expected;
  for (std::size_t r = 0; r + 1 < level_begin.size(); ++r) {
    std::vector<std::pair<double, int>> keyed;
    for (std::uint32_t i = level_begin[r]; i < level_begin[r + 1]; ++i)
      keyed.push_back({-sums.self[i], int(i)});
    std::sort(keyed.begin(), keyed.end());
    for (const auto& k : keyed) expected.push_back(k.second);
  }
  EXPECT_EQ(sums.order, expected);
  EXPECT_EQ(sums.order, (std::vector<int>{0, 3, 4, 1, 2, 14, 8, 11, 9, 6, 12, 13, 7, 5, 10, 15}));
}

TEST(MatchPrep, LevelOrderSettlesSelfSimsThatShareAFloat) {
  // prepare_order sorts by the float of each self sim (insertion sort up to 32 nodes, a radix
  // sort beyond) and settles runs of equal floats by the doubles: levels of 1, 20, 100 and 640
  // nodes whose sims often share a float (neighbouring doubles, equal values, zeros of both
  // signs), against sorting (-self, index) pairs.
  std::mt19937 random(5);
  std::uniform_int_distribution<int> pick(0, 5);
  std::uniform_real_distribution<double> value(-2.0, 2.0);
  for (int trial = 0; trial < 40; ++trial) {
    MatchPrep::Sums sums;
    const std::vector<std::uint32_t> level_begin = {0, 1, 21, 121, 761};
    double last = 0.25;
    for (std::uint32_t i = 0; i < level_begin.back(); ++i) {
      switch (pick(random)) {
        case 0:
          last = value(random);
          break;
        case 1:
          last = std::nextafter(last, 10.0);
          break;  // most often the same float
        case 2:
          break;  // equal
        case 3:
          last = i % 2 ? 0.0 : -0.0;
          break;
        case 4:
          last = 1.0 + value(random) * 1e-9;
          break;  // one float, many doubles
        default:
          last = std::ldexp(value(random), int(i % 40) - 20);
      }
      sums.self.push_back(last);
    }
    prepare_order(level_begin, 3, sums);
    std::vector<int> expected;
    for (std::size_t r = 0; r + 1 < level_begin.size(); ++r) {
      std::vector<std::pair<double, int>> keyed;
      for (std::uint32_t i = level_begin[r]; i < level_begin[r + 1]; ++i)
        keyed.push_back({-sums.self[i] + 0.0, int(i)});  // + 0.0: both zeros as one
      std::sort(keyed.begin(), keyed.end());
      for (const auto& k : keyed) expected.push_back(k.second);
    }
    ASSERT_EQ(sums.order, expected) << "trial " << trial;
  }
}
