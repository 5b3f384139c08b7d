// Layout (rows by mu interval, ordered by barycentre sweeps) and text of the graph SVG.
#include "render/graph_svg.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numeric>
#include <vector>

#include "common/errors.hpp"
#include "render/colour_map.hpp"

namespace arg {

namespace {

// Fixed-point text that does not depend on the C locale (the server may have set one).
std::string num(double x, int decimals = 1) {
  char buf[32];
  if (!std::isfinite(x)) x = 0;
  if (std::fabs(x) < 0.5 * std::pow(10.0, -decimals)) x = 0;  // no "-0.0"
  const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::fixed, decimals);
  return std::string(buf, r.ptr);
}

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string hex(Rgb c) {
  static const char digits[] = "0123456789abcdef";
  std::string s = "#";
  for (std::uint8_t v : {c.r, c.g, c.b}) s += digits[v >> 4], s += digits[v & 15];
  return s;
}

}  // namespace

std::string arg_graph_svg(const ArgGraph& g, int level) {
  if (level < 0 || level > g.levels() || std::size_t(level) + 1 >= g.level_begin.size())
    throw InputError("svg: level " + std::to_string(level) + " is not in 0.." +
                     std::to_string(g.levels()));
  const int first = int(g.level_begin[std::size_t(level)]);
  const int count = int(g.level_begin[std::size_t(level) + 1]) - first;
  const int intervals = 1 << level;
  const double per_level = g.levels() + 1.0;
  const double plot_h = 360, unit = 110, gap = 8;

  const auto n_nodes = static_cast<std::size_t>(count);
  std::vector<double> x(n_nodes), y(n_nodes), radius(n_nodes);
  for (int i = 0; i < count; ++i) {
    const ArgNode& n = g.nodes[std::size_t(first + i)];
    x[std::size_t(i)] = unit * n.r * std::sin(n.phi) * std::sin(n.theta);
    y[std::size_t(i)] = plot_h * (1 - (n.interval + 0.5) / intervals);
    radius[std::size_t(i)] = 3 + 15 * std::sqrt(std::clamp(n.a * per_level, 0.0, 1.0));
  }
  // Edges within the level, as neighbour lists for the layout and as pairs for the drawing.
  std::vector<std::pair<int, int>> edges;
  std::vector<std::vector<int>> neighbours(n_nodes);
  for (int i = 0; i < count; ++i) {
    const ArgNode& n = g.nodes[std::size_t(first + i)];
    for (std::uint32_t k = 0; k < n.adj_count; ++k) {
      const int j = int(g.adjacency[n.adj_begin + k]) - first;
      if (j < 0 || j >= count) continue;
      neighbours[std::size_t(i)].push_back(j);
      if (j > i) edges.emplace_back(i, j);
    }
  }
  // Rows of nodes by interval, first ordered by the projection and packed. The projection
  // alone crosses edges wherever the ARG's theta flipped a part to the other side, so then
  // sweep up and down the rows, moving each node to the mean position of its neighbours (the
  // barycentre heuristic of layered graph drawing) while keeping discs apart.
  std::vector<std::vector<int>> rows(static_cast<std::size_t>(intervals));
  for (int i = 0; i < count; ++i)
    rows[std::size_t(g.nodes[std::size_t(first + i)].interval)].push_back(i);
  auto place_row = [&](std::vector<int>& row, const std::vector<double>& key) {
    std::stable_sort(row.begin(), row.end(),
                     [&](int a, int b) { return key[std::size_t(a)] < key[std::size_t(b)]; });
    std::vector<double> placed(row.size());
    double shift = 0;
    for (std::size_t j = 0; j < row.size(); ++j) {
      const std::size_t i = std::size_t(row[j]);
      placed[j] = key[i];
      if (j > 0)
        placed[j] =
            std::max(placed[j], placed[j - 1] + radius[std::size_t(row[j - 1])] + radius[i] + gap);
      shift += placed[j] - key[i];
    }
    if (!row.empty()) shift /= double(row.size());
    for (std::size_t j = 0; j < row.size(); ++j) x[std::size_t(row[j])] = placed[j] - shift;
  };
  for (auto& row : rows) place_row(row, x);
  for (int sweep = 0; sweep < 16; ++sweep) {
    for (int step = 0; step < intervals; ++step) {
      const int k = sweep % 2 ? intervals - 1 - step : step;
      std::vector<double> key = x;
      for (int i : rows[std::size_t(k)]) {
        const auto& nb = neighbours[std::size_t(i)];
        if (nb.empty()) continue;
        double mean = 0;
        for (int j : nb) mean += x[std::size_t(j)];
        key[std::size_t(i)] = mean / double(nb.size());
      }
      place_row(rows[std::size_t(k)], key);
    }
  }

  const double label_w = 48, margin = 12;
  double lo = 0, hi = 0;
  for (int i = 0; i < count; ++i) {
    lo = std::min(lo, x[std::size_t(i)] - radius[std::size_t(i)]);
    hi = std::max(hi, x[std::size_t(i)] + radius[std::size_t(i)]);
  }
  const double left = margin + label_w - lo, top = margin + 22;
  const double width = label_w + (hi - lo) + 2 * margin, height = plot_h + top + margin + 8;

  std::string svg;
  svg += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(width, 0) + "\" height=\"" +
         num(height, 0) + "\" viewBox=\"0 0 " + num(width, 0) + " " + num(height, 0) +
         "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  svg += "<title>" +
         escape("Reeb graph, level " + std::to_string(level) + ": " + std::to_string(count) +
                " nodes, " + std::to_string(edges.size()) + " edges") +
         "</title>\n";
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  // The mu axis with a tick at every interval boundary.
  const double axis_x = margin + label_w - 8;
  std::string axis = "M" + num(axis_x) + " " + num(top) + "V" + num(top + plot_h);
  for (int k = 0; k <= intervals; ++k)
    axis += "M" + num(axis_x - 4) + " " + num(top + plot_h * k / intervals) + "h4";
  svg += "<path d=\"" + axis + "\" stroke=\"#888\" fill=\"none\"/>\n";
  svg += "<text x=\"" + num(axis_x - 6) + "\" y=\"" + num(top + 4) +
         "\" text-anchor=\"end\">mu=1</text>\n";
  svg += "<text x=\"" + num(axis_x - 6) + "\" y=\"" + num(top + plot_h + 4) +
         "\" text-anchor=\"end\">mu=0</text>\n";
  svg += "<text x=\"" + num(margin) + "\" y=\"" + num(margin + 4) + "\">" +
         escape("level " + std::to_string(level) + ", " + std::to_string(count) + " nodes") +
         "</text>\n";
  svg += "<g stroke=\"#333\" stroke-width=\"1.5\">\n";
  for (auto [i, j] : edges)
    svg += "<line x1=\"" + num(left + x[std::size_t(i)]) + "\" y1=\"" +
           num(top + y[std::size_t(i)]) + "\" x2=\"" + num(left + x[std::size_t(j)]) + "\" y2=\"" +
           num(top + y[std::size_t(j)]) + "\"/>\n";
  svg += "</g>\n<g stroke=\"#222\" stroke-width=\"1\">\n";
  for (int i = 0; i < count; ++i) {
    const ArgNode& n = g.nodes[std::size_t(first + i)];
    const std::string title = "level " + std::to_string(level) + " node " + std::to_string(i) +
                              ": area " + num(n.a * per_level, 3) + ", mu " + num(n.mu_min, 3) +
                              "-" + num(n.mu_max, 3);
    svg += "<circle cx=\"" + num(left + x[std::size_t(i)]) + "\" cy=\"" +
           num(top + y[std::size_t(i)]) + "\" r=\"" + num(radius[std::size_t(i)]) + "\" fill=\"" +
           hex(mu_colour((n.interval + 0.5) / intervals)) + "\"><title>" + escape(title) +
           "</title></circle>\n";
  }
  svg += "</g>\n</svg>\n";
  return svg;
}

}  // namespace arg
