// The module itself: magic block, settings and version.
#include "graph/serialize.hpp"

#include "arg_bridge.hpp"
#include "arg_guc.hpp"
#include "arg_ivf.hpp"
#include "arg_vdb.hpp"

extern "C" {
#include "utils/builtins.h"

PG_MODULE_MAGIC;

void _PG_init(void);

void _PG_init(void) {
  argpg::define_gucs();
  argpg::register_distance_field();
  argpg::ivf::define_reloptions();
}

PG_FUNCTION_INFO_V1(arg_version);

// arg_version(): the extension's version and the binary format it writes.
Datum arg_version(PG_FUNCTION_ARGS) {
  PG_RETURN_TEXT_P(cstring_to_text(
      psprintf("arg %s (binary format %d)", ARG_VERSION, static_cast<int>(arg::kFormatVersion))));
}

}  // extern "C"
