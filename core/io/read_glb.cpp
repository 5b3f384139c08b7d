// Reading binary glTF 2.0 (GLB) meshes of the default scene, with per-triangle base colour.
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "common/errors.hpp"
#include "io/format_readers.hpp"
#include "io/glb_container.hpp"
#include "io/gltf.hpp"
#include "io/gltf_accessor.hpp"
#include "io/image.hpp"
#include "io/texture_sampling.hpp"

namespace arg::io {

namespace {

constexpr int kMaxNodeDepth = 64;

// Registered with tinygltf instead of its stb_image loader: decodes nothing. Images in buffer
// views are decoded later from the buffer, and only the base colour textures that are used;
// images from data: URIs exist only here, so their encoded bytes are kept as they are.
bool keep_encoded_image(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                        const unsigned char* bytes, int size, void*) {
  image->as_is = true;
  if (image->bufferView < 0 && bytes && size > 0) image->image.assign(bytes, bytes + size);
  return true;
}

// tinygltf opens files named by URIs; the server's file system is never an input, so every
// file operation fails (check_gltf_json already rejects such URIs; this is the second guard).
bool no_file_exists(const std::string&, void*) {
  return false;
}
std::string no_expand_path(const std::string&, void*) {
  return {};
}
bool no_read_file(std::vector<unsigned char>*, std::string* error, const std::string&, void*) {
  if (error) *error = "external files are not supported";
  return false;
}
bool no_write_file(std::string* error, const std::string&, const std::vector<unsigned char>&,
                   void*) {
  if (error) *error = "external files are not supported";
  return false;
}
bool no_file_size(std::size_t*, std::string* error, const std::string&, void*) {
  if (error) *error = "external files are not supported";
  return false;
}

// tinygltf 2.9 (Debian 13) added GetFileSizeInBytes to its callbacks and refuses callbacks with
// a null one; 2.8 (Debian 12) has no such member.
template <class Callbacks>
auto set_file_size(Callbacks& fs, int) -> decltype(fs.GetFileSizeInBytes = &no_file_size, void()) {
  fs.GetFileSizeInBytes = &no_file_size;
}
template <class Callbacks>
void set_file_size(Callbacks&, long) {}

tinygltf::FsCallbacks no_file_system() {
  tinygltf::FsCallbacks fs{};  // every member null first, whatever a version adds
  fs.FileExists = &no_file_exists;
  fs.ExpandFilePath = &no_expand_path;
  fs.ReadWholeFile = &no_read_file;
  fs.WriteWholeFile = &no_write_file;
  set_file_size(fs, 0);
  fs.user_data = nullptr;
  return fs;
}

// Installs the callbacks: 2.9 says whether it took them (it keeps its own file system when it
// does not), 2.8 takes them and says nothing.
template <class Loader>
auto install_callbacks(Loader& loader, int)
    -> decltype(bool(loader.SetFsCallbacks(no_file_system(), nullptr))) {
  std::string error;
  return loader.SetFsCallbacks(no_file_system(), &error);
}
template <class Loader>
bool install_callbacks(Loader& loader, long) {
  loader.SetFsCallbacks(no_file_system());
  return true;
}

Eigen::Matrix4d local_transform(const tinygltf::Node& node, const std::string& what) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  if (node.matrix.size() == 16) {
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) m(r, c) = node.matrix[std::size_t(4 * c + r)];
    }
  } else if (!node.matrix.empty()) {
    throw_input_error("GLB", what, "a node matrix needs 16 numbers");
  } else {
    Eigen::Vector3d t(0, 0, 0), s(1, 1, 1);
    Eigen::Quaterniond q(1, 0, 0, 0);
    if (node.translation.size() == 3)
      t = {node.translation[0], node.translation[1], node.translation[2]};
    if (node.scale.size() == 3) s = {node.scale[0], node.scale[1], node.scale[2]};
    if (node.rotation.size() == 4) {
      q = Eigen::Quaterniond(node.rotation[3], node.rotation[0], node.rotation[1],
                             node.rotation[2]);
      if (q.norm() > 0) q.normalize();
    }
    m.topLeftCorner<3, 3>() = q.toRotationMatrix() * s.asDiagonal();
    m.topRightCorner<3, 1>() = t;
  }
  if (!m.allFinite()) throw_input_error("GLB", what, "node transform is not finite");
  return m;
}

