// libFuzzer target: build_arg_bytes on small meshes of any format, checking the ARG it returns.
#include "fuzz_support.hpp"
#include "gen/generate_models.hpp"
#include "graph/serialize.hpp"
#include "match/similarity.hpp"
#include "pipeline/build_arg.hpp"

namespace arg::fuzz {

inline const ArgGraph& reference_graph() {
  static const ArgGraph graph = [] {
    BuildOptions options;
    options.levels = 4;
    options.base_points = 16;
    return build_arg(generate_model("human", 0, 10, true).mesh, options);
  }();
  return graph;
}

inline int fuzz_build(const std::uint8_t* data, std::size_t size) {
  Limits limits;
  limits.max_input_bytes = std::size_t(1) << 20;
  limits.max_vertices = 5'000;
  limits.max_triangles = 5'000;
  limits.max_image_pixels = 65'536;
  // The options follow from the size, so that the fuzzer meets every kind of mu and a few levels
  // without spending input bytes on them (which would hide the format from detection).
  BuildOptions options;
  options.mu = MuKind(size % 3);
  options.levels = 3 + int(size / 3 % 3);
  options.base_points = 16;
  try {
    const std::string bytes = build_arg_bytes(as_bytes(data, size), {}, options, limits);
    const ArgGraph graph = deserialize_arg(bytes);
    ARG_FUZZ_CHECK(serialize_arg(graph) == bytes);
    ARG_FUZZ_CHECK(graph.levels() == options.levels && graph.options.mu == options.mu);
    const double forth = arg_similarity(graph, reference_graph());
    ARG_FUZZ_CHECK(forth >= 0.0 && forth <= 1.0);
    ARG_FUZZ_CHECK(forth == arg_similarity(reference_graph(), graph));
    ARG_FUZZ_CHECK(arg_similarity(graph, graph) == 0.0);
  } catch (const Error&) {
  }
  return 0;
}

}  // namespace arg::fuzz

ARG_FUZZ_ENTRY(arg::fuzz::fuzz_build)
