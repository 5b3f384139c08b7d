// The coarse-to-fine matching with branch labels, Tung's rule and node groups.
#include "match/mpair.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include "match/child_halves.hpp"
#include "match/match_prep.hpp"
#include "match/node_similarity.hpp"
#include "match/sim_key.hpp"

namespace arg {

namespace {

// Matching state of one graph; buffers are reused between calls on the same thread.
struct Side {
  const ArgGraph* g = nullptr;
  std::vector<int> group;  // per node: match group, -1 when unmatched
  // Per branch (a chain of only-neighbours, labelled as one): its label, 0 when none.
  std::vector<int> branch_label;
  // Per node: its only neighbour in the interval below and above (when there is no MatchPrep,
  // for the branches).
  std::vector<std::array<int, 2>> own_only;
  const MatchKey* key = nullptr;  // per node, from the MatchPrep or worked out
  std::vector<MatchKey> own_keys;
  const SimKey* sim = nullptr;  // per node, when its MatchPrep has them
  // Per node, its children in index order: children[child_begin[i], child_begin[i + 1]), the
  // upper half of its interval's from child_mid[i] (match/child_halves.hpp); when `halved` is
  // false the candidate scan reads whole intervals.
  bool halved = false;
  const std::uint32_t* child_begin = nullptr;
  const std::uint32_t* child_mid = nullptr;
  const std::uint32_t* children = nullptr;
  std::vector<std::uint32_t> own_child_begin, own_child_mid, own_children;
  const MatchPrep* prep = nullptr;  // its neighbour lists, when it has a MatchPrep

  void reset(const ArgGraph& graph, const MatchPrep* given) {
    g = &graph;
    prep = prep_shape_fits(given, graph) ? given : nullptr;
    if (graph.nodes.empty() && !prep)
      throw std::logic_error("a graph without node records came to matching without its prep");
    group.assign(prep ? prep->keys.size() : graph.nodes.size(), -1);
    if (prep) {
      key = prep->keys.data();
      sim = prep->sim_keys.empty() ? nullptr : prep->sim_keys.data();
      halved = !prep->child_begin.empty();
      child_begin = prep->child_begin.data();
      child_mid = prep->child_mid.data();
      children = prep->children.data();
      branch_label.assign(std::size_t(prep->branches), 0);
    } else {
      prepare_nodes(graph, own_only, own_keys);
      key = own_keys.data();
      sim = nullptr;
      halved = prepare_child_halves(graph, own_keys, own_child_begin, own_child_mid, own_children);
      child_begin = own_child_begin.data();
      child_mid = own_child_mid.data();
      children = own_children.data();
      branch_label.assign(std::size_t(prepare_branches(own_only, own_keys)), 0);
    }
  }
  const ArgNode& node(int i) const { return g->nodes[std::size_t(i)]; }

  int label(int i) const { return branch_label[std::size_t(key[i].branch)]; }
  // Labels the branch through i: its chain of neighbours up and down while it does not fork.
  void label_branch(int i, int value) { branch_label[std::size_t(key[i].branch)] = value; }

  int parent_group(int i) const {
    int p = key[i].parent;
    return p < 0 ? -2 : group[std::size_t(p)];  // -2: a root, whose "parent" always matches
  }
};

// For Tung and Schmitt's rule: the distinct matched groups of the parents of a node's
// neighbours below (side 0) and above (side 1). Parents are settled before a level starts,
// so this is computed at most once per node and level. Up to four groups are kept per side.
struct NeighbourParents {
  std::uint64_t level_stamp = 0;  // valid for the level of this stamp only
  int group[2][4];
  int count[2];
};

// Fills `np` for node i. Kept out of line: it runs once a node and level, while the check in
// LevelParents::of, inlined into the candidate scan, runs at every candidate.
[[gnu::noinline]] void find_neighbour_parents(const Side& side, int i, NeighbourParents& np) {
  np.count[0] = np.count[1] = 0;
  auto add = [&np](int up, int gp) {
    int* list = np.group[up];
    int& c = np.count[up];
    bool seen = false;
    for (int q = 0; q < c; ++q) seen |= list[q] == gp;
    if (!seen && c < 4) list[c++] = gp;
  };
  if (const MatchPrep* prep = side.prep) {
    // The same groups from the prepared neighbour lists.
    const std::uint32_t split = prep->neighbour_split[std::size_t(i)];
    for (std::uint32_t k = prep->neighbour_begin[std::size_t(i)];
         k < prep->neighbour_begin[std::size_t(i) + 1]; ++k) {
      const int gp = side.parent_group(int(prep->neighbours[k]));
      if (gp >= 0) add(k >= split ? 1 : 0, gp);
    }
    return;
  }
  const ArgNode& n = side.node(i);
  const std::uint32_t* adj = side.g->adjacency.data() + n.adj_begin;
  for (std::uint32_t k = 0; k < n.adj_count; ++k) {
    const int j = int(adj[k]);
    const int gp = side.parent_group(j);
    if (gp >= 0) add(j > i ? 1 : 0, gp);  // nodes of a level are sorted by interval
  }
}

// Per node of the current level, computed on first use: most nodes never get past the cheaper
// tests of `candidate`, and this was a fifth of a comparison when done for every node. Entries
// carry the stamp of the level they were found at, so a new level needs no clearing pass.
struct LevelParents {
  std::vector<NeighbourParents> entry;
  std::uint64_t stamp = 0;  // grows by one a level, over all calls on the thread
  int begin = 0;

