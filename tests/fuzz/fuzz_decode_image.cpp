// libFuzzer target: decode_image (PNG, JPEG, TGA, BMP through OpenImageIO) with a small pixel cap.
#include "fuzz_support.hpp"
#include "io/image.hpp"

namespace arg::fuzz {

inline int fuzz_decode_image(const std::uint8_t* data, std::size_t size) {
  Limits limits = reader_limits();
  limits.max_image_pixels = 1'000'000;
  try {
    const Image image = decode_image(as_bytes(data, size), limits);
    ARG_FUZZ_CHECK(image.width > 0 && image.height > 0);
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    ARG_FUZZ_CHECK(pixels <= limits.max_image_pixels);
    ARG_FUZZ_CHECK(image.rgb.size() == 3 * pixels);
  } catch (const Error&) {
  }
  return 0;
}

}  // namespace arg::fuzz

ARG_FUZZ_ENTRY(arg::fuzz::fuzz_decode_image)
