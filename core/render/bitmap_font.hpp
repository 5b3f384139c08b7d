// A tiny built-in 5x7 bitmap font for captions and legend numbers (no font library needed).
#pragma once

#include <string_view>

#include "render/canvas.hpp"

namespace arg {

inline constexpr int kGlyphHeight = 7;   // above the baseline; descenders take one row more
inline constexpr int kGlyphAdvance = 6;  // 5 columns of ink and one of space

// Width in pixels of `text` drawn at `scale` (each font pixel a scale x scale square).
int text_width(std::string_view text, int scale = 1);

// Draws printable ASCII with its top-left corner at (x, y); characters without a glyph show
// as '?'. Clipped at the picture's edges.
void draw_text(Image& image, int x, int y, std::string_view text, Rgb colour, int scale = 1);

}  // namespace arg
