// PANORAMA (Papadakis et al. 2010): low-frequency Fourier magnitudes of the panoramic views.
#pragma once

#include <vector>

#include "features/panoramic_views.hpp"
#include "graph/whole_shape_layout.hpp"
#include "mesh/mesh.hpp"

namespace arg {

inline constexpr int kPanoramaHeight = 64;      // N: views of 128 angles x 64 heights
inline constexpr double kPanoramaRadius = 2.5;  // cylinder radius, in RMS radii of the surface

// Per view, for u = 0..angular and v = 0..axial, (|F(v, u)| + |F(-v, u)|) / 2 / (N * 2N) of
// the view's 2D discrete Fourier transform (v along the axis, u around it). A turn about the
// axis only shifts the view around, which leaves the magnitudes unchanged; averaging v and -v
// makes them blind to the axis's sign as well. So only the choice of axes matters.
std::vector<float> panorama_features(const PanoramicViews& views, int angular, int axial);

// Per view, the mean and the standard deviation of the absolute Haar wavelet coefficients in
// each band of a `levels`-level decomposition (three detail bands per level, then what is
// left), 2 (3 levels + 1) values per view: how much detail the views hold at each scale,
// which the low Fourier frequencies leave out (Papadakis et al.'s second part).
std::vector<float> panorama_wavelet_features(const PanoramicViews& views, int levels);

// The stored descriptor: per frame the Fourier then the wavelet features of the views, first
// in the frame of the mesh (the surface's principal axes), then in its normals' frame
// (normal_pose), kPanoramaSize values. Expects the centred, scaled, aligned frame of apply_pose.
std::vector<float> panorama_descriptor(const Mesh& posed, const StopRequested& stop = {});

// Per frame, the mean of two distances in [0, 1]: the L1 distance of the Fourier features over
// 6 (capped at 1; unrelated models lie about 3 apart: the median on SHREC 2007, SHREC 2011 and
// the PSB soups is 2.4 to 2.9) and the Canberra distance of the wavelet features (Papadakis et
// al. compare them so; with 0.01 added to each denominator) over their count. The better (smaller)
// of the two frames counts; a frame is compared with the same frame of the other model. Either
// vector missing or of the wrong size: 1.
double panorama_distance(const std::vector<float>& a, const std::vector<float>& b);
// The same of two arrays of kPanoramaSize values.
double panorama_distance(const float* a, const float* b);

}  // namespace arg
