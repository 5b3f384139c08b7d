// Shape-DNA (Reuter et al. 2006): the first eigenvalues of the Laplace-Beltrami operator.
#pragma once

#include <vector>

#include "common/limits.hpp"
#include "graph/whole_shape_layout.hpp"
#include "mesh/mesh.hpp"

namespace arg {

// The first `count` non-zero eigenvalues lambda_i of -Delta u = lambda u on the largest
// component of `mesh` (cotangent weights, lumped mass, free boundary), each times area / (4 pi
// i), which Weyl's law brings near 1 and which no scaling changes. They depend only on the
// surface's metric, so bending (a new pose) leaves them nearly as they are, while proportions
// and topology change them: the intrinsic descriptor of the ARG's whole-shape terms. Computed
// on a copy whose short edges are collapsed to about 2000 vertices (the low eigenvalues barely
// notice, and the solve is several times cheaper). Empty when the eigen-solver does not converge or
// the mesh is too small (fewer than 3 count vertices). Deterministic.
std::vector<float> laplace_spectrum(const Mesh& mesh, int count = kSpectrumSize,
                                    const StopRequested& stop = {});

// The Euclidean distance of the logarithms over 5, capped at 1 (unrelated models lie about 2.3
// apart on SHREC 2007 and SHREC 2011). Either vector empty or of another size: 1.
double spectrum_distance(const std::vector<float>& a, const std::vector<float>& b);
// The same of two arrays of `count` (> 0) values.
double spectrum_distance(const float* a, const float* b, std::size_t count);

}  // namespace arg
