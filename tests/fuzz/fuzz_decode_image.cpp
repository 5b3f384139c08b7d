// libFuzzer target: decode_image (PNG, JPEG, TGA, BMP through OpenImageIO) with a small pixel cap.
#include <zlib.h>

#include <string>

#include "fuzz_support.hpp"
#include "io/image.hpp"

namespace arg::fuzz {

// The input with every PNG chunk's CRC made right: decode_image refuses a wrong CRC before
// libpng runs, so without this almost no mutation of a chunk's contents would reach libpng.
inline std::string with_png_crcs_fixed(std::string png) {
  const auto u8 = [&](std::size_t i) { return std::uint32_t(static_cast<unsigned char>(png[i])); };
  for (std::size_t at = 8; png.size() - at >= 12;) {
    const std::uint32_t length = u8(at) << 24 | u8(at + 1) << 16 | u8(at + 2) << 8 | u8(at + 3);
    if (length > png.size() - at - 12) break;
    const auto* type = reinterpret_cast<const Bytef*>(png.data() + at + 4);
    const uLong crc = crc32(crc32(0L, Z_NULL, 0), type, uInt(4 + length));
    for (int k = 0; k < 4; ++k) png[at + 8 + length + std::size_t(k)] = char(crc >> (24 - 8 * k));
    at += 12 + std::size_t(length);
  }
  return png;
}

inline void decode_and_check(std::string_view bytes) {
  Limits limits = reader_limits();
  limits.max_image_pixels = 1'000'000;
  try {
    const Image image = decode_image(bytes, limits);
    ARG_FUZZ_CHECK(image.width > 0 && image.height > 0);
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    ARG_FUZZ_CHECK(pixels <= limits.max_image_pixels);
    ARG_FUZZ_CHECK(image.rgb.size() == 3 * pixels);
  } catch (const Error&) {
  }
}

inline int fuzz_decode_image(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes = as_bytes(data, size);
  decode_and_check(bytes);
  if (bytes.substr(0, 8) == "\x89PNG\r\n\x1a\n")
    decode_and_check(with_png_crcs_fixed(std::string(bytes)));
  return 0;
}

}  // namespace arg::fuzz

ARG_FUZZ_ENTRY(arg::fuzz::fuzz_decode_image)
