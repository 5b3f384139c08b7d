// Reading a mesh from bytes in memory: format dispatch, texture, triangulation and the report.
#include "io/read_mesh.hpp"

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
  Mesh mesh = io::soup_to_mesh(soup, texture ? &*texture : nullptr, sampler, builder, report,
                               texture_out ? &triangle_uv : nullptr);
  if (texture_out) {
    *texture_out = MeshTexture{};
    // The texture the coordinates refer to: the caller's (OBJ, PLY), or the one a GLB's reader
    // kept (it decoded it once already, so this cannot fail where that did not).
    if (texture) {
      texture_out->encoded = std::string(options.texture);
      texture_out->image = std::move(*texture);
      texture_out->sampler = sampler;
    } else if (!soup.display_texture.empty()) {
      texture_out->encoded = std::move(soup.display_texture);
      texture_out->image = decode_image(texture_out->encoded, limits);
      texture_out->sampler = soup.display_sampler;
    }
    if (!texture_out->image.empty()) texture_out->uv = std::move(triangle_uv);
  }
  report.vertices_read = soup.vertex_count();
  report.faces_read = soup.faces_seen;
  if (report_out) *report_out = std::move(report);
  return mesh;
}

}  // namespace arg
