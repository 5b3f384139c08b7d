// libFuzzer target: deserialize_arg on raw bytes, with and without the digest check.
//
// With the digest checked, what the reader accepts must serialise back unchanged. Without it (a
// stored value read back, serialize.hpp), node values are not checked and mutated bytes reach the
// structural checks directly; whatever passes them must be safe to match and give a finite
// search descriptor, and a ranking's row reader must agree with it (check_packed_reader).
#include "fuzz_support.hpp"
#include "gen/generate_models.hpp"
#include "graph/comparable.hpp"
#include "graph/serialize.hpp"
#include "match/similarity.hpp"
#include "pipeline/build_arg.hpp"
#include "search/search_descriptor.hpp"

namespace arg::fuzz {

inline const ArgGraph& binary_reference_graph() {
  static const ArgGraph graph = [] {
    BuildOptions options;
    options.levels = 3;
    options.base_points = 16;
    return build_arg(generate_model("fourleg", 1, 10, true).mesh, options);
  }();
  return graph;
}

// The same read back from its bytes, as a ranking's query is (its histograms byte codes).
inline const ArgGraph& binary_reference_value() {
  static const ArgGraph graph = stored_form(binary_reference_graph());
  return graph;
}

inline int fuzz_arg_binary(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes = as_bytes(data, size);
  try {
    const ArgGraph graph = deserialize_arg(bytes);
    ARG_FUZZ_CHECK(serialize_arg(graph) == bytes);
    ARG_FUZZ_CHECK(arg_from_text(arg_to_text(bytes)) == bytes);
  } catch (const Error&) {
  }
  try {
    const ArgGraph graph = deserialize_arg(bytes, /*check_digest=*/false);
    std::string resealed(bytes);
    reseal_arg_digest(resealed);
    ARG_FUZZ_CHECK(serialize_arg(graph) == resealed);
    exercise_matching(graph, binary_reference_graph());
    // The first stage's descriptor of a value read unchecked is finite: a cube, and an index on
    // it, never holds a NaN or an infinity.
    for (float x : search_descriptor(graph)) ARG_FUZZ_CHECK(std::isfinite(x));
    // Any value the reader accepts, of any format, gets a verdict and a reason that names it.
    ARG_FUZZ_CHECK(comparable(graph, binary_reference_graph()) ==
                   incomparable_reason(graph, binary_reference_graph()).empty());
    ARG_FUZZ_CHECK(!rebuild_needed(graph) || graph.format < kFormatVersion ||
                   graph.builder_version / 100 != current_builder_version() / 100);
  } catch (const Error&) {
  }
  check_packed_reader(bytes, binary_reference_value());
  return 0;
}

}  // namespace arg::fuzz

ARG_FUZZ_ENTRY(arg::fuzz::fuzz_arg_binary)
