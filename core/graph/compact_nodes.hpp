// Format 3's node records: 39 bytes a node, neighbours as 2-byte indices, colour on its own.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "common/byte_io.hpp"
#include "graph/arg_graph.hpp"

namespace arg {

// One record, little-endian: parent's index in the level above (0xffff on level 0), interval,
// number of neighbours in the next interval, mu range within the interval (2 bytes), theta,
// phi and r (one byte each), area, length and volume (2 bytes each), then the cords, mean and
// Gaussian curvature histograms (8 bytes each, as fractions of the area). See quantise.hpp.
inline constexpr std::size_t kCompactNodeSize = 15 + kCordBins + 2 * kCurvatureBins;
inline constexpr std::size_t kCompactColourSize = 3 * kColourBins;  // per node, fractions of a
// The barycentre's radius is stored up to 4 RMS radii (matching reads it up to 2).
inline constexpr float kMaxStoredRadius = 4.0f;

// Per node, its neighbours in the next interval (the records' third byte): each undirected
// edge is counted once, at its lower end.
std::vector<std::uint32_t> up_neighbour_counts(const ArgGraph& g);

// Every record, then every node's neighbours in the next interval as indices in their level
// (a node with 255 or more has the count beyond 255 in 2 bytes before its list). `up` is
// up_neighbour_counts(g). Expects a level of at most 65,535 nodes (pool_fragments bounds them
// far lower).
void write_compact_nodes(const ArgGraph& g, const std::vector<std::uint32_t>& up, ByteWriter& out);

// Reads `g.nodes.size()` records and `edges` neighbour indices, checking every field against
// the level table (already checked), and links the graph. Throws InputError.
void read_compact_nodes(ByteReader& in, ArgGraph& g, std::uint32_t edges);

// The colour histograms of every node, kCompactColourSize bytes each.
void write_compact_colour(const ArgGraph& g, ByteWriter& out);
void read_compact_colour(std::string_view payload, ArgGraph& g);

}  // namespace arg
