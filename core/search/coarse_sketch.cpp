// A sketch's cheap stand-in, read straight from its bytes.
#include "search/coarse_sketch.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "graph/panorama_codes.hpp"
#include "graph/quantise.hpp"
#include "match/term_weights.hpp"

namespace arg {

namespace {

// The sketch's layout (search/shape_sketch.cpp): magic, version, parts, flags (and in version 2
// the digest), graph blocks, then the panorama's block scales and codes, then the spectrum.
// Offsets below are from the graph blocks' start less 8 (version 1's header).
constexpr std::size_t kHeader = 8, kGraphAt = kHeader;
constexpr std::size_t kPanoramaAt = kGraphAt + 4 * kSketchGraphDims;
constexpr std::size_t kCodesAt = kPanoramaAt + 4 * kPanoramaBlocks;
constexpr std::uint8_t kPartPanorama = 1, kPartSpectrum = 2, kPartColour = 4;
constexpr std::size_t kColourValues = 3 * kSearchColourBins;
constexpr std::size_t kBlocksPerFrame = 2 * kPanoramaViews;

float float_at(const unsigned char* p) {
  const std::uint32_t bits = std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 |
                             std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
  float x;
  std::memcpy(&x, &bits, 4);
  return x;
}

// ln(x) for x > 0 from its bits: the exponent, and log2(1 + m) ~ m (1.3466 - 0.3466 m) for the
// mantissa m (within 0.005 in log2 units): enough to order candidates, and no call into libm.
float fast_log(float x) {
  std::uint32_t bits;
  std::memcpy(&bits, &x, 4);
  const float e = float(int((bits >> 23) & 0xff) - 127);
  const float m = float(bits & 0x7fffff) * (1.0f / 8388608.0f);
  return (e + m * (1.3466f - 0.3466f * m)) * 0.69314718f;
}

// The offset of value (u, v) of view `view` of `frame` within the panorama.
std::size_t fourier_index(int frame, int view, int u, int v) {
  return std::size_t(frame) * kPanoramaPerFrame + std::size_t(view) * kPanoramaPerView +
         std::size_t(u) * (kPanoramaAxial + 1) + std::size_t(v);
}

}  // namespace

CoarseQuery coarse_query(const ShapeSketch& s) {
  CoarseQuery q;
  q.flags = s.flags;
  q.has_panorama = s.has_panorama, q.has_spectrum = s.has_spectrum, q.has_colour = s.has_colour;
  q.graph = s.graph;
  std::size_t k = 0;
  for (int frame = 0; frame < 2; ++frame)
    for (int view = 0; view < 6; ++view)
      for (int u = 0; u <= kCoarseAngular; ++u)
        for (int v = 0; v <= kCoarseAxial; ++v)
          q.panorama[k++] = s.panorama[fourier_index(frame, view, u, v)];
  for (std::size_t i = 0; i < q.log_spectrum.size(); ++i)
    q.log_spectrum[i] = s.has_spectrum ? fast_log(s.spectrum[i]) : 0.0f;
  return q;
}

double coarse_sketch_distance(const CoarseQuery& q, std::string_view bytes) {
  constexpr double kNever = std::numeric_limits<double>::infinity();
  const auto* b = reinterpret_cast<const unsigned char*>(bytes.data());
  if (bytes.size() < kHeader || std::memcmp(b, "ARGS", 4) != 0) return kNever;
  const std::size_t header = sketch_header_size(b[4]);
  if (header == 0 || bytes.size() < header - kHeader + kPanoramaAt) return kNever;
  const std::uint8_t parts = b[5];
  const std::uint16_t flags = std::uint16_t(b[6] | b[7] << 8);
  // The digest is not checked here: an entry near enough is read whole (read_shape_sketch)
  // before it counts.
  b += header - kHeader;
  bytes.remove_prefix(header - kHeader);
  const bool panorama = (parts & kPartPanorama) != 0, spectrum = (parts & kPartSpectrum) != 0;
  const std::size_t spectrum_at = panorama ? kCodesAt + kPanoramaSize : kPanoramaAt;
  if (bytes.size() != spectrum_at + (spectrum ? 4 * std::size_t(kSpectrumSize) : 0)) return kNever;
  const TermWeights t = term_weights(Weights{}, std::uint16_t(q.flags | flags),
                                     q.has_panorama && panorama, q.has_spectrum && spectrum);
  double pano = 0, spec = 0;
  if (t.panorama > 0) {
    const float* squares = code_squares().data();
    double best = 1.0;
    std::size_t k = 0;
    for (int frame = 0; frame < 2; ++frame) {
      double l1 = 0;
      for (int view = 0; view < 6; ++view) {
        const float scale = float_at(b + kPanoramaAt + 4 * (frame * kBlocksPerFrame + view));
        for (int u = 0; u <= kCoarseAngular; ++u)
          for (int v = 0; v <= kCoarseAxial; ++v)
            l1 +=
                std::fabs(double(q.panorama[k++]) -
                          double(scale * squares[b[kCodesAt + fourier_index(frame, view, u, v)]]));
      }
      best = std::min(best, l1 / 6);
    }
    pano = best;
  }
  if (t.spectrum > 0) {
    double sum = 0;
    for (int i = 0; i < kSpectrumSize; ++i) {
      const float x = float_at(b + spectrum_at + 4 * std::size_t(i));
      if (!(x > 0) || !std::isfinite(x)) return kNever;
      const double d = double(q.log_spectrum[std::size_t(i)]) - fast_log(x);
      sum += d * d;
    }
    spec = std::min(1.0, std::sqrt(sum) / 5);
  }
  const bool colour = q.has_colour && (parts & kPartColour) != 0;
  const std::size_t end = colour ? kSketchGraphDims : kSketchGraphDims - kColourValues;
  double l1 = 0;
  for (std::size_t k = 0; k < end; ++k)
    l1 += std::fabs(double(q.graph[k]) - double(float_at(b + kGraphAt + 4 * k)));
  const double d = mix_terms(t, kSketchGraphMix * l1, pano, spec);
  return std::isnan(d) ? kNever : d;
}

double coarse_distance(const CoarseQuery& a, const CoarseQuery& b) {
  const TermWeights t =
      term_weights(Weights{}, std::uint16_t(a.flags | b.flags), a.has_panorama && b.has_panorama,
                   a.has_spectrum && b.has_spectrum);
  double pano = 0, spec = 0;
  if (t.panorama > 0) {
    double best = 1.0;
    constexpr std::size_t kPerFrame = kCoarsePanorama / 2;
    for (std::size_t frame = 0; frame < 2; ++frame) {
      double l1 = 0;
      for (std::size_t k = frame * kPerFrame; k < (frame + 1) * kPerFrame; ++k)
        l1 += std::fabs(double(a.panorama[k]) - double(b.panorama[k]));
      best = std::min(best, l1 / 6);
    }
    pano = best;
  }
  if (t.spectrum > 0) {
    double sum = 0;
    for (std::size_t i = 0; i < a.log_spectrum.size(); ++i) {
      const double d = double(a.log_spectrum[i]) - double(b.log_spectrum[i]);
      sum += d * d;
    }
    spec = std::min(1.0, std::sqrt(sum) / 5);
  }
  const std::size_t end =
      a.has_colour && b.has_colour ? kSketchGraphDims : kSketchGraphDims - kColourValues;
  double l1 = 0;
  for (std::size_t k = 0; k < end; ++k) l1 += std::fabs(double(a.graph[k]) - double(b.graph[k]));
  return mix_terms(t, kSketchGraphMix * l1, pano, spec);
}

}  // namespace arg
