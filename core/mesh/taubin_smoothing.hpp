// Taubin's lambda|mu smoothing: a low-pass filter on vertex positions that does not shrink.
#pragma once

#include "common/limits.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_edges.hpp"

namespace arg {

// `iterations` pairs of umbrella steps v += lambda (mean of neighbours - v), then the same with
// mu (Taubin 1995: lambda 0.5, mu -0.53 pass low frequencies and damp the highest, so noise of
// the size of an edge fades while the shape keeps its size). Connectivity and colours are kept.
Mesh taubin_smoothing(const Mesh& mesh, const MeshEdges& edges, int iterations, double lambda = 0.5,
                      double mu = -0.53, const StopRequested& stop = {});

}  // namespace arg
