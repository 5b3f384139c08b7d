// Recognising a texture image's format and checking its byte layout before the decoder sees it.
#pragma once

#include <cstdint>
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

// The width and height a JPEG's frame header (its first SOFn marker segment) declares, read by
// walking the marker segments from the start of the data. libjpeg allocates a progressive
// image's coefficients for all its pixels while OpenImageIO opens it, before the caller could
// check the size (fuzzing found 183 bytes declaring 65000 x 65000 that asked for 8 GB), so the
// pixel cap is applied to this first. Throws InputError when a segment runs past the data, the
// scan starts before any frame header, or the frame declares no height (a DNL marker, which
// libjpeg does not read).
struct JpegFrameSize {
  std::uint32_t width = 0, height = 0;
};
JpegFrameSize jpeg_frame_size(std::string_view bytes);

}  // namespace arg
