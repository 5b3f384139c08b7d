// A closed, manifold stand-in for a polygon soup, an open mesh or a mesh of several parts.
#pragma once

#include <vector>

#include "common/limits.hpp"
#include "mesh/mesh.hpp"

namespace arg {

struct ProxyOptions {
  int resolution = 48;  // grid cells along the longest side of the bounding box
  double offset = 1.0;  // in cells: how far outside the input the proxy surface lies
  // Of the 26 lattice directions, how many a point the flood from the border reached must see
  // out along (to the border, never within `offset` of the input) to stay outside; 0 keeps
  // the flood as it is. 8 was chosen on psb_soups' clean models and their copies with holes,
  // noise and resampling (docs/BENCHMARKS.md). A corner step is sqrt(3) cells long, so with an
  // offset under 0.87 cells a line of sight could pass between two points of a wall's band.
  int min_open = 8;
};

struct Proxy {
  Mesh mesh;                     // closed, manifold, oriented outwards; colour from `source`
  std::vector<int> source_face;  // per proxy triangle: the nearest triangle of the input
};

// The boundary of everything a viewer outside cannot reach without coming within `offset`
// cells of the input: holes and cracks narrower than about two offsets are closed, touching
// or interpenetrating parts become one surface, enclosed cavities are filled, a sheet becomes
// a thin closed slab. A hole wider than that lets the flood in, but what it reached inside a
// shape sees out only through the holes: such points (fewer than `min_open` open directions)
// are filled too, so a closed shape with large holes keeps its volume, while a sheet or a dish,
// whose points see out widely, stays thin. The inside of a deep bowl, which sees out only
// through its rim, is filled as well (the views, made from the model as given, still see the
// bowl). mu, the Reeb graph and the node attributes are then defined as on a
// solid, which the geodesic integral needs (Tung and Schmitt: "mu works with meshes that have
// only one connected component"). Parts farther apart than two offsets stay separate
// components. Needs a registered distance field (mesh/distance_field.hpp).
Proxy watertight_proxy(const Mesh& mesh, const ProxyOptions& options = {},
                       const StopRequested& stop = {});

}  // namespace arg
