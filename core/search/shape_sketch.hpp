// A search's second stage: SIM's whole-shape terms and the graph blocks, small enough per row.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "graph/arg_graph.hpp"
#include "graph/whole_shape_layout.hpp"
#include "match/weights.hpp"
#include "search/search_descriptor.hpp"

namespace arg {

// The search descriptor's blocks that stand for the graph (curvature, node counts, largest
// areas, colour): the sketch's stand-in for SIM's graph term.
inline constexpr int kSketchGraphDims = kSearchDims - (kSearchColourAt - kSearchPanoramaAt);

// What SIM reads besides the nodes: the panorama and the spectrum exactly as the value holds
// them (a format-3 value's panorama to the bit; a format-2 value's is coded as format 3 codes
// it), the summary flags and whether the value has colour, which decide which terms count, and
// the graph blocks. About 2.6 kB, against 10-20 kB for a whole value: a query reads thousands of
// candidates' sketches in tens of milliseconds, so SIM ranks only the few hundred nearest.
// Plain data (no allocation, trivially copyable): the extension keeps a query's in a
// function's cache and reads each row's into one it reuses.
struct ShapeSketch {
  std::uint16_t flags = 0;  // the value's summary flags (kFlagProxy, kFlagWideOpen, ...)
  bool has_panorama = false, has_spectrum = false, has_colour = false;
  std::array<float, kSketchGraphDims> graph{};
  std::array<float, kPanoramaSize> panorama{};
  std::array<float, kSpectrumSize> spectrum{};
};

// The sketch of a graph (the graph blocks with default weights, as arg_global's). A panorama or
// spectrum with a value out of the range the formats accept (an unchecked stored value) is
// left out, so the sketch always reads back.
ShapeSketch shape_sketch(const ArgGraph& graph);

// Bytes: "ARGS", the version (2), a byte of parts (1 panorama, 2 spectrum, 4 colour), the flags
// (uint16), a digest (uint64: FNV-1a over every other byte, so a changed byte is refused), the
// graph blocks (float32, finite, >= 0; colour's zero without colour), the panorama's codes
// (graph/panorama_codes.hpp), the spectrum (float32 in [1e-6, 1e3]); little-endian, nothing
// after. Version 1 (arg 0.2.0's stored sketch columns) is the same without the digest: still
// read, never written.
inline constexpr std::uint8_t kSketchVersion = 2;
// Bytes before the graph blocks in a sketch of `version` (0 for a version not read here).
inline constexpr std::size_t sketch_header_size(std::uint8_t version) {
  return version == 1 ? 8 : version == 2 ? 16 : 0;
}
std::string write_shape_sketch(const ShapeSketch& sketch);
// Strict: every byte checked (InputError naming what is wrong and where; a version-2 sketch's
// digest first); allocates nothing unless it fails.
void read_shape_sketch(std::string_view bytes, ShapeSketch& out);
// read_shape_sketch's checks alone (input of the text and binary forms, what arg_sketch made).
void validate_sketch_bytes(std::string_view bytes);
// Recomputes a version-2 sketch's digest in place, so that bytes changed on purpose pass the
// digest check and reach the others. For tests and fuzzing only; throws InputError when the
// bytes are not a version-2 sketch's header at least.
void reseal_sketch_digest(std::string& bytes);

// Text form: "sketch1:" then the bytes in padded base64; the reader accepts exactly that and
// checks the bytes as read_shape_sketch does, returning them.
std::string sketch_to_text(std::string_view bytes);
std::string sketch_from_text(std::string_view text);

// How much the graph blocks' taxicab distance counts for SIM's graph term. Chosen by recall of
// SIM's ten nearest among the sketch's nearest (tests/scale/descriptor_study.sh): 0.05 on a
// generated catalogue of 20,000 models, 0.1 on the three labelled sets, which lose at most
// .006 with 0.05 (docs/BENCHMARKS.md "Second stage").
inline constexpr double kSketchGraphMix = 0.05;

// SIM with its graph term replaced by kSketchGraphMix x the graph blocks' taxicab distance: the
// same weights, the same rules for proxies, wide-open surfaces, colour and missing terms, the
// panorama's and the spectrum's distances exactly SIM's.
// `graph_mix` other than kSketchGraphMix: for the study that chose it.
double sketch_distance(const ShapeSketch& a, const ShapeSketch& b, const Weights& weights = {},
                       double graph_mix = kSketchGraphMix);

}  // namespace arg
