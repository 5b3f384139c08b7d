// MPAIR on graphs drawn by hand: identity, Tung's rule, branch labels, groups and symmetry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include "match/mpair.hpp"
#include "match/node_similarity.hpp"
#include "match/similarity.hpp"
#include "match/weights.hpp"

using namespace arg;

namespace {

// A multiresolution graph drawn node by node, level by level and in interval order, as the
// builder lays them out. Every histogram of a node holds its whole area in one bin, so that
// its sums are the node's area as in a built graph.
class Sketch {
 public:
  explicit Sketch(int levels) {
    g_.options.levels = levels;
    g_.summary.has_colour = 1;
  }

  int node(int level, int interval, int parent, float a, float theta, int bin = 0) {
    ArgNode n;
    n.level = std::uint16_t(level);
    n.interval = std::uint16_t(interval);
    n.parent = parent;
    n.a = n.l = a;
    n.r = 1;
    n.theta = theta;
    n.phi = float(M_PI / 2);
    n.cords[std::size_t(bin)] = n.curv_mean[std::size_t(bin)] = a;
    n.curv_gauss[std::size_t(bin)] = a;
    for (int c = 0; c < 3; ++c) n.colour[std::size_t(c * kColourBins + bin)] = a;
    const float width = 1.0f / float(1 << level);
    n.mu_min = float(interval) * width, n.mu_max = n.mu_min + width;
    g_.nodes.push_back(n);
    return int(g_.nodes.size()) - 1;
  }
  void link(int i, int j) { edges_.emplace_back(i, j); }
  ArgNode& operator[](int i) { return g_.nodes[std::size_t(i)]; }

  ArgGraph graph() const {
    ArgGraph g = g_;
    const std::size_t n = g.nodes.size();
    for (std::size_t i = 1; i < n; ++i)
      if (std::make_pair(g.nodes[i - 1].level, g.nodes[i - 1].interval) >
          std::make_pair(g.nodes[i].level, g.nodes[i].interval))
        throw std::logic_error("sketch nodes out of (level, interval) order");
    g.level_begin.assign(std::size_t(g.levels()) + 2, std::uint32_t(n));
    for (std::size_t i = n; i-- > 0;) g.level_begin[g.nodes[i].level] = std::uint32_t(i);
    g.level_begin[0] = 0;
    std::vector<std::vector<std::uint32_t>> kids(n), adj(n);
    for (std::size_t i = 0; i < n; ++i)
      if (g.nodes[i].parent >= 0) kids[std::size_t(g.nodes[i].parent)].push_back(std::uint32_t(i));
    for (auto [i, j] : edges_)
      adj[std::size_t(i)].push_back(std::uint32_t(j)),
          adj[std::size_t(j)].push_back(std::uint32_t(i));
    for (std::size_t i = 0; i < n; ++i) {
      std::sort(adj[i].begin(), adj[i].end());
      g.nodes[i].child_begin = std::uint32_t(g.children.size());
      g.nodes[i].child_count = std::uint32_t(kids[i].size());
      g.children.insert(g.children.end(), kids[i].begin(), kids[i].end());
      g.nodes[i].adj_begin = std::uint32_t(g.adjacency.size());
      g.nodes[i].adj_count = std::uint32_t(adj[i].size());
      g.adjacency.insert(g.adjacency.end(), adj[i].begin(), adj[i].end());
    }
    return g;
  }

 private:
  ArgGraph g_;
  std::vector<std::pair<int, int>> edges_;
};

// The nodes of a fork: a root; below it P, and Q1, Q2 above it; at the finest level P splits
// into p0 and the two nodes f1, f2 of one interval, each leading up into its own branch
// (q1a, q1b under Q1; q2a, q2b under Q2). Larger nodes come first in the matching.
struct Fork {
  int root, P, Q1, Q2, p0, f1, f2, q1a, q2a, q1b, q2b;
  Sketch s{2};

