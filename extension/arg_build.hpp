// Building an ARG datum from mesh bytes, shared by arg_build() and arg_index_trigger().
#pragma once

#include <string_view>

struct varlena;  // postgres.h; not included here so C++ headers can still follow this one

namespace argpg {

// Reads and builds under the session's caps and cancel; raises the error on failure (so call
// it outside guarded()). `texture` and `options` may be empty.
varlena* build_arg_datum(std::string_view mesh, std::string_view texture, std::string_view options);

}  // namespace argpg
