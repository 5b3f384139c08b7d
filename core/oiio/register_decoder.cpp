// Programs that link this object (argtool, tests, benchmarks) decode images with OpenImageIO.
#include "io/image_decoder.hpp"
#include "oiio/oiio_image.hpp"

namespace {
// The core's decoder slot is a constant-initialised atomic, so this may run in any order.
const bool registered = (arg::set_image_decoder(&arg::oiio_decode_image), true);
}  // namespace
