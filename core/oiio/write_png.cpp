// PNG output through OpenImageIO's ImageOutput, the library the project already reads images with.
#include "oiio/write_png.hpp"

#include <OpenImageIO/imageio.h>

#include "common/errors.hpp"
#include "oiio/oiio_image.hpp"

namespace arg {

void write_png(const Image& image, const std::string& path) {
  if (image.empty() || image.rgb.size() != std::size_t(image.width) * std::size_t(image.height) * 3)
    throw InputError("png: " + path + ": empty or malformed picture");
  auto out = OIIO::ImageOutput::create("png");
  if (!out) throw InputError("png: no OpenImageIO PNG writer: " + OIIO::geterror());
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
  spec.attribute("compression", "zip:9");  // smaller files; the docs keep them in git
  if (!out->open(path, spec))
    throw InputError("png: cannot write " + path + ": " + out->geterror());
  if (!out->write_image(OIIO::TypeDesc::UINT8, image.rgb.data()) || !out->close())
    throw InputError("png: cannot write " + path + ": " + out->geterror());
}

}  // namespace arg

extern "C" ARG_IMAGE_EXPORT void* arg_oiio_png_writer() {
  return reinterpret_cast<void*>(&arg::write_png);
}
