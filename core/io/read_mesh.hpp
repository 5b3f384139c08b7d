// Reading a mesh from bytes in memory, whatever its format (detected from the content).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "common/limits.hpp"
#include "io/image.hpp"
#include "io/polygon_soup.hpp"
#include "io/texture_sampling.hpp"
#include "mesh/mesh.hpp"

namespace arg {

enum class MeshFormat { Off, Obj, Ply, Stl, Glb, Unknown };

// "OFF", "OBJ", "PLY", "STL", "GLB" or "unknown".
const char* format_name(MeshFormat format);

// Guesses the format from the first bytes (magic numbers, keywords); never throws.
MeshFormat detect_mesh_format(std::string_view bytes);

// The most distinct images an OBJ's material textures map; the 3D view loads at most this many
// (argtool view-data keeps the same cap for a GLB's).
constexpr std::size_t kMaxDisplayImages = 16;

// A texture image for the faces of one OBJ material (usemtl NAME), for display only.
struct MaterialTexture {
  std::string material;
  std::string_view image;  // PNG, JPEG, TGA or BMP bytes
};

struct ReadOptions {
  Limits limits;
  // Optional texture image (PNG, JPEG, TGA, ...) for formats that keep it outside the mesh (OBJ).
  std::string_view texture;
  // For display only (read with a MeshTexture): each OBJ material's texture. The mesh and its
  // colours never depend on them (colour comes from `texture` alone); ignored by other formats.
  std::vector<MaterialTexture> material_textures;
  StopRequested stop;
  // The format, when the caller knows it; Unknown means detect it from the content.
  MeshFormat format = MeshFormat::Unknown;
  // Called once the file has said how large it is, before the reader allocates for it: the
  // counts a PLY or OFF header declares, a binary STL's triangles (vertices taken as half of
  // them, a closed surface's count), an OBJ's after its first scan. Faces are polygons as
  // stored, so at most the triangles to come. It may throw to refuse the input (a build's
  // memory estimate does); not called for GLB, whose counts are spread over its accessors.
  std::function<void(std::size_t vertices, std::size_t faces)> declared_counts;
};

// What the reader saw and did, for `argtool info` and error reports.
struct ReadReport {
  MeshFormat format = MeshFormat::Unknown;
  std::size_t vertices_read = 0;
  std::size_t faces_read = 0;             // polygons as stored in the file
  std::size_t polygons_triangulated = 0;  // faces with more than three corners
  std::string colour_source = "none";     // "texture", "vertex", "face", "material" or "none"
  std::string variant;                    // e.g. "binary_big_endian", "COFF", "ascii"
  std::size_t triangles = 0;              // rows of the returned mesh's F
  std::size_t faces_skipped = 0;          // faces with fewer than three distinct corners
  std::vector<std::string> warnings;      // what was ignored, e.g. an unusable texture
};

// The textures of a mesh and where they lie on each triangle, kept beside the mesh for display
// (the 3D view maps them); the method never reads them, and the mesh is the same whether they
// are asked for or not.
struct MeshTexture {
  // Each image once, as the file or the caller gave it (PNG, JPEG, TGA, BMP), and decoded.
  std::vector<io::DisplayImage> images;
  // How triangles map them: an image, its sampler, the colour multiplying it. An OBJ has one
  // (its texture, white); a GLB one per base colour texture and baseColorFactor its materials use.
  std::vector<io::DisplayMap> maps;
  // 6 per row of the mesh's F: (s, t) at corners 0, 1, 2; NaN for a triangle without them (a
  // GLB primitive without a texture, an OBJ face without vt).
  std::vector<float> uv;
  // Per row of the mesh's F: its index in maps, or -1 (and NaN in uv) when it has none.
  std::vector<int> triangle_map;

  bool empty() const { return maps.empty() || uv.empty(); }
};

// Parses `bytes` into a triangle mesh with per-triangle colour when the input has any.
// Throws InputError (naming format and line/offset) or LimitError. With `texture`, also keeps
// the texture coordinates of an OBJ read with its texture, or of each GLB primitive whose base
// colour texture decodes, with those textures (left empty when there is none). An OBJ read with
// material_textures maps each face by its material instead (a material without a usable image,
// or a face before any usemtl, maps none; the warnings name such materials).
Mesh read_mesh(std::string_view bytes, const ReadOptions& options = {},
               ReadReport* report = nullptr, MeshTexture* texture = nullptr);

}  // namespace arg
