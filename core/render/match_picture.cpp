// Layout of the match picture: panels, pair colours by rank, links, rank labels, notes.
#include "render/match_picture.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "common/errors.hpp"
#include "render/bitmap_font.hpp"
#include "render/colour_map.hpp"
#include "render/draw_shapes.hpp"
#include "render/render_model.hpp"

namespace arg {

namespace {

struct RankedGroup {
  int group = 0;
  double sim = 0;
};

}  // namespace

MatchPicture render_match_picture(const NodePositions& a, const NodePositions& b,
                                  const std::vector<MatchPair>& matches,
                                  const MatchPictureOptions& options) {
  const int level = options.level;
  if (level < 0 || level >= int(a.levels.size()) || level >= int(b.levels.size()))
    throw InputError("render: level " + std::to_string(level) + " is missing in a model");
  const std::size_t count_a = a.levels[std::size_t(level)].centre.size(),
                    count_b = b.levels[std::size_t(level)].centre.size();

  // Groups of this level, best sim first; ties keep the order the matcher founded them in.
  std::map<int, double> group_sim;
  std::vector<MatchPair> rows;
  for (const MatchPair& p : matches)
    if (p.level == level && p.a_node >= 0 && std::size_t(p.a_node) < count_a && p.b_node >= 0 &&
        std::size_t(p.b_node) < count_b) {
      rows.push_back(p);
      group_sim.emplace(p.group, p.sim);
    }
  std::vector<RankedGroup> ranked;
  for (auto [g, s] : group_sim) ranked.push_back({g, s});
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const RankedGroup& x, const RankedGroup& y) { return x.sim > y.sim; });
  std::map<int, int> rank_of;
  for (std::size_t k = 0; k < ranked.size(); ++k) rank_of[ranked[k].group] = int(k);

  const Rgb unmatched{255, 255, 255};
  std::vector<Rgb> fill_a(count_a, unmatched), fill_b(count_b, unmatched);
  std::vector<int> rank_a(count_a, -1), rank_b(count_b, -1);
  for (const MatchPair& p : rows) {
    const int r = rank_of[p.group];
    fill_a[std::size_t(p.a_node)] = fill_b[std::size_t(p.b_node)] = pair_colour(r);
    rank_a[std::size_t(p.a_node)] = rank_b[std::size_t(p.b_node)] = r;
  }

  RenderOptions ro;
  ro.width = ro.height = options.panel;
  ro.level = level;
  ro.shading = options.shading;
  ro.view = options.view;
  ro.clay = true;
  ro.legend = false;
  ro.title = options.title_a;
  const RenderedModel left = render_model(a, ro, fill_a);
  ro.title = options.title_b;
  const RenderedModel right = render_model(b, ro, fill_b);

  const int ts = text_scale_for(options.panel, options.panel);
  const int width = 2 * options.panel;
  int scale = ts;
  for (const std::string& line : options.notes)
    if (text_width(line, scale) > width - 8 * ts) scale = 1;
  const int line_h = (kGlyphHeight + 4) * scale;
  const int notes_h = options.notes.empty() ? 0 : int(options.notes.size()) * line_h + 8 * ts;

  MatchPicture out;
  out.image = make_canvas(width, options.panel + notes_h, kRenderBackground);
  blit(out.image, left.image, 0, 0);
  blit(out.image, right.image, options.panel, 0);
  fill_rect(out.image, options.panel, 0, 1, options.panel, {200, 200, 200});
  fill_rect(out.image, 0, options.panel, width, 1, {200, 200, 200});

  // Links from disc edge to disc edge, worst pair first so the best ones end up on top.
  std::vector<const MatchPair*> order;
  for (const MatchPair& p : rows) order.push_back(&p);
  std::stable_sort(order.begin(), order.end(), [&](const MatchPair* x, const MatchPair* y) {
    return rank_of[x->group] > rank_of[y->group];
  });
  const double line = std::max(1.0, options.panel / 384.0);
  for (const MatchPair* p : order) {
    const DrawnNode& m = left.nodes[std::size_t(p->a_node)];
    const DrawnNode& n = right.nodes[std::size_t(p->b_node)];
    const double x0 = m.x, y0 = m.y, x1 = n.x + options.panel, y1 = n.y;
    const double len = std::hypot(x1 - x0, y1 - y0);
    if (!(len > m.radius + n.radius)) continue;
    const double ux = (x1 - x0) / len, uy = (y1 - y0) / len;
    const bool top = rank_of[p->group] < options.ranked_labels;
    draw_line(out.image, x0 + ux * m.radius, y0 + uy * m.radius, x1 - ux * n.radius,
              y1 - uy * n.radius, top ? 2 * line : line, pair_colour(rank_of[p->group]),
              top ? 0.85 : 0.5);
    ++out.links;
  }
  // Rank numbers beside the nodes of the best pairs.
  auto label = [&](const std::vector<DrawnNode>& nodes, const std::vector<int>& rank, int dx) {
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if (rank[i] < 0 || rank[i] >= options.ranked_labels) continue;
      const std::string text = std::to_string(rank[i] + 1);
      const int x = int(std::lround(nodes[i].x + nodes[i].radius + 2)) + dx;
      const int y = int(std::lround(nodes[i].y - nodes[i].radius - kGlyphHeight * ts));
      fill_rect(out.image, x - 1, y - 1, text_width(text, ts) + 2, kGlyphHeight * ts + 2,
                {255, 255, 255}, 0.8);
      draw_text(out.image, x, y, text, kRenderInk, ts);
    }
  };
  label(left.nodes, rank_a, 0);
  label(right.nodes, rank_b, options.panel);
  for (std::size_t k = 0; k < options.notes.size(); ++k)
    draw_text(out.image, 4 * ts, options.panel + 4 * ts + int(k) * line_h, options.notes[k],
              kRenderInk, scale);
  for (int r : rank_a) out.matched_a += r >= 0;
  for (int r : rank_b) out.matched_b += r >= 0;
  return out;
}

}  // namespace arg
