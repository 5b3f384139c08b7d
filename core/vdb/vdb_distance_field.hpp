// The OpenVDB side of the project, built as its own shared library (arg_vdb).
#pragma once

#include "mesh/distance_field.hpp"

#define ARG_VDB_EXPORT __attribute__((visibility("default")))

namespace arg {

// The DistanceFieldFunction of mesh/distance_field.hpp (register it with set_distance_field).
ARG_VDB_EXPORT DistanceField vdb_distance_field(const Mesh& mesh, const SampleGrid& grid,
                                                double band, const StopRequested& stop);

}  // namespace arg

// For dlopen: the address of vdb_distance_field (the extension looks this symbol up).
extern "C" ARG_VDB_EXPORT void* arg_vdb_distance_field();
