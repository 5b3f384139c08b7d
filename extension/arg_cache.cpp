// The per-call-site cache of deserialised ARGs (see arg_cache.hpp).
#include "arg_cache.hpp"

#include <cstdint>
#include <string>

#include "graph/serialize.hpp"

#include "arg_guc.hpp"

extern "C" {
#include "access/detoast.h"
}

namespace argpg {

namespace {

struct ToastKey {
  Oid relation = InvalidOid;  // InvalidOid: the value did not come as an on-disk toast pointer
  Oid value = InvalidOid;
};

struct Slot {
  bool valid = false;      // `graph` is the value described below
  bool confirmed = false;  // `bytes` holds a copy of it
  ToastKey toast;
  std::size_t size = 0;
  std::uint64_t digest = 0;
  std::string bytes;
  arg::ArgGraph graph;
  bool repeated = false;    // the last graph_of() found `graph` already there
  bool prep_valid = false;  // `prep` describes `graph`
  arg::MatchPrep prep;
  // The last value read by packed_row_of: its header, and whether `packed` holds it.
  std::size_t packed_size = 0;
  std::uint64_t packed_digest = 0;
  arg::PackedGraph packed;
};

ToastKey toast_key(Datum raw) {
  ToastKey key;
  const varlena* value = reinterpret_cast<const varlena*>(DatumGetPointer(raw));
  if (VARATT_IS_EXTERNAL_ONDISK(value)) {
    varatt_external pointer;
    VARATT_EXTERNAL_GET_POINTER(pointer, value);
    key.relation = pointer.va_toastrelid;
    key.value = pointer.va_valueid;
  }
  return key;
}

std::uint64_t raw_digest(std::string_view bytes) {
  std::uint64_t digest = 0;
  if (bytes.size() >= arg::kDigestOffset + arg::kDigestSize)
    std::memcpy(&digest, bytes.data() + arg::kDigestOffset, arg::kDigestSize);
  return digest;
}

}  // namespace

struct GraphCache {
  Slot slots[2];
};

namespace {

void release(void* data) {
  auto* holder = static_cast<GraphCacheHolder*>(data);
  delete holder->cache;
  holder->cache = nullptr;
}

}  // namespace

GraphCacheHolder* graph_cache(FunctionCallInfo fcinfo) {
  if (!query_cache_enabled()) return nullptr;
  FmgrInfo* flinfo = fcinfo->flinfo;
  if (!flinfo->fn_extra) {
    auto* holder = static_cast<GraphCacheHolder*>(
        MemoryContextAllocZero(flinfo->fn_mcxt, sizeof(GraphCacheHolder)));
    holder->on_reset.func = release;
    holder->on_reset.arg = holder;
    MemoryContextRegisterResetCallback(flinfo->fn_mcxt, &holder->on_reset);
    flinfo->fn_extra = holder;
  }
  return static_cast<GraphCacheHolder*>(flinfo->fn_extra);
}

GraphArg graph_arg(FunctionCallInfo fcinfo, GraphCacheHolder* holder, int slot, int argno) {
  GraphArg argument{PG_GETARG_DATUM(argno), nullptr, nullptr};
  if (holder && holder->cache) {
    // Reads plain fields only: nothing here allocates or throws.
    const Slot& s = holder->cache->slots[slot];
    const ToastKey key = toast_key(argument.raw);
    if (s.valid && key.relation != InvalidOid && s.toast.relation == key.relation &&
        s.toast.value == key.value) {
      argument.cached = &s.graph;
      return argument;
    }
  }
  argument.value = PG_GETARG_ARG_PP(argno);
  return argument;
}

const arg::ArgGraph& graph_of(GraphCacheHolder* holder, int slot, const GraphArg& argument,
                              arg::ArgGraph& scratch) {
  if (argument.cached) {
    holder->cache->slots[slot].repeated = true;  // only a holder's slot can be found cached
    return *argument.cached;
  }
  const std::string_view bytes = view(argument.value);
  if (!holder) {
    arg::deserialize_arg_into(bytes, scratch, /*check_digest=*/false);
    return scratch;
  }
  if (!holder->cache) holder->cache = new GraphCache();
  Slot& s = holder->cache->slots[slot];
  const ToastKey key = toast_key(argument.raw);
  const std::uint64_t digest = raw_digest(bytes);
  const bool same_header = s.valid && s.size == bytes.size() && s.digest == digest;
  if (same_header && s.confirmed && std::memcmp(s.bytes.data(), bytes.data(), bytes.size()) == 0) {
    s.toast = key;
    s.repeated = true;
    return s.graph;
  }
  // Read anew. The second time running that a slot sees the same size and digest, the argument
  // probably repeats: keep its bytes so that later calls can compare them.
  const bool keep_bytes = same_header && !s.confirmed;
  s.valid = s.confirmed = s.repeated = s.prep_valid = false;
  // Into the slot's graph: a ranking reads row after row, and the storage stays.
  arg::deserialize_arg_into(bytes, s.graph, /*check_digest=*/false);
  s.toast = key;
  s.size = bytes.size();
  s.digest = digest;
  s.valid = true;
  if (keep_bytes) {
    s.bytes.assign(bytes.data(), bytes.size());
    s.confirmed = true;
  }
  return s.graph;
}

const arg::MatchPrep* match_prep_of(GraphCacheHolder* holder, int slot,
                                    const arg::Weights& weights) {
  if (!holder || !holder->cache) return nullptr;
  Slot& s = holder->cache->slots[slot];
  if (!s.valid || !s.repeated) return nullptr;
  if (!s.prep_valid || !(s.prep.weights == weights)) {
    s.prep_valid = false;
    arg::prepare_match(s.graph, weights, s.prep);
    s.prep_valid = true;
  }
  return &s.prep;
}

int repeating_slot(const GraphCacheHolder* holder) {
  if (!holder || !holder->cache) return -1;
  const Slot* s = holder->cache->slots;
  const bool r0 = s[0].valid && s[0].repeated, r1 = s[1].valid && s[1].repeated;
  return r0 == r1 ? -1 : r0 ? 0 : 1;
}

arg::PackedGraph* packed_row_of(GraphCacheHolder* holder, int slot, const GraphArg& argument,
                                const arg::Weights& weights) {
  if (!holder || argument.cached) return nullptr;
  if (!holder->cache) holder->cache = new GraphCache();
  Slot& s = holder->cache->slots[slot];
  const std::string_view bytes = view(argument.value);
  const std::uint64_t digest = raw_digest(bytes);
  if (s.packed_size == bytes.size() && s.packed_digest == digest) return nullptr;
  s.repeated = false;
  s.packed_size = 0;  // until read
  if (!arg::read_packed_graph(bytes, weights, s.packed)) return nullptr;
  s.packed_size = bytes.size();
  s.packed_digest = digest;
  return &s.packed;
}

}  // namespace argpg
