// SIM between ARGs: identity, symmetry, positivity, and the weights that drive it.
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "common/errors.hpp"
#include "match/similarity.hpp"
#include "match/weights.hpp"
#include "pipeline/build_arg.hpp"
#include "test_shapes.hpp"

using namespace arg;

namespace {

// The message parse_weights gives for `text`, or "accepted".
std::string weights_error(const char* text) {
  try {
    parse_weights(text);
  } catch (const InputError& e) {
    return std::string(e.what());
  }
  return std::string("accepted");
}

const std::vector<ArgGraph>& shapes() {
  static const std::vector<ArgGraph> graphs = [] {
    std::vector<ArgGraph> g;
    g.push_back(build_arg(test::torus()));
    g.push_back(build_arg(test::torus(2.5, 0.5, 70, 28)));
    g.push_back(build_arg(test::capsule()));
    g.push_back(build_arg(test::capsule(2, 0.7)));
    g.push_back(build_arg(test::sphere(40, 60, 2, 1, 0.7)));
    g.push_back(build_arg(test::sphere()));
    return g;
  }();
  return graphs;
}

}  // namespace

TEST(Similarity, SelfSimilarityIsZeroForEveryPreset) {
  for (const char* preset : {"arg", "mrg", "shape", "colour", "arg level_ratio=0.5"})
    for (const ArgGraph& g : shapes())
      EXPECT_EQ(arg_similarity(g, g, parse_weights(preset)), 0.0) << preset;
}

TEST(Similarity, IsExactlySymmetricAndWithinZeroAndOne) {
  const auto& g = shapes();
  for (const char* preset : {"arg", "mrg", "arg level_ratio=0.6"})
    for (std::size_t i = 0; i < g.size(); ++i)
      for (std::size_t j = 0; j < g.size(); ++j) {
        Weights w = parse_weights(preset);
        double ab = arg_similarity(g[i], g[j], w), ba = arg_similarity(g[j], g[i], w);
        EXPECT_EQ(ab, ba) << i << " " << j;
        EXPECT_GE(ab, 0.0);
        EXPECT_LE(ab, 1.0);
        if (i != j) {
          EXPECT_GT(ab, 0.0) << i << " " << j;
        }
      }
}

TEST(Similarity, ATorusIsCloserToATorusThanToACapsule) {
  const auto& g = shapes();
  EXPECT_LT(arg_similarity(g[0], g[1]), arg_similarity(g[0], g[2]));
  EXPECT_LT(arg_similarity(g[2], g[3]), arg_similarity(g[2], g[0]));
}

TEST(Similarity, MatchesListPairsOfBothGraphsLevelByLevel) {
  const auto& g = shapes();
  std::vector<MatchPair> pairs;
  double s = arg_similarity(g[0], g[1], Weights{}, &pairs);
  EXPECT_GT(s, 0.0);
  ASSERT_FALSE(pairs.empty());
  EXPECT_EQ(pairs.front().level, 0);
  for (std::size_t k = 1; k < pairs.size(); ++k) EXPECT_LE(pairs[k - 1].level, pairs[k].level);
  // Swapping the arguments swaps the sides of every pair.
  std::vector<MatchPair> swapped;
  arg_similarity(g[1], g[0], Weights{}, &swapped);
  ASSERT_EQ(swapped.size(), pairs.size());
  std::multiset<std::tuple<int, int, int>> forward, backward;
  for (auto& p : pairs) forward.insert({p.level, p.a_node, p.b_node});
  for (auto& p : swapped) backward.insert({p.level, p.b_node, p.a_node});
  EXPECT_EQ(forward, backward);
}

TEST(Similarity, AProxyGraphCountsItsShareGraphOnProxy) {
  const auto& g = shapes();
  ArgGraph proxy = g[1];
  proxy.summary.flags |= kFlagProxy;
  Weights w = weights_preset("arg");
  for (float share : {1.0f, 0.5f, 0.0f}) {
    w.graph_on_proxy = share;
    const SimilarityParts mesh = similarity_parts(g[0], g[1], w);
    const SimilarityParts parts = similarity_parts(g[0], proxy, w);
    EXPECT_DOUBLE_EQ(mesh.w_graph, w.graph) << "no proxy, full weight";
    EXPECT_DOUBLE_EQ(parts.w_graph, double(w.graph) * share);
    EXPECT_EQ(parts.w_spectrum, 0.0) << "a proxy has no spectrum term";
    EXPECT_EQ(similarity_parts(proxy, g[0], w).sim, parts.sim) << "symmetric";
    const double mean = (parts.w_graph * parts.graph + parts.w_panorama * parts.panorama) /
                        (parts.w_graph + parts.w_panorama);
    EXPECT_NEAR(parts.sim, mean, 1e-12);
  }
  // With no share left for the graph, SIM is the views' distance alone.
  EXPECT_NEAR(similarity_parts(g[0], proxy, w).sim, similarity_parts(g[0], proxy, w).panorama,
              1e-12);
}

