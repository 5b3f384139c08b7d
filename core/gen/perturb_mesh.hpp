// A seeded random rotation, scale and jitter of a mesh, for invariance and robustness tests.
#pragma once

#include <cstdint>

#include "mesh/mesh.hpp"

namespace arg {

// Turns `mesh` by a uniformly random rotation about its bounding-box centre, scales it by a
// factor uniform in [0.5, 2] about that centre, then moves every vertex by a random offset
// uniform in a ball of radius `noise` times the input's mean edge length (0 = no jitter; keep it
// well below 0.5 so no triangle flips). Connectivity and colours are kept. The same (mesh,
// seed, noise) gives bit-identical output on every platform. Throws InputError for a negative
// or non-finite noise.
Mesh perturb_mesh(const Mesh& mesh, std::uint64_t seed, double noise);

}  // namespace arg
