// The codecs of format 3: how each float of an ARG is stored in one or two bytes, and back.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace arg {

// Every codec is exact on its own output: quantising a decoded value gives back the same code,
// so a value read and written again keeps its bytes (test_quantise.cpp checks every code).
// The decoders are defined here, inline: they run on every node of every row a query ranks
// (docs/BENCHMARKS.md, "ARG values", has what each choice below saved).

// [0, 1] in 65,535 steps (areas, lengths, volumes): 1.5e-5, far below what SIM resolves.
std::uint16_t quantise_unit16(float x);
// float(q / 65535.0), multiplied rather than divided (three a node on every row of a ranking):
// the same float for every code, which test_quantise.cpp checks code by code.
inline float unit16_value(std::uint16_t q) {
  return float(q * (1.0 / 65535.0));
}

// [lo, hi] in 255 steps, clamped (angles, the barycentre's radius, a node's mu range).
std::uint8_t quantise_byte(float x, float lo, float hi);
inline float byte_value(std::uint8_t q, float lo, float hi) {
  return float(lo + (double(hi) - lo) * (q / 255.0));
}

// A histogram whose bins sum to `total` (a node's area): each bin as a fraction of the total
// in 255 steps, so small nodes keep their shape, the codes summing to 255 (largest
// remainders) so the bins read back sum to the total again. At most 64 bins; a total of 0
// stores zeros.
void quantise_bins(const float* bins, std::size_t count, float total, std::uint8_t* out);
// A code's worth of a histogram of `total`: bin k is float(code k) * code_step(total), in every
// reader (graph/compact_nodes.cpp, match/sim_key.hpp), so that their bins agree to the bit.
inline float code_step(float total) {
  return total / 255.0f;
}
inline void bins_values(const std::uint8_t* q, std::size_t count, float total, float* out) {
  const float step = code_step(total);  // one multiplication a bin
  for (std::size_t k = 0; k < count; ++k) out[k] = float(q[k]) * step;
}

// A block of non-negative values with a heavy tail (the panorama's spectra): the square root
// of each value over the block's largest, in 255 steps; small values keep their precision
// relative to the others. Returns the block's scale (its largest value), which the reader
// needs back; a block whose largest value is below kMinBlockScale is stored as zeros, scale 0.
inline constexpr float kMinBlockScale = 1e-6f;
float quantise_sqrt_block(const float* x, std::size_t count, std::uint8_t* out);
// (k / 255)^2 for every code k.
const std::array<float, 256>& code_squares();
inline void sqrt_block_values(const std::uint8_t* q, std::size_t count, float scale, float* out) {
  const float* squares = code_squares().data();
  std::size_t k = 0;
  for (; k + 4 <= count; k += 4) {  // four at a time: fewer loop counts for the same work
    const float x0 = squares[q[k]], x1 = squares[q[k + 1]], x2 = squares[q[k + 2]],
                x3 = squares[q[k + 3]];
    out[k] = scale * x0, out[k + 1] = scale * x1, out[k + 2] = scale * x2, out[k + 3] = scale * x3;
  }
  for (; k < count; ++k) out[k] = scale * squares[q[k]];
}

// Whether codes are those the writer makes, so that a value read is written back byte for
// byte: a histogram's codes sum to at most 255, and to 0 when its total's code is 0; a block's
// largest code is 255 under a scale in [kMinBlockScale, ...), and every code is 0 under scale 0.
inline bool canonical_bins(const std::uint8_t* q, std::size_t count, std::uint16_t total_code) {
  unsigned sum = 0;
  for (std::size_t k = 0; k < count; ++k) sum += q[k];
  return total_code == 0 ? sum == 0 : sum <= 255;
}
// canonical_bins of three histograms of eight codes side by side (a node record's cords and
// curvatures), under one total: read on every node of every row a ranking reads. SSE2's
// psadbw sums eight bytes at once.
inline bool canonical_bins_3x8(const std::uint8_t* q, std::uint16_t total_code) {
#if defined(__SSE2__)
  const __m128i zero = _mm_setzero_si128();
  const __m128i first = _mm_sad_epu8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(q)), zero);
  const __m128i third =
      _mm_sad_epu8(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(q + 16)), zero);
  const unsigned s0 = unsigned(_mm_cvtsi128_si32(first)),
                 s1 = unsigned(_mm_extract_epi16(first, 4)),
                 s2 = unsigned(_mm_cvtsi128_si32(third));
  return total_code == 0 ? (s0 | s1 | s2) == 0 : (s0 <= 255) & (s1 <= 255) & (s2 <= 255);
#else
  return canonical_bins(q, 8, total_code) && canonical_bins(q + 8, 8, total_code) &&
         canonical_bins(q + 16, 8, total_code);
#endif
}
inline bool canonical_sqrt_block(const std::uint8_t* q, std::size_t count, float scale) {
  // memchr is vectorised; a panorama is read on every row ranked.
  if (scale != 0) return scale >= kMinBlockScale && std::memchr(q, 255, count) != nullptr;
  for (std::size_t k = 0; k < count; ++k)
    if (q[k] != 0) return false;
  return true;
}

}  // namespace arg
