// Surface detail: how far smoothing moves the surface, at two scales (hair and faces against
// glaze).
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace arg {

struct DetailOptions {
  int bins = 16;                  // per scale, over log10 of the displacement
  double low = -5, high = -1;     // that range of log10 (RMS radius units); outside: end bins
  std::vector<int> steps{4, 32};  // Taubin iterations of each scale
};

// For each scale, the area-weighted histogram (sums to 1) of how far each vertex moves under that
// many Taubin steps (lambda .5, mu -.53, over the mesh's edges); the scales one after the other.
// Expects the posed mesh (unit RMS radius, as posed_for_descriptors makes it). All zeros for a
// mesh without area.
std::vector<float> surface_detail(const Mesh& posed, const DetailOptions& options = {});

}  // namespace arg