// A copy of `g` whose nodes below level 0 have their curvature histograms moved one bin up:
// the same matches (the loss does not read them), less shared below the coarsest level.
ArgGraph curvature_moved_below_level_0(const ArgGraph& g) {
  ArgGraph h = g;
  for (ArgNode& n : h.nodes)
    if (n.level > 0)
      std::rotate(n.curv_mean.rbegin(), n.curv_mean.rbegin() + 1, n.curv_mean.rend());
  return h;
}

TEST(Similarity, LevelRatioWeighsTheCoarseLevelsAgainstTheFineOnes) {
  const ArgGraph& g = shapes()[0];
  const ArgGraph h = curvature_moved_below_level_0(g);
  auto sim = [&](const char* ratio) {
    return arg_similarity(g, h, parse_weights(std::string("graph level_ratio=") + ratio));
  };
  // Only level 0 counts at 0: the two graphs are alike there.
  EXPECT_EQ(sim("0"), 0.0);
  // The fine levels' difference counts less the smaller the ratio.
  EXPECT_GT(sim("1"), sim("0.75"));
  EXPECT_GT(sim("0.75"), sim("0.5"));
  EXPECT_GT(sim("0.5"), 0.0);
  // 1 is SIM as it always was: the default, and the `mrg` and `part` presets' value.
  EXPECT_EQ(sim("1"), arg_similarity(g, h, weights_preset("graph")));
  EXPECT_FLOAT_EQ(weights_preset("mrg").level_ratio, 1.0f);
  EXPECT_FLOAT_EQ(weights_preset("part").level_ratio, 1.0f);
}

TEST(Weights, LevelRatioIsOnTheMixingGridUpToOne) {
  EXPECT_FLOAT_EQ(parse_weights("level_ratio=0.65").level_ratio, 0.65f);
  for (const char* bad : {"level_ratio=1.05", "level_ratio=0.33", "level_ratio=-0.05"})
    EXPECT_THROW(parse_weights(bad), InputError) << bad;
  EXPECT_NE(weights_error("level_ratio=2").find("[0, 1]"), std::string::npos);
}

TEST(Weights, GraphOnProxyIsAShareOnTheMixingGrid) {
  EXPECT_FLOAT_EQ(parse_weights("graph_on_proxy=0.35").graph_on_proxy, 0.35f);
  EXPECT_FLOAT_EQ(weights_preset("mrg").graph_on_proxy, 1.0f) << "the graph alone, as before";
  EXPECT_FLOAT_EQ(weights_preset("graph").graph_on_proxy, 1.0f);
  for (const char* bad : {"graph_on_proxy=1.05", "graph_on_proxy=0.33", "graph_on_proxy=-0.05"})
    EXPECT_THROW(parse_weights(bad), InputError) << bad;
  try {
    parse_weights("graph_on_proxy=2");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("[0, 1]"), std::string::npos) << e.what();
  }
}

TEST(Weights, TextRoundTripAndPresets) {
  for (std::string_view preset : weight_presets()) {
    Weights w = weights_preset(preset);
    EXPECT_EQ(parse_weights(format_weights(w)), w) << preset;
    EXPECT_EQ(parse_weights(preset), w);
  }
  Weights w = parse_weights("shape lambda_4=0.25, norm=l2 tung=off");
  EXPECT_FLOAT_EQ(w.lambda_4, 0.25f);
  EXPECT_TRUE(w.l2);
  EXPECT_FALSE(w.tung_rule);
  EXPECT_FALSE(weights_preset("mrg").tung_rule);
}

TEST(Weights, RejectBadTextWithAClearMessage) {
  EXPECT_NE(weights_error("alpha_l=-1").find("alpha_l"), std::string::npos);
  EXPECT_NE(weights_error("alpha_l=nan").find("not a finite number"), std::string::npos);
  EXPECT_NE(weights_error("bogus=1").find("unknown key"), std::string::npos);
  EXPECT_NE(weights_error("fancy").find("not a preset"), std::string::npos);
  EXPECT_NE(weights_error("").find("empty"), std::string::npos);
  EXPECT_NE(weights_error("alpha_s=0 beta_s=0 lambda_1=0 lambda_2=0 lambda_3=0 lambda_4=0")
                .find("positive"),
            std::string::npos);
  EXPECT_NE(weights_error("alpha_l=").find("malformed"), std::string::npos);
}

