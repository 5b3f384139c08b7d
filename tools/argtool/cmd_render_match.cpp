// argtool render-match: two models side by side, matched nodes linked, SIM explained, as PNG.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "command_registry.hpp"
#include "load_arg.hpp"
#include "match/similarity.hpp"
#include "match/similarity_terms.hpp"
#include "plugin_libraries.hpp"
#include "render/bitmap_font.hpp"
#include "render/match_picture.hpp"
#include "render/render_model.hpp"
#include "render_input.hpp"

namespace {

struct RenderMatchArgs {
  std::string a, b, output, weights = "arg", shading = "smooth", view = "front";
  int level = 2, size = 512;
  arg::BuildOptions options;
};

std::string fixed(double x, int decimals) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, x);
  return buf;
}

// `head` followed by the items, wrapped after `width` characters onto indented lines.
std::vector<std::string> wrap(const std::string& head, const std::vector<std::string>& items,
                              std::size_t width) {
  std::vector<std::string> lines = {head};
  for (const std::string& item : items) {
    if (lines.back().size() + 1 + item.size() > width && lines.back().size() > 4)
      lines.push_back("   ");
    lines.back() += " " + item;
  }
  return lines;
}

// "1 - graph SIM = 0.55 = curvature 0.21 + cords 0.12 + ...", the largest terms first.
std::vector<std::string> term_lines(const arg::SimilarityTerms& t, double sim, std::size_t width) {
  std::vector<std::pair<std::string, double>> terms = {
      {"a", t.a},          {"l", t.l}, {"v", t.v}, {"cords", t.cords}, {"curvature", t.curvature},
      {"colour", t.colour}};
  std::stable_sort(terms.begin(), terms.end(),
                   [](const auto& x, const auto& y) { return x.second > y.second; });
  std::vector<std::string> items;
  for (std::size_t k = 0; k < terms.size(); ++k)
    items.push_back((k ? "+ " : "") + terms[k].first + " " + fixed(terms[k].second, 4));
  return wrap("1 - graph SIM = " + fixed(1 - sim, 4) + " =", items, width);
}

int run_render_match(const RenderMatchArgs& a) {
  const auto start = std::chrono::steady_clock::now();
  if (a.level > a.options.levels)
    throw std::runtime_error("--level " + std::to_string(a.level) + " is finer than --levels " +
                             std::to_string(a.options.levels));
  const arg::Weights w = arg::parse_weights(a.weights);
  const argtool::RenderInput x = argtool::load_render_input(a.a, a.options),
                             y = argtool::load_render_input(a.b, a.options);
  std::vector<arg::MatchPair> pairs;
  const arg::SimilarityParts parts = arg::similarity_parts(x.graph, y.graph, w, &pairs);
  const double sim = arg::arg_similarity(x.graph, y.graph, w);
  const arg::SimilarityTerms terms = arg::similarity_terms(x.graph, y.graph, w, pairs);

  arg::MatchPictureOptions mo;
  mo.panel = a.size;
  mo.level = a.level;
  mo.shading = arg::parse_shading(a.shading);
  mo.view = arg::parse_view(a.view);
  mo.title_a = "A: " + x.name;
  mo.title_b = "B: " + y.name;
  const int ts = arg::text_scale_for(a.size, a.size);
  const auto width = std::size_t((2 * a.size - 8 * ts) / (arg::kGlyphAdvance * ts));
  mo.notes.push_back("SIM(A, B) = " + fixed(sim, 4) + "   (weights " + a.weights + ")");
  mo.notes.push_back("= mean of graph " + fixed(parts.graph, 4) + " (x" + fixed(parts.w_graph, 2) +
                     "), panorama " + fixed(parts.panorama, 4) + " (x" +
                     fixed(parts.w_panorama, 2) + "), spectrum " + fixed(parts.spectrum, 4) +
                     " (x" + fixed(parts.w_spectrum, 2) + ")");
  for (const std::string& line : term_lines(terms, parts.graph, width)) mo.notes.push_back(line);

  // The best pairs at the drawn level, as numbered in the picture.
  std::map<int, std::pair<std::vector<int>, std::vector<int>>> members;
  std::map<int, double> group_sim;
  for (const arg::MatchPair& p : pairs)
    if (p.level == a.level) {
      auto& m = members[p.group];
      if (std::find(m.first.begin(), m.first.end(), p.a_node) == m.first.end())
        m.first.push_back(p.a_node);
      if (std::find(m.second.begin(), m.second.end(), p.b_node) == m.second.end())
        m.second.push_back(p.b_node);
      group_sim[p.group] = p.sim;
    }
  std::vector<std::pair<int, double>> ranked(group_sim.begin(), group_sim.end());
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const auto& p, const auto& q) { return p.second > q.second; });
  std::vector<std::string> best;
  for (std::size_t k = 0; k < ranked.size() && k < std::size_t(mo.ranked_labels); ++k) {
    auto join = [](const std::vector<int>& v) {
      std::string s;
      for (std::size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + std::to_string(v[i]);
      return s;
    };
    const auto& m = members[ranked[k].first];
    best.push_back(std::to_string(k + 1) + ": A" + join(m.first) + "-B" + join(m.second) + " " +
                   fixed(ranked[k].second, 3) + (k + 1 < ranked.size() ? " " : ""));
  }
  if (!best.empty())
    for (const std::string& line :
         wrap("best at level " + std::to_string(a.level) + " (sim):", best, width))
      mo.notes.push_back(line);

  const arg::MatchPicture picture = arg::render_match_picture(x.positions, y.positions, pairs, mo);
  argtool::write_png(picture.image, a.output);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "SIM %.6f; wrote %s (%dx%d, level %d: %d links, %d of %zu and %d of %zu nodes "
      "matched, %.0f ms)\n",
      sim, a.output.c_str(), picture.image.width, picture.image.height, a.level, picture.links,
      picture.matched_a, x.positions.levels[std::size_t(a.level)].centre.size(), picture.matched_b,
      y.positions.levels[std::size_t(a.level)].centre.size(), ms);
  return 0;
}

const bool registered = argtool::register_command(
    "render-match", "draw two models side by side with their matched nodes linked, as PNG",
    [](CLI::App& app) {
      auto a = std::make_shared<RenderMatchArgs>();
      app.add_option("a", a->a, "first mesh file")->required()->check(CLI::ExistingFile);
      app.add_option("b", a->b, "second mesh file")->required()->check(CLI::ExistingFile);
      app.add_option("-o,--output", a->output, "PNG to write")->required();
      app.add_option("--weights", a->weights,
                     "preset (arg, part, mrg, graph, shape, colour) or key=value text")
          ->capture_default_str();
      app.add_option("--level", a->level, "level whose matched pairs are drawn")
          ->check(CLI::Range(0, arg::kMaxLevels))
          ->capture_default_str();
      app.add_option("--size", a->size, "width and height of each model's panel in pixels")
          ->check(CLI::Range(128, 2048))
          ->capture_default_str();
      app.add_option("--view", a->view,
                     "front, side, top or AZIMUTH,ELEVATION[,ROLL] in degrees, for both models")
          ->capture_default_str();
      app.add_option("--shading", a->shading, "flat or smooth")
          ->check(CLI::IsMember({"flat", "smooth"}))
          ->capture_default_str();
      argtool::add_build_flags(app, a->options);
      return [a] { return run_render_match(*a); };
    });

}  // namespace