  Fork() {
    root = s.node(0, 0, -1, 0.3f, 0.0f);
    P = s.node(1, 0, root, 0.15f, 0.0f);
    Q1 = s.node(1, 1, root, 0.1f, 0.0f);
    Q2 = s.node(1, 1, root, 0.08f, 1.0f);
    s.link(P, Q1), s.link(P, Q2);
    p0 = s.node(2, 0, P, 0.08f, 0.0f);
    f1 = s.node(2, 1, P, 0.07f, 0.0f);
    f2 = s.node(2, 1, P, 0.06f, 1.0f);
    q1a = s.node(2, 2, Q1, 0.05f, 0.0f);
    q2a = s.node(2, 2, Q2, 0.045f, 1.0f);
    q1b = s.node(2, 3, Q1, 0.04f, 0.0f);
    q2b = s.node(2, 3, Q2, 0.035f, 1.0f);
    s.link(p0, f1), s.link(p0, f2), s.link(f1, q1a), s.link(f2, q2a);
    s.link(q1a, q1b), s.link(q2a, q2b);
  }
};

struct Matching {
  std::vector<MatchGroup> groups;
  std::vector<double> sims;
  double numerator = 0, self_x = 0;

  // The nodes of Y matched with node m of X (empty when m is unmatched).
  std::vector<int> partners(int m) const {
    for (const MatchGroup& g : groups)
      for (int x : g.x)
        if (x == m) return g.y;
    return {};
  }
};

Matching match(const ArgGraph& x, const ArgGraph& y, const Weights& w) {
  Matching m;
  m.numerator = match_graphs(x, y, w, &m.groups, &m.sims, &m.self_x);
  return m;
}

Weights with(bool tung, bool groups) {
  Weights w;
  w.tung_rule = tung, w.groups = groups;
  return w;
}

// Every match below the root level pairs nodes whose parents were matched to each other.
void expect_parents_matched(const Matching& m, const ArgGraph& x, const ArgGraph& y) {
  std::set<std::pair<int, int>> pairs;
  for (const MatchGroup& g : m.groups)
    for (int a : g.x)
      for (int b : g.y) pairs.insert({a, b});
  for (const MatchGroup& g : m.groups) {
    if (g.level == 0) continue;
    for (int a : g.x)
      for (int b : g.y)
        EXPECT_TRUE(pairs.count({x.nodes[std::size_t(a)].parent, y.nodes[std::size_t(b)].parent}))
            << "nodes " << a << " and " << b;
  }
}

}  // namespace

TEST(MatchGraphs, IdenticalGraphsMatchNodeForNodeAtTheirFullSim) {
  const Fork f;
  const ArgGraph g = f.s.graph();
  for (const Weights& w : {with(true, false), with(false, false), with(true, true)}) {
    const Matching m = match(g, g, w);
    ASSERT_EQ(m.groups.size(), g.nodes.size());
    for (const MatchGroup& group : m.groups) {
      EXPECT_EQ(group.x, group.y);
      EXPECT_EQ(group.x.size(), 1u);
      EXPECT_EQ(group.loss, 0.0);
    }
    // Every node met itself: the numerator is the graph's own sim, SIM's maximum (to float
    // rounding: node_self_sim adds the weights in float, node_sim weighs each term in double).
    EXPECT_NEAR(m.numerator, m.self_x, 1e-7 * m.self_x);
    EXPECT_GT(m.self_x, 0.0);
  }
  // A copy that differs outside the nodes goes through the matching too, and scores 0.
  ArgGraph copy = g;
  copy.global[0] = 1;
  std::vector<MatchPair> pairs;
  EXPECT_NEAR(graph_similarity(g, copy, Weights{}, &pairs), 0.0, 1e-7);
  ASSERT_EQ(pairs.size(), g.nodes.size());
  for (const MatchPair& p : pairs) EXPECT_EQ(p.a_node, p.b_node);
}

