// A closed, manifold stand-in for a polygon soup, an open mesh or a mesh of several parts.
#pragma once

#include <vector>

#include "common/limits.hpp"
#include "mesh/mesh.hpp"

namespace arg {

struct ProxyOptions {
  int resolution = 48;  // grid cells along the longest side of the bounding box
  double offset = 1.0;  // in cells: how far outside the input the proxy surface lies
};

struct Proxy {
  Mesh mesh;                     // closed, manifold, oriented outwards; colour from `source`
  std::vector<int> source_face;  // per proxy triangle: the nearest triangle of the input
};

// The boundary of everything a viewer outside cannot reach without coming within `offset`
// cells of the input: holes and cracks narrower than about two offsets are closed, touching
// or interpenetrating parts become one surface, enclosed cavities are filled, a sheet becomes
// a thin closed slab. mu, the Reeb graph and the node attributes are then defined as on a
// solid, which the geodesic integral needs (Tung and Schmitt: "mu works with meshes that have
// only one connected component"). Parts farther apart than two offsets stay separate
// components. Needs a registered distance field (mesh/distance_field.hpp).
Proxy watertight_proxy(const Mesh& mesh, const ProxyOptions& options = {},
                       const StopRequested& stop = {});

}  // namespace arg
