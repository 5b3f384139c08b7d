// The multiresolution Reeb graph: nodes per level, adjacency, parent links (Hilaga's MRG).
#pragma once

#include <utility>
#include <vector>

#include "mesh/mesh_edges.hpp"
#include "reeb/slice_intervals.hpp"

namespace arg {

struct ReebLevel {
  std::vector<int> interval;  // per node
  std::vector<int> parent;    // per node: node index at the level above (-1 at level 0)
  std::vector<std::pair<int, int>> edges;  // adjacency (i < j), sorted, unique
};

struct ReebGraph {
  std::vector<ReebLevel> levels;  // levels[0] is the coarsest (one interval)
  std::vector<int> piece_node;    // finest-level node of each piece
  int loops = 0;                  // independent cycles of the finest graph (genus estimate)
};

// Finest level: one node per connected set of pieces in an interval (pieces of one interval
// touching along a mesh edge are connected); nodes touch when one triangle has pieces in both.
// Coarser levels merge intervals 2j and 2j+1: connected children become one parent.
ReebGraph reeb_levels(const SlicedSurface& sliced, const MeshEdges& edges, int levels,
                      const StopRequested& stop = {});

}  // namespace arg
