// The versioned binary form of an ARG and its strict reader; also the lossless text form.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "graph/arg_graph.hpp"

namespace arg {

struct CompactRecords;  // graph/compact_nodes.hpp

// The version this build writes; it reads 1 (no proxy option, no sections), 2 (float records,
// float sections) and 3 (byte-coded records and sections, colour only when there is colour).
inline constexpr std::uint16_t kFormatVersion = 3;

// Where every format keeps its 64-bit content digest (FNV-1a of every other byte): a reader
// that needs only the digest (hashing, the canonical order, a cache's key) reads these bytes.
inline constexpr std::size_t kDigestOffset = 16, kDigestSize = 8;

// Little-endian bytes: header (magic, versions, options, counts, summary, global descriptor,
// surface options, in format 3 the pooled components), then the nodes and their links, then
// tagged sections (the spectrum, the panorama, in format 3 the colour). Written in
// graph.format, so a value read is written back in the format it came in. Format 3 stores
// each number in one or two bytes (graph/quantise.hpp, graph/compact_nodes.hpp): a graph
// written and read back differs from the one built by those codes' rounding, which is why
// build_arg returns stored_form of what it built. Deterministic: equal graphs give equal bytes.
std::string serialize_arg(const ArgGraph& graph);

// The graph as a reader of its bytes sees it: serialised and read back. Reading and writing
// it again keeps every byte.
ArgGraph stored_form(const ArgGraph& graph);

// Strict reader: checks sizes, counts, ranges, ordering, links both ways, finiteness and the
// digest; throws InputError saying what is wrong and at which offset. `check_digest` false
// skips only the digest (a pass over every byte), for values already validated on input, such
// as those a database stores: every index is still checked, so even a corrupted stored value
// cannot make the reader or the matcher read out of bounds.
ArgGraph deserialize_arg(std::string_view bytes, bool check_digest = true);

// The same into `graph`, reusing its storage (a ranking reads row after row into one graph).
// On error `graph` holds a partial value: read it again before use.
void deserialize_arg_into(std::string_view bytes, ArgGraph& graph, bool check_digest = true);

// Reads a format-3 value without colour as deserialize_arg_into(bytes, head, false) would,
// but leaves its node section undecoded in `nodes` (read_compact_records: every check made)
// and head.nodes, children and adjacency empty: for a reader that needs only some of each
// node (a ranking's row, match/packed_graph.hpp). Returns false, having read only the header,
// for other values: read them whole. Throws InputError as deserialize_arg does.
bool read_compact_value(std::string_view bytes, ArgGraph& head, CompactRecords& nodes);

// Only the checks, no copy.
void validate_arg_bytes(std::string_view bytes);

// The ranges of a node's values, checked on input for float records (formats 1 and 2): unit
// values within [0, 1.0001], r within [0, 1e6], theta and phi within their angles, an ordered
// mu range, every histogram bin a unit value. Throws InputError naming node `i`. Format 3's
// codes decode into these ranges (tests/unit/test_compact_nodes.cpp).
void check_node_values(const ArgNode& n, std::size_t i);

// 64-bit content digest stored in the header (used for equality, hashing and canonical order).
std::uint64_t arg_digest(std::string_view bytes);

// Recomputes the digest of `bytes` (a header long at least) in place, so that a value whose
// other bytes were changed on purpose passes the digest check and reaches the structural
// checks. For tests and fuzzing only; throws InputError when `bytes` is too short.
void reseal_arg_digest(std::string& bytes);

// Text form: "arg1:" followed by standard base64 of the binary form.
std::string arg_to_text(std::string_view bytes);
// Accepts exactly that form (no spaces, padding required) and validates the decoded bytes.
std::string arg_from_text(std::string_view text);

}  // namespace arg
