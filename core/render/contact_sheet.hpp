// A contact sheet: pictures in a grid, each with caption lines under it, and a title on top.
#pragma once

#include <string>
#include <vector>

#include "render/canvas.hpp"

namespace arg {

struct SheetCell {
  Image picture;
  std::vector<std::string> caption;  // lines under the picture, cut to the cell's width
  bool framed = false;               // a coloured frame, e.g. around the query
  Rgb frame{214, 39, 40};
};

// Rows of `columns` cells as wide as the widest picture; text at `text_scale`.
Image contact_sheet(const std::vector<SheetCell>& cells, int columns, const std::string& title,
                    int text_scale = 1);

}  // namespace arg
