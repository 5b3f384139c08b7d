// arg_build: mesh bytes (OFF, OBJ, PLY, STL, GLB; detected) and an optional texture to an ARG.
#include "pipeline/build_arg.hpp"

#include "arg_bridge.hpp"
#include "arg_build.hpp"
#include "arg_guc.hpp"
#include "arg_image.hpp"

namespace argpg {

varlena* build_arg_datum(std::string_view mesh, std::string_view texture,
                         std::string_view options) {
  const arg::Limits limits = current_limits();
  const int max_threads = max_build_threads();
  varlena* result = nullptr;
  prepare_image_decoder(mesh, texture);
  bool over_memory = false;
  Outcome out = guarded([&] {
    arg::BuildOptions parsed = arg::parse_build_options(options);
    if (parsed.threads > max_threads) parsed.threads = max_threads;  // never changes the result
    try {
      result = to_varlena(arg::build_arg_bytes(mesh, texture, parsed, limits, stop_requested));
    } catch (const arg::MemoryLimitError&) {
      over_memory = true;
      throw;
    }
  });
  if (over_memory)
    ereport(ERROR, (errcode(ERRCODE_PROGRAM_LIMIT_EXCEEDED),
                    errmsg("cannot build ARG: %s (arg.max_build_memory)", out.message),
                    errhint("A superuser may raise arg.max_build_memory, or the mesh may be "
                            "simplified first.")));
  raise_if_failed(out, ERRCODE_INVALID_PARAMETER_VALUE, "cannot build ARG");
  return result;
}

}  // namespace argpg

extern "C" {

PG_FUNCTION_INFO_V1(arg_build_mesh);
PG_FUNCTION_INFO_V1(arg_build_textured);

// arg_build(mesh bytea, options text DEFAULT '')
Datum arg_build_mesh(PG_FUNCTION_ARGS) {
  PG_RETURN_POINTER(argpg::build_arg_datum(argpg::view(PG_GETARG_BYTEA_PP(0)), {},
                                           argpg::view(PG_GETARG_TEXT_PP(1))));
}

// arg_build(mesh bytea, texture bytea, options text DEFAULT '')
Datum arg_build_textured(PG_FUNCTION_ARGS) {
  PG_RETURN_POINTER(argpg::build_arg_datum(argpg::view(PG_GETARG_BYTEA_PP(0)),
                                           argpg::view(PG_GETARG_BYTEA_PP(1)),
                                           argpg::view(PG_GETARG_TEXT_PP(2))));
}

}  // extern "C"
