// argtool view-data: a mesh as the browser's 3D view draws it (surface, colours, mu, nodes), JSON.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "command_registry.hpp"
#include "common/errors.hpp"
#include "io/read_mesh.hpp"
#include "load_arg.hpp"
#include "pipeline/node_positions.hpp"
#include "pipeline/node_region.hpp"
#include "pipeline/surface_texture.hpp"
#include "plugin_libraries.hpp"
#include "render/upright_frame.hpp"
#include "render_input.hpp"
#include "up_option.hpp"

namespace {

// The largest texture the 3D view maps: WebGL promises 4096 pixels a side on nearly every
// device, and the page sends it as it is; larger ones are shown in the colours baked from them.
constexpr int kMaxTextureSide = 4096;
constexpr std::size_t kMaxTextureBytes = std::size_t(32) << 20;
// The most images one view maps (a page loads each): the faces of others show their colours.
// The same cap as the core's on an OBJ's material images.
constexpr std::size_t kMaxTextureImages = arg::kMaxDisplayImages;

struct ViewDataArgs {
  std::string mesh, texture, output, texture_output;
  std::string up;                      // the file axis that points up (--up), for the view's start
  std::vector<std::string> materials;  // --material NAME=PATH, as given
  long max_triangles = 500000;
  arg::BuildOptions options;
};

void add_note(std::string& note, const std::string& more) {
  note += (note.empty() ? "" : "; ") + more;
}

// One --material value: NAME=PATH, split at the last '=' (a material's name may hold one).
std::pair<std::string, std::string> material_option(const std::string& value) {
  const std::size_t eq = value.rfind('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == value.size())
    throw std::runtime_error("--material '" + value +
                             "': give NAME=PATH, a material's name and its texture image");
  return {value.substr(0, eq), value.substr(eq + 1)};
}

// The mesh as read, with its texture when `want_texture` (OBJ: `texture_path`, or each
// material's; GLB: its own). A separate texture that cannot be read is left out, with the
// reason in `note`, as are the materials' textures that are not shown.
arg::Mesh read_view_mesh(const ViewDataArgs& a, bool want_texture, arg::MeshTexture& texture,
                         std::string& note) {
  const std::string bytes = argtool::read_file_bytes(a.mesh);
  if (bytes.compare(0, 4, "ARGR") == 0)
    throw std::runtime_error(a.mesh + ": an ARG file has no surface to draw; give the mesh");
  const std::string image = a.texture.empty() ? std::string() : argtool::read_file_bytes(a.texture);
  arg::ReadOptions read;
  read.texture = image;
  std::vector<std::pair<std::string, std::string>> materials;  // name, image bytes
  for (const std::string& value : a.materials) {
    auto [name, path] = material_option(value);
    materials.emplace_back(std::move(name), argtool::read_file_bytes(path));
  }
  for (const auto& [name, encoded] : materials) read.material_textures.push_back({name, encoded});
  arg::ReadReport report;
  arg::Mesh mesh;
  try {
    try {
      mesh = arg::read_mesh(bytes, read, &report, want_texture ? &texture : nullptr);
    } catch (const arg::Error& e) {
      // decode_image's errors (bad bytes, too many pixels) start so; the mesh's name its format.
      if (image.empty() || std::string(e.what()).rfind("image: ", 0) != 0) throw;
      note = std::string("the texture cannot be read (") + e.what() + "): shown without it";
      read.texture = {};
      report = {};
      mesh = arg::read_mesh(bytes, read, &report, want_texture ? &texture : nullptr);
    }
  } catch (const arg::Error& e) {
    throw std::runtime_error(a.mesh + ": " + e.what());
  }
  if (texture.empty() && note.empty())
    for (const std::string& warning : report.warnings)
      if (warning.find("texture") != std::string::npos) note = warning;
  if (!texture.empty() && !materials.empty())
    for (const std::string& warning : report.warnings)
      if (warning.find("material") != std::string::npos) add_note(note, warning);
  return mesh;
}

const char* image_type(const std::string& encoded) {
  if (encoded.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0) return "image/png";
  if (encoded.compare(0, 3, "\xff\xd8\xff") == 0) return "image/jpeg";
  return nullptr;
}

const char* wrap_name(arg::io::TextureWrap wrap) {
  switch (wrap) {
    case arg::io::TextureWrap::ClampToEdge:
      return "clamp";
    case arg::io::TextureWrap::MirroredRepeat:
      return "mirror";
    case arg::io::TextureWrap::Repeat:
      break;
  }
  return "repeat";
}

// Writes one image for the page (PNG and JPEG as given, others as PNG); returns its MIME type.
std::string write_image(const arg::io::DisplayImage& image, const std::string& path) {
  const char* type = image_type(image.encoded);
  if (type && image.encoded.size() <= kMaxTextureBytes) {
    argtool::write_file_bytes(path, image.encoded);
    return type;
  }
  argtool::write_png(image.image, path);
  return "image/png";
}

// The textures the page maps: the images written (image i at PATH-i) with their MIME types, and
// the maps of those (their image renumbered). An image too large to map, or past the first
// kMaxTextureImages, is left out with the reason in `note`: its faces keep their colours.
struct PageTextures {
  std::vector<std::string> types;         // per image written
  std::vector<arg::io::DisplayMap> maps;  // those whose image was written
  std::vector<int> map_of;                // per map of the mesh: its index in maps, or -1
  std::vector<int> image_of;              // per image of the mesh: its index in types, or -1
};

PageTextures write_textures(const arg::MeshTexture& texture, const std::string& path,
                            std::string& note) {
  PageTextures out;
  std::size_t too_many = 0;
  for (const arg::io::DisplayImage& image : texture.images) {
    const int w = image.image.width, h = image.image.height;
    if (w > kMaxTextureSide || h > kMaxTextureSide) {
      add_note(note, "a texture is " + std::to_string(w) + " x " + std::to_string(h) +
                         " pixels, more than the 3D view's " + std::to_string(kMaxTextureSide) +
                         " a side: shown in the colours taken from it");
      out.image_of.push_back(-1);
    } else if (out.types.size() == kMaxTextureImages) {
      ++too_many;
      out.image_of.push_back(-1);
    } else {
      out.image_of.push_back(int(out.types.size()));
      out.types.push_back(write_image(image, path + "-" + std::to_string(out.types.size())));
    }
  }
  if (too_many)
    add_note(note, std::to_string(too_many) + " textures past the first " +
                       std::to_string(kMaxTextureImages) +
                       " are shown in the colours taken from them");
  for (const arg::io::DisplayMap& map : texture.maps) {
    const int image = map.image >= 0 && std::size_t(map.image) < out.image_of.size()
                          ? out.image_of[std::size_t(map.image)]
                          : -1;
    out.map_of.push_back(image < 0 ? -1 : int(out.maps.size()));
    if (image < 0) continue;
    out.maps.push_back(map);
    out.maps.back().image = image;
  }
  return out;
}

// Numbers as JSON text: 6 significant digits are below a pixel on any screen; NaN cannot occur
// (the pipeline refuses non-finite input) but would be written as 0 to keep the JSON valid.
void put_number(std::string& out, double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", std::isfinite(x) ? x : 0.0);
  out += buf;
}

template <class Each>
void put_array(std::string& out, const char* key, std::size_t n, Each each) {
  out += '"';
  out += key;
  out += "\":[";
  for (std::size_t i = 0; i < n; ++i) {
    if (i) out += ',';
    each(i);
  }
  out += ']';
}

int run_view_data(const ViewDataArgs& a) {
  const bool want_texture = !a.texture_output.empty();
  arg::MeshTexture texture;
  std::string note;
  const arg::Mesh input = read_view_mesh(a, want_texture, texture, note);
  if (input.F.rows() > a.max_triangles)
    throw std::runtime_error("too large to display: " + std::to_string(input.F.rows()) +
                             " triangles, more than the limit of " +
                             std::to_string(a.max_triangles));
  PageTextures page;
  if (!texture.empty()) page = write_textures(texture, a.texture_output, note);
  const bool mapped = !page.maps.empty();
  // The model's surface in the ARG's frame (principal axes on x, y, z), so that the nodes sit
  // where the ARG measured them; with a texture, its coordinates on it.
  arg::SurfaceTexture uv;
  // A model built on its proxy is shown as itself, the nodes carried over from the proxy.
  const arg::NodePositions p =
      mapped ? arg::node_positions_with_texture(input, texture.uv, a.options, &uv, {},
                                                arg::ShownSurface::Own)
             : arg::node_positions(input, a.options, {}, arg::ShownSurface::Own);
  const arg::Mesh& m = p.mesh;
  const auto nv = std::size_t(m.V.rows()), nf = std::size_t(m.F.rows());
  std::string out = "{\"format\":1,";
  // The canonical view (argtool upright) in the same frame: the 3D view starts from it.
  const arg::UprightFrame frame =
      arg::upright_frame(m, argtool::upright_hint(a.mesh, a.up, p.pose.rotation));
  put_array(out, "up", 3, [&](std::size_t i) { put_number(out, frame.up[long(i)]); });
  out += ',';
  put_array(out, "front", 3, [&](std::size_t i) { put_number(out, frame.front[long(i)]); });
  out += ',';
  put_array(out, "positions", 3 * nv,
            [&](std::size_t i) { put_number(out, m.V(long(i / 3), long(i % 3))); });
  out += ',';
  put_array(out, "faces", 3 * nf,
            [&](std::size_t i) { out += std::to_string(m.F(long(i / 3), long(i % 3))); });
  out += ',';
  // Per face 0..255 RGB, or none: the 3D view then shades a neutral clay.
  if (m.has_colour()) {
    put_array(out, "face_colours", 3 * nf, [&](std::size_t i) {
      out += std::to_string(
          int(std::lround(std::clamp(m.C(long(i / 3), long(i % 3)), 0.0f, 1.0f) * 255)));
    });
  } else {
    out += "\"face_colours\":null";
  }
  out += ',';
  // The textures' coordinates per corner of each face (v = 0 at the image's bottom row, as
  // three.js takes them), each face's texture (-1: none, drawn in its colour), the textures
  // (an image, its wrapping, the colour multiplying it) and the images (written at PATH-i); or
  // nulls, with the reason in texture_note when the file has a texture that is not mapped.
  if (mapped) {
    std::vector<int> face_texture(nf, -1);
    for (std::size_t f = 0; f < nf; ++f) {
      const int from = uv.origin[f];
      if (!uv.textured[f] || from < 0) continue;
      const int map = texture.triangle_map[std::size_t(from)];
      if (map >= 0) face_texture[f] = page.map_of[std::size_t(map)];
    }
    put_array(out, "uvs", 6 * nf, [&](std::size_t i) {
      const int map = face_texture[i / 6];
      const float x = map < 0 ? 0.0f : uv.uv[i];
      const bool flip = map >= 0 && !page.maps[std::size_t(map)].sampler.v_origin_bottom;
      put_number(out, flip && i % 2 ? 1.0 - x : x);
    });
    out += ',';
    put_array(out, "face_textures", nf,
              [&](std::size_t f) { out += std::to_string(face_texture[f]); });
    nlohmann::json textures = nlohmann::json::array(), images = nlohmann::json::array();
    // The factor as the file wrote it (a float read back: 0.1, not 0.100000001).
    const auto decimal = [](float x) { return std::round(double(x) * 1e6) / 1e6; };
    for (const arg::io::DisplayMap& map : page.maps)
      textures.push_back(
          {{"image", map.image},
           {"wrap_s", wrap_name(map.sampler.wrap_s)},
           {"wrap_t", wrap_name(map.sampler.wrap_t)},
           {"factor", {decimal(map.factor[0]), decimal(map.factor[1]), decimal(map.factor[2])}}});
    for (std::size_t i = 0; i < texture.images.size(); ++i) {
      if (page.image_of[i] < 0) continue;
      images.push_back({{"type", page.types[std::size_t(page.image_of[i])]},
                        {"width", texture.images[i].image.width},
                        {"height", texture.images[i].image.height}});
    }
    out += ",\"textures\":" + textures.dump() + ",\"images\":" + images.dump();
  } else {
    out += "\"uvs\":null,\"face_textures\":null,\"textures\":null,\"images\":null";
  }
  out += ",\"texture_note\":" + (note.empty() ? std::string("null") : nlohmann::json(note).dump());
  out += ',';
  put_array(out, "mu", nv, [&](std::size_t i) { put_number(out, p.mu[i]); });
  out += ",\"levels\":[";
  for (std::size_t r = 0; r < p.levels.size(); ++r) {
    const arg::NodePlacementLevel& level = p.levels[r];
    out += r ? ",{" : "{";
    put_array(out, "centres", 3 * level.centre.size(),
              [&](std::size_t i) { put_number(out, level.centre[i / 3][long(i % 3)]); });
    out += ',';
    put_array(out, "areas", level.area.size(),
              [&](std::size_t i) { put_number(out, level.area[i]); });
    out += ',';
    put_array(out, "edges", 2 * level.edges.size(), [&](std::size_t i) {
      out += std::to_string(i % 2 ? level.edges[i / 2].second : level.edges[i / 2].first);
    });
    out += ',';
    // The node owning each face's middle, for colouring a node's surface and for telling
    // which node a click hit.
    put_array(out, "face_nodes", nf,
              [&](std::size_t f) { out += std::to_string(arg::face_node(p, int(r), int(f))); });
    out += '}';
  }
  out += "]}\n";
  argtool::write_file_bytes(a.output, out);
  std::printf("wrote %s (%zu vertices, %zu triangles, %zu levels)\n", a.output.c_str(), nv, nf,
              p.levels.size());
  for (std::size_t i = 0; i < texture.images.size(); ++i) {
    const int written = page.image_of.empty() ? -1 : page.image_of[i];
    if (written < 0) continue;
    std::printf("wrote %s-%d (%s, %d x %d)\n", a.texture_output.c_str(), written,
                page.types[std::size_t(written)].c_str(), texture.images[i].image.width,
                texture.images[i].image.height);
  }
  if (!note.empty()) std::printf("note: %s\n", note.c_str());
  return 0;
}

const bool registered = argtool::register_command(
    "view-data",
    "a mesh as a 3D view draws it: aligned surface, colours, mu and each level's nodes, as JSON",
    [](CLI::App& app) {
      auto a = std::make_shared<ViewDataArgs>();
      app.add_option("mesh", a->mesh, "mesh file")->required()->check(CLI::ExistingFile);
      app.add_option("-o,--output", a->output, "JSON to write")->required();
      app.add_option("--texture", a->texture, "texture image for OBJ")->check(CLI::ExistingFile);
      app.add_option("--material", a->materials,
                     "NAME=PATH: the texture image of an OBJ's material NAME (usemtl), "
                     "repeatable; the view maps each face's, --texture still colours the mesh")
          ->allow_extra_args(false)
          ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
      app.add_option("--texture-output", a->texture_output,
                     "where to write the textures the view maps: image i (from 0) at PATH-i, "
                     "PNG or JPEG, with their coordinates in the JSON; without it, none is mapped");
      app.add_option("--max-triangles", a->max_triangles,
                     "refuse a mesh with more triangles than this (too large to display)")
          ->check(CLI::Range(1L, 100000000L))
          ->capture_default_str();
      argtool::add_up_option(app, a->up);
      argtool::add_build_flags(app, a->options);
      return [a] { return run_view_data(*a); };
    });

}  // namespace
