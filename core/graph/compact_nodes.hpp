// Format 3's node records: 39 bytes a node, neighbours as 2-byte indices, colour on its own.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include "common/byte_io.hpp"
#include "graph/arg_graph.hpp"
#include "graph/quantise.hpp"

namespace arg {

// One record, little-endian: parent's index in the level above (0xffff on level 0), interval,
// number of neighbours in the next interval, mu range within the interval (2 bytes), theta,
// phi and r (one byte each), area, length and volume (2 bytes each), then the cords, mean and
// Gaussian curvature histograms (8 bytes each, as fractions of the area). See quantise.hpp.
inline constexpr std::size_t kCompactNodeSize = 15 + kCordBins + 2 * kCurvatureBins;
inline constexpr std::size_t kCompactColourSize = 3 * kColourBins;  // per node, fractions of a
// The barycentre's radius is stored up to 4 RMS radii (matching reads it up to 2).
inline constexpr float kMaxStoredRadius = 4.0f;

namespace compact_detail {
inline std::uint16_t get16(const unsigned char* at) {
  return std::uint16_t(at[0] | at[1] << 8);
}
// byte_value(q, lo, hi) of every code q for theta, phi and r: a lookup instead of a division
// (three a node, on every row of a ranking), the same bits.
extern const std::array<float, 256> theta_values, phi_values, radius_values;
}  // namespace compact_detail

// A record's numbers as every reader decodes them (into a node record or a match key).
struct CompactScalars {
  float a, l, v, r, theta, phi;
};
inline CompactScalars compact_scalars(const unsigned char* rec) {
  using namespace compact_detail;
  return {unit16_value(get16(rec + 9)),  unit16_value(get16(rec + 11)),
          unit16_value(get16(rec + 13)), radius_values[rec[8]],
          theta_values[rec[6]],          phi_values[rec[7]]};
}
// Where a record's histogram codes start: cords, then mean and Gaussian curvature.
inline constexpr std::size_t kCompactCodesAt = 15;

// Per node, its neighbours in the next interval (the records' third byte): each undirected
// edge is counted once, at its lower end.
std::vector<std::uint32_t> up_neighbour_counts(const ArgGraph& g);

// Every record, then every node's neighbours in the next interval as indices in their level
// (a node with 255 or more has the count beyond 255 in 2 bytes before its list). `up` is
// up_neighbour_counts(g). Expects a level of at most 65,535 nodes (pool_fragments bounds them
// far lower).
void write_compact_nodes(const ArgGraph& g, const std::vector<std::uint32_t>& up, ByteWriter& out);

// A node section read and checked but not decoded: the records where they lie in the value,
// each node's parent and interval, and the edges as (lower end, upper end) pairs sorted by
// lower end, then upper end.
struct CompactRecords {
  const unsigned char* records = nullptr;  // kCompactNodeSize bytes a node, inside the value
  std::vector<std::int32_t> parent;        // -1 on level 0
  std::vector<std::uint16_t> interval;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
};

// Reads `count` records and `edges` neighbour indices, checking every field against the level
// table (already checked): parents, intervals, mu ranges, histogram codes, the order of nodes
// and of neighbours. The one check of format 3's nodes. Throws InputError.
void read_compact_records(ByteReader& in, const std::vector<std::uint32_t>& level_begin,
                          std::size_t count, std::uint32_t edges, CompactRecords& out);

// read_compact_records for `g.nodes.size()` nodes, decoded into g's records and linked.
void read_compact_nodes(ByteReader& in, ArgGraph& g, std::uint32_t edges);

// The colour histograms of every node, kCompactColourSize bytes each.
void write_compact_colour(const ArgGraph& g, ByteWriter& out);
void read_compact_colour(std::string_view payload, ArgGraph& g);

}  // namespace arg
