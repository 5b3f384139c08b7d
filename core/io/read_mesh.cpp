// Reading a mesh from bytes in memory: format dispatch, texture, triangulation and the report.
#include "io/read_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "common/errors.hpp"
#include "io/format_readers.hpp"
#include "io/image.hpp"
#include "io/soup_to_mesh.hpp"

namespace arg {

Mesh read_mesh(std::string_view bytes, const ReadOptions& options, ReadReport* report_out,
               MeshTexture* texture_out) {
  const Limits& limits = options.limits;
  if (bytes.size() > limits.max_input_bytes) {
    throw LimitError("mesh input of " + std::to_string(bytes.size()) + " bytes, more than " +
                     std::to_string(limits.max_input_bytes));
  }
  ReadReport report;
  report.format =
      options.format != MeshFormat::Unknown ? options.format : detect_mesh_format(bytes);
  if (report.format == MeshFormat::Unknown) {
    throw InputError("unrecognised mesh format (expected OFF, OBJ, PLY, STL or GLB)");
  }
  io::PolygonSoup soup;
  io::SoupBuilder builder(soup, format_name(report.format), limits, options.stop);
  builder.set_declared_counts_check(options.declared_counts);
  soup.keep_display_texture = texture_out != nullptr;
  switch (report.format) {
    case MeshFormat::Off:
      io::read_off(bytes, builder, report);
      break;
    case MeshFormat::Obj:
      io::read_obj(bytes, builder, report);
      break;
    case MeshFormat::Ply:
      io::read_ply(bytes, builder, report);
      break;
    case MeshFormat::Stl:
      io::read_stl(bytes, builder, report);
      break;
    case MeshFormat::Glb:
      io::read_glb(bytes, builder, report);
      break;
    case MeshFormat::Unknown:
      break;
  }
  check_interrupt(options.stop);

  // A separate texture only means something for a mesh with texture coordinates of its own.
  std::optional<Image> texture;
  if (!options.texture.empty()) {
    if (report.format == MeshFormat::Glb) {
      report.warnings.push_back("the separate texture is ignored: GLB embeds its textures");
    } else if (!io::soup_has_texture_coordinates(soup)) {
      report.warnings.push_back(
          "the separate texture is ignored: the mesh has no texture coordinates");
    } else {
      texture = decode_image(options.texture, limits);
    }
  }
  io::TextureSampler sampler;  // OBJ and PLY: repeat, v = 0 at the bottom
  std::vector<float> triangle_uv;
  std::vector<int> triangle_face;
  Mesh mesh = io::soup_to_mesh(soup, texture ? &*texture : nullptr, sampler, builder, report,
                               texture_out ? &triangle_uv : nullptr,
                               texture_out ? &triangle_face : nullptr);
  if (texture_out) {
    *texture_out = MeshTexture{};
    // The textures the coordinates refer to: the caller's (OBJ, PLY) for every triangle that
    // has coordinates, or those a GLB's reader kept, by the map of each triangle's face.
    const std::size_t triangles = triangle_face.size();
    std::vector<int> map(triangles, -1);
    if (texture) {
      texture_out->images.push_back({std::string(options.texture), std::move(*texture)});
      texture_out->maps.push_back({0, sampler, {1, 1, 1}});
      std::fill(map.begin(), map.end(), 0);
    } else if (!soup.display_maps.empty()) {
      texture_out->images = std::move(soup.display_images);
      texture_out->maps = std::move(soup.display_maps);
      for (std::size_t t = 0; t < triangles; ++t) {
        const auto f = std::size_t(triangle_face[t]);
        if (f < soup.face_display_map.size()) map[t] = soup.face_display_map[f];
      }
    }
    if (!texture_out->maps.empty()) {
      for (std::size_t t = 0; t < triangles; ++t) {
        bool finite = true;
        for (std::size_t i = 0; i < 6; ++i)
          finite = finite && std::isfinite(triangle_uv[6 * t + i]);
        if (!finite || map[t] < 0) {
          map[t] = -1;
          std::fill_n(triangle_uv.begin() + std::ptrdiff_t(6 * t), 6,
                      std::numeric_limits<float>::quiet_NaN());
        }
      }
      texture_out->uv = std::move(triangle_uv);
      texture_out->triangle_map = std::move(map);
    }
  }
  report.vertices_read = soup.vertex_count();
  report.faces_read = soup.faces_seen;
  if (report_out) *report_out = std::move(report);
  return mesh;
}

}  // namespace arg
