// libFuzzer target: read_shape_sketch and the text form; accepted sketches round-trip.
#include <cmath>

#include "fuzz_support.hpp"
#include "search/shape_sketch.hpp"

namespace arg::fuzz {

inline int fuzz_sketch(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes = as_bytes(data, size);
  try {
    ShapeSketch s;
    read_shape_sketch(bytes, s);
    // Checked values are written back byte for byte (the codes are canonical).
    ARG_FUZZ_CHECK(write_shape_sketch(s) == bytes);
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
  return 0;
}

}  // namespace arg::fuzz

ARG_FUZZ_ENTRY(arg::fuzz::fuzz_sketch)
