// The panorama's byte codec, shared by format 3 (serialize.cpp) and search sketches.
#include "graph/panorama_codes.hpp"

#include <cmath>
#include <cstdint>
#include <string>

#include "graph/quantise.hpp"

namespace arg {

namespace {

constexpr std::size_t kWaveletPerView = kPanoramaWavelet / kPanoramaViews;
static_assert(kPanoramaFourier == kPanoramaViews * kPanoramaPerView &&
              kPanoramaWavelet % kPanoramaViews == 0);

// Calls f(offset, count) on each block of the panorama, in order.
template <class F>
void for_each_panorama_block(F&& f) {
  for (std::size_t frame = 0; frame < 2; ++frame) {
    const std::size_t begin = frame * kPanoramaPerFrame;
    for (std::size_t v = 0; v < kPanoramaViews; ++v)
      f(begin + v * kPanoramaPerView, kPanoramaPerView);
    for (std::size_t v = 0; v < kPanoramaViews; ++v)
      f(begin + kPanoramaFourier + v * kWaveletPerView, kWaveletPerView);
  }
}

}  // namespace

void write_panorama_codes(const float* panorama, ByteWriter& out) {
  std::string codes(kPanoramaSize, '\0');
  for_each_panorama_block([&](std::size_t at, std::size_t count) {
    out.put(quantise_sqrt_block(panorama + at, count, reinterpret_cast<std::uint8_t*>(&codes[at])));
  });
  out.put_bytes(codes);
}

void read_panorama_codes(ByteReader& in, float* panorama) {
  float scale[kPanoramaBlocks];
  for (float& x : scale) {
    x = in.get<float>();
    if (!std::isfinite(x) || x < 0 || x > 1.0001f) in.fail("panorama scale out of range");
  }
  const auto* q = reinterpret_cast<const std::uint8_t*>(in.get_bytes(kPanoramaSize).data());
  std::size_t b = 0;
  for_each_panorama_block([&](std::size_t at, std::size_t count) {
    if (!canonical_sqrt_block(q + at, count, scale[b]))
      in.fail("panorama block " + std::to_string(b) + "'s codes do not match its scale");
    sqrt_block_values(q + at, count, scale[b++], panorama + at);
  });
}

}  // namespace arg
