// Where the registered image decoder is kept.
#include "io/image_decoder.hpp"

#include <atomic>

namespace arg {

namespace {
std::atomic<ImageDecoder> registered{nullptr};
}  // namespace

void set_image_decoder(ImageDecoder decoder) {
  registered.store(decoder);
}

ImageDecoder image_decoder() {
  return registered.load();
}

}  // namespace arg
