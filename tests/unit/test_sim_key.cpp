// Sim keys: the group sims read from byte codes are node_sim's bits, and matching with them
// (and with the prepared children) gives the same pairs and SIM as matching without.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "gen/generate_models.hpp"
#include "graph/serialize.hpp"
#include "match/match_prep.hpp"
#include "match/node_similarity.hpp"
#include "match/sim_key.hpp"
#include "match/similarity.hpp"
#include "pipeline/build_arg.hpp"

using namespace arg;

namespace {

// Branching generated models (figures, animals, an octopus, a cup), read back from their
// stored bytes as a ranking sees them; the last two without colour.
const std::vector<ArgGraph>& stored_graphs() {
  static const std::vector<ArgGraph> all = [] {
    std::vector<ArgGraph> g;
    const char* classes[] = {"human", "human", "fourleg", "octopus", "cup", "chair"};
    for (int k = 0; k < 6; ++k) {
      const GeneratedModel m = generate_model(classes[k], k, 32, /*colour=*/k < 4);
      g.push_back(deserialize_arg(serialize_arg(build_arg(m.mesh))));
    }
    return g;
  }();
  return all;
}

bool same_bits(double x, double y) {
  return std::memcmp(&x, &y, sizeof x) == 0;
}

}  // namespace

TEST(SimKey, StoredGraphsHaveKeysAndJustBuiltOnesDoNot) {
  std::vector<SimKey> keys;
  for (const ArgGraph& g : stored_graphs()) {
    ASSERT_TRUE(make_sim_keys(g, keys));
    EXPECT_EQ(keys.size(), g.nodes.size());
  }
  // A histogram that is not byte codes of its node's area (a value of format 1 or 2, or one
  // changed in memory): no keys, so the sims read the float records.
  ArgGraph nudged = stored_graphs()[0];
  ArgNode& n = nudged.nodes[nudged.nodes.size() / 2];
  ASSERT_GT(n.curv_gauss[3] + n.curv_gauss[4], 0.0f);
  const std::size_t k = n.curv_gauss[3] > 0 ? 3 : 4;
  n.curv_gauss[k] = std::nextafter(n.curv_gauss[k], 1.0f);
  EXPECT_FALSE(make_sim_keys(nudged, keys));
  EXPECT_TRUE(keys.empty());
  MatchPrep prep;
  prepare_match(nudged, weights_preset("arg"), prep);
  EXPECT_TRUE(prep.sim_keys.empty());
  EXPECT_TRUE(prep_fits(&prep, nudged, weights_preset("arg")));
}

TEST(SimKey, KeySimIsNodeSimBitForBit) {
  std::vector<SimKey> kx, ky;
  const ArgGraph &x = stored_graphs()[0], &y = stored_graphs()[2];
  ASSERT_TRUE(make_sim_keys(x, kx));
  ASSERT_TRUE(make_sim_keys(y, ky));
  for (const char* preset : {"arg", "mrg", "shape", "graph"}) {
    Weights w = weights_preset(preset);
    w.lambda_4 = 0;  // key_sim leaves colour to its caller
    int differing = 0;
    for (std::size_t i = 0; i < x.nodes.size(); ++i)
      for (std::size_t j = 0; j < y.nodes.size(); ++j)
        differing += !same_bits(key_sim(kx[i], ky[j], w), node_sim(x.nodes[i], y.nodes[j], w));
    EXPECT_EQ(differing, 0) << preset;
  }
}

