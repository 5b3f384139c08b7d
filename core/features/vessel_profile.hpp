// The vessel profile: a shape's radius along its axis of symmetry, as pottery is classified.
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace arg {

struct ProfileOptions {
  int bins = 24;        // height bins between the surface's low and high tail quantiles
  double tail = 0.01;   // the share of the surface left below the first bin and above the last
  int samples = 16384;  // area-uniform surface points, from a fixed seed
  int harmonics = 6;    // of the radius about the axis, for the symmetry score
};

struct VesselProfile {
  int axis = 0;              // 0, 1, 2: the x, y or z axis of the posed frame
  double symmetry = 0;       // 1 for a surface of revolution about the axis, lower the less round
  double low = 0, high = 0;  // the heights the bins span (the surface's tail quantiles)
  // Per height bin, lowest height first; a bin without samples has zero in all three.
  std::vector<double> area;    // the fraction of the surface in the bin; sums to 1
  std::vector<double> radius;  // the mean distance of its samples to the axis
  std::vector<double> spread;  // their standard deviation (walls, handles, a square section)
};

// The profile about one axis of `posed` (centred, aligned, unit RMS radius, as
// posed_for_descriptors makes it). Symmetry is 1 minus the area-weighted mean, over the height
// bins, of how much the radius varies with the direction about the axis (the RMS of its first
// harmonics relative to the mean radius, clipped to [0, 1]).
VesselProfile profile_about_axis(const Mesh& posed, int axis, const ProfileOptions& options = {});

// The profile about whichever of the three axes gives the highest symmetry (the first on ties).
VesselProfile vessel_profile(const Mesh& posed, const ProfileOptions& options = {});

// The descriptor the quality harness stores: symmetry, height (high - low), then area, radius
// and spread per bin, the last two divided by the surface's mean radius.
std::vector<float> profile_vector(const VesselProfile& profile);

// L1 distance between two profile vectors over height, area, radius and spread, the smaller of
// the two directions along the axis (an upturned vase is the same vase); symmetry is not
// compared.
// Vectors of different sizes are as far apart as the sizes allow: the sum of both's magnitudes.
double profile_distance(const std::vector<float>& a, const std::vector<float>& b);

}  // namespace arg
