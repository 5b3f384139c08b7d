// arg_build: mesh bytes (OFF, OBJ, PLY, STL, GLB; detected) and an optional texture to an ARG.
#include "build/build_arg.hpp"

#include "arg_bridge.hpp"
#include "arg_guc.hpp"
#include "arg_image.hpp"

namespace {

Datum build(const varlena* mesh, const varlena* texture, const varlena* options) {
  const arg::Limits limits = argpg::current_limits();
  const int max_threads = argpg::max_build_threads();
  varlena* result = nullptr;
  argpg::prepare_image_decoder(argpg::view(mesh),
                               texture ? argpg::view(texture) : std::string_view());
  argpg::Outcome out = argpg::guarded([&] {
    arg::BuildOptions parsed = arg::parse_build_options(argpg::view(options));
    if (parsed.threads > max_threads) parsed.threads = max_threads;  // never changes the result
    const std::string_view image = texture ? argpg::view(texture) : std::string_view();
    result = argpg::to_varlena(
        arg::build_arg_bytes(argpg::view(mesh), image, parsed, limits, argpg::stop_requested));
  });
  argpg::raise_if_failed(out, ERRCODE_INVALID_PARAMETER_VALUE, "cannot build ARG");
  PG_RETURN_POINTER(result);
}

}  // namespace

extern "C" {

PG_FUNCTION_INFO_V1(arg_build_mesh);
PG_FUNCTION_INFO_V1(arg_build_textured);

// arg_build(mesh bytea, options text DEFAULT '')
Datum arg_build_mesh(PG_FUNCTION_ARGS) {
  return build(PG_GETARG_BYTEA_PP(0), nullptr, PG_GETARG_TEXT_PP(1));
}

// arg_build(mesh bytea, texture bytea, options text DEFAULT '')
Datum arg_build_textured(PG_FUNCTION_ARGS) {
  return build(PG_GETARG_BYTEA_PP(0), PG_GETARG_BYTEA_PP(1), PG_GETARG_TEXT_PP(2));
}

}  // extern "C"
