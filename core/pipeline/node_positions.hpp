// Where an ARG's nodes sit on its mesh: 3D barycentres in the aligned frame, and mu per vertex.
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "common/build_options.hpp"
#include "common/limits.hpp"
#include "mesh/mesh.hpp"
#include "mesh/normalize_pose.hpp"

namespace arg {

// One level of the Reeb graph laid over the surface. Node k here is node k of the same level of
// the ArgGraph that build_arg makes from the same mesh and options.
struct NodePlacementLevel {
  std::vector<Eigen::Vector3d> centre;     // area-weighted barycentre of the node's region
  std::vector<double> area;                // share of the surface, sums to 1 over the level
  std::vector<int> interval;               // mu interval at this level
  std::vector<std::pair<int, int>> edges;  // adjacency (i < j), sorted
  std::vector<int> parent;                 // node index at the level above; -1 at level 0
};

struct NodePositions {
  // The surface the graph was built on (the cleaned, pose-normalised mesh, or its watertight
  // proxy when the build used one), in the frame in which the ARG measures its barycentres
  // (centre of mass at the origin, principal axes on x, y, z, unit RMS radius). A mesh built on
  // a collapsed copy (PreparedSurface::coarse) is shown as the fine cleaned mesh: mu and the
  // nodes' pieces are the copy's, carried through the collapse's vertex map; one built on a
  // proxy, with ShownSurface::Own, as the model's own surface.
  Mesh mesh;
  bool on_proxy = false;                   // the graph was built on a watertight proxy
  Pose pose;                               // what took the input into that frame (apply_pose)
  std::vector<double> mu;                  // mu_N in [0, 1] per vertex of `mesh`
  std::vector<NodePlacementLevel> levels;  // levels[0] is the coarsest
  // Which finest node owns each part of a triangle: triangle f has one piece per finest mu
  // interval from face_first_interval[f], numbered from face_piece_begin[f] (size F + 1).
  std::vector<int> face_first_interval, face_piece_begin;
  std::vector<int> piece_node;
};

// What a picture of a model built on its watertight proxy shows.
enum class ShownSurface {
  Built,  // the surface the graph was built on: the proxy
  // The model's own surface (cleaned and posed, in pieces as it came): each vertex takes the mu
  // of the proxy's nearest vertex and each triangle the pieces of the proxy triangle whose
  // centre is nearest its centre, so node_at answers for it; the nodes' barycentres stay the
  // proxy's, as the ARG measured them. A proxy blurs what is smaller than its voxels (a soup's
  // thin parts and small pieces, their textures); a curator looks at the model itself.
  Own,
};

// Reruns the geometric part of build_arg (clean, pose, mu, slice, Reeb levels) and keeps what
// the ARG throws away but a picture needs. The ARG stores barycentres as (r, theta, phi) with
// theta = atan(y/x), which cannot tell x from -x, so drawings take them from here instead.
// Throws like build_arg.
NodePositions node_positions(const Mesh& mesh, const BuildOptions& options = {},
                             const StopRequested& stop = {},
                             ShownSurface shown = ShownSurface::Built);

// The node of `level` that owns the point of triangle `face` where mu is `mu` (for instance
// the surface seen at a pixel); -1 when face or level is out of range.
int node_at(const NodePositions& positions, int level, int face, double mu);

}  // namespace arg