TextureWrap wrap_mode(int mode) {
  switch (mode) {
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
      return TextureWrap::ClampToEdge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
      return TextureWrap::MirroredRepeat;
    default:
      return TextureWrap::Repeat;
  }
}

class GlbReader {
 public:
  GlbReader(const tinygltf::Model& model, SoupBuilder& out, ReadReport& report)
      : model_(model), out_(out), report_(report) {}

  void read_scene() {
    std::vector<int> roots;
    if (!model_.scenes.empty()) {
      const int scene = model_.defaultScene >= 0 ? model_.defaultScene : 0;
      if (std::size_t(scene) >= model_.scenes.size()) {
        throw_input_error("GLB", "", "default scene " + std::to_string(scene) + " does not exist");
      }
      roots = model_.scenes[std::size_t(scene)].nodes;
    } else {
      // No scene: every node that is nobody's child.
      std::vector<char> is_child(model_.nodes.size(), 0);
      for (const tinygltf::Node& n : model_.nodes) {
        for (int c : n.children) {
          if (c >= 0 && std::size_t(c) < is_child.size()) is_child[std::size_t(c)] = 1;
        }
      }
      for (std::size_t i = 0; i < model_.nodes.size(); ++i) {
        if (!is_child[i]) roots.push_back(int(i));
      }
    }
    visited_.assign(model_.nodes.size(), 0);
    for (int root : roots) visit(root, Eigen::Matrix4d::Identity(), 0);
  }

  void finish() {
    PolygonSoup& soup = out_.soup();
    if (textured_) {
      soup.face_colour_source = "texture";
    } else if (vertex_coloured_) {
      soup.face_colour_source = "vertex";
    } else if (material_coloured_) {
      soup.face_colour_source = "material";
    } else {
      soup.face_rgb.clear();
    }
  }

