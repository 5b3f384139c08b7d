// Decoding texture images from memory with OpenImageIO, without touching the file system.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <string>

#include "common/errors.hpp"
#include "oiio/oiio_image.hpp"

namespace arg {

namespace {

[[noreturn]] void fail(const std::string& what) {
  throw InputError("image: " + what);
}

}  // namespace

Image oiio_decode_image(std::string_view bytes, const char* format, const Limits& limits) {
  auto input = OIIO::ImageInput::create(format);
  if (!input) fail(std::string("no OpenImageIO reader for ") + format + ": " + OIIO::geterror());
  // Without I/O proxy support OpenImageIO would open the "file name" below from disk.
  if (!input->supports("ioproxy"))
    fail(std::string("the ") + format + " reader cannot read memory");
  OIIO::Filesystem::IOMemReader proxy(bytes.data(), bytes.size());
  input->set_ioproxy(&proxy);
  input->threads(1);
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);  // keep colour as stored under transparency
  void* proxy_pointer = &proxy;
  config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy_pointer);
  OIIO::ImageSpec spec;
  if (!input->open(std::string("/nonexistent/in-memory.") + format, spec, config)) {
    fail(std::string(format) + ": " + input->geterror());
  }
  if (spec.width <= 0 || spec.height <= 0 || spec.depth != 1 || spec.nchannels <= 0) {
    fail(std::string(format) + ": unsupported image dimensions");
  }
  const std::uint64_t pixels = std::uint64_t(spec.width) * std::uint64_t(spec.height);
  if (pixels > limits.max_image_pixels) {
    throw LimitError("image: " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                     " pixels, more than " + std::to_string(limits.max_image_pixels));
  }
  const int channels = spec.nchannels >= 3 ? 3 : 1;
  std::vector<std::uint8_t> pixels_read(pixels * std::size_t(channels));
  if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, pixels_read.data())) {
    fail(std::string(format) + ": " + input->geterror());
  }
  input->close();
  Image image;
  image.width = spec.width;
  image.height = spec.height;
  if (channels == 3) {
    image.rgb = std::move(pixels_read);
  } else {
    image.rgb.resize(3 * pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
      image.rgb[3 * i] = image.rgb[3 * i + 1] = image.rgb[3 * i + 2] = pixels_read[i];
    }
  }
  return image;
}

}  // namespace arg

extern "C" ARG_IMAGE_EXPORT void* arg_oiio_image_decoder() {
  return reinterpret_cast<void*>(&arg::oiio_decode_image);
}