TEST(MatchGraphs, TungsRuleMatchesAForkNodeToTheOneLeadingIntoTheMatchedBranch) {
  // In Y the two fork nodes look like each other's counterpart in X: f1 resembles Y's f2,
  // which leads up into the branch matched with f1's.
  const Fork fx;
  Fork fy;
  std::swap(fy.s[fy.f1].theta, fy.s[fy.f2].theta);
  std::swap(fy.s[fy.f1].a, fy.s[fy.f2].a);
  const ArgGraph x = fx.s.graph(), y = fy.s.graph();
  const Weights tung = with(true, false), hilaga = with(false, false);
  EXPECT_LT(node_loss(x.nodes[std::size_t(fx.f1)], y.nodes[std::size_t(fy.f2)], 2, tung),
            node_loss(x.nodes[std::size_t(fx.f1)], y.nodes[std::size_t(fy.f1)], 2, tung));
  // Without the rule f1 takes the look-alike, and the branches above, labelled crosswise,
  // can then match nothing.
  const Matching without = match(x, y, hilaga);
  EXPECT_EQ(without.partners(fx.f1), std::vector<int>{fy.f2});
  EXPECT_EQ(without.partners(fx.f2), std::vector<int>{fy.f1});
  for (int q : {fx.q1a, fx.q2a, fx.q1b, fx.q2b}) EXPECT_TRUE(without.partners(q).empty()) << q;
  // With it, the neighbours above f1 (under Q1) and above Y's f2 (under Q2) have parents
  // matched elsewhere, so f1 is matched with Y's f1 and every branch follows.
  const Matching with_rule = match(x, y, tung);
  EXPECT_EQ(with_rule.partners(fx.f1), std::vector<int>{fy.f1});
  EXPECT_EQ(with_rule.partners(fx.f2), std::vector<int>{fy.f2});
  for (int q : {fx.q1a, fx.q2a, fx.q1b, fx.q2b})
    EXPECT_EQ(with_rule.partners(q), std::vector<int>{q});
  EXPECT_GT(with_rule.numerator, without.numerator);
  EXPECT_LT(graph_similarity(x, y, tung), graph_similarity(x, y, hilaga));
  expect_parents_matched(without, x, y);
  expect_parents_matched(with_rule, x, y);
}

TEST(MatchGraphs, ChildrenAreMatchedOnlyToChildrenOfTheirParentsMatch) {
  // Two branches Q1, Q2; in Y the first node of each branch looks like the other's.
  auto draw = [](bool crossed) {
    Sketch s(2);
    const int root = s.node(0, 0, -1, 0.3f, 0.0f);
    const int P = s.node(1, 0, root, 0.15f, 0.0f);
    const int Q1 = s.node(1, 1, root, 0.1f, 0.0f), Q2 = s.node(1, 1, root, 0.08f, 1.0f);
    s.link(P, Q1), s.link(P, Q2);
    const int p0 = s.node(2, 0, P, 0.08f, 0.0f), p1 = s.node(2, 1, P, 0.07f, 0.0f);
    const int q1a = s.node(2, 2, Q1, 0.05f, crossed ? 1.0f : 0.0f);
    const int q2a = s.node(2, 2, Q2, 0.045f, crossed ? 0.0f : 1.0f);
    const int q1b = s.node(2, 3, Q1, 0.04f, 0.0f), q2b = s.node(2, 3, Q2, 0.035f, 1.0f);
    s.link(p0, p1), s.link(p1, q1a), s.link(p1, q2a), s.link(q1a, q1b), s.link(q2a, q2b);
    return s.graph();
  };
  const ArgGraph x = draw(false), y = draw(true);
  const int Q1 = 2, Q2 = 3, q1a = 6, q2a = 7;
  for (const Weights& w : {with(false, false), with(true, false)}) {
    const Matching m = match(x, y, w);
    EXPECT_EQ(m.partners(Q1), std::vector<int>{Q1});
    EXPECT_EQ(m.partners(Q2), std::vector<int>{Q2});
    // q1a's look-alike in Y is under Q2; only Y's q1a, under Q1's match, may take it.
    EXPECT_LT(node_loss(x.nodes[q1a], y.nodes[q2a], 2, w),
              node_loss(x.nodes[q1a], y.nodes[q1a], 2, w));
    EXPECT_EQ(m.partners(q1a), std::vector<int>{q1a});
    EXPECT_EQ(m.partners(q2a), std::vector<int>{q2a});
    EXPECT_EQ(m.groups.size(), x.nodes.size());
    expect_parents_matched(m, x, y);
  }
}

