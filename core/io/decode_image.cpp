// Checking texture image bytes (format, chunk layout, size cap) before the decoder sees them.
#include <cstring>
#include <string>

#include "common/errors.hpp"
#include "io/image.hpp"
#include "io/image_decoder.hpp"

namespace arg {

namespace {

// OpenImageIO plugin names; the format is chosen from the content, never from a file name.
const char* sniff(std::string_view b) {
  auto starts = [&](std::string_view magic) { return b.substr(0, magic.size()) == magic; };
  if (starts("\x89PNG\r\n\x1a\n")) return "png";
  if (starts("\xFF\xD8\xFF")) return "jpeg";
  if (starts("BM") && b.size() > 26) return "bmp";
  // TGA has no magic number: check the header fields that have only a few legal values.
  if (b.size() >= 18) {
    const auto u = [&](std::size_t i) { return static_cast<unsigned char>(b[i]); };
    const unsigned type = u(2), colour_map = u(1), bits = u(16);
    const bool type_ok =
        type == 1 || type == 2 || type == 3 || type == 9 || type == 10 || type == 11;
    const bool bits_ok = bits == 8 || bits == 15 || bits == 16 || bits == 24 || bits == 32;
    if (colour_map <= 1 && type_ok && bits_ok) return "targa";
  }
  return nullptr;
}

[[noreturn]] void fail(const std::string& what) {
  throw InputError("image: " + what);
}

// OpenImageIO 2.4's PNG reader leaks its error message whenever libpng long-jumps out of a read
// past the end of the data, so check first that every chunk lies inside the data up to IEND.
void check_png_chunks(std::string_view b) {
  std::size_t at = 8;
  for (;;) {
    if (b.size() - at < 12) fail("png: truncated data (no IEND chunk)");
    const auto* p = reinterpret_cast<const unsigned char*>(b.data() + at);
    const std::uint32_t length =
        std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
    if (length > b.size() - at - 12) {
      fail("png: the chunk at byte offset " + std::to_string(at) +
           " runs past the end of the data");
    }
    const bool end = b.substr(at + 4, 4) == "IEND";
    at += 12 + std::size_t(length);
    if (end) return;
  }
}

// OpenImageIO 2.4's TGA reader indexes the colour map with unchecked values (a colour-mapped
// image with an empty map crashes it), so only true-colour and greyscale TGA reach it.
void check_tga_header(std::string_view b) {
  const auto u = [&](std::size_t i) { return static_cast<unsigned char>(b[i]); };
  if (u(1) != 0 || u(2) == 1 || u(2) == 9) {
    fail(
        "tga: colour-mapped images are not supported (save the texture as true-colour TGA, PNG "
        "or JPEG)");
  }
}

}  // namespace

Image decode_image(std::string_view bytes, const Limits& limits) {
  if (bytes.size() > limits.max_input_bytes) {
    throw LimitError("image: " + std::to_string(bytes.size()) + " bytes, more than " +
                     std::to_string(limits.max_input_bytes));
  }
  const char* format = sniff(bytes);
  if (!format) fail("not a PNG, JPEG, TGA or BMP image");
  if (std::string_view(format) == "png") check_png_chunks(bytes);
  if (std::string_view(format) == "targa") check_tga_header(bytes);
  const ImageDecoder decoder = image_decoder();
  if (!decoder) throw Error("image: no image decoder is loaded (see io/image_decoder.hpp)");
  return decoder(bytes, format, limits);
}

}  // namespace arg