 private:
  void visit(int index, const Eigen::Matrix4d& parent, int depth) {
    const std::string what = "node " + std::to_string(index);
    if (index < 0 || std::size_t(index) >= model_.nodes.size()) {
      throw_input_error("GLB", what, "does not exist");
    }
    if (depth > kMaxNodeDepth) {
      throw_input_error("GLB", what, "node tree deeper than " + std::to_string(kMaxNodeDepth));
    }
    if (visited_[std::size_t(index)]) {
      throw_input_error("GLB", what, "reached twice (the node hierarchy must be a tree)");
    }
    visited_[std::size_t(index)] = 1;
    const tinygltf::Node& node = model_.nodes[std::size_t(index)];
    const Eigen::Matrix4d world = parent * local_transform(node, what);
    if (node.mesh >= 0) {
      if (std::size_t(node.mesh) >= model_.meshes.size()) {
        throw_input_error("GLB", what, "refers to missing mesh " + std::to_string(node.mesh));
      }
      const tinygltf::Mesh& mesh = model_.meshes[std::size_t(node.mesh)];
      for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        read_primitive(mesh.primitives[p],
                       "mesh " + std::to_string(node.mesh) + " primitive " + std::to_string(p),
                       world);
      }
    }
    for (int child : node.children) visit(child, world, depth + 1);
  }

  // The decoded image of texture `texture`, or nullptr (with a warning) when unavailable.
  const Image* texture_image(int texture, TextureSampler& sampler) {
    if (texture < 0 || std::size_t(texture) >= model_.textures.size()) return nullptr;
    const tinygltf::Texture& t = model_.textures[std::size_t(texture)];
    if (t.sampler >= 0 && std::size_t(t.sampler) < model_.samplers.size()) {
      sampler.wrap_s = wrap_mode(model_.samplers[std::size_t(t.sampler)].wrapS);
      sampler.wrap_t = wrap_mode(model_.samplers[std::size_t(t.sampler)].wrapT);
    }
    const int source = t.source;
    if (source < 0 || std::size_t(source) >= model_.images.size()) return nullptr;
    auto cached = images_.find(source);
    if (cached != images_.end()) return cached->second ? &*cached->second : nullptr;
    std::optional<Image>& slot = images_[source];
    const tinygltf::Image& image = model_.images[std::size_t(source)];
    std::string_view encoded;
    if (image.bufferView >= 0 && std::size_t(image.bufferView) < model_.bufferViews.size()) {
      const tinygltf::BufferView& view = model_.bufferViews[std::size_t(image.bufferView)];
      if (view.buffer >= 0 && std::size_t(view.buffer) < model_.buffers.size()) {
        const auto& data = model_.buffers[std::size_t(view.buffer)].data;
        if (view.byteOffset <= data.size() && view.byteLength <= data.size() - view.byteOffset) {
          encoded = std::string_view(reinterpret_cast<const char*>(data.data()) + view.byteOffset,
                                     view.byteLength);
        }
      }
    } else if (!image.image.empty()) {
      encoded =
          std::string_view(reinterpret_cast<const char*>(image.image.data()), image.image.size());
    }
    encoded_[source] = encoded;
    const std::string what = "image " + std::to_string(source);
    if (encoded.empty()) {
      report_.warnings.push_back(what + " is not embedded; its texture is ignored");
      return nullptr;
    }
    try {
      slot = decode_image(encoded, out_.limits());
    } catch (const InputError& e) {
      report_.warnings.push_back(what + " could not be decoded (" + e.what() +
                                 "); its texture is ignored");
      return nullptr;
    }
    return &*slot;
  }

  void read_primitive(const tinygltf::Primitive& prim, const std::string& what,
                      const Eigen::Matrix4d& world) {
    out_.set_locator([&what] { return what; });
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      report_.warnings.push_back(what + ": points and lines are skipped");
      return;
    }
    const auto position_it = prim.attributes.find("POSITION");
    if (position_it == prim.attributes.end()) {
      report_.warnings.push_back(what + ": no POSITION attribute; skipped");
      return;
    }
    const GltfAccessor positions(model_, position_it->second, what + " POSITION");
    if (positions.components() != 3) throw_input_error("GLB", what, "POSITION is not a VEC3");
    const std::size_t n = positions.count();

    // Corner indices, then triangles in the primitive's own numbering.
    std::vector<std::uint32_t> corners;
    if (prim.indices >= 0) {
      const GltfAccessor indices(model_, prim.indices, what + " indices");
      corners.resize(indices.count());
      for (std::size_t i = 0; i < corners.size(); ++i) {
        corners[i] = indices.index(i);
        if (corners[i] >= n) {
          throw_input_error("GLB", what,
                            "index " + std::to_string(i) + " is " + std::to_string(corners[i]) +
                                " but the primitive has " + std::to_string(n) + " vertices");
        }
      }
    } else {
      corners.resize(n);
      for (std::size_t i = 0; i < n; ++i) corners[i] = std::uint32_t(i);
    }
    std::vector<std::array<std::uint32_t, 3>> triangles;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      for (std::size_t i = 0; i + 2 < corners.size(); i += 3) {
        triangles.push_back({corners[i], corners[i + 1], corners[i + 2]});
      }
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      for (std::size_t i = 0; i + 2 < corners.size(); ++i) {
        if (i % 2 == 0) {
          triangles.push_back({corners[i], corners[i + 1], corners[i + 2]});
        } else {
          triangles.push_back({corners[i + 1], corners[i], corners[i + 2]});
        }
      }
    } else {
      for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
        triangles.push_back({corners[0], corners[i], corners[i + 1]});
      }
    }
    if (triangles.size() > out_.limits().max_triangles) {
      out_.fail_limit(what + ": more than " + std::to_string(out_.limits().max_triangles) +
                      " triangles");
    }

    // Colour: texture at TEXCOORD_n, else COLOR_0, else the material's base colour factor.
    std::array<double, 4> factor{1, 1, 1, 1};
    int texture = -1, texcoord_set = 0;
    if (prim.material >= 0 && std::size_t(prim.material) < model_.materials.size()) {
      const auto& pbr = model_.materials[std::size_t(prim.material)].pbrMetallicRoughness;
      if (pbr.baseColorFactor.size() == 4) {
        for (std::size_t i = 0; i < 4; ++i) factor[i] = pbr.baseColorFactor[i];
      }
      texture = pbr.baseColorTexture.index;
      texcoord_set = pbr.baseColorTexture.texCoord;
    }
    TextureSampler sampler;
    sampler.v_origin_bottom = false;  // glTF: v = 0 is the top row of the image
    const Image* image = texture >= 0 ? texture_image(texture, sampler) : nullptr;
    std::optional<GltfAccessor> uv, colour;
    const auto uv_it = prim.attributes.find("TEXCOORD_" + std::to_string(texcoord_set));
    if (image && uv_it != prim.attributes.end()) {
      uv.emplace(model_, uv_it->second, what + " TEXCOORD");
      if (uv->components() != 2 || uv->count() < n) {
        throw_input_error("GLB", what, "TEXCOORD is not a VEC2 per vertex");
      }
    }
    const auto colour_it = prim.attributes.find("COLOR_0");
    if (!uv && colour_it != prim.attributes.end()) {
      colour.emplace(model_, colour_it->second, what + " COLOR_0");
      if ((colour->components() != 3 && colour->components() != 4) || colour->count() < n) {
        throw_input_error("GLB", what, "COLOR_0 is not a VEC3 or VEC4 per vertex");
      }
    }
    // The faces of every texture that decodes keep their coordinates and map for display.
    const int display =
        uv && out_.soup().keep_display_texture ? display_map(texture, *image, sampler, factor) : -1;
    if (uv) {
      textured_ = true;
    } else if (colour) {
      vertex_coloured_ = true;
    } else if (factor[0] != 1 || factor[1] != 1 || factor[2] != 1) {
      material_coloured_ = true;
    }

    // Vertices, placed in the scene.
    const int base = int(out_.soup().vertex_count());
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector4d p(positions.value(i, 0), positions.value(i, 1), positions.value(i, 2),
                              1);
      if (!p.allFinite()) {
        throw_input_error("GLB", what, "position " + std::to_string(i) + " is not finite");
      }
      const Eigen::Vector4d q = world * p;
      out_.add_vertex(q[0], q[1], q[2]);
    }
    // A mirroring transform turns the faces inside out unless the winding is reversed.
    const bool flip = world.topLeftCorner<3, 3>().determinant() < 0;
    for (const auto& t : triangles) {
      int corner[3] = {base + int(t[0]), base + int(t[1]), base + int(t[2])};
      if (flip) std::swap(corner[1], corner[2]);
      const int face = out_.add_face(corner, 3);
      std::array<float, 3> rgb{1, 1, 1};
      if (uv) {
        double st[3][2];
        for (int k = 0; k < 3; ++k) {
          st[k][0] = uv->value(t[std::size_t(k)], 0);
          st[k][1] = uv->value(t[std::size_t(k)], 1);
        }
        rgb = triangle_texture_colour(*image, st, sampler);
        if (display >= 0 && face >= 0) keep_corner_uvs(face, st, flip, display);
      } else if (colour) {
        rgb = {0, 0, 0};
        for (int k = 0; k < 3; ++k) {
          for (int c = 0; c < 3; ++c)
            rgb[std::size_t(c)] += float(colour->value(t[std::size_t(k)], c) / 3);
        }
      }
      out_.set_face_colour(face, float(rgb[0] * factor[0]), float(rgb[1] * factor[1]),
                           float(rgb[2] * factor[2]));
    }
    out_.set_locator({});
  }

  // The index in the soup's display maps of texture `texture` (whose image decoded to `image`)
  // multiplied by `factor`, added with its image on first use.
  int display_map(int texture, const Image& image, const TextureSampler& sampler,
                  const std::array<double, 4>& factor) {
    PolygonSoup& soup = out_.soup();
    const std::array<float, 3> rgb{float(factor[0]), float(factor[1]), float(factor[2])};
    const auto key = std::make_pair(texture, rgb);
    const auto found = display_maps_.find(key);
    if (found != display_maps_.end()) return found->second;
    const int source = model_.textures[std::size_t(texture)].source;
    auto image_index = display_images_.find(source);
    if (image_index == display_images_.end()) {
      image_index = display_images_.emplace(source, int(soup.display_images.size())).first;
      soup.display_images.push_back({std::string(encoded_[source]), image});
    }
    const int map = int(soup.display_maps.size());
    soup.display_maps.push_back({image_index->second, sampler, rgb});
    display_maps_.emplace(key, map);
    return map;
  }

  // Corner texture coordinates of `face` in its corner order (corners 1 and 2 swapped when the
  // transform mirrors), and its display map; non-finite ones leave the face without either, as
  // the colour sampling tolerates them.
  void keep_corner_uvs(int face, const double st[3][2], bool flip, int map) {
    float uv[6];
    for (int k = 0; k < 3; ++k) {
      const int from = flip && k > 0 ? 3 - k : k;
      uv[2 * k] = float(st[from][0]);
      uv[2 * k + 1] = float(st[from][1]);
    }
    for (float x : uv)
      if (!std::isfinite(x)) return;
    out_.set_corner_uvs(face, uv, 3);
    std::vector<int>& maps = out_.soup().face_display_map;
    if (maps.size() <= std::size_t(face)) maps.resize(std::size_t(face) + 1, -1);
    maps[std::size_t(face)] = map;
  }

  const tinygltf::Model& model_;
  SoupBuilder& out_;
  ReadReport& report_;
  std::vector<char> visited_;
  std::map<int, std::optional<Image>> images_;
  std::map<int, std::string_view> encoded_;  // each image's bytes, as texture_image found them
  std::map<int, int> display_images_;        // glTF image -> index in the soup's display images
  // (glTF texture, factor) -> index in the soup's display maps
  std::map<std::pair<int, std::array<float, 3>>, int> display_maps_;
  bool textured_ = false, vertex_coloured_ = false, material_coloured_ = false;
};

}  // namespace

void read_glb(std::string_view bytes, SoupBuilder& out, ReadReport& report) {
  const GlbChunks chunks = check_glb_container(bytes);
  check_gltf_json(chunks);
  report.variant = "glTF 2.0 binary";
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&keep_encoded_image, nullptr);
  if (!install_callbacks(loader, 0))
    throw std::logic_error("glTF reader: tinygltf refused the callbacks that shut out files");
  tinygltf::Model model;
  std::string error, warning;
  if (!loader.LoadBinaryFromMemory(&model, &error, &warning,
                                   reinterpret_cast<const unsigned char*>(bytes.data()),
                                   static_cast<unsigned int>(chunks.length), "")) {
    while (!error.empty() && (error.back() == '\n' || error.back() == ' ')) error.pop_back();
    throw_input_error("GLB", "", "tinygltf: " + (error.empty() ? "cannot parse" : error));
  }
  out.set_immediate_index_check(true);
  GlbReader reader(model, out, report);
  reader.read_scene();
  reader.finish();
}

}  // namespace arg::io
