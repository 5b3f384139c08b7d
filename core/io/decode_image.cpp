// Decoding texture image bytes: size cap and layout checks, then the loaded decoder.
#include <cstdint>
#include <string>

#include "common/errors.hpp"
#include "io/image.hpp"
#include "io/image_decoder.hpp"
#include "io/image_format_checks.hpp"

namespace arg {

Image decode_image(std::string_view bytes, const Limits& limits) {
  if (bytes.size() > limits.max_input_bytes) {
    throw LimitError("image: " + std::to_string(bytes.size()) + " bytes, more than " +
                     std::to_string(limits.max_input_bytes));
  }
  const char* format = sniff_image_format(bytes);
  if (!format) throw InputError("image: not a PNG, JPEG, TGA or BMP image");
  check_image_layout(bytes, format);
  if (std::string_view(format) == "jpeg") {
    const JpegFrameSize size = jpeg_frame_size(bytes);
    if (std::uint64_t(size.width) * size.height > limits.max_image_pixels) {
      throw LimitError("image: " + std::to_string(size.width) + "x" + std::to_string(size.height) +
                       " pixels, more than " + std::to_string(limits.max_image_pixels));
    }
  }
  const ImageDecoder decoder = image_decoder();
  if (!decoder) throw Error("image: no image decoder is loaded (see io/image_decoder.hpp)");
  return decoder(bytes, format, limits);
}

}  // namespace arg
