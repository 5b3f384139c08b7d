// arg_rebuild_needed(arg): whether this library would build a stored ARG differently.
#include "graph/comparable.hpp"
#include "graph/serialize.hpp"

#include "arg_bridge.hpp"

extern "C" {

PG_FUNCTION_INFO_V1(arg_rebuild_needed);

// arg_rebuild_needed(arg) RETURNS boolean. STABLE, not IMMUTABLE, in SQL: the answer for the
// same value changes when a newer library is installed, so it must not feed an index.
Datum arg_rebuild_needed(PG_FUNCTION_ARGS) {
  const varlena* value = PG_GETARG_ARG_PP(0);
  bool needed = false;
  argpg::Outcome out = argpg::guarded([&] {
    needed = arg::rebuild_needed(arg::deserialize_arg(argpg::view(value), /*check_digest=*/false));
  });
  argpg::raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot read ARG");
  PG_RETURN_BOOL(needed);
}

}  // extern "C"
