// Attributes of every Reeb graph node: MRG's a and l plus the ARG's geometry and features.
#pragma once

#include <vector>

#include "features/curvature.hpp"
#include "graph/arg_graph.hpp"
#include "mesh/mesh.hpp"
#include "reeb/reeb_levels.hpp"
#include "reeb/slice_intervals.hpp"

namespace arg {

// Per level, per node (in ReebGraph order): every ArgNode field except the link fields.
// The mesh must be pose-normalised (centre at the origin, principal axes, unit RMS radius).
// a, v and the curvature and colour histograms are computed on the finest level and summed
// into parents; l, the barycentre and the cords histogram are measured on each node's own
// region (the paper defines cords about the node's barycentre, which is not additive).
// Returns the total enclosed volume through `volume` (0 when the surface encloses none).
std::vector<std::vector<ArgNode>> node_attributes(const Mesh& mesh, const SlicedSurface& sliced,
                                                  const ReebGraph& reeb,
                                                  const TriangleCurvature& curvature,
                                                  double* volume = nullptr,
                                                  const StopRequested& stop = {});

}  // namespace arg
