// The Augmented Reeb Graph in memory: fixed-size node records laid out as in the binary form.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "common/build_options.hpp"

namespace arg {

inline constexpr int kCordBins = 8;
inline constexpr int kCurvatureBins = 8;
inline constexpr int kColourBins = 8;  // per channel
inline constexpr int kGlobalDims = 48;

// One node of the multiresolution graph. Plain data; the binary form stores these records
// verbatim (little-endian), so reading is validation plus one copy.
struct ArgNode {
  std::uint16_t level = 0;     // 0 (coarsest) .. levels
  std::uint16_t interval = 0;  // index of the mu interval at this level, 0 .. 2^level - 1
  std::int32_t parent = -1;    // node index at level - 1; -1 at level 0
  std::uint32_t child_begin = 0, child_count = 0;  // range in ArgGraph::children
  std::uint32_t adj_begin = 0, adj_count = 0;      // range in ArgGraph::adjacency
  float a = 0;                                     // relative area, a level sums to 1/(levels+1)
  float l = 0;       // relative mu length, a level sums to 1/(levels+1)
  float r = 0;       // barycentre in spherical coordinates in the aligned, scaled frame
  float theta = 0;   // arctan(y/x) in [-pi/2, pi/2]
  float phi = 0;     // arccos(z/r) in [0, pi]
  float v = 0;       // relative volume, a level sums to about 1/(levels+1) on closed meshes
  float mu_min = 0;  // mu range actually covered by the node's region
  float mu_max = 0;
  std::array<float, kCordBins> cords{};           // area-weighted, sums to a
  std::array<float, kCurvatureBins> curv_mean{};  // area-weighted, sums to a
  std::array<float, kCurvatureBins> curv_gauss{};
  std::array<float, 3 * kColourBins> colour{};  // R, G, B histograms, each sums to a (or 0)
};

// Whole-model facts kept in the header.
// Summary flags. Open: the mesh had boundary edges. Proxy: mu and the graph were computed on
// its watertight proxy. Wide open: its boundary is longer than 4 sqrt(area) (a sheet, or
// openings far larger than a scan's holes), so its spectrum is not the closed shape's.
// Pooled: the graph held more nodes than a level may keep, and its smallest connected
// components were pooled into one (pipeline/pool_fragments.hpp).
inline constexpr std::uint16_t kFlagOpen = 1, kFlagProxy = 2, kFlagWideOpen = 4, kFlagPooled = 8;

struct ArgSummary {
  std::uint32_t triangles = 0;  // after cleaning and refinement
  std::uint32_t vertices = 0;
  std::uint16_t components = 0;  // connected components of the cleaned mesh
  std::uint16_t genus = 0;       // independent loops of the finest Reeb graph
  std::uint16_t has_colour = 0;
  std::uint16_t flags = 0;   // kFlagOpen | kFlagProxy | kFlagWideOpen | kFlagPooled
  float area = 0;            // surface area before scale normalisation
  float volume = 0;          // enclosed volume before scale normalisation
  float scale = 0;           // the factor applied to reach unit RMS radius
  std::uint16_t pooled = 0;  // components pooled into one (format 3; capped at 65,535)
};

struct ArgGraph {
  std::uint16_t format = 3;  // binary format it was read in (or will be written in): 1 to 3
  BuildOptions options;
  std::uint32_t builder_version = 0;  // major * 10000 + minor * 100 + patch
  ArgSummary summary;
  std::array<float, kGlobalDims> global{};  // compact descriptor for filtering (D2, cords, stats)
  std::vector<ArgNode> nodes;               // sorted by (level, interval)
  std::vector<std::uint32_t> level_begin;   // levels + 2 entries: nodes of level r are
                                            // [level_begin[r], level_begin[r + 1])
  std::vector<std::uint32_t> children;      // CSR targets of ArgNode::child_begin/count
  std::vector<std::uint32_t> adjacency;     // CSR targets of ArgNode::adj_begin/count
  // Whole-shape descriptors that SIM weighs beside the graph (empty in format-1 values):
  std::vector<float> panorama;  // kPanoramaSize values (graph/whole_shape_layout.hpp)
  std::vector<float> spectrum;  // kSpectrumSize values (graph/whole_shape_layout.hpp)

  int levels() const { return options.levels; }
};

// Builder version as stored in ARGs made by this build of the core.
std::uint32_t current_builder_version();

// Fills the links from the nodes' parents and an undirected edge list: each node's children in
// index order, its neighbours sorted, repeated edges once. Node ranges must be set already.
void link_graph(ArgGraph& g, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges);

}  // namespace arg
