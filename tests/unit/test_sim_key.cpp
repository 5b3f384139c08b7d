// Sim keys: the group sims read from byte codes are node_sim's bits, and matching with them
// gives the same pairs and SIM as matching without.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "match/match_prep.hpp"
#include "match/node_similarity.hpp"
#include "match/sim_key.hpp"
#include "match/similarity.hpp"
#include "test_stored_graphs.hpp"

using namespace arg;

namespace {

using test::stored_graphs;

bool same_bits(double x, double y) {
  return std::memcmp(&x, &y, sizeof x) == 0;
}

}  // namespace

TEST(SimKey, StoredGraphsHaveKeysAndANudgedBinRemovesThem) {
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

TEST(SimKey, MatchingWithKeysGivesTheSamePairsAndSim) {
  for (const char* preset : {"arg", "mrg", "colour", "shape", "graph"}) {
    const Weights w = weights_preset(preset);
    std::vector<MatchPrep> preps(stored_graphs().size());
    for (std::size_t i = 0; i < preps.size(); ++i) {
      prepare_match(stored_graphs()[i], w, preps[i]);
      ASSERT_EQ(preps[i].sim_keys.size(), stored_graphs()[i].nodes.size());
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
