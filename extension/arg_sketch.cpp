// The `arg_sketch` type: text and binary forms, arg_sketch(arg), arg_sketch_distance and <~>.
#include <type_traits>

#include "graph/serialize.hpp"
#include "search/shape_sketch.hpp"

#include "arg_bridge.hpp"
#include "arg_weights.hpp"

extern "C" {
#include "libpq/pqformat.h"
#include "utils/memutils.h"
}

namespace {

// The last value each argument of arg_sketch_distance had, read: the query's sketch is the
// same on every row, so it is read once a query, not once a row. Plain data in fn_mcxt.
struct Slot {
  Size length;  // of `bytes`; 0 when nothing valid is held
  Size capacity;
  char* bytes;
  arg::ShapeSketch sketch;
};
struct DistanceCache {
  Slot slots[2];
};
static_assert(std::is_trivially_copyable_v<arg::ShapeSketch>, "kept in zeroed palloc memory");

// The sketch of argument `argno`, read into its slot unless the slot holds the same bytes.
// Allocation (which may raise) happens before the guarded read; a failed read empties the slot.
const arg::ShapeSketch& sketch_arg(FunctionCallInfo fcinfo, DistanceCache* cache, int argno) {
  const varlena* value = (varlena*)PG_DETOAST_DATUM_PACKED(PG_GETARG_DATUM(argno));
  const std::string_view bytes = argpg::view(value);
  Slot& s = cache->slots[argno];
  if (s.length == bytes.size() && s.length > 0 && std::memcmp(s.bytes, bytes.data(), s.length) == 0)
    return s.sketch;
  s.length = 0;
  // A larger value gets a new buffer; the old one stays in fn_mcxt until the query ends (a few
  // kB a growth, and sketches differ little in size).
  if (s.capacity < bytes.size()) {
    s.bytes = static_cast<char*>(MemoryContextAlloc(fcinfo->flinfo->fn_mcxt, bytes.size()));
    s.capacity = bytes.size();
  }
  argpg::Outcome out = argpg::guarded([&] { arg::read_shape_sketch(bytes, s.sketch); });
  argpg::raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot read arg_sketch");
  std::memcpy(s.bytes, bytes.data(), bytes.size());
  s.length = bytes.size();
  return s.sketch;
}

Datum distance(FunctionCallInfo fcinfo, const arg::Weights& weights) {
  FmgrInfo* flinfo = fcinfo->flinfo;
  if (!flinfo->fn_extra)
    flinfo->fn_extra = MemoryContextAllocZero(flinfo->fn_mcxt, sizeof(DistanceCache));
  auto* cache = static_cast<DistanceCache*>(flinfo->fn_extra);
  const arg::ShapeSketch& a = sketch_arg(fcinfo, cache, 0);
  const arg::ShapeSketch& b = sketch_arg(fcinfo, cache, 1);
  double d = 0;
  argpg::Outcome out = argpg::guarded([&] { d = arg::sketch_distance(a, b, weights); });
  argpg::raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot compare arg_sketch values");
  PG_RETURN_FLOAT8(d);
}

}  // namespace

extern "C" {

PG_FUNCTION_INFO_V1(arg_sketch_in);
PG_FUNCTION_INFO_V1(arg_sketch_out);
PG_FUNCTION_INFO_V1(arg_sketch_recv);
PG_FUNCTION_INFO_V1(arg_sketch_send);
PG_FUNCTION_INFO_V1(arg_sketch);
PG_FUNCTION_INFO_V1(arg_sketch_distance);
PG_FUNCTION_INFO_V1(arg_sketch_dist);

// Text to arg_sketch: "sketch1:" and base64, every byte checked.
Datum arg_sketch_in(PG_FUNCTION_ARGS) {
  const char* input = PG_GETARG_CSTRING(0);
  varlena* result = nullptr;
  argpg::Outcome out =
      argpg::guarded([&] { result = argpg::to_varlena(arg::sketch_from_text(input)); });
  argpg::raise_if_failed(out, ERRCODE_INVALID_TEXT_REPRESENTATION,
                         "invalid input syntax for type arg_sketch");
  PG_RETURN_POINTER(result);
}

Datum arg_sketch_out(PG_FUNCTION_ARGS) {
  const varlena* value = (varlena*)PG_DETOAST_DATUM_PACKED(PG_GETARG_DATUM(0));
  char* result = nullptr;
  argpg::Outcome out =
      argpg::guarded([&] { result = argpg::to_cstring(arg::sketch_to_text(argpg::view(value))); });
  argpg::raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot output arg_sketch value");
  PG_RETURN_CSTRING(result);
}

// Binary input: the bytes, checked before they are stored.
Datum arg_sketch_recv(PG_FUNCTION_ARGS) {
  StringInfo buf = (StringInfo)PG_GETARG_POINTER(0);
  const char* bytes = buf->data + buf->cursor;
  const int size = buf->len - buf->cursor;
  argpg::Outcome out = argpg::guarded(
      [&] { arg::validate_sketch_bytes(std::string_view(bytes, static_cast<std::size_t>(size))); });
  argpg::raise_if_failed(out, ERRCODE_INVALID_BINARY_REPRESENTATION,
                         "invalid binary input for type arg_sketch");
  bytea* result = (bytea*)palloc(VARHDRSZ + size);
  SET_VARSIZE(result, VARHDRSZ + size);
  pq_copymsgbytes(buf, VARDATA(result), size);
  PG_RETURN_BYTEA_P(result);
}

Datum arg_sketch_send(PG_FUNCTION_ARGS) {
  const varlena* value = (varlena*)PG_DETOAST_DATUM_PACKED(PG_GETARG_DATUM(0));
  StringInfoData buf;
  pq_begintypsend(&buf);
  pq_sendbytes(&buf, VARDATA_ANY(value), VARSIZE_ANY_EXHDR(value));
  PG_RETURN_BYTEA_P(pq_endtypsend(&buf));
}

// arg_sketch(arg) RETURNS arg_sketch. Reads the value as arg_global does (no digest check:
// the stored value was checked when it came in).
Datum arg_sketch(PG_FUNCTION_ARGS) {
  const varlena* value = PG_GETARG_ARG_PP(0);
  varlena* result = nullptr;
  argpg::Outcome out = argpg::guarded([&] {
    const arg::ArgGraph g = arg::deserialize_arg(argpg::view(value), /*check_digest=*/false);
    const std::string bytes = arg::write_shape_sketch(arg::shape_sketch(g));
    // shape_sketch leaves out what its reader would refuse; checked again here, so that no
    // stored sketch is one arg_sketch_distance cannot read.
    arg::validate_sketch_bytes(bytes);
    result = argpg::to_varlena(bytes);
  });
  argpg::raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot read ARG");
  PG_RETURN_POINTER(result);
}

// arg_sketch_distance(a arg_sketch, b arg_sketch, weights arg_weights DEFAULT 'arg') RETURNS
// float8: SIM with its graph term replaced by the graph blocks' distance (shape_sketch.hpp).
Datum arg_sketch_distance(PG_FUNCTION_ARGS) {
  return distance(fcinfo, argpg::to_weights(*PG_GETARG_ARG_WEIGHTS_P(2)));
}

// arg_sketch_dist(a, b), the operator <~>: the same with the default weights, as arg_ivf ranks.
Datum arg_sketch_dist(PG_FUNCTION_ARGS) {
  return distance(fcinfo, arg::Weights{});
}

}  // extern "C"
