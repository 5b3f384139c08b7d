// The compact global descriptor of an ARG for two-stage search: arg_global_vector (float8[])
// and arg_global (a cube point, for a GiST index ordered by the taxicab distance <#>).
//
// The values are the core's search_descriptor (weighted level sums of what SIM compares:
// curvature, per-level cords histograms, volumes and node counts, the largest node areas of
// levels 1..3, colour) less the blocks that tell models apart the least, so that they fit in
// contrib/cube's 100 dimensions: the relative volume of each level (it sums to about the same
// on every closed mesh) and the level-0 cords (they repeat level 1's on most models). Measured
// on SHREC 2007 and on generated models (tests/scale/descriptor_study.sh), dropping them leaves
// the recall of two-stage search within 0.001 of the whole descriptor's.
#include <array>

#include "graph/search_descriptor.hpp"
#include "graph/serialize.hpp"

#include "arg_bridge.hpp"

extern "C" {
#include "catalog/pg_type.h"
#include "extension/cube/cubedata.h"
#include "utils/array.h"
}

namespace {

// The layout search_descriptor writes: curvature (mean, Gaussian), then per level the cords
// histogram, the volume and the node count, then 4 areas of levels 1..3, then colour.
constexpr int kCurvatureDims = 2 * arg::kCurvatureBins;
constexpr int kLevelDims = arg::kCordBins + 2;
static_assert(arg::kSearchDims ==
                  kCurvatureDims + arg::kSearchLevels * kLevelDims + 3 * 4 + 3 * arg::kColourBins,
              "search_descriptor's layout changed: update the kept dimensions");

constexpr bool kept(int k) {
  if (k < kCurvatureDims || k >= kCurvatureDims + arg::kSearchLevels * kLevelDims) return true;
  const int level = (k - kCurvatureDims) / kLevelDims, within = (k - kCurvatureDims) % kLevelDims;
  if (within == arg::kCordBins) return false;  // the level's volume
  return !(level == 0 && within < arg::kCordBins);
}

constexpr int count_kept() {
  int n = 0;
  for (int k = 0; k < arg::kSearchDims; ++k) n += kept(k);
  return n;
}

constexpr int kCubeDims = count_kept();  // 98
static_assert(kCubeDims <= CUBE_MAX_DIM, "the descriptor must fit in a cube");

using Global = std::array<double, kCubeDims>;

// The descriptor of argument 0, computed inside guarded() into plain data.
Global descriptor_of(FunctionCallInfo fcinfo) {
  const varlena* value = PG_GETARG_ARG_PP(0);
  Global d{};
  argpg::Outcome out = argpg::guarded([&] {
    const std::array<float, arg::kSearchDims> f =
        arg::search_descriptor(arg::deserialize_arg(argpg::view(value), /*check_digest=*/false));
    std::size_t j = 0;
    for (int k = 0; k < arg::kSearchDims; ++k)
      if (kept(k)) d[j++] = double(f[std::size_t(k)]);
  });
  argpg::raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot read ARG");
  return d;
}

}  // namespace

extern "C" {

PG_FUNCTION_INFO_V1(arg_global_vector);
PG_FUNCTION_INFO_V1(arg_global);

// arg_global_vector(arg) RETURNS float8[]: the 98 values of the descriptor.
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
