// Deserialised ARGs kept across the calls of one SQL expression, so that ranking a table against
// one query (ORDER BY descr <~> $1, or a join with the query's row) reads the query's ARG once,
// not once per row.
//
// Outside guarded(), graph_cache() finds or makes the cache of the call site: plain data in
// fn_extra, allocated in fn_mcxt with a reset callback that frees the C++ state when the
// query's memory goes (no leak across queries, even on error). graph_arg() then looks each
// argument up before detoasting it, and graph_of(), inside guarded(), returns its graph.
//
// An argument is the value seen last time in its slot when either
//  - it is the same on-disk toast pointer (same toast table, same value id: the value cannot
//    change while a query can still see it; PostGIS's toast cache relies on the same fact), or
//  - its bytes are equal (size and stored digest first, then memcmp; never the digest alone).
#pragma once

#include <string_view>

#include "graph/arg_graph.hpp"
#include "match/match_prep.hpp"
#include "match/packed_graph.hpp"
#include "match/weights.hpp"

#include "arg_bridge.hpp"

namespace argpg {

struct GraphCache;  // C++ state: created and changed only inside guarded()

struct GraphCacheHolder {
  MemoryContextCallback on_reset;  // deletes `cache`
  GraphCache* cache;
};

// Outside guarded() (it may raise): the holder of this call site, made on first use; nullptr
// when arg.query_cache is off.
GraphCacheHolder* graph_cache(FunctionCallInfo fcinfo);

// An `arg` argument on its way to a graph.
struct GraphArg {
  Datum raw;                    // as passed (maybe a toast pointer)
  const arg::ArgGraph* cached;  // found by toast pointer: no detoasting was needed
  const varlena* value;         // otherwise the detoasted value
};

// Outside guarded() (detoasting may raise): argument `argno`, kept in cache slot `slot` (0 or 1).
GraphArg graph_arg(FunctionCallInfo fcinfo, GraphCacheHolder* holder, int slot, int argno);

// Inside guarded(): the argument's graph, from the cache or read without the digest pass (stored
// values were fully checked on input) and remembered. Without a holder, reads into `scratch`.
const arg::ArgGraph& graph_of(GraphCacheHolder* holder, int slot, const GraphArg& argument,
                              arg::ArgGraph& scratch);

// Inside guarded(), after graph_of(): the matcher's per-graph parts of the slot's graph for
// these weights, made once and kept while the slot keeps its value (a ranking's query), or
// nullptr when the slot's value just changed (a ranking's rows: preparing each would cost more
// than it saves) or there is no holder. A value found by its toast pointer is prepared from its
// second call on; an inline value only from its third (its second re-reads it to keep its bytes).
const arg::MatchPrep* match_prep_of(GraphCacheHolder* holder, int slot,
                                    const arg::Weights& weights);

// Inside guarded(): the slot that held the same value in the last call while the other did not
// (a ranking's query), or -1.
int repeating_slot(const GraphCacheHolder* holder);

// Inside guarded(): the argument read as a ranking's row, straight into the slot's
// PackedGraph with its prep for these weights (match/packed_graph.hpp), or nullptr when it is
// better read whole by graph_of(): the slot already holds it, it has the header of the last row
// read so (it may repeat: graph_of keeps such values), it is not format 3 without colour, or
// there is no holder. The slot's graph keeps the value it held.
arg::PackedGraph* packed_row_of(GraphCacheHolder* holder, int slot, const GraphArg& argument,
                                const arg::Weights& weights);

}  // namespace argpg
