// Reading a mesh from bytes in memory: format dispatch, texture, triangulation and the report.
#include "io/read_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <utility>

#include "common/errors.hpp"
#include "io/format_readers.hpp"
#include "io/image.hpp"
#include "io/soup_to_mesh.hpp"

namespace arg {

namespace {

// The display maps of an OBJ's materials, added to `texture` (each image decoded once, at most
// kMaxDisplayImages of them), and each of soup.material_names' index in them; -1 for a material
// without a usable image, with a warning naming it.
std::vector<int> material_maps(const io::PolygonSoup& soup, const ReadOptions& options,
                               const io::TextureSampler& sampler, MeshTexture& texture,
                               ReadReport& report) {
  std::vector<int> map_of(soup.material_names.size(), -1);
  // By content, so materials that share an image share it; why an image is unusable, if it is.
  std::map<std::string_view, std::pair<int, std::string>> image_of;
  for (std::size_t m = 0; m < soup.material_names.size(); ++m) {
    const std::string& name = soup.material_names[m];
    const auto& given = options.material_textures;
    const auto it = std::find_if(given.begin(), given.end(),
                                 [&](const MaterialTexture& t) { return t.material == name; });
    if (it == given.end() || it->image.empty()) {
      report.warnings.push_back("material '" + name +
                                "' has no texture image: its faces are shown without one");
      continue;
    }
    auto found = image_of.find(it->image);
    if (found == image_of.end()) {
      std::pair<int, std::string> image{-1, ""};
      if (texture.images.size() == kMaxDisplayImages) {
        image.second = "more than " + std::to_string(kMaxDisplayImages) + " images to map";
      } else {
        check_interrupt(options.stop);
        // Display only: an image that does not decode leaves its faces unmapped, no more.
        try {
          Image decoded = decode_image(it->image, options.limits);
          image.first = int(texture.images.size());
          texture.images.push_back({std::string(it->image), std::move(decoded)});
        } catch (const InputError& e) {
          image.second = e.what();
        } catch (const LimitError& e) {
          image.second = e.what();
        }
      }
      found = image_of.emplace(it->image, std::move(image)).first;
    }
    if (found->second.first < 0) {
      report.warnings.push_back("the texture of material '" + name + "' is not shown (" +
                                found->second.second + ")");
      continue;
    }
    map_of[m] = int(texture.maps.size());
    texture.maps.push_back({found->second.first, sampler, {1, 1, 1}});
  }
  return map_of;
}

}  // namespace

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
  // Materials' textures: an OBJ's faces map them by usemtl, for display only.
  const bool by_material =
      texture_out && !options.material_textures.empty() && report.format == MeshFormat::Obj;
  soup.keep_face_materials = by_material;
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
    if (by_material && !io::soup_has_texture_coordinates(soup)) {
      report.warnings.push_back(
          "the materials' textures are not shown: the mesh has no texture coordinates");
    } else if (by_material && !soup.face_material.empty()) {
      const std::vector<int> map_of = material_maps(soup, options, sampler, *texture_out, report);
      for (std::size_t t = 0; t < triangles; ++t) {
        const auto f = std::size_t(triangle_face[t]);
        const int material = f < soup.face_material.size() ? soup.face_material[f] : -1;
        if (material >= 0) map[t] = map_of[std::size_t(material)];
      }
    }
    if (!texture_out->maps.empty()) {
      // Mapped by material; a separate texture only colours the mesh.
    } else if (texture) {
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
