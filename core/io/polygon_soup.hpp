// The polygon soup every mesh reader fills before triangulation, and the builder that checks it.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "common/limits.hpp"
#include "io/image.hpp"
#include "io/texture_sampling.hpp"

namespace arg::io {

// An image a reader found for display: as the file has it, and decoded.
struct DisplayImage {
  std::string encoded;
  Image image;
};

// How faces map an image: its index in the images, its sampler, and the colour that multiplies
// it (a glTF material's baseColorFactor, RGB).
struct DisplayMap {
  int image = 0;
  TextureSampler sampler;
  std::array<float, 3> factor{1, 1, 1};
};

// Vertices and polygons as the file stores them, with whatever colour or texture coordinates it
// carries. Optional per-element arrays are either empty or full length, NaN meaning "not given".
struct PolygonSoup {
  std::vector<double> xyz;                 // 3 per vertex
  std::vector<int> corners;                // the corners of all faces, one face after the other
  std::vector<std::size_t> face_begin{0};  // face f owns corners[face_begin[f], face_begin[f+1])
  std::vector<float> vertex_rgb;           // 3 per vertex, in [0,1]
  std::vector<float> face_rgb;             // 3 per face, in [0,1]
  std::vector<float> vertex_uv;            // 2 per vertex
  std::vector<float> corner_uv;            // 2 per corner
  // What face_rgb stands for when the mesh takes its colour from it ("face", or "texture",
  // "vertex", "material" when a reader computed per-face colour itself, as the GLB reader does).
  std::string face_colour_source = "face";
  // For display only (read_mesh's MeshTexture), kept when keep_display_texture is set: a reader
  // that samples its own textures (GLB) puts the corner texture coordinates of its textured
  // faces in corner_uv, each image they use in display_images, each (image, sampler, factor) in
  // display_maps and each face's map in face_display_map (-1: none; empty when no face has one).
  bool keep_display_texture = false;
  std::vector<DisplayImage> display_images;
  std::vector<DisplayMap> display_maps;
  std::vector<int> face_display_map;
  // Also for display, kept when keep_face_materials is set (an OBJ read with material textures):
  // the materials its faces use (usemtl names, in order of first use) and each face's index in
  // them (-1: none; empty when the faces could not be matched to their lines).
  bool keep_face_materials = false;
  std::vector<std::string> material_names;
  std::vector<int> face_material;
  std::size_t faces_seen = 0;     // faces in the file, including skipped ones
  std::size_t faces_skipped = 0;  // faces with fewer than three corners

  std::size_t vertex_count() const { return xyz.size() / 3; }
  std::size_t face_count() const { return face_begin.size() - 1; }
};

// Appends to a PolygonSoup while enforcing the Limits, finite coordinates and (optionally at once)
// valid corner indices. Its errors name the format and, through the locator, the line or offset.
class SoupBuilder {
 public:
  using Locate = std::function<std::string()>;
  using DeclaredCounts = std::function<void(std::size_t vertices, std::size_t faces)>;

  SoupBuilder(PolygonSoup& soup, std::string format, const Limits& limits,
              const StopRequested& stop);

  // Where the reader is now ("line 12", "byte offset 3400"); empty if unknown.
  void set_locator(Locate locate) { locate_ = std::move(locate); }
  // When true, corner indices are checked against the vertices read so far (formats whose
  // vertices come before their faces); otherwise check_indices() does it at the end.
  void set_immediate_index_check(bool on) { immediate_index_check_ = on; }
  // The caller's check of the counts a file declares (ReadOptions::declared_counts).
  void set_declared_counts_check(DeclaredCounts check) { declared_check_ = std::move(check); }
  // Readers call this once they know the counts and before they allocate for them.
  void declared_counts(std::size_t vertices, std::size_t faces) const {
    if (declared_check_) declared_check_(vertices, faces);
  }

  int add_vertex(double x, double y, double z);
  // A vertex whose coordinates follow through set_vertex (an OpenMesh importer gets the point
  // later).
  int add_vertex_unset();
  void set_vertex(int v, double x, double y, double z);
  // Returns the face index, or -1 when the face has fewer than three corners and is skipped.
  int add_face(const int* indices, std::size_t count);
  void set_vertex_colour(int v, float r, float g, float b);
  void set_face_colour(int f, float r, float g, float b);
  void set_vertex_uv(int v, float s, float t);
  // Texture coordinates for the corners of face f (2 floats each); ignored unless one per corner.
  void set_corner_uvs(int f, const float* uv, std::size_t count);

  // Throws InputError naming the first face whose corner is not a vertex.
  void check_indices() const;

  std::string where() const;
  [[noreturn]] void fail(const std::string& message) const;
  [[noreturn]] void fail_limit(const std::string& message) const;
  const std::string& format() const { return format_; }
  const Limits& limits() const { return limits_; }
  PolygonSoup& soup() { return soup_; }
  void poll();

 private:
  PolygonSoup& soup_;
  std::string format_;
  Limits limits_;
  const StopRequested& stop_;
  Locate locate_;
  DeclaredCounts declared_check_;
  bool immediate_index_check_ = true;
  std::size_t triangles_ = 0;
  std::size_t ticks_ = 0;
};

// Throws InputError "<format>: <where>: <message>" (where may be empty).
[[noreturn]] void throw_input_error(const std::string& format, const std::string& where,
                                    const std::string& message);

// Rejects a header's vertex and face counts that the `left` bytes after it cannot hold (at
// least `min_vertex_bytes` and `min_face_bytes` each) or that exceed the caps, before anything
// is allocated for them. InputError / LimitError through `out`; then the caller's check of the
// counts (SoupBuilder::declared_counts).
void check_declared_counts(SoupBuilder& out, std::size_t vertices, std::size_t faces,
                           std::size_t min_vertex_bytes, std::size_t min_face_bytes,
                           std::size_t left);

}  // namespace arg::io
