// Software z-buffer rasterisation of a lit triangle mesh painted by a scalar per vertex.
#pragma once

#include <string_view>
#include <vector>

#include "mesh/mesh.hpp"
#include "render/canvas.hpp"
#include "render/view_camera.hpp"

namespace arg {

enum class Shading { Flat, Smooth };

// "flat" or "smooth"; throws InputError otherwise.
Shading parse_shading(std::string_view text);

// What lies under each pixel centre: the nearest surface's depth (growing towards the
// viewer; -infinity where no triangle was drawn), its triangle (-1: none) and its value.
struct SurfaceBuffer {
  int width = 0, height = 0;
  std::vector<float> depth;
  std::vector<int> face;
  std::vector<float> value;
};

struct SurfacePaint {
  std::vector<Rgb> ramp;  // colours of values 0 .. 1 in equal steps; one entry paints uniformly
  // When > 0, values in [k / bands, (k + 1) / bands) with odd k are drawn a little darker, so
  // the intervals that the Reeb graph slices show as stripes.
  int bands = 0;
  // Each face painted with its own colour (the mesh's C) instead of the ramp, without bands,
  // when the mesh has colours; the ramp otherwise.
  bool own_colours = false;
};

// A ramp of `steps` colours sampled from `colour_of(t)` at t = k / (steps - 1).
template <class ColourOf>
std::vector<Rgb> sample_ramp(ColourOf colour_of, int steps = 256) {
  std::vector<Rgb> ramp;
  for (int k = 0; k < steps; ++k)
    ramp.push_back(colour_of(steps > 1 ? double(k) / (steps - 1) : 0));
  return ramp;
}

// Draws the triangles over `image` with a z-buffer (value: one scalar per vertex, interpolated
// per pixel and looked up in the ramp). Lit by a key light from the upper left and a weaker
// fill light, both two-sided so open meshes show their inner side too. Flat shading uses face
// normals, smooth shading area-weighted vertex normals. Returns what each pixel shows.
SurfaceBuffer rasterise_mesh(Image& image, const Mesh& mesh, const std::vector<double>& value,
                             const ViewCamera& camera, Shading shading, const SurfacePaint& paint);

}  // namespace arg
