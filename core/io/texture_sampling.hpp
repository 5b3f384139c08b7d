// Sampling a texture image at texture coordinates, and the colour of one textured triangle.
#pragma once

#include <array>

#include "io/image.hpp"

namespace arg::io {

enum class TextureWrap { Repeat, ClampToEdge, MirroredRepeat };

struct TextureSampler {
  TextureWrap wrap_s = TextureWrap::Repeat;
  TextureWrap wrap_t = TextureWrap::Repeat;
  // OBJ (and PLY) put v = 0 at the bottom of the image; glTF puts it at the top.
  bool v_origin_bottom = true;
};

// Bilinear sample, RGB in [0,1].
std::array<float, 3> sample_texture(const Image& image, double s, double t,
                                    const TextureSampler& sampler);

// The colour of a triangle: the mean of the texture at its three corners and at their centroid.
std::array<float, 3> triangle_texture_colour(const Image& image, const double uv[3][2],
                                             const TextureSampler& sampler);

// The mean colour of the whole image (for faces that have no texture coordinates).
std::array<float, 3> mean_texture_colour(const Image& image);

}  // namespace arg::io
