// The compact global descriptor of an ARG for two-stage search: arg_global_vector (float8[])
// and arg_global (a cube point, for a GiST index ordered by the taxicab distance <#>).
//
// The values are the core's search_descriptor: what SIM weighs most (the panorama's lowest
// frequencies, the spectrum, curvature, node counts and the largest node areas, colour) in 92
// numbers, within contrib/cube's 100 dimensions.
#include <algorithm>
#include <array>

#include "graph/serialize.hpp"
#include "search/search_descriptor.hpp"

#include "arg_bridge.hpp"

extern "C" {
#include "catalog/pg_type.h"
#include "extension/cube/cubedata.h"
#include "utils/array.h"
}

namespace {

constexpr int kCubeDims = arg::kSearchDims;  // 92
static_assert(kCubeDims <= CUBE_MAX_DIM, "the descriptor must fit in a cube");

using Global = std::array<double, kCubeDims>;

// The descriptor of argument 0, computed inside guarded() into plain data.
Global descriptor_of(FunctionCallInfo fcinfo) {
  const varlena* value = PG_GETARG_ARG_PP(0);
  Global d{};
  argpg::Outcome out = argpg::guarded([&] {
    const std::array<float, arg::kSearchDims> f =
        arg::search_descriptor(arg::deserialize_arg(argpg::view(value), /*check_digest=*/false));
    std::copy(f.begin(), f.end(), d.begin());
  });
  argpg::raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot read ARG");
  return d;
}

}  // namespace

extern "C" {

PG_FUNCTION_INFO_V1(arg_global_vector);
PG_FUNCTION_INFO_V1(arg_global);

// arg_global_vector(arg) RETURNS float8[]: the 92 values of the descriptor.
Datum arg_global_vector(PG_FUNCTION_ARGS) {
  const Global d = descriptor_of(fcinfo);
  Datum elems[kCubeDims];
  for (std::size_t k = 0; k < d.size(); ++k) elems[k] = Float8GetDatum(d[k]);
  PG_RETURN_ARRAYTYPE_P(
      construct_array(elems, kCubeDims, FLOAT8OID, sizeof(float8), FLOAT8PASSBYVAL, 'd'));
}

// arg_global(arg) RETURNS cube: the same values as a cube point, laid out as contrib/cube's
// public header says (the value cube(arg_global_vector(a)) gives, without a second call).
Datum arg_global(PG_FUNCTION_ARGS) {
  const Global d = descriptor_of(fcinfo);
  const Size size = POINT_SIZE(kCubeDims);
  NDBOX* point = static_cast<NDBOX*>(palloc0(size));
  SET_VARSIZE(point, size);
  SET_DIM(point, kCubeDims);
  SET_POINT_BIT(point);
  for (std::size_t k = 0; k < d.size(); ++k) point->x[k] = d[k];
  PG_RETURN_POINTER(point);
}

}  // extern "C"
