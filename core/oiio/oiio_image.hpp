// The OpenImageIO side of the project, built as its own shared library (arg_image).
#pragma once

#include <string>
#include <string_view>

#include "common/limits.hpp"
#include "io/image.hpp"

#define ARG_IMAGE_EXPORT __attribute__((visibility("default")))

namespace arg {

// The ImageDecoder of io/image_decoder.hpp (register it with set_image_decoder).
ARG_IMAGE_EXPORT Image oiio_decode_image(std::string_view bytes, const char* format,
                                         const Limits& limits);

}  // namespace arg

// For dlopen: the address of oiio_decode_image (the extension looks this symbol up).
extern "C" ARG_IMAGE_EXPORT void* arg_oiio_image_decoder();
// For dlopen: the address of write_png (argtool looks this symbol up).
extern "C" ARG_IMAGE_EXPORT void* arg_oiio_png_writer();
