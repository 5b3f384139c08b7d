// A plain SVG line chart: axes, grid, one coloured polyline and legend entry per curve.
#include "eval/pr_plot.hpp"

#include <cstdio>

namespace arg {

std::string precision_recall_svg(const std::vector<PrCurve>& curves, const std::string& title) {
  const double left = 60, top = 40, width = 440, height = 320;
  static const char* colours[] = {"#d62728", "#1f77b4", "#2ca02c", "#ff7f0e",
                                  "#9467bd", "#8c564b", "#e377c2"};
  std::string svg;
  char buf[512];
  auto add = [&](const char* fmt, auto... args) {
    std::snprintf(buf, sizeof buf, fmt, args...);
    svg += buf;
  };
  add("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
      "font-family=\"sans-serif\" font-size=\"12\">\n",
      int(left + width + 150), int(top + height + 50));
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  std::string escaped;
  for (char c : title)
    escaped += c == '<' ? std::string("&lt;") : c == '&' ? std::string("&amp;") : std::string(1, c);
  add("<text x=\"%g\" y=\"24\" font-size=\"14\">%s</text>\n", left, escaped.c_str());
  for (int k = 0; k <= 10; ++k) {
    double x = left + width * k / 10.0, y = top + height * (1 - k / 10.0);
    add("<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"#ddd\"/>\n", x, top, x,
        top + height);
    add("<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"#ddd\"/>\n", left, y, left + width,
        y);
    add("<text x=\"%g\" y=\"%g\" text-anchor=\"middle\">%.1f</text>\n", x, top + height + 16,
        k / 10.0);
    add("<text x=\"%g\" y=\"%g\" text-anchor=\"end\">%.1f</text>\n", left - 6, y + 4, k / 10.0);
  }
  add("<rect x=\"%g\" y=\"%g\" width=\"%g\" height=\"%g\" fill=\"none\" stroke=\"black\"/>\n", left,
      top, width, height);
  add("<text x=\"%g\" y=\"%g\" text-anchor=\"middle\">recall</text>\n", left + width / 2,
      top + height + 36);
  add("<text x=\"16\" y=\"%g\" transform=\"rotate(-90 16 %g)\" "
      "text-anchor=\"middle\">precision</text>\n",
      top + height / 2, top + height / 2);
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const char* colour = colours[c % 7];
    std::string points;
    const auto& p = curves[c].precision;
    for (std::size_t k = 0; k < p.size(); ++k) {
      std::snprintf(buf, sizeof buf, "%.1f,%.1f ", left + width * double(k + 1) / double(p.size()),
                    top + height * (1 - p[k]));
      points += buf;
    }
    svg += "<polyline fill=\"none\" stroke-width=\"2\" stroke=\"" + std::string(colour) +
           "\" points=\"" + points + "\"/>\n";
    add("<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"%s\" stroke-width=\"2\"/>\n",
        left + width + 15, top + 10 + 18.0 * double(c), left + width + 40,
        top + 10 + 18.0 * double(c), colour);
    std::string name;
    for (char ch : curves[c].name)
      name += ch == '<'   ? std::string("&lt;")
              : ch == '&' ? std::string("&amp;")
                          : std::string(1, ch);
    add("<text x=\"%g\" y=\"%g\">%s</text>\n", left + width + 45, top + 14 + 18.0 * double(c),
        name.c_str());
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace arg
