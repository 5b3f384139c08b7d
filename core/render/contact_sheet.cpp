// Grid layout of the contact sheet and caption clipping.
#include "render/contact_sheet.hpp"

#include <algorithm>

#include "render/bitmap_font.hpp"
#include "render/render_model.hpp"

namespace arg {

namespace {

// The longest prefix that fits, marked with ".." when something was cut.
std::string fit_text(const std::string& text, int width, int scale) {
  if (text_width(text, scale) <= width) return text;
  std::string cut = text;
  while (!cut.empty() && text_width(cut + "..", scale) > width) cut.pop_back();
  return cut + "..";
}

}  // namespace

Image contact_sheet(const std::vector<SheetCell>& cells, int columns, const std::string& title,
                    int text_scale) {
  columns = std::max(1, std::min(columns, int(std::max<std::size_t>(cells.size(), 1))));
  int cell_w = 1, picture_h = 1;
  std::size_t lines = 0;
  for (const SheetCell& c : cells) {
    cell_w = std::max(cell_w, c.picture.width);
    picture_h = std::max(picture_h, c.picture.height);
    lines = std::max(lines, c.caption.size());
  }
  const int line_h = (kGlyphHeight + 3) * text_scale;
  const int gap = 6 * text_scale;
  const int cell_h = picture_h + 3 * text_scale + int(lines) * line_h;
  const int title_h = title.empty() ? 0 : kGlyphHeight * text_scale + 2 * gap;
  const int rows = (int(cells.size()) + columns - 1) / columns;
  Image sheet = make_canvas(gap + columns * (cell_w + gap),
                            title_h + gap + std::max(rows, 1) * (cell_h + gap), kRenderBackground);
  if (!title.empty())
    draw_text(sheet, gap, gap, fit_text(title, sheet.width - 2 * gap, text_scale), kRenderInk,
              text_scale);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const SheetCell& c = cells[k];
    const int x = gap + int(k % std::size_t(columns)) * (cell_w + gap);
    const int y = title_h + gap + int(k / std::size_t(columns)) * (cell_h + gap);
    const int px = x + (cell_w - c.picture.width) / 2;
    blit(sheet, c.picture, px, y);
    if (c.framed) {
      const int t = std::max(2, text_scale + 1);
      fill_rect(sheet, px, y, c.picture.width, t, c.frame);
      fill_rect(sheet, px, y + c.picture.height - t, c.picture.width, t, c.frame);
      fill_rect(sheet, px, y, t, c.picture.height, c.frame);
      fill_rect(sheet, px + c.picture.width - t, y, t, c.picture.height, c.frame);
    }
    for (std::size_t i = 0; i < c.caption.size(); ++i) {
      const std::string text = fit_text(c.caption[i], cell_w, text_scale);
      draw_text(sheet, x + (cell_w - text_width(text, text_scale)) / 2,
                y + c.picture.height + 3 * text_scale + int(i) * line_h, text, kRenderInk,
                text_scale);
    }
  }
  return sheet;
}

}  // namespace arg