  void start_level(int level_begin, int level_end) {
    ++stamp, begin = level_begin;
    if (entry.size() < std::size_t(level_end - level_begin))
      entry.resize(std::size_t(level_end - level_begin));
  }
  const NeighbourParents& of(const Side& side, int i) {
    NeighbourParents& np = entry[std::size_t(i - begin)];
    if (np.level_stamp != stamp) find_neighbour_parents(side, i, np), np.level_stamp = stamp;
    return np;
  }
};

// Where the parents of the neighbours of m and of n on one side are matched, at least one
// of m's is matched to one of n's.
bool neighbours_agree(const NeighbourParents& a, const NeighbourParents& b) {
  for (int side = 0; side < 2; ++side) {
    if (a.count[side] == 0 || b.count[side] == 0) continue;
    bool shared = false;
    for (int p = 0; p < a.count[side] && !shared; ++p)
      for (int q = 0; q < b.count[side]; ++q) shared |= a.group[side][p] == b.group[side][q];
    if (!shared) return false;
  }
  return true;
}

// A match founded by one node of each graph; further members are listed in `extra`.
struct Founded {
  int level, x, y;
  double loss;
};

struct Scratch {
  Side x, y;
  MatchPrep::Sums own_sums;           // X's self sims and order when it comes without a MatchPrep
  std::vector<OrderKey> keyed;        // prepare_sums' scratch
  std::vector<int> y_interval_begin;  // per interval of the current level: first Y node
  LevelParents x_parents, y_parents;
  std::vector<Founded> groups;
  std::vector<std::pair<int, int>> extra_x, extra_y;  // (group, node) beyond the founders
};

// The calling thread's scratch, looked up once a call. Not inlined on purpose: in a shared
// library (the extension) the compiler otherwise repeats the thread-local lookup, a call to
// __tls_get_addr, at every use (fifty sites here, 3.5% of a ranking in SQL).
[[gnu::noinline]] Scratch& thread_scratch() {
  thread_local Scratch s;
  return s;
}

// node_sim of X's node m and Y's node n, from their sim keys when both sides have them (the
// same bits from a sixth of the bytes of a node record).
double pair_sim(const Side& X, int m, const Side& Y, int n, const Weights& w) {
  if (!X.sim || !Y.sim) return node_sim(X.node(m), Y.node(n), w);
  double s = key_sim(X.sim[m], Y.sim[n], w);
  if (w.lambda_4 > 0) s += w.lambda_4 * histogram_min(X.node(m).colour, Y.node(n).colour) / 3.0;
  return s;
}

bool candidate(const Side& X, const Side& Y, int m, int n, int parent_group_m) {
  return Y.group[std::size_t(n)] < 0 && parent_group_m == Y.parent_group(n) &&
         X.label(m) == Y.label(n);
}

// Unmatched nodes of `side` whose parent is matched join a group founded at this level by a
// node of the same interval and parent (nodes of one interval are contiguous), choosing the
// group of least loss against its founder on the other side. Records (group, node) in `extra`.
void extend_groups(const Side& side, const Side& other, const std::vector<Founded>& groups,
                   int first_group, int begin, int end, bool is_x, const Weights& w,
                   std::vector<std::pair<int, int>>& extra) {
  for (int u = begin; u < end; ++u) {
    if (side.group[std::size_t(u)] >= 0 || side.parent_group(u) < 0) continue;
    const ArgNode& nu = side.node(u);
    int lo = u, hi = u;
    while (lo > begin && side.node(lo - 1).interval == nu.interval) --lo;
    while (hi + 1 < end && side.node(hi + 1).interval == nu.interval) ++hi;
    int best = -1;
    double best_loss = 0;
    for (int v = lo; v <= hi; ++v) {
      const int gid = side.group[std::size_t(v)];
      if (gid < first_group || side.node(v).parent != nu.parent) continue;
      const Founded& grp = groups[std::size_t(gid)];
      if ((is_x ? grp.x : grp.y) != v) continue;  // v joined a group itself; use founders
      double loss = node_loss(nu, other.node(is_x ? grp.y : grp.x), side.g->levels(), w);
      if (best < 0 || loss < best_loss) best = gid, best_loss = loss;
    }
    if (best >= 0) extra.emplace_back(best, u);
  }
}

}  // namespace

double match_graphs(const ArgGraph& gx, const MatchPrep* px, const ArgGraph& gy,
                    const MatchPrep* py, const Weights& w, std::vector<MatchGroup>* groups_out,
                    std::vector<double>* group_sim, double* self_x) {
  Scratch& s = thread_scratch();
  Side& X = s.x;
  Side& Y = s.y;
  X.reset(gx, px), Y.reset(gy, py);
  // A head (match/packed_graph.hpp) has only its keys: what would read node records is out.
  if ((gx.nodes.empty() || gy.nodes.empty()) && (!X.sim || !Y.sim || w.groups || w.lambda_4 > 0))
    throw std::logic_error("a graph without node records cannot be matched with these weights");
  s.groups.clear();
  if (group_sim) group_sim->clear();
  const int levels = std::min(gx.levels(), gy.levels());
  const MatchPrep::Sums* sums = X.prep ? X.prep->sums(w.lambda_4 != 0) : nullptr;
  if (sums && sums->order.size() != sums->self.size()) sums = nullptr;
  if (!sums && gx.nodes.empty())
    throw std::logic_error("a graph without node records came to matching first without its order");
  if (!sums) {
    prepare_sums(gx, w, s.own_sums, &s.keyed);
    sums = &s.own_sums;
  }
  if (self_x) *self_x = sums->total;
  int next_label = 1;
  double numerator = 0;
  std::vector<std::pair<int, int>> all_extra_x, all_extra_y;  // only filled for groups_out
  for (int r = 0; r <= levels; ++r) {
    const double scale = level_scale(w.level_ratio, r);
    const int xb = int(gx.level_begin[std::size_t(r)]),
              xe = int(gx.level_begin[std::size_t(r) + 1]);
    const int yb = int(gy.level_begin[std::size_t(r)]),
              ye = int(gy.level_begin[std::size_t(r) + 1]);
    const int first_group = int(s.groups.size());
    // Where each interval's nodes start in Y's level (nodes are sorted by interval).
    const int* y_interval_begin;
    if (Y.prep) {
      y_interval_begin = Y.prep->interval_begin.data() + interval_offset(r);
    } else {
      s.y_interval_begin.resize((std::size_t(1) << r) + 1);
      prepare_interval_begin(gy, r, s.y_interval_begin.data());
      y_interval_begin = s.y_interval_begin.data();
    }
    if (w.tung_rule) {
      s.x_parents.start_level(xb, xe);
      s.y_parents.start_level(yb, ye);
    }
    // X's nodes by decreasing own sim, ties by index.
    for (int k = xb; k < xe; ++k) {
      const int m = sums->order[std::size_t(k)];
      const int pg = X.parent_group(m);
      if (pg == -1) continue;  // parent unmatched: the subtree stays unmatched
      const MatchKey& km = X.key[m];
      int best = -1;
      double best_loss = 0, best_sim = -1;
      const int label_m = X.label(m);               // labels change only once m is matched
      const NeighbourParents* parents_m = nullptr;  // found when a candidate first needs them
      // `child` tells that n is a child of the Y node in m's parent's group, so its parent's
      // group is m's: only its own group and label are then asked (with & rather than &&: one
      // branch on their outcome, which is not predictable, instead of two).
      auto consider = [&](int n, bool child) {
        if (child ? !((Y.group[std::size_t(n)] < 0) & (label_m == Y.label(n)))
                  : !candidate(X, Y, m, n, pg))
          return;
        const double loss = node_loss(km, Y.key[n], gx.levels(), w);
        if (best >= 0 && loss > best_loss) return;
        // Tung's rule after the loss: a candidate that loses on it is dropped either way, and
        // the neighbours' parents cost more than the loss.
        if (w.tung_rule) {
          if (!parents_m) parents_m = &s.x_parents.of(X, m);
          if (!neighbours_agree(*parents_m, s.y_parents.of(Y, n))) return;
        }
        // Equal losses are settled by the larger sim, computed only then.
        if (best >= 0 && loss == best_loss) {
          if (best_sim < 0) best_sim = pair_sim(X, m, Y, best, w);
          const double sim = pair_sim(X, m, Y, n, w);
          if (sim <= best_sim) return;
          best_sim = sim;
        } else {
          best_sim = -1;
        }
        best = n, best_loss = loss;
      };
      if (pg >= 0 && X.halved && Y.halved && !w.groups) {
        // A candidate's parent is the one node of Y in m's parent's group (groups of several
        // nodes need w.groups): its children in m's interval, in index order, are the
        // interval's candidates as a scan of the whole interval would meet them. m lies in a
        // half of its parent's interval (X's children are in halves), which is Y's parent's.
        const int parent = s.groups[std::size_t(pg)].y;
        const std::uint32_t upper = km.interval & 1u;  // 1: the upper half, selected by sums
        const std::uint32_t begin = Y.child_begin[parent], mid = Y.child_mid[parent],
                            end = Y.child_begin[parent + 1];
        const std::uint32_t from = begin + upper * (mid - begin), to = mid + upper * (end - mid);
        for (std::uint32_t c = from; c < to; ++c) consider(int(Y.children[c]), true);
      } else {
        // Only Y's nodes of m's interval can be candidates.
        const int y_end = y_interval_begin[km.interval + 1];
        for (int n = y_interval_begin[km.interval]; n < y_end; ++n) consider(n, false);
      }
      if (best < 0) continue;
      const int gid = int(s.groups.size());
      s.groups.push_back({r, m, best, best_loss});
      X.group[std::size_t(m)] = gid;
      Y.group[std::size_t(best)] = gid;
      if (X.label(m) == 0) {
        X.label_branch(m, next_label);
        Y.label_branch(best, next_label);
        ++next_label;
      }
    }
    s.extra_x.clear(), s.extra_y.clear();
    if (w.groups) {
      extend_groups(X, Y, s.groups, first_group, xb, xe, true, w, s.extra_x);
      extend_groups(Y, X, s.groups, first_group, yb, ye, false, w, s.extra_y);
    }
    for (auto [gid, u] : s.extra_x) X.group[std::size_t(u)] = gid;
    for (auto [gid, u] : s.extra_y) Y.group[std::size_t(u)] = gid;
    // sim of each group of this level; groups with extra members compare summed attributes.
    const bool any_extra = !s.extra_x.empty() || !s.extra_y.empty();
    for (int k = first_group; k < int(s.groups.size()); ++k) {
      const Founded& g = s.groups[std::size_t(k)];
      double sim;
      bool grown = false;
      if (any_extra)
        for (auto& e : s.extra_x) grown |= e.first == k;
      if (any_extra)
        for (auto& e : s.extra_y) grown |= e.first == k;
      if (!grown) {
        sim = pair_sim(X, g.x, Y, g.y, w);
      } else {
        NodeMass mx, my;
        mx.add(gx.nodes[std::size_t(g.x)]), my.add(gy.nodes[std::size_t(g.y)]);
        for (auto& e : s.extra_x)
          if (e.first == k) mx.add(gx.nodes[std::size_t(e.second)]);
        for (auto& e : s.extra_y)
          if (e.first == k) my.add(gy.nodes[std::size_t(e.second)]);
        sim = node_sim(mx, my, w);
      }
      numerator += sim * scale;
      if (group_sim) group_sim->push_back(sim);
    }
    if (groups_out) {
      all_extra_x.insert(all_extra_x.end(), s.extra_x.begin(), s.extra_x.end());
      all_extra_y.insert(all_extra_y.end(), s.extra_y.begin(), s.extra_y.end());
    }
  }
  if (groups_out) {
    groups_out->clear();
    for (const Founded& g : s.groups) groups_out->push_back({g.level, {g.x}, {g.y}, g.loss});
    for (auto [gid, u] : all_extra_x) (*groups_out)[std::size_t(gid)].x.push_back(u);
    for (auto [gid, u] : all_extra_y) (*groups_out)[std::size_t(gid)].y.push_back(u);
  }
  return numerator;
}

double match_graphs(const ArgGraph& x, const ArgGraph& y, const Weights& weights,
                    std::vector<MatchGroup>* groups, std::vector<double>* group_sim,
                    double* self_x) {
  return match_graphs(x, nullptr, y, nullptr, weights, groups, group_sim, self_x);
}

}  // namespace arg
