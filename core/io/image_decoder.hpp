// The pluggable image decoder: the core checks image bytes, a loaded library decodes them.
#pragma once

#include <string_view>

#include "common/limits.hpp"
#include "io/image.hpp"

namespace arg {

// Decodes `bytes` already known to be of `format` ("png", "jpeg", "targa" or "bmp"); throws
// InputError or LimitError like decode_image.
using ImageDecoder = Image (*)(std::string_view bytes, const char* format, const Limits& limits);

// OpenImageIO drags hundreds of shared libraries (and their threads) into every process that
// links it, so the core does not: programs register core/oiio's decoder at start-up, and the
// extension loads it on the first texture. Thread-safe.
void set_image_decoder(ImageDecoder decoder);
ImageDecoder image_decoder();

}  // namespace arg
