// The first stages every consumer of the method shares: clean, pose, and the surface mu runs on.
#pragma once

#include <cmath>
#include <optional>

#include "common/limits.hpp"
#include "mesh/clean_mesh.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_edges.hpp"
#include "mesh/normalize_pose.hpp"
#include "pipeline/build_options.hpp"

namespace arg {

struct PreparedSurface {
  CleanReport clean;
  Pose pose;
  std::size_t components = 0;  // connected components of the cleaned mesh
  double boundary_length = 0;  // of its boundary edges, in the units of `posed`
  double area = 0;             // of `posed`
  Mesh posed;                  // the cleaned mesh, centred, aligned and scaled (apply_pose)
  MeshEdges posed_edges;       // its edges
  std::optional<Mesh> proxy;   // its watertight proxy, when options.surface chose one

  // A boundary longer than sqrt(area) (kFlagWideOpen): a sheet, or openings far larger than
  // holes in a scan; geodesics on it are not those of the closed shape.
  bool wide_open() const { return boundary_length > std::sqrt(area); }

  // What mu, the Reeb graph and the node attributes are computed on.
  const Mesh& surface() const { return proxy ? *proxy : posed; }
};

// Cleans `input`, normalises its pose and, for surface=proxy (or auto on a mesh in pieces or
// with non-manifold edges: build_options.hpp), makes its proxy in the same frame. Throws
// InputError for a mesh without area.
PreparedSurface prepare_surface(const Mesh& input, const BuildOptions& options,
                                const StopRequested& stop = {});

}  // namespace arg