TEST(Weights, ReadableNamesSetTheSameWeightAsThePapersSymbols) {
  // Written out here rather than read from weight_keys(), so a name moved to another weight
  // fails this test.
  const std::pair<const char*, float Weights::*> names[] = {
      {"loss_area", &Weights::alpha_l},   {"loss_length", &Weights::beta_l},
      {"loss_radius", &Weights::gamma_l}, {"loss_theta", &Weights::delta_l},
      {"loss_phi", &Weights::eps_l},      {"area", &Weights::alpha_s},
      {"length", &Weights::beta_s},       {"volume", &Weights::lambda_1},
      {"cords", &Weights::lambda_2},      {"curvature", &Weights::lambda_3},
      {"colour", &Weights::lambda_4},     {"color", &Weights::lambda_4},
  };
  for (const auto& [name, member] : names) {
    const Weights w = parse_weights(std::string(name) + "=7.5");
    EXPECT_FLOAT_EQ(w.*member, 7.5f) << name;
    Weights expected = weights_preset("arg");
    expected.*member = 7.5f;
    EXPECT_EQ(w, expected) << name << " sets nothing else";
  }
  EXPECT_EQ(parse_weights("shape curvature=2"), parse_weights("shape lambda_3=2"));
  // Every readable name in the list parses like its symbol.
  int readable = 0;
  for (const WeightKey& k : weight_keys())
    if (k.name != k.symbol) {
      ++readable;
      EXPECT_TRUE(k.words.empty()) << k.name;
      EXPECT_EQ(parse_weights(std::string(k.name) + "=0.5"),
                parse_weights(std::string(k.symbol) + "=0.5"))
          << k.name;
    }
  EXPECT_EQ(readable, 12);
}

TEST(Weights, TheCanonicalTextKeepsThePapersSymbols) {
  const std::string text = format_weights(parse_weights("curvature=2 loss_phi=0.1 colour=0"));
  EXPECT_EQ(text, format_weights(parse_weights("lambda_3=2 eps_l=0.1 lambda_4=0")));
  EXPECT_NE(text.find("lambda_3=2 "), std::string::npos) << text;
  for (const WeightKey& k : weight_keys()) {
    if (k.name != k.symbol) {
      EXPECT_EQ(text.find(std::string(k.name) + "="), std::string::npos) << k.name << ": " << text;
    }
  }
  EXPECT_EQ(format_weights(weights_preset("arg")),
            "alpha_l=0.3 beta_l=0.15 gamma_l=0.15 delta_l=0.2 eps_l=0.2 alpha_s=0.65 beta_s=0.35 "
            "lambda_1=0.3 lambda_2=0.5 lambda_3=12 lambda_4=1 graph=1 panorama=2.5 spectrum=0.75 "
            "graph_on_proxy=0.75 level_ratio=1 norm=l1 tung=on groups=off");
  // `part` is `arg` with 0.2.0's cords and curvature, and nothing else.
  EXPECT_EQ(format_weights(weights_preset("part")),
            format_weights(parse_weights("arg lambda_2=1 lambda_3=3")));
}

TEST(Weights, ABareWordIsAPresetAndKeyEqualsValueIsAWeight) {
  EXPECT_EQ(parse_weights("colour"), weights_preset("colour"));
  EXPECT_EQ(parse_weights("color"), weights_preset("colour"));
  const Weights w = parse_weights("colour=2");
  EXPECT_FLOAT_EQ(w.lambda_4, 2.0f);
  EXPECT_FLOAT_EQ(w.lambda_3, weights_preset("arg").lambda_3);
  EXPECT_FLOAT_EQ(parse_weights("colour colour=2").lambda_4, 2.0f);
  EXPECT_EQ(parse_weights("graph"), weights_preset("graph"));
  EXPECT_FLOAT_EQ(parse_weights("graph=2").panorama, weights_preset("arg").panorama);
}

TEST(Weights, AWeightGivenTwiceIsAnErrorThatNamesBothSpellings) {
  const std::string both = weights_error("curvature=2 lambda_3=3");
  EXPECT_NE(both.find("curvature"), std::string::npos) << both;
  EXPECT_NE(both.find("lambda_3"), std::string::npos) << both;
  EXPECT_NE(weights_error("lambda_3=3, curvature=3").find("both set lambda_3"), std::string::npos);
  EXPECT_NE(weights_error("colour=1 color=1").find("both set lambda_4"), std::string::npos);
  EXPECT_NE(weights_error("lambda_3=2 lambda_3=2").find("lambda_3 is given twice"),
            std::string::npos);
  EXPECT_NE(weights_error("norm=l1 norm=l2").find("norm is given twice"), std::string::npos);
  EXPECT_NE(weights_error("panorama=1 panorama=1").find("given twice"), std::string::npos);
  // A preset, then a key: the key changes the preset's value, which is not a repetition.
  EXPECT_FLOAT_EQ(parse_weights("mrg curvature=2").lambda_3, 2.0f);
}

TEST(PartMatching, AtTheFinestLevelSubGraphsWithoutChildrenCompare) {
  const ArgGraph& g = shapes()[0];
  for (const PartMatch& p : part_match(g, g.levels(), 0, g)) {
    EXPECT_GE(p.score, 0.0);
    EXPECT_LE(p.score, 1.0);
  }
}