TEST(MatchGraphs, BranchLabelsKeepABranchWhole) {
  // A loop at the finest level: p0 forks into u1 and u2, which run up into v1 and v2 and
  // join again at w. u and v are children of different parents (P below, Q above) and both
  // branches pass through both, so parents do not tell the branches apart; labels do. In Y,
  // v1 and v2 look like each other's counterpart.
  auto draw = [](bool crossed) {
    Sketch s(2);
    const int root = s.node(0, 0, -1, 0.5f, 0.0f);
    const int P = s.node(1, 0, root, 0.25f, 0.0f), Q = s.node(1, 1, root, 0.25f, 0.0f);
    s.link(P, Q);
    const int p0 = s.node(2, 0, P, 0.03f, 0.0f);
    const int u1 = s.node(2, 1, P, 0.1f, 0.0f), u2 = s.node(2, 1, P, 0.09f, 1.0f);
    const int v1 = s.node(2, 2, Q, 0.08f, crossed ? 1.0f : 0.0f);
    const int v2 = s.node(2, 2, Q, 0.07f, crossed ? 0.0f : 1.0f);
    const int w = s.node(2, 3, Q, 0.03f, 0.5f);
    s.link(p0, u1), s.link(p0, u2), s.link(u1, v1), s.link(u2, v2), s.link(v1, w), s.link(v2, w);
    return s.graph();
  };
  const ArgGraph x = draw(false), y = draw(true);
  const int u1 = 4, u2 = 5, v1 = 6, v2 = 7;
  for (const Weights& w : {with(false, false), with(true, false)}) {
    const Matching m = match(x, y, w);
    // u1 and u2 are matched first, each labelling its branch up to v on both sides ...
    EXPECT_EQ(m.partners(u1), std::vector<int>{u1});
    EXPECT_EQ(m.partners(u2), std::vector<int>{u2});
    // ... so v1 goes with u1's partner's branch although v2 of Y resembles it more.
    EXPECT_LT(node_loss(x.nodes[v1], y.nodes[v2], 2, w), node_loss(x.nodes[v1], y.nodes[v1], 2, w));
    EXPECT_EQ(m.partners(v1), std::vector<int>{v1});
    EXPECT_EQ(m.partners(v2), std::vector<int>{v2});
    expect_parents_matched(m, x, y);
  }
}

