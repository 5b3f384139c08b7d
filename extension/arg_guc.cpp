// The extension's settings. Each one caps a resource, switches a cache or sets how much of an
// arg_ivf index a search reads; none changes a value that a function returns, so results never
// depend on the session (IMMUTABLE stays true).
#include "arg_guc.hpp"

#include <climits>

#include "search/sketch_cells.hpp"

#include "arg_bridge.hpp"

extern "C" {
#include "utils/guc.h"
}

namespace argpg {

namespace {

const arg::Limits kDefaults;

int max_input_kb = int(kDefaults.max_input_bytes >> 10);
int max_vertices = int(kDefaults.max_vertices);
int max_triangles = int(kDefaults.max_triangles);
int max_texture_pixels = int(kDefaults.max_image_pixels);
int max_build_memory_mb = int(kDefaults.max_build_bytes >> 20);
int build_threads = 1;
bool query_cache = true;
int ivf_probes_setting = 4;
int ivf_candidates_setting = 0;
int iterative_scan_setting = int(IterativeScan::StrictOrder);
int max_scan_tuples_setting = 20000;

const config_enum_entry kIterativeScanValues[] = {
    {"off", int(IterativeScan::Off), false},
    {"strict_order", int(IterativeScan::StrictOrder), false},
    {"relaxed_order", int(IterativeScan::RelaxedOrder), false},
    {nullptr, 0, false}};

}  // namespace

void define_gucs() {
  // Caps protect the server, so only a superuser may raise them (PGC_SUSET).
  DefineCustomIntVariable("arg.max_input_size",
                          "Largest mesh or texture image, in bytes, that arg_build accepts.",
                          "Larger inputs fail with SQLSTATE 54000.", &max_input_kb, max_input_kb, 1,
                          1024 * 1024, PGC_SUSET, GUC_UNIT_KB, nullptr, nullptr, nullptr);
  DefineCustomIntVariable("arg.max_vertices",
                          "Most vertices a mesh given to arg_build may declare.",
                          "Larger meshes fail with SQLSTATE 54000.", &max_vertices, max_vertices, 3,
                          INT_MAX, PGC_SUSET, 0, nullptr, nullptr, nullptr);
  DefineCustomIntVariable("arg.max_triangles",
                          "Most triangles a mesh given to arg_build may declare.",
                          "Larger meshes fail with SQLSTATE 54000.", &max_triangles, max_triangles,
                          1, INT_MAX, PGC_SUSET, 0, nullptr, nullptr, nullptr);
  DefineCustomIntVariable("arg.max_texture_pixels",
                          "Most pixels a texture image given to arg_build may have.",
                          "Larger images fail with SQLSTATE 54000.", &max_texture_pixels,
                          max_texture_pixels, 1, INT_MAX, PGC_SUSET, 0, nullptr, nullptr, nullptr);
  DefineCustomIntVariable(
      "arg.max_build_memory", "Most memory one arg_build may take.",
      "A build whose estimate from the mesh's vertices and triangles is larger is refused before "
      "it allocates, and one whose allocations grow past it is stopped; both fail with SQLSTATE "
      "54000.",
      &max_build_memory_mb, max_build_memory_mb, 1, INT_MAX, PGC_SUSET, GUC_UNIT_MB, nullptr,
      nullptr, nullptr);
  DefineCustomIntVariable(
      "arg.max_build_threads", "Most threads one arg_build may use for its threads= option.",
      "The number of threads never changes the ARG; 1 keeps every build in the backend's own "
      "thread.",
      &build_threads, 1, 1, 64, PGC_SUSET, 0, nullptr, nullptr, nullptr);
  DefineCustomBoolVariable(
      "arg.query_cache",
      "Keeps the deserialised ARG of an argument that repeats across calls, such as the query "
      "of ORDER BY descr <~> $1.",
      nullptr, &query_cache, true, PGC_USERSET, 0, nullptr, nullptr, nullptr);
  DefineCustomIntVariable(
      "arg.ivf_probes", "Cells of an arg_ivf index that a search reads.",
      "More cells find more of the exact nearest and take longer; at least the index's lists "
      "makes the search exact.",
      &ivf_probes_setting, ivf_probes_setting, 1, int(arg::kMaxSketchCells), PGC_USERSET, 0,
      nullptr, nullptr, nullptr);
  DefineCustomIntVariable(
      "arg.ivf_candidates",
      "Nearest candidates by sketch that a search of an arg_ivf index of arg values ranks by "
      "SIM at a time.",
      "More candidates find more of the exact nearest and take longer (one SIM each); 0 "
      "chooses by the index's size (25 up to about 300,000 rows, 25 more a decade beyond).",
      &ivf_candidates_setting, ivf_candidates_setting, 0, 100000, PGC_USERSET, 0, nullptr, nullptr,
      nullptr);
  DefineCustomEnumVariable(
      "arg.iterative_scan",
      "Whether a search of an arg_ivf index of arg values goes on past its first candidates "
      "while rows are wanted (a WHERE clause rejected some).",
      "strict_order leaves out rows nearer than one already returned, so the order is exact; "
      "relaxed_order returns them; off stops after the first candidates.",
      &iterative_scan_setting, iterative_scan_setting, kIterativeScanValues, PGC_USERSET, 0,
      nullptr, nullptr, nullptr);
  DefineCustomIntVariable(
      "arg.max_scan_tuples", "Most candidates one iterative arg_ivf search ranks by SIM.",
      "Bounds the time of a search whose WHERE clause rejects most rows; the first candidates "
      "are always ranked.",
      &max_scan_tuples_setting, max_scan_tuples_setting, 1, INT_MAX, PGC_USERSET, 0, nullptr,
      nullptr, nullptr);
  MarkGUCPrefixReserved("arg");
}

arg::Limits current_limits() {
  arg::Limits limits;
  limits.max_input_bytes = std::size_t(max_input_kb) << 10;
  limits.max_vertices = std::size_t(max_vertices);
  limits.max_triangles = std::size_t(max_triangles);
  limits.max_image_pixels = std::size_t(max_texture_pixels);
  limits.max_build_bytes = std::size_t(max_build_memory_mb) << 20;
  return limits;
}

int max_build_threads() {
  return build_threads;
}

bool query_cache_enabled() {
  return query_cache;
}

int ivf_probes() {
  return ivf_probes_setting;
}

int ivf_candidates(double index_rows) {
  return ivf_candidates_setting > 0 ? ivf_candidates_setting
                                    : int(arg::default_candidates(index_rows));
}

IterativeScan iterative_scan() {
  return IterativeScan(iterative_scan_setting);
}

int max_scan_tuples() {
  return max_scan_tuples_setting;
}

}  // namespace argpg
