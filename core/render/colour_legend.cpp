// Layout of the colour legend: caption, bar, ticks, numbers.
#include "render/colour_legend.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "render/bitmap_font.hpp"

namespace arg {

void draw_colour_legend(Image& image, int x, int y, int w, int h, const SurfacePaint& paint,
                        std::string_view caption, Rgb ink, int text_scale) {
  if (paint.ramp.empty()) return;
  const int line = kGlyphHeight * text_scale;
  const int label_w = text_width("0.5", text_scale);
  const int bar_w = std::max(6, std::min(w - label_w - 3 * text_scale - 4, 8 * text_scale));
  const int bar_x = x + 2;
  const int top = y + line + line / 2 + line / 2, bottom = y + h - line / 2 - 1;
  if (bottom - top < 8 || bar_w <= 0) return;
  draw_text(image, x + std::max(0, (bar_w + label_w - text_width(caption, text_scale)) / 2), y,
            caption, ink, text_scale);
  const int steps = int(paint.ramp.size());
  for (int row = top; row <= bottom; ++row) {
    const double t = double(bottom - row) / double(bottom - top);
    Rgb c = paint.ramp[std::size_t(std::lround(t * (steps - 1)))];
    if (paint.bands > 0 && std::min(int(t * paint.bands), paint.bands - 1) % 2) c = scaled(c, 0.8);
    fill_rect(image, bar_x, row, bar_w, 1, c);
  }
  // Frame and band ticks.
  fill_rect(image, bar_x - 1, top - 1, bar_w + 2, 1, ink);
  fill_rect(image, bar_x - 1, bottom + 1, bar_w + 2, 1, ink);
  fill_rect(image, bar_x - 1, top - 1, 1, bottom - top + 3, ink);
  fill_rect(image, bar_x + bar_w, top - 1, 1, bottom - top + 3, ink);
  const int tick_x = bar_x + bar_w + 1;
  if (paint.bands > 0 && paint.bands <= 32)
    for (int k = 1; k < paint.bands; ++k) {
      const int row = bottom - int(std::lround(double(k) / paint.bands * (bottom - top)));
      fill_rect(image, tick_x, row, 2 * text_scale, 1, ink);
    }
  const char* labels[] = {"0", "0.5", "1"};
  for (int k = 0; k < 3; ++k) {
    const int row = bottom - int(std::lround(0.5 * k * (bottom - top)));
    fill_rect(image, tick_x, row, 3 * text_scale, 1, ink);
    draw_text(image, tick_x + 4 * text_scale, row - line / 2, labels[k], ink, text_scale);
  }
}

}  // namespace arg
