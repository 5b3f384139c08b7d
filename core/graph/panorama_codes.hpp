// The panorama in bytes: a float scale per block, then one sqrt code per value (format 3,
// sketches).
#pragma once

#include <cstddef>

#include "common/byte_io.hpp"
#include "graph/whole_shape_layout.hpp"

namespace arg {

// Blocks: per frame, each view's Fourier features, then each view's wavelet features; each
// block has its own scale, so a view's small spectrum keeps its precision beside a large one.
inline constexpr std::size_t kPanoramaViews = 6, kPanoramaBlocks = 2 * 2 * kPanoramaViews;
inline constexpr std::size_t kPanoramaCodesSize = 4 * kPanoramaBlocks + kPanoramaSize;

// Writes kPanoramaCodesSize bytes for kPanoramaSize values. Values decoded from codes are
// written back to the same bytes (quantise.hpp), so a format-3 value's panorama and its
// sketch's are the same floats.
void write_panorama_codes(const float* panorama, ByteWriter& out);

// Reads kPanoramaCodesSize bytes into kPanoramaSize values; fails through `in` (InputError)
// on a scale that is not finite or not in [0, 1], or codes the writer would not make.
void read_panorama_codes(ByteReader& in, float* panorama);

}  // namespace arg
