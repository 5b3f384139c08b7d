// The extension's settings (prefix "arg.", reserved): knobs that never change a function's
// result.
#pragma once

#include "common/limits.hpp"

namespace argpg {

// Registers the settings; called once from _PG_init.
void define_gucs();

// The input caps as set now (arg.max_input_size, arg.max_vertices, arg.max_triangles,
// arg.max_texture_pixels). Plain values: safe inside guarded().
arg::Limits current_limits();

// arg.max_build_threads: the most threads a build may use, whatever its `threads=` option says.
int max_build_threads();

// arg.query_cache: keep the deserialised ARG of a repeated argument across calls.
bool query_cache_enabled();

// arg.ivf_probes: how many cells of an arg_ivf index a search reads.
int ivf_probes();

}  // namespace argpg
