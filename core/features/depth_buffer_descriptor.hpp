// Vranic's depth-buffer descriptor: low-frequency 2D Fourier magnitudes of six depth images.
#pragma once

#include <vector>

#include "features/depth_images.hpp"

namespace arg {

// For each view, |F(u, v)| / N^2 of the image's discrete Fourier transform at the frequencies
// with |u| + |v| <= band, one of each conjugate pair (v > 0, or v = 0 and u >= 0): band^2 +
// band + 1 values per view, the mean depth (u = v = 0) first. Magnitudes do not change when
// the surface shifts by whole pixels, which absorbs small errors of the centring.
std::vector<float> depth_buffer_descriptor(const DepthImages& images, int band);

}  // namespace arg
