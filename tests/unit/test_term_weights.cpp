// SIM's mixing rule: one function, followed by SIM, the sketch distance and the weight search.
#include <gtest/gtest.h>

#include <vector>

#include "eval/term_matrices.hpp"
#include "match/similarity.hpp"
#include "match/term_weights.hpp"
#include "search/shape_sketch.hpp"
#include "test_stored_graphs.hpp"

namespace arg {
namespace {

TEST(TermWeights, FollowsTheRuleForEachKindOfPair) {
  const Weights w;  // graph 1, panorama 2.5, spectrum 0.75, graph_on_proxy 0.75
  TermWeights t = term_weights(w, 0, true, true);
  EXPECT_EQ(t.graph, 1.0);
  EXPECT_EQ(t.panorama, 2.5);
  EXPECT_EQ(t.spectrum, 0.75);
  t = term_weights(w, kFlagProxy, true, true);
  EXPECT_EQ(t.graph, double(w.graph * w.graph_on_proxy)) << "a proxy's share of the graph";
  EXPECT_EQ(t.spectrum, 0.0) << "a proxy's spectrum is its shell's";
  t = term_weights(w, kFlagWideOpen | kFlagOpen, true, true);
  EXPECT_EQ(t.graph, 1.0);
  EXPECT_EQ(t.spectrum, 0.0) << "a wide-open surface's spectrum is its openings'";
  t = term_weights(w, kFlagOpen | kFlagPooled, false, true);
  EXPECT_EQ(t.panorama, 0.0) << "a term one model lacks is left out";
  EXPECT_EQ(t.spectrum, 0.75) << "open with its holes filled, pooled: still its own surface";
  // Nothing left: the graph alone (format-1 values), even at a graph weight of 0.
  Weights none = w;
  none.graph = 0;
  t = term_weights(none, 0, false, false);
  EXPECT_EQ(t.graph, 1.0);
  EXPECT_EQ(t.panorama + t.spectrum, 0.0);
}

TEST(TermWeights, MixesAsAWeightedMean) {
  const TermWeights t{1, 2, 1};
  EXPECT_DOUBLE_EQ(mix_terms(t, 0.4, 0.1, 0.3), (0.4 + 0.2 + 0.3) / 4);
  EXPECT_EQ(mix_terms({1, 0, 0}, 0.25, 7, 9), 0.25) << "a term of weight 0 adds nothing";
}

// Weights that give each term its turn: the defaults, the graph alone, no graph, no proxy share.
std::vector<Weights> weight_choices() {
  std::vector<Weights> all(4);
  all[1] = weights_preset("graph");
  all[2].graph = 0;
  all[3].graph_on_proxy = 0.35f, all[3].spectrum = 2;
  return all;
}

// The graphs of test_stored_graphs.hpp, with one marked as built on a proxy and one as wide
// open, so that every branch of the rule is taken.
std::vector<ArgGraph> kinds_of_models() {
  std::vector<ArgGraph> g = test::stored_graphs();
  g[1].summary.flags |= kFlagProxy;
  g[2].summary.flags |= kFlagOpen | kFlagWideOpen;
  g[5].spectrum.clear();
  return g;
}

TEST(TermWeights, TheWeightSearchScoresEveryPairAsSimToTheBit) {
  const std::vector<ArgGraph> g = kinds_of_models();
  std::vector<const ArgGraph*> pointers;
  for (const ArgGraph& x : g) pointers.push_back(&x);
  const TermMatrices m = term_matrices(pointers);
  for (const Weights& w : weight_choices())
    for (std::size_t i = 0; i < g.size(); ++i)
      for (std::size_t j = 0; j < g.size(); ++j) {
        if (i == j) continue;
        const double graph = graph_similarity(g[i], g[j], w);
        EXPECT_EQ(mixed_similarity(m, i, j, w, graph), arg_similarity(g[i], g[j], w))
            << i << " against " << j << " under " << format_weights(w);
      }
}

TEST(TermWeights, TheSketchDistanceWeighsTheTermsAsSim) {
  const std::vector<ArgGraph> g = kinds_of_models();
  for (const Weights& w : weight_choices())
    for (std::size_t i = 0; i < g.size(); ++i)
      for (std::size_t j = 0; j < g.size(); ++j) {
        ShapeSketch a = shape_sketch(g[i]), b = shape_sketch(g[j]);
        const SimilarityParts p = similarity_parts(g[i], g[j], w);
        // Without its graph stand-in, the sketch's distance is SIM's mix of the same terms.
        const TermWeights t{p.w_graph, p.w_panorama, p.w_spectrum};
        EXPECT_EQ(sketch_distance(a, b, w, 0.0), mix_terms(t, 0.0, p.panorama, p.spectrum))
            << i << " against " << j << " under " << format_weights(w);
      }
}

TEST(TermWeights, TheSharesAddUpToSimToTheBit) {
  const std::vector<ArgGraph> g = kinds_of_models();
  for (const Weights& w : weight_choices())
    for (std::size_t i = 0; i < g.size(); ++i)
      for (std::size_t j = 0; j < g.size(); ++j) {
        const SimilarityParts p = similarity_parts(g[i], g[j], w);
        const TermWeights t{p.w_graph, p.w_panorama, p.w_spectrum};
        const TermShares s = term_shares(t, p.graph, p.panorama, p.spectrum);
        EXPECT_EQ(s.graph, p.share_graph);
        EXPECT_EQ(s.panorama, p.share_panorama);
        EXPECT_EQ(s.spectrum, p.share_spectrum);
        // In the order arg_sim_terms lists them, as SQL's sum() adds them.
        EXPECT_EQ(p.share_graph + p.share_panorama + p.share_spectrum,
                  arg_similarity(g[i], g[j], w))
            << i << " against " << j << " under " << format_weights(w);
      }
}

}  // namespace
}  // namespace arg
