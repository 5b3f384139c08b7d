// Writing a picture as a PNG file with OpenImageIO.
#pragma once

#include <string>

#include "io/image.hpp"

namespace arg {

// Writes 8-bit RGB without metadata that changes between runs, so the same picture gives the
// same bytes. Throws InputError naming the path when the file cannot be written.
void write_png(const Image& image, const std::string& path);

}  // namespace arg
