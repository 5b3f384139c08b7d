// libFuzzer target: read_shape_sketch and the text form; accepted sketches round-trip.
#include <cmath>

#include "fuzz_support.hpp"
#include "search/shape_sketch.hpp"

namespace arg::fuzz {

// The bytes as given, then (for a version-2 header) with their digest sealed again, so that
// mutations reach the checks after the digest's.
inline void fuzz_sketch_bytes(std::string_view bytes) {
  try {
    ShapeSketch s;
    read_shape_sketch(bytes, s);
    // Checked values are written back byte for byte (the codes are canonical); a version-1
    // sketch is written as version 2 and reads back the same.
    const std::string written = write_shape_sketch(s);
    if (bytes[4] == char(kSketchVersion)) ARG_FUZZ_CHECK(written == bytes);
    ShapeSketch again;
    read_shape_sketch(written, again);
    ARG_FUZZ_CHECK(write_shape_sketch(again) == written);
    ARG_FUZZ_CHECK(sketch_from_text(sketch_to_text(bytes)) == bytes);
    // Against itself 0; against a sketch without parts and under every preset, finite, >= 0 and
    // symmetric.
    ARG_FUZZ_CHECK(sketch_distance(s, s) == 0.0);
    ShapeSketch bare;
    for (const char* preset : {"arg", "mrg", "graph", "shape", "colour"}) {
      const Weights w = parse_weights(preset);
      const double d = sketch_distance(s, bare, w);
      ARG_FUZZ_CHECK(std::isfinite(d) && d >= 0);
      ARG_FUZZ_CHECK(d == sketch_distance(bare, s, w));
    }
  } catch (const Error&) {
  }
}

inline int fuzz_sketch(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes = as_bytes(data, size);
  fuzz_sketch_bytes(bytes);
  if (size >= 16 && bytes[4] == 2) {
    std::string sealed(bytes);
    reseal_sketch_digest(sealed);
    fuzz_sketch_bytes(sealed);
  }
  return 0;
}

}  // namespace arg::fuzz

ARG_FUZZ_ENTRY(arg::fuzz::fuzz_sketch)
