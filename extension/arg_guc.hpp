// The extension's settings (prefix "arg.", reserved): knobs that never change a function's
// result.
#pragma once

#include "common/limits.hpp"

namespace argpg {

// Registers the settings; called once from _PG_init.
void define_gucs();

// The input caps as set now (arg.max_input_size, arg.max_vertices, arg.max_triangles,
// arg.max_texture_pixels) and the build's memory (arg.max_build_memory). Plain values: safe
// inside guarded().
arg::Limits current_limits();

// arg.max_build_threads: the most threads a build may use, whatever its `threads=` option says.
int max_build_threads();

// arg.query_cache: keep the deserialised ARG of a repeated argument across calls.
bool query_cache_enabled();

// arg.ivf_probes: how many cells of an arg_ivf index a search reads (and reads further at a
// time, in an iterative scan).
int ivf_probes();

// arg.ivf_candidates: how many of an arg_ivf index's nearest candidates by sketch a search of
// `arg` values ranks by SIM at a time, for an index of `index_rows` rows (the setting's 0
// leaves it to the index's size: search/sketch_cells.hpp default_candidates).
int ivf_candidates(double index_rows);

// arg.iterative_scan: whether a search of an arg_ivf index of `arg` values goes on past its
// first batch of candidates when the executor asks for more rows (a filter rejected them), and
// whether rows nearer than one already returned are then left out (strict) or returned.
enum class IterativeScan { Off = 0, StrictOrder = 1, RelaxedOrder = 2 };
IterativeScan iterative_scan();

// arg.max_scan_tuples: the most candidates one iterative search ranks by SIM.
int max_scan_tuples();

}  // namespace argpg
