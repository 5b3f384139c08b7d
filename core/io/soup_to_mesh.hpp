// Turning a polygon soup into the pipeline's triangle mesh, with one colour per triangle.
#pragma once

#include <vector>

#include "io/image.hpp"
#include "io/polygon_soup.hpp"
#include "io/read_mesh.hpp"
#include "io/texture_sampling.hpp"
#include "mesh/mesh.hpp"

namespace arg::io {

// Triangulates every face (repeated consecutive corners removed first), and colours each
// triangle from, in this order of preference: `texture` sampled at the corners' texture
// coordinates (per corner, else per vertex; faces without any get the texture's mean colour),
// the per-face colours, the mean of its corners' vertex colours. Fills polygons_triangulated,
// triangles, faces_skipped, colour_source and warnings of `report`. Throws InputError when no
// triangle is left. With `triangle_uv`, also gives each triangle's texture coordinates as the
// colouring above takes them (6 per triangle, NaN for one without), whatever `texture` is.
Mesh soup_to_mesh(const PolygonSoup& soup, const Image* texture, const TextureSampler& sampler,
                  SoupBuilder& out, ReadReport& report, std::vector<float>* triangle_uv = nullptr,
                  std::vector<int>* triangle_face = nullptr);

// Whether the soup has texture coordinates a texture could be sampled at.
bool soup_has_texture_coordinates(const PolygonSoup& soup);

}  // namespace arg::io
