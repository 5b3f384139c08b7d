// Recognising a texture image's format and checking its byte layout before the decoder sees it.
#pragma once

#include <string_view>

namespace arg {

// The OpenImageIO plugin name ("png", "jpeg", "targa", "bmp") for the image in `bytes`, chosen
// from the content (never a file name), or nullptr when it is none of them.
const char* sniff_image_format(std::string_view bytes);

// OpenImageIO 2.4's readers trust the headers they read (fuzzing found a segfault in the TGA
// reader and an uncaught exception in the BMP reader, both of which would end a database
// backend), so the layout is checked here first: every PNG chunk lies inside the data and has a
// correct checksum; a BMP is uncompressed with a palette and rows that fit in the data; a TGA is
// true-colour or greyscale and, uncompressed, holds all its pixels. Throws InputError naming
// what is wrong.
void check_image_layout(std::string_view bytes, std::string_view format);

}  // namespace arg
