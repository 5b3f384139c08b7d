// Shape sketches: made from a graph, written, read strictly, compared.
#include "search/shape_sketch.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "common/base64.hpp"
#include "common/byte_io.hpp"
#include "common/hash.hpp"
#include "features/laplace_spectrum.hpp"
#include "features/panorama_descriptor.hpp"
#include "graph/panorama_codes.hpp"
#include "match/term_weights.hpp"

namespace arg {

namespace {

constexpr const char* kTextTag = "sketch1:";
constexpr char kMagic[4] = {'A', 'R', 'G', 'S'};
constexpr std::uint8_t kPartPanorama = 1, kPartSpectrum = 2, kPartColour = 4;
// The graph blocks' colour values come last.
constexpr std::size_t kColourValues = 3 * kSearchColourBins;
static_assert(kSearchColourAt + 3 * kSearchColourBins == kSearchDims, "colour ends the descriptor");
constexpr std::uint16_t kKnownFlags = kFlagOpen | kFlagProxy | kFlagWideOpen | kFlagPooled;

// Where a version-2 sketch keeps its digest, and the digest of its other bytes.
constexpr std::size_t kDigestAt = 8, kDigestSize = 8;
std::uint64_t sketch_digest(std::string_view bytes) {
  return fnv1a_64(bytes.substr(kDigestAt + kDigestSize), fnv1a_64(bytes.substr(0, kDigestAt)));
}

bool in_graph_blocks(int k) {
  return k < kSearchPanoramaAt || k >= kSearchColourAt;
}

// Whether every value lies in [lo, hi] (NaN does not).
bool all_within(const std::vector<float>& v, float lo, float hi) {
  return std::all_of(v.begin(), v.end(), [&](float x) { return x >= lo && x <= hi; });
}

}  // namespace

ShapeSketch shape_sketch(const ArgGraph& g) {
  ShapeSketch s;
  s.flags = g.summary.flags & kKnownFlags;
  s.has_colour = g.summary.has_colour != 0;
  const std::array<float, kSearchDims> d = search_descriptor(g);
  // The descriptor's graph blocks are finite; a forged colour could still make one negative.
  for (int k = 0, j = 0; k < kSearchDims; ++k)
    if (in_graph_blocks(k)) s.graph[std::size_t(j++)] = std::max(0.0f, d[std::size_t(k)]);
  // Rankings read stored values without range checks (serialize.hpp): a part out of the range
  // the formats accept counts as missing, so that every sketch made here reads back.
  s.has_panorama = g.panorama.size() == s.panorama.size() && all_within(g.panorama, 0, 1.0001f);
  if (s.has_panorama) std::copy(g.panorama.begin(), g.panorama.end(), s.panorama.begin());
  s.has_spectrum = g.spectrum.size() == s.spectrum.size() && all_within(g.spectrum, 1e-6f, 1e3f);
  if (s.has_spectrum) std::copy(g.spectrum.begin(), g.spectrum.end(), s.spectrum.begin());
  return s;
}

std::string write_shape_sketch(const ShapeSketch& s) {
  ByteWriter out;
  out.put_bytes(std::string_view(kMagic, 4));
  out.put(kSketchVersion);
  out.put(std::uint8_t((s.has_panorama ? kPartPanorama : 0) | (s.has_spectrum ? kPartSpectrum : 0) |
                       (s.has_colour ? kPartColour : 0)));
  out.put(std::uint16_t(s.flags & kKnownFlags));
  out.put(std::uint64_t(0));  // the digest, once the rest is written
  for (float x : s.graph) out.put(x);
  if (s.has_panorama) write_panorama_codes(s.panorama.data(), out);
  if (s.has_spectrum)
    for (float x : s.spectrum) out.put(x);
  std::string bytes = std::move(out.bytes());
  reseal_sketch_digest(bytes);
  return bytes;
}

void read_shape_sketch(std::string_view bytes, ShapeSketch& s) {
  ByteReader in(bytes, "arg_sketch");
  if (in.get_bytes(4) != std::string_view(kMagic, 4)) in.fail("not a sketch (no ARGS magic)");
  const auto version = in.get<std::uint8_t>();
  if (sketch_header_size(version) == 0)
    in.fail("sketch version " + std::to_string(version) + ", this library reads versions 1 to " +
            std::to_string(kSketchVersion));
  const auto parts = in.get<std::uint8_t>();
  if (parts & ~(kPartPanorama | kPartSpectrum | kPartColour))
    in.fail("unknown parts in the sketch");
  s.flags = in.get<std::uint16_t>();
  if (s.flags & ~kKnownFlags) in.fail("unknown summary flags in the sketch");
  if (version >= 2 && in.get<std::uint64_t>() != sketch_digest(bytes))
    in.fail("digest mismatch (corrupted sketch)");
  for (float& x : s.graph) {
    x = in.get<float>();
    if (!std::isfinite(x) || x < 0) in.fail("graph block value negative or not finite");
  }
  s.has_colour = (parts & kPartColour) != 0;
  for (std::size_t k = s.graph.size() - kColourValues; k < s.graph.size() && !s.has_colour; ++k)
    if (s.graph[k] != 0) in.fail("colour values in a sketch without colour");
  s.has_panorama = (parts & kPartPanorama) != 0;
  if (s.has_panorama) read_panorama_codes(in, s.panorama.data());
  s.has_spectrum = (parts & kPartSpectrum) != 0;
  if (s.has_spectrum) {
    for (float& x : s.spectrum) {
      x = in.get<float>();
      // The range format 3 accepts (serialize.cpp), so a sketch's eigenvalues are a value's.
      if (!std::isfinite(x) || x < 1e-6f || x > 1e3f) in.fail("eigenvalue out of range");
    }
  }
  if (in.remaining() != 0)
    in.fail(std::to_string(in.remaining()) + " bytes after the end of the sketch");
}

void validate_sketch_bytes(std::string_view bytes) {
  ShapeSketch check;
  read_shape_sketch(bytes, check);
}

void reseal_sketch_digest(std::string& bytes) {
  if (bytes.size() < kDigestAt + kDigestSize || bytes[4] != 2)
    throw InputError("arg_sketch: not a version-2 sketch header");
  ByteWriter digest;
  digest.put(sketch_digest(bytes));
  bytes.replace(kDigestAt, kDigestSize, digest.bytes());
}

std::string sketch_to_text(std::string_view bytes) {
  return kTextTag + base64_encode(bytes);
}

std::string sketch_from_text(std::string_view text) {
  if (text.substr(0, std::strlen(kTextTag)) != kTextTag)
    throw InputError("arg_sketch: text form must start with \"" + std::string(kTextTag) + "\"");
  std::string bytes = base64_decode(text.substr(std::strlen(kTextTag)));
  validate_sketch_bytes(bytes);
  return bytes;
}

double sketch_distance(const ShapeSketch& a, const ShapeSketch& b, const Weights& w,
                       double graph_mix) {
  const TermWeights t = term_weights(w, a.flags | b.flags, a.has_panorama && b.has_panorama,
                                     a.has_spectrum && b.has_spectrum);
  double panorama = 0, spectrum = 0;
  if (t.panorama > 0) panorama = panorama_distance(a.panorama.data(), b.panorama.data());
  if (t.spectrum > 0)
    spectrum = spectrum_distance(a.spectrum.data(), b.spectrum.data(), a.spectrum.size());
  // Colour weighs nothing in SIM unless both models have it (similarity_terms.hpp).
  const std::size_t end =
      a.has_colour && b.has_colour ? a.graph.size() : a.graph.size() - kColourValues;
  double l1 = 0;
  for (std::size_t k = 0; k < end; ++k) l1 += std::fabs(double(a.graph[k]) - b.graph[k]);
  return mix_terms(t, graph_mix * l1, panorama, spectrum);
}

}  // namespace arg