TEST(MatchGraphs, GroupsLetASiblingJoinTheMatchOfItsInterval) {
  // X: a body w with two arms v, u in one interval; Y: a body with one arm n as large as both.
  Sketch sx(1), sy(1);
  const int rx = sx.node(0, 0, -1, 0.5f, 0.0f);
  const int w = sx.node(1, 0, rx, 0.14f, 0.0f);
  const int v = sx.node(1, 1, rx, 0.2f, 0.2f), u = sx.node(1, 1, rx, 0.16f, 0.4f);
  sx.link(w, v), sx.link(w, u);
  const int ry = sy.node(0, 0, -1, 0.5f, 0.0f);
  const int wy = sy.node(1, 0, ry, 0.14f, 0.0f), n = sy.node(1, 1, ry, 0.36f, 0.3f);
  sy.link(wy, n);
  const ArgGraph x = sx.graph(), y = sy.graph();

  const Matching alone = match(x, y, with(true, false));
  EXPECT_EQ(alone.partners(v), std::vector<int>{n});
  EXPECT_TRUE(alone.partners(u).empty());
  const Matching grouped = match(x, y, with(true, true));
  ASSERT_EQ(grouped.groups.size(), 2u);
  EXPECT_EQ(grouped.groups[1].x, (std::vector<int>{v, u}));
  EXPECT_EQ(grouped.groups[1].y, std::vector<int>{n});
  // The group is worth the sim of the arms' summed attributes against the one arm.
  NodeMass arms, arm;
  arms.add(x.nodes[std::size_t(v)]), arms.add(x.nodes[std::size_t(u)]);
  arm.add(y.nodes[std::size_t(n)]);
  const Weights w_on = with(true, true);
  EXPECT_DOUBLE_EQ(grouped.sims[1], node_sim(arms, arm, w_on));
  EXPECT_NEAR(
      grouped.numerator - alone.numerator,
      node_sim(arms, arm, w_on) - node_sim(x.nodes[std::size_t(v)], y.nodes[std::size_t(n)], w_on),
      1e-12);
  EXPECT_GT(grouped.numerator, alone.numerator);
  // Both rows of the group carry its one sim.
  std::vector<MatchPair> pairs;
  graph_similarity(x, y, w_on, &pairs);
  ASSERT_EQ(pairs.size(), 3u);
  EXPECT_EQ(pairs[1].group, pairs[2].group);
  EXPECT_EQ(pairs[1].sim, pairs[2].sim);
  EXPECT_EQ(std::make_pair(pairs[1].a_node, pairs[2].a_node), std::make_pair(1, 2));
}

TEST(MatchGraphs, SimIsExactlySymmetricThoughTheGreedyMatchingIsNot) {
  // One interval of two nodes on each side. X's first node (first by index) and Y's second
  // (first by its larger volume, which sim counts and loss does not) each prefer the other
  // side's first node, so which side leads decides the pairs.
  auto draw = [](float theta1, float theta2, int bin1, int bin2, float v2) {
    Sketch s(1);
    const int r = s.node(0, 0, -1, 0.5f, 0.0f);
    const int w = s.node(1, 0, r, 0.2f, 0.0f);
    const int n1 = s.node(1, 1, r, 0.15f, theta1, bin1);
    const int n2 = s.node(1, 1, r, 0.15f, theta2, bin2);
    s[n2].v = v2;
    s.link(w, n1), s.link(w, n2);
    return s.graph();
  };
  const ArgGraph x = draw(0.0f, 1.0f, 0, 1, 0.15f), y = draw(0.1f, 0.3f, 1, 0, 0.3f);
  const Weights w;
  const Matching xy = match(x, y, w), yx = match(y, x, w);
  EXPECT_EQ(xy.partners(2), std::vector<int>{2});
  EXPECT_EQ(yx.partners(3), std::vector<int>{2});
  EXPECT_GT(std::fabs(xy.numerator - yx.numerator), 0.1);
  // SIM matches the two in one canonical order, whichever comes first.
  std::vector<MatchPair> ab, ba;
  const double sab = graph_similarity(x, y, w, &ab), sba = graph_similarity(y, x, w, &ba);
  EXPECT_EQ(sab, sba);
  EXPECT_EQ(graph_similarity(x, y, w), sab);
  EXPECT_EQ(arg_similarity(x, y, w), arg_similarity(y, x, w));
  EXPECT_GT(sab, 0.0);
  std::multiset<std::tuple<int, int, int, double>> forward, backward;
  for (const MatchPair& p : ab) forward.insert({p.level, p.a_node, p.b_node, p.sim});
  for (const MatchPair& p : ba) backward.insert({p.level, p.b_node, p.a_node, p.sim});
  EXPECT_EQ(forward, backward);
}
