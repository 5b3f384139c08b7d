// The pluggable unsigned distance field: the core asks for it, a loaded library computes it.
#pragma once

#include <cstdint>
#include <vector>

#include "common/limits.hpp"
#include "mesh/marching_tetrahedra.hpp"
#include "mesh/mesh.hpp"

namespace arg {

// Per grid point (i fastest, then j, then k): the distance to the nearest triangle and that
// triangle, for points within `band` of the surface; points farther away hold `far` and -1.
struct DistanceField {
  SampleGrid grid;
  float far = 0;
  std::vector<float> distance;
  std::vector<std::int32_t> nearest;
};

// Computes the field of `mesh` on `grid` out to `band` (in the mesh's units), polling `stop`;
// throws like the core (InputError, Interrupted, std::bad_alloc). Deterministic.
using DistanceFieldFunction = DistanceField (*)(const Mesh& mesh, const SampleGrid& grid,
                                                double band, const StopRequested& stop);

// OpenVDB, which computes it, brings 56 MB of code and thread pools into every process that
// links it, so the core does not: programs register core/vdb's function at start-up and the
// extension loads it on the first model that needs it. Thread-safe.
void set_distance_field(DistanceFieldFunction function);
DistanceFieldFunction distance_field_function();

// Calls the registered function; throws std::runtime_error when none is registered.
DistanceField unsigned_distance_field(const Mesh& mesh, const SampleGrid& grid, double band,
                                      const StopRequested& stop = {});

}  // namespace arg
