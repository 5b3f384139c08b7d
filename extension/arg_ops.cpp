// Equality, canonical order and hashing of `arg` values, for =, DISTINCT, GROUP BY, UNION and
// hash or merge joins. The binary form is deterministic (equal graphs give equal bytes), so
// equality is byte equality. The header stores a 64-bit content digest: hashing reads only
// those 8 bytes, and the canonical order (a total order that means nothing about shape: use
// <~> for that) sorts by digest, then size, then bytes, so most comparisons never detoast a
// whole value.
#include "arg_bridge.hpp"
#include "graph/serialize.hpp"

extern "C" {
#include "access/detoast.h"
#include "common/hashfn.h"
}

namespace {

constexpr int32 kDigestAt = int32(arg::kDigestOffset), kDigestSize = int32(arg::kDigestSize);

// The stored digest's bytes (only those are detoasted), or fewer if the value is shorter.
varlena* digest_slice(Datum value) {
  return PG_DETOAST_DATUM_SLICE(value, kDigestAt, kDigestSize);
}

// The digest as a number, read little-endian as stored (0 for a value too short to have one).
uint64 digest_of(Datum value) {
  varlena* slice = digest_slice(value);
  uint64 digest = 0;
  if (VARSIZE_ANY_EXHDR(slice) == kDigestSize) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(VARDATA_ANY(slice));
    for (int i = kDigestSize - 1; i >= 0; --i) digest = (digest << 8) | bytes[i];
  }
  pfree(slice);
  return digest;
}

// <0, 0, >0 as a comes before, equals or comes after b; `equality_only` may stop at "differs".
int compare(FunctionCallInfo fcinfo, bool equality_only) {
  const Datum da = PG_GETARG_DATUM(0), db = PG_GETARG_DATUM(1);
  const Size size_a = toast_raw_datum_size(da), size_b = toast_raw_datum_size(db);
  if (equality_only && size_a != size_b) return 1;
  const uint64 digest_a = digest_of(da), digest_b = digest_of(db);
  if (digest_a != digest_b) return digest_a < digest_b ? -1 : 1;
  if (size_a != size_b) return size_a < size_b ? -1 : 1;
  varlena* a = PG_GETARG_ARG_PP(0);
  varlena* b = PG_GETARG_ARG_PP(1);
  const int order = std::memcmp(VARDATA_ANY(a), VARDATA_ANY(b), VARSIZE_ANY_EXHDR(a));
  PG_FREE_IF_COPY(a, 0);
  PG_FREE_IF_COPY(b, 1);
  return order;
}

}  // namespace

extern "C" {

PG_FUNCTION_INFO_V1(arg_eq);
PG_FUNCTION_INFO_V1(arg_ne);
PG_FUNCTION_INFO_V1(arg_lt);
PG_FUNCTION_INFO_V1(arg_le);
PG_FUNCTION_INFO_V1(arg_gt);
PG_FUNCTION_INFO_V1(arg_ge);
PG_FUNCTION_INFO_V1(arg_cmp);
PG_FUNCTION_INFO_V1(arg_hash);
PG_FUNCTION_INFO_V1(arg_hash_extended);

Datum arg_eq(PG_FUNCTION_ARGS) {
  PG_RETURN_BOOL(compare(fcinfo, true) == 0);
}

Datum arg_ne(PG_FUNCTION_ARGS) {
  PG_RETURN_BOOL(compare(fcinfo, true) != 0);
}

Datum arg_lt(PG_FUNCTION_ARGS) {
  PG_RETURN_BOOL(compare(fcinfo, false) < 0);
}

Datum arg_le(PG_FUNCTION_ARGS) {
  PG_RETURN_BOOL(compare(fcinfo, false) <= 0);
}

Datum arg_gt(PG_FUNCTION_ARGS) {
  PG_RETURN_BOOL(compare(fcinfo, false) > 0);
}

Datum arg_ge(PG_FUNCTION_ARGS) {
  PG_RETURN_BOOL(compare(fcinfo, false) >= 0);
}

Datum arg_cmp(PG_FUNCTION_ARGS) {
  const int order = compare(fcinfo, false);
  PG_RETURN_INT32(order < 0 ? -1 : order > 0 ? 1 : 0);
}

Datum arg_hash(PG_FUNCTION_ARGS) {
  varlena* digest = digest_slice(PG_GETARG_DATUM(0));
  const Datum result = hash_any(reinterpret_cast<const unsigned char*>(VARDATA_ANY(digest)),
                                static_cast<int>(VARSIZE_ANY_EXHDR(digest)));
  pfree(digest);
  PG_RETURN_DATUM(result);
}

Datum arg_hash_extended(PG_FUNCTION_ARGS) {
  varlena* digest = digest_slice(PG_GETARG_DATUM(0));
  const Datum result =
      hash_any_extended(reinterpret_cast<const unsigned char*>(VARDATA_ANY(digest)),
                        static_cast<int>(VARSIZE_ANY_EXHDR(digest)), PG_GETARG_INT64(1));
  pfree(digest);
  PG_RETURN_DATUM(result);
}

}  // extern "C"
