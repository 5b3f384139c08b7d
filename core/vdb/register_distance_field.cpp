// Programs that link this object (argtool, tests, benchmarks) get distance fields from OpenVDB.
#include "mesh/distance_field.hpp"
#include "vdb/vdb_distance_field.hpp"

namespace {
// The core's slot is a constant-initialised atomic, so this may run in any order.
const bool registered = (arg::set_distance_field(&arg::vdb_distance_field), true);
}  // namespace