TEST(SimKey, MatchingWithKeysAndChildrenGivesTheSamePairsAndSim) {
  for (const char* preset : {"arg", "mrg", "colour", "shape", "graph"}) {
    const Weights w = weights_preset(preset);
    std::vector<MatchPrep> preps(stored_graphs().size());
    for (std::size_t i = 0; i < preps.size(); ++i) {
      prepare_match(stored_graphs()[i], w, preps[i]);
      ASSERT_EQ(preps[i].sim_keys.size(), stored_graphs()[i].nodes.size());
      ASSERT_EQ(preps[i].child_mid.size(), stored_graphs()[i].nodes.size());  // in halves
    }
    for (std::size_t i = 0; i < preps.size(); ++i)
      for (std::size_t j = 0; j < preps.size(); ++j) {
        const ArgGraph &a = stored_graphs()[i], &b = stored_graphs()[j];
        std::vector<MatchPair> plain, prepared;
        const double s0 = arg_similarity(a, b, w, &plain);
        const double s1 = arg_similarity(a, b, w, &prepared, &preps[i], &preps[j]);
        EXPECT_TRUE(same_bits(s0, s1)) << preset << " " << i << " " << j;
        ASSERT_EQ(plain.size(), prepared.size()) << preset << " " << i << " " << j;
        for (std::size_t k = 0; k < plain.size(); ++k) {
          EXPECT_EQ(plain[k].a_node, prepared[k].a_node);
          EXPECT_EQ(plain[k].b_node, prepared[k].b_node);
          EXPECT_TRUE(same_bits(plain[k].sim, prepared[k].sim));
        }
      }
  }
}

TEST(SimKey, PreparedChildrenAreEachNodesChildrenInIndexOrderAndInHalves) {
  const ArgGraph& g = stored_graphs()[3];
  MatchPrep prep;
  prepare_match(g, weights_preset("arg"), prep);
  ASSERT_EQ(prep.child_begin.size(), g.nodes.size() + 1);
  std::size_t total = 0;
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    std::vector<std::uint32_t> expected;
    for (std::size_t c = 0; c < g.nodes.size(); ++c)
      if (g.nodes[c].parent == int(i)) expected.push_back(std::uint32_t(c));
    const std::vector<std::uint32_t> got(prep.children.begin() + prep.child_begin[i],
                                         prep.children.begin() + prep.child_begin[i + 1]);
    EXPECT_EQ(got, expected) << i;
    total += expected.size();
    // Children in the lower half of i's interval, then those in the upper half.
    for (std::uint32_t c = prep.child_begin[i]; c < prep.child_begin[i + 1]; ++c)
      EXPECT_EQ(g.nodes[prep.children[c]].interval,
                2 * g.nodes[i].interval + (c >= prep.child_mid[i] ? 1 : 0));
  }
  EXPECT_EQ(prep.children.size(), total);
}

TEST(SimKey, TheChildrenScanFindsWhatTheIntervalScanFinds) {
  // With each node's children listed backwards, a graph's own lists are not in index order and
  // match_graphs scans whole intervals for it; its MatchPrep sorts them and scans children.
  for (const char* preset : {"arg", "graph"}) {
    const Weights w = weights_preset(preset);
    for (std::size_t i = 0; i < stored_graphs().size(); ++i) {
      ArgGraph backwards = stored_graphs()[i];
      for (const ArgNode& n : backwards.nodes)
        std::reverse(backwards.children.begin() + n.child_begin,
                     backwards.children.begin() + n.child_begin + n.child_count);
      MatchPrep prep;
      prepare_match(backwards, w, prep);
      for (std::size_t j = 0; j < stored_graphs().size(); ++j) {
        if (j == i) continue;  // the graph itself: SIM 0 without matching
        const ArgGraph& other = stored_graphs()[j];
        std::vector<MatchPair> scanned, ordered;
        const double s0 = arg_similarity(backwards, other, w, &scanned);
        const double s1 = arg_similarity(stored_graphs()[i], other, w, &ordered);
        EXPECT_TRUE(same_bits(s0, s1)) << preset << " " << i << " " << j;
        EXPECT_EQ(scanned.size(), ordered.size());
        EXPECT_TRUE(same_bits(arg_similarity(backwards, other, w, nullptr, &prep, nullptr), s0));
      }
    }
  }
}
