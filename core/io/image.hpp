// A decoded texture image (8-bit RGB, top row first) and decoding one from bytes in memory.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "common/limits.hpp"

namespace arg {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // 3 bytes per pixel, row 0 is the top of the picture

  bool empty() const { return width <= 0 || height <= 0; }
};

// Decodes a PNG, JPEG, true-colour or greyscale TGA (including run-length encoded) or
// uncompressed BMP image held in memory, with OpenImageIO reading from the bytes (never from a
// file) once io/image_format_checks.hpp has checked the layout. Grey images are expanded to RGB and
// alpha is dropped. Checks width*height against limits.max_image_pixels before any pixel is
// read. Throws InputError ("image: ...") or LimitError.
Image decode_image(std::string_view bytes, const Limits& limits);

}  // namespace arg
