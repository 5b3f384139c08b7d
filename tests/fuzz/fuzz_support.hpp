// Helpers shared by the libFuzzer targets and their regression test: limits, invariants, errors.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>

#include "common/errors.hpp"
#include "common/limits.hpp"
#include "graph/serialize.hpp"
#include "io/read_mesh.hpp"
#include "match/match_prep.hpp"
#include "match/packed_graph.hpp"
#include "match/similarity.hpp"
#include "match/weights.hpp"
#include "mesh/mesh.hpp"

namespace arg::fuzz {

// A broken invariant: deliberately not an arg::Error, so nothing treats it as an expected outcome
// (libFuzzer reports the uncaught exception as a crash; the regression test as a failure).
class InvariantViolation : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

#define ARG_FUZZ_CHECK(condition)                                                        \
  do {                                                                                   \
    if (!(condition))                                                                    \
      throw ::arg::fuzz::InvariantViolation(std::string(__FILE__) + ":" +                \
                                            std::to_string(__LINE__) + ": " #condition); \
  } while (0)

inline std::string_view as_bytes(const std::uint8_t* data, std::size_t size) {
  return std::string_view(reinterpret_cast<const char*>(data), size);
}

// Small caps so that every run is fast and no input can ask for much memory.
inline Limits reader_limits() {
  Limits limits;
  limits.max_input_bytes = std::size_t(4) << 20;
  limits.max_vertices = 200'000;
  limits.max_triangles = 200'000;
  limits.max_image_pixels = 1'000'000;
  return limits;
}

// What every mesh read_mesh returns must satisfy, whatever the input was.
inline void check_mesh(const Mesh& mesh, const ReadReport& report, const Limits& limits) {
  ARG_FUZZ_CHECK(mesh.F.rows() > 0);
  ARG_FUZZ_CHECK(std::size_t(mesh.V.rows()) <= limits.max_vertices);
  ARG_FUZZ_CHECK(std::size_t(mesh.F.rows()) <= limits.max_triangles);
  ARG_FUZZ_CHECK(report.triangles == std::size_t(mesh.F.rows()));
  ARG_FUZZ_CHECK(mesh.C.rows() == 0 || mesh.C.rows() == mesh.F.rows());
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    for (int c = 0; c < 3; ++c) ARG_FUZZ_CHECK(std::isfinite(mesh.V(v, c)));
  for (Eigen::Index t = 0; t < mesh.F.rows(); ++t)
    for (int c = 0; c < 3; ++c) ARG_FUZZ_CHECK(mesh.F(t, c) >= 0 && mesh.F(t, c) < mesh.V.rows());
  for (Eigen::Index t = 0; t < mesh.C.rows(); ++t)
    for (int c = 0; c < 3; ++c) ARG_FUZZ_CHECK(mesh.C(t, c) >= 0.0f && mesh.C(t, c) <= 1.0f);
}

// A 2x2 uncompressed true-colour TGA, passed as the separate texture so that meshes with texture
// coordinates (OBJ, PLY) go through texture sampling too.
inline std::string_view tiny_texture() {
  static const unsigned char tga[] = {0, 0,  2, 0,   0, 0, 0, 0,   0, 0, 0, 0,   2,   0,   2,
                                      0, 24, 0, 255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
  return std::string_view(reinterpret_cast<const char*>(tga), sizeof tga);
}

// read_mesh with the format forced, so that the fuzzer explores that reader whatever the bytes
// look like; any arg::Error is an expected outcome.
inline int fuzz_read_mesh_as(MeshFormat format, const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes = as_bytes(data, size);
  (void)detect_mesh_format(bytes);  // never throws
  ReadOptions options;
  options.limits = reader_limits();
  options.format = format;
  options.texture = tiny_texture();
  try {
    ReadReport report;
    const Mesh mesh = read_mesh(bytes, options, &report);
    ARG_FUZZ_CHECK(report.format == format);
    check_mesh(mesh, report, options.limits);
  } catch (const Error&) {
  }
  return 0;
}

// Matches a graph that came from hostile bytes against a valid one, both ways, with itself and
// by parts. Its values may be anything (NaN included): only memory safety and defined behaviour
// are promised, so the results are not checked.
inline void exercise_matching(const ArgGraph& graph, const ArgGraph& other) {
  (void)arg_similarity(graph, other);
  (void)arg_similarity(other, graph);
  (void)arg_similarity(graph, graph);
  (void)part_match(graph, graph.levels(), 0, other);
}

// A ranking's row reader (match/packed_graph.hpp) refuses what the full reader without the
// digest refuses, with the same message, and what it reads compares with `query` (a value read
// from bytes, so it has sim keys; another model, so that the heads differ) exactly as the
// decoded graph does, under weights with and without Tung's rule and with other mixes.
inline void check_packed_reader(std::string_view bytes, const ArgGraph& query) {
  std::string full_error, packed_error;
  ArgGraph decoded;
  try {
    deserialize_arg_into(bytes, decoded, /*check_digest=*/false);
  } catch (const Error& e) {
    full_error = e.what();
  }
  for (const char* preset : {"arg", "graph", "shape"}) {
    const Weights w = weights_preset(preset);
    PackedGraph row;
    bool packed = false;
    packed_error.clear();
    try {
      packed = read_packed_graph(bytes, w, row);
    } catch (const Error& e) {
      packed_error = e.what();
    }
    if (!packed_error.empty()) ARG_FUZZ_CHECK(packed_error == full_error);
    if (!packed) return;  // a format other than 3, or colour: only its header was read
    ARG_FUZZ_CHECK(full_error.empty());
    MatchPrep prep;
    prepare_match(query, w, prep);
    double sim = -1;
    if (packed_similarity(query, &prep, row, w, sim)) {
      const double whole = arg_similarity(query, decoded, w, nullptr, &prep, nullptr);
      ARG_FUZZ_CHECK(std::memcmp(&sim, &whole, sizeof sim) == 0);
    }
  }
}

}  // namespace arg::fuzz

// Each target defines its body as a function and, unless the regression test includes it,
// the libFuzzer entry point calling it.
#ifdef ARG_FUZZ_NO_MAIN
#define ARG_FUZZ_ENTRY(function)
#else
#define ARG_FUZZ_ENTRY(function)                                                      \
  extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) { \
    return function(data, size);                                                      \
  }
#endif
