// Tests of reading GLB: primitives, node transforms, colour sources and hostile files.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "common/errors.hpp"
#include "input_error.hpp"
#include "io/read_mesh.hpp"
#include "test_io_support.hpp"

namespace arg {
namespace {

using test_io::Bytes;

constexpr int kUByte = 5121, kUShort = 5123, kFloat = 5126;

// Assembles the JSON and BIN chunks of a GLB.
class Gltf {
 public:
  int view(const std::string& bytes) {
    while (bin_.size() % 4) bin_.push_back('\0');
    views_.push_back("{\"buffer\":0,\"byteOffset\":" + std::to_string(bin_.size()) +
                     ",\"byteLength\":" + std::to_string(bytes.size()) + "}");
    bin_ += bytes;
    return int(views_.size()) - 1;
  }
  int accessor(const std::string& bytes, int component, std::size_t count, const char* type,
               bool normalized = false) {
    const int v = view(bytes);
    accessors_.push_back("{\"bufferView\":" + std::to_string(v) +
                         ",\"componentType\":" + std::to_string(component) +
                         ",\"count\":" + std::to_string(count) + ",\"type\":\"" + type + "\"" +
                         (normalized ? ",\"normalized\":true" : "") + "}");
    return int(accessors_.size()) - 1;
  }
  // `rest`: the meshes, nodes, scenes, materials... members of the JSON object.
  std::string glb(const std::string& rest) const {
    std::string json = "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":" +
                       std::to_string(bin_.size()) + "}],\"bufferViews\":[" + join(views_) +
                       "],\"accessors\":[" + join(accessors_) + "]," + rest + "}";
    return pack(json, bin_);
  }
  static std::string pack(std::string json, std::string bin) {
    while (json.size() % 4) json += ' ';
    while (bin.size() % 4) bin += '\0';
    Bytes b;
    b.text("glTF").u32le(2).u32le(
        std::uint32_t(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size())));
    b.u32le(std::uint32_t(json.size())).u32le(0x4E4F534A).text(json);
    if (!bin.empty()) b.u32le(std::uint32_t(bin.size())).u32le(0x004E4942).text(bin);
    return b.str();
  }

 private:
  static std::string join(const std::vector<std::string>& items) {
    std::string s;
    for (const auto& i : items) s += (s.empty() ? "" : ",") + i;
    return s;
  }
  std::string bin_;
  std::vector<std::string> views_, accessors_;
};

std::string floats(const std::vector<double>& values) {
  Bytes b;
  for (double v : values) b.f32le(float(v));
  return b.str();
}

std::vector<double> cube_positions() {
  std::vector<double> p;
  for (const auto& v : test_io::cube_vertices()) p.insert(p.end(), v.begin(), v.end());
  return p;
}

std::string cube_indices_ushort() {
  Bytes b;
  for (const auto& t : test_io::cube_triangles()) {
    for (int k : t) b.u16le(std::uint16_t(k));
  }
  return b.str();
}

// The indexed cube under the given nodes ("nodes" and "scenes" members).
std::string cube_glb(const std::string& nodes_and_scenes, const std::string& primitive_extra = "",
                     Gltf* g = nullptr) {
  Gltf local;
  Gltf& gltf = g ? *g : local;
  const int pos = gltf.accessor(floats(cube_positions()), kFloat, 8, "VEC3");
  const int idx = gltf.accessor(cube_indices_ushort(), kUShort, 36, "SCALAR");
  return gltf.glb(
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
      "},\"indices\":" + std::to_string(idx) + primitive_extra + "}]}]," + nodes_and_scenes);
}

const std::string kOneNode = "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"scene\":0";

std::string error_of(const std::string& bytes) {
  return input_error_of([&] { read_mesh(bytes); });
}

TEST(ReadGlb, TheIndexedCubeReadsAsTheOffCube) {
  ReadReport report;
  const Mesh mesh = read_mesh(cube_glb(kOneNode), {}, &report);
  test_io::expect_same_shape(read_mesh(test_io::cube_off()), mesh);
  EXPECT_EQ(report.format, MeshFormat::Glb);
  EXPECT_EQ(report.variant, "glTF 2.0 binary");
  EXPECT_EQ(report.colour_source, "none");
  EXPECT_FALSE(mesh.has_colour());
}

TEST(ReadGlb, NonIndexedPrimitivesAsInFox) {
  std::vector<double> p;
  const auto& v = test_io::cube_vertices();
  for (const auto& t : test_io::cube_triangles()) {
    for (int k : t) p.insert(p.end(), v[std::size_t(k)].begin(), v[std::size_t(k)].end());
  }
  Gltf g;
  const int pos = g.accessor(floats(p), kFloat, 36, "VEC3");
  const Mesh mesh = read_mesh(g.glb("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" +
                                    std::to_string(pos) + "}}]}]," + kOneNode));
  EXPECT_EQ(mesh.V.rows(), 36);
  test_io::expect_same_shape(read_mesh(test_io::cube_off()), mesh);
}

TEST(ReadGlb, NodeTransformsPlaceTheMesh) {
  // Translation and scale: the cube [10,12] x [0,2] x [0,2].
  Mesh mesh =
      read_mesh(cube_glb("\"nodes\":[{\"mesh\":0,\"translation\":[10,0,0],\"scale\":[2,2,2]}],"
                         "\"scenes\":[{\"nodes\":[0]}]"));
  EXPECT_NEAR(mesh.V.col(0).minCoeff(), 10, 1e-9);
  EXPECT_NEAR(mesh.V.col(0).maxCoeff(), 12, 1e-9);
  EXPECT_NEAR(test_io::mesh_area(mesh), 24, 1e-9);
  EXPECT_NEAR(test_io::mesh_volume(mesh), 8, 1e-9);
  // The same as a column-major matrix, under a parent that moves it up by 5.
  mesh =
      read_mesh(cube_glb("\"nodes\":[{\"children\":[1],\"translation\":[0,5,0]},"
                         "{\"mesh\":0,\"matrix\":[2,0,0,0, 0,2,0,0, 0,0,2,0, "
                         "10,0,0,1]}],\"scenes\":[{\"nodes\":[0]}]"));
  EXPECT_NEAR(mesh.V.col(0).minCoeff(), 10, 1e-9);
  EXPECT_NEAR(mesh.V.col(1).minCoeff(), 5, 1e-9);
  EXPECT_NEAR(mesh.V.col(1).maxCoeff(), 7, 1e-9);
  // A quarter turn about z keeps the volume; a mirror keeps it positive by flipping the winding.
  mesh =
      read_mesh(cube_glb("\"nodes\":[{\"mesh\":0,\"rotation\":[0,0,0.70710678,0.70710678]}],"
                         "\"scenes\":[{\"nodes\":[0]}]"));
  EXPECT_NEAR(mesh.V.col(0).minCoeff(), -1, 1e-6);
  EXPECT_NEAR(test_io::mesh_volume(mesh), 1, 1e-6);
  mesh = read_mesh(
      cube_glb("\"nodes\":[{\"mesh\":0,\"scale\":[-1,1,1]}],\"scenes\":[{\"nodes\":[0]}]"));
  EXPECT_NEAR(test_io::mesh_volume(mesh), 1, 1e-9);
  // Two nodes sharing the mesh: two cubes.
  mesh =
      read_mesh(cube_glb("\"nodes\":[{\"mesh\":0},{\"mesh\":0,\"translation\":[3,0,0]}],"
                         "\"scenes\":[{\"nodes\":[0,1]}]"));
  EXPECT_EQ(mesh.F.rows(), 24);
}

TEST(ReadGlb, StripsFansAndByteIndices) {
  Gltf g;
  const int pos = g.accessor(floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}), kFloat, 4, "VEC3");
  Bytes strip;
  strip.u8(0).u8(1).u8(3).u8(2);
  const int s = g.accessor(strip.str(), kUByte, 4, "SCALAR");
  Bytes fan;
  fan.u8(0).u8(1).u8(2).u8(3);
  const int f = g.accessor(fan.str(), kUByte, 4, "SCALAR");
  const std::string p = "{\"attributes\":{\"POSITION\":" + std::to_string(pos) + "},\"indices\":";
  const Mesh mesh = read_mesh(g.glb("\"meshes\":[{\"primitives\":[" + p + std::to_string(s) +
                                    ",\"mode\":5}," + p + std::to_string(f) + ",\"mode\":6}," + p +
                                    std::to_string(f) + ",\"mode\":1}]}]," + kOneNode));
  EXPECT_EQ(mesh.F.rows(), 4);
  EXPECT_NEAR(test_io::mesh_area(mesh), 2, 1e-9);
}

// One triangle near the top of the texture and one near the bottom.
std::string textured_glb(const std::string& sampler, const std::string& factor,
                         const std::string& nodes = kOneNode) {
  const std::string png = test_io::encode_image("png", 4, 4, [](int, int y) {
    return y < 2 ? std::array<std::uint8_t, 3>{255, 0, 0} : std::array<std::uint8_t, 3>{0, 0, 255};
  });
  Gltf g;
  const int pos =
      g.accessor(floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 0, 0, 6, 0, 0, 5, 1, 0}), kFloat, 6, "VEC3");
  // glTF: v = 0 is the top row of the image.
  const int uv = g.accessor(floats({0.3, 0.2, 0.6, 0.2, 0.4, 0.3, 0.3, 0.8, 0.6, 0.8, 0.4, 0.7}),
                            kFloat, 6, "VEC2");
  const int image = g.view(png);
  return g.glb("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
               ",\"TEXCOORD_0\":" + std::to_string(uv) + "},\"material\":0}]}]," + nodes +
               ",\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}" +
               factor + "}}],\"textures\":[{\"source\":0,\"sampler\":0}],\"samplers\":[" + sampler +
               "],\"images\":[{\"bufferView\":" + std::to_string(image) +
               ",\"mimeType\":\"image/png\"}]");
}

TEST(ReadGlb, BaseColourTextureSampledWithVZeroAtTheTop) {
  ReadReport report;
  Mesh mesh = read_mesh(textured_glb("{}", ""), {}, &report);
  ASSERT_TRUE(mesh.has_colour());
  EXPECT_EQ(report.colour_source, "texture");
  EXPECT_NEAR(mesh.C(0, 0), 1, 1e-6);  // top: red
  EXPECT_NEAR(mesh.C(0, 2), 0, 1e-6);
  EXPECT_NEAR(mesh.C(1, 0), 0, 1e-6);  // bottom: blue
  EXPECT_NEAR(mesh.C(1, 2), 1, 1e-6);
  // The factor multiplies the texture.
  mesh = read_mesh(textured_glb("{}", ",\"baseColorFactor\":[0.5,1,1,1]"));
  EXPECT_NEAR(mesh.C(0, 0), 0.5, 1e-6);
}

TEST(ReadGlb, Texcoord0AndItsImageAreKeptForDisplay) {
  const std::string glb = textured_glb("{\"wrapS\":33071}", "");
  MeshTexture texture;
  ReadReport report;
  const Mesh mesh = read_mesh(glb, {}, &report, &texture);
  ASSERT_FALSE(texture.empty());
  ASSERT_EQ(texture.images.size(), 1u);
  ASSERT_EQ(texture.maps.size(), 1u);
  EXPECT_EQ(texture.images[0].encoded.compare(0, 4, "\x89PNG"), 0);
  EXPECT_EQ(texture.images[0].image.width, 4);
  const io::DisplayMap& map = texture.maps[0];
  EXPECT_EQ(map.image, 0);
  EXPECT_FALSE(map.sampler.v_origin_bottom);
  EXPECT_EQ(map.sampler.wrap_s, io::TextureWrap::ClampToEdge);
  EXPECT_EQ(map.sampler.wrap_t, io::TextureWrap::Repeat);
  EXPECT_EQ(map.factor, (std::array<float, 3>{1, 1, 1}));
  const std::vector<float> expected = {0.3f, 0.2f, 0.6f, 0.2f, 0.4f, 0.3f,
                                       0.3f, 0.8f, 0.6f, 0.8f, 0.4f, 0.7f};
  EXPECT_EQ(texture.uv, expected);
  EXPECT_EQ(texture.triangle_map, (std::vector<int>{0, 0}));
  const Mesh plain = read_mesh(glb);
  EXPECT_EQ(mesh.V, plain.V);
  EXPECT_EQ(mesh.F, plain.F);
  EXPECT_EQ(mesh.C, plain.C);
  EXPECT_EQ(report.colour_source, "texture");
}

// Three primitives of one mesh: a triangle with texture A, one with texture B and a factor, one
// with only a factor; then a fourth with texture A again under another factor.
std::string three_materials_glb(bool fourth = false) {
  const auto plain = [](std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    return test_io::encode_image("png", 2, 2, [=](int, int) {
      return std::array<std::uint8_t, 3>{r, g, b};
    });
  };
  Gltf g;
  const int tri = g.accessor(floats({0, 0, 0, 1, 0, 0, 0, 1, 0}), kFloat, 3, "VEC3");
  const int far = g.accessor(floats({5, 0, 0, 6, 0, 0, 5, 1, 0}), kFloat, 3, "VEC3");
  const int top = g.accessor(floats({0, 5, 0, 1, 5, 0, 0, 6, 0}), kFloat, 3, "VEC3");
  const int back = g.accessor(floats({0, 0, 5, 1, 0, 5, 0, 1, 5}), kFloat, 3, "VEC3");
  const int uv = g.accessor(floats({0.1, 0.1, 0.9, 0.1, 0.1, 0.9}), kFloat, 3, "VEC2");
  const int a = g.view(plain(200, 0, 200)), b = g.view(plain(0, 180, 0));
  const auto prim = [&](int pos, int material, bool textured) {
    return "{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
           (textured ? ",\"TEXCOORD_0\":" + std::to_string(uv) : std::string()) +
           "},\"material\":" + std::to_string(material) + "}";
  };
  std::string prims = prim(tri, 0, true) + "," + prim(far, 1, true) + "," + prim(top, 2, false);
  if (fourth) prims += "," + prim(back, 3, true);
  return g.glb("\"meshes\":[{\"primitives\":[" + prims + "]}]," + kOneNode +
               ",\"materials\":["
               "{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}}},"
               "{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":1},"
               "\"baseColorFactor\":[0.5,1,0.25,1]}},"
               "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.2,0.4,0.6,1]}},"
               "{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0},"
               "\"baseColorFactor\":[1,0.5,1,1]}}],"
               "\"textures\":[{\"source\":0},{\"source\":1,\"sampler\":0}],"
               "\"samplers\":[{\"wrapS\":33648}],"
               "\"images\":[{\"bufferView\":" +
               std::to_string(a) + ",\"mimeType\":\"image/png\"},{\"bufferView\":" +
               std::to_string(b) + ",\"mimeType\":\"image/png\"}]");
}

TEST(ReadGlb, EachPrimitiveKeepsItsOwnTextureAndFactorForDisplay) {
  MeshTexture texture;
  ReadReport report;
  const std::string glb = three_materials_glb();
  const Mesh mesh = read_mesh(glb, {}, &report, &texture);
  ASSERT_EQ(mesh.F.rows(), 3);
  ASSERT_EQ(texture.images.size(), 2u);
  ASSERT_EQ(texture.maps.size(), 2u);
  EXPECT_EQ(texture.triangle_map, (std::vector<int>{0, 1, -1}));
  EXPECT_EQ(texture.maps[0].image, 0);
  EXPECT_EQ(texture.maps[1].image, 1);
  EXPECT_EQ(texture.maps[0].factor, (std::array<float, 3>{1, 1, 1}));
  EXPECT_EQ(texture.maps[1].factor, (std::array<float, 3>{0.5f, 1, 0.25f}));
  EXPECT_EQ(texture.maps[0].sampler.wrap_s, io::TextureWrap::Repeat);
  EXPECT_EQ(texture.maps[1].sampler.wrap_s, io::TextureWrap::MirroredRepeat);
  EXPECT_EQ(texture.images[1].image.width, 2);
  EXPECT_EQ(texture.images[1].image.rgb[1], 180);  // green: image B
  for (std::size_t i = 0; i < 12; ++i) EXPECT_FALSE(std::isnan(texture.uv[i])) << i;
  for (std::size_t i = 12; i < 18; ++i) EXPECT_TRUE(std::isnan(texture.uv[i])) << i;
  // The colours the ARG is built from: each texture times its factor, and the untextured
  // primitive's factor; the same whether the display textures are asked for or not.
  const Mesh plain = read_mesh(glb);
  EXPECT_EQ(mesh.C, plain.C);
  EXPECT_NEAR(mesh.C(0, 0), 200.0 / 255, 1e-3);
  EXPECT_NEAR(mesh.C(1, 0), 0, 1e-6);
  EXPECT_NEAR(mesh.C(1, 1), 180.0 / 255, 1e-3);
  EXPECT_NEAR(mesh.C(1, 2), 0, 1e-6);
  EXPECT_NEAR(mesh.C(2, 0), 0.2, 1e-6);
  EXPECT_NEAR(mesh.C(2, 2), 0.6, 1e-6);
  EXPECT_EQ(report.colour_source, "texture");
}

TEST(ReadGlb, ATextureUnderTwoFactorsIsTwoMapsOfOneImage) {
  MeshTexture texture;
  read_mesh(three_materials_glb(true), {}, nullptr, &texture);
  ASSERT_EQ(texture.images.size(), 2u);
  ASSERT_EQ(texture.maps.size(), 3u);
  EXPECT_EQ(texture.triangle_map, (std::vector<int>{0, 1, -1, 2}));
  EXPECT_EQ(texture.maps[2].image, 0);
  EXPECT_EQ(texture.maps[2].factor, (std::array<float, 3>{1, 0.5f, 1}));
}

TEST(ReadGlb, AMirroringNodeKeepsEachCornersTextureCoordinates) {
  // The one node, given a scale of -1 on x: the reader reverses the winding.
  const std::string glb = textured_glb(
      "{}", "",
      "\"nodes\":[{\"mesh\":0,\"scale\":[-1,1,1]}],\"scenes\":[{\"nodes\":[0]}],\"scene\":0");
  MeshTexture texture;
  const Mesh mesh = read_mesh(glb, {}, nullptr, &texture);
  ASSERT_EQ(texture.uv.size(), 12u);
  EXPECT_EQ(mesh.F(0, 1), 2);  // wound the other way
  // Corner k of triangle f keeps the coordinates its vertex has in the file.
  const std::vector<double> file_uv = {0.3, 0.2, 0.6, 0.2, 0.4, 0.3, 0.3, 0.8, 0.6, 0.8, 0.4, 0.7};
  for (int f = 0; f < 2; ++f)
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 2; ++i)
        EXPECT_FLOAT_EQ(texture.uv[std::size_t(6 * f + 2 * k + i)],
                        float(file_uv[std::size_t(2 * mesh.F(f, k) + i)]));
}

TEST(ReadGlb, ATexcoordAccessorShorterThanThePositionsIsRefused) {
  const std::string png = test_io::encode_image("png", 2, 2, [](int, int) {
    return std::array<std::uint8_t, 3>{9, 9, 9};
  });
  Gltf g;
  const int pos = g.accessor(floats({0, 0, 0, 1, 0, 0, 0, 1, 0}), kFloat, 3, "VEC3");
  const int uv = g.accessor(floats({0, 0, 1, 0}), kFloat, 2, "VEC2");
  const int image = g.view(png);
  const std::string glb =
      g.glb("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
            ",\"TEXCOORD_0\":" + std::to_string(uv) + "},\"material\":0}]}]," + kOneNode +
            ",\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}}}],"
            "\"textures\":[{\"source\":0}],\"images\":[{\"bufferView\":" +
            std::to_string(image) + ",\"mimeType\":\"image/png\"}]");
  MeshTexture texture;
  try {
    read_mesh(glb, {}, nullptr, &texture);
    FAIL() << "read a GLB with 2 texture coordinates for 3 vertices";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("TEXCOORD is not a VEC2 per vertex"), std::string::npos)
        << e.what();
  }
}

// A cube whose base colour texture is eight bytes that no decoder reads.
std::string cube_with_undecodable_texture() {
  return cube_glb(
      kOneNode +
          ",\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}}}],"
          "\"textures\":[{\"source\":0}],"
          "\"images\":[{\"uri\":\"data:image/png;base64,AAECAwQFBgc=\"}]",
      ",\"material\":0");
}

TEST(ReadGlb, AnUnusableTextureLeavesNothingToMap) {
  const std::string garbage = cube_with_undecodable_texture();
  MeshTexture texture;
  read_mesh(garbage, {}, nullptr, &texture);
  EXPECT_TRUE(texture.empty());
}

TEST(ReadGlb, VertexColoursAndMaterialColours) {
  Gltf g;
  const int pos = g.accessor(floats({0, 0, 0, 1, 0, 0, 0, 1, 0}), kFloat, 3, "VEC3");
  Bytes rgba;
  for (int i = 0; i < 3; ++i) rgba.u8(255).u8(0).u8(0).u8(255);
  const int col = g.accessor(rgba.str(), kUByte, 3, "VEC4", true);
  ReadReport report;
  Mesh mesh = read_mesh(
      g.glb("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
            ",\"COLOR_0\":" + std::to_string(col) + "}}]}]," + kOneNode),
      {}, &report);
  ASSERT_TRUE(mesh.has_colour());
  EXPECT_EQ(report.colour_source, "vertex");
  EXPECT_NEAR(mesh.C(0, 0), 1, 1e-6);
  mesh = read_mesh(
      cube_glb(
          kOneNode +
              ",\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.5,0.25,1,1]}}]",
          ",\"material\":0"),
      {}, &report);
  ASSERT_TRUE(mesh.has_colour());
  EXPECT_EQ(report.colour_source, "material");
  EXPECT_NEAR(mesh.C(5, 1), 0.25, 1e-6);
}

TEST(ReadGlb, AnUnusableTextureIsAWarningNotAnError) {
  const std::string garbage = cube_with_undecodable_texture();
  ReadReport report;
  const Mesh mesh = read_mesh(garbage, {}, &report);
  EXPECT_EQ(mesh.F.rows(), 12);
  EXPECT_FALSE(report.warnings.empty());
}

// A URI that is not data: names a file on the server, which is never opened.
TEST(ReadGlb, AnImageInAnExternalFileIsRejectedWithoutOpeningIt) {
  const std::string external = cube_glb(
      kOneNode +
          ",\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}}}],"
          "\"textures\":[{\"source\":0}],\"images\":[{\"uri\":\"/etc/passwd\"}]",
      ",\"material\":0");
  const std::string message = error_of(external);
  EXPECT_NE(message.find("image 0 refers to an external file"), std::string::npos) << message;
}

// glTF requires byteLength >= 1; tinygltf indexes the first byte of an embedded buffer, so a
// zero-length one is rejected before it runs (found by fuzz_read_glb).
TEST(ReadGlb, AZeroLengthBufferIsAnInputError) {
  std::string glb = cube_glb(kOneNode);
  const std::string key = "\"buffers\":[{\"byteLength\":";
  const std::size_t at = glb.find(key);
  ASSERT_NE(at, std::string::npos);
  std::size_t digits = at + key.size();
  while (glb[digits] >= '0' && glb[digits] <= '9') glb[digits++] = ' ';
  glb[at + key.size()] = '0';  // same length: the JSON chunk header stays right
  const std::string message = error_of(glb);
  EXPECT_NE(message.find("buffer 0 has byteLength 0"), std::string::npos) << message;
}

TEST(ReadGlb, HostileNodeGraphsAreInputErrors) {
  EXPECT_NE(error_of(cube_glb("\"nodes\":[{\"mesh\":0,\"children\":[1]},{\"children\":[0]}],"
                              "\"scenes\":[{\"nodes\":[0]}]"))
                .find("twice"),
            std::string::npos);
  std::string chain = "\"nodes\":[";
  for (int i = 0; i < 100; ++i) chain += "{\"children\":[" + std::to_string(i + 1) + "]},";
  chain += "{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]";
  EXPECT_NE(error_of(cube_glb(chain)).find("deeper"), std::string::npos);
  EXPECT_NE(
      error_of(cube_glb("\"nodes\":[{\"mesh\":3}],\"scenes\":[{\"nodes\":[0]}]")).find("mesh 3"),
      std::string::npos);
  EXPECT_NE(error_of(cube_glb("\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"scene\":4"))
                .find("scene"),
            std::string::npos);
}

TEST(ReadGlb, HostileBuffersAndAccessorsAreInputErrors) {
  Gltf g;
  const int pos = g.accessor(floats(cube_positions()), kFloat, 8, "VEC3");
  const int big = g.accessor(floats(cube_positions()), kFloat, 9, "VEC3");  // one too many
  const int idx = g.accessor(cube_indices_ushort(), kUShort, 36, "SCALAR");
  Bytes bad_index;
  bad_index.u16le(0).u16le(1).u16le(8);
  const int bad = g.accessor(bad_index.str(), kUShort, 3, "SCALAR");
  auto prim = [&](int p, int i) {
    return g.glb("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(p) +
                 "},\"indices\":" + std::to_string(i) + "}]}]," + kOneNode);
  };
  EXPECT_EQ(read_mesh(prim(pos, idx)).F.rows(), 12);
  EXPECT_NE(error_of(prim(big, idx)).find("run past"), std::string::npos)
      << error_of(prim(big, idx));
  EXPECT_NE(error_of(prim(pos, bad)).find("8"), std::string::npos);
  // Buffers: an external file, and a second buffer claiming the BIN chunk.
  EXPECT_NE(error_of(Gltf::pack("{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":4,"
                                "\"uri\":\"/etc/passwd\"}]}",
                                ""))
                .find("external"),
            std::string::npos);
  EXPECT_NE(error_of(Gltf::pack("{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":4},{"
                                "\"byteLength\":4}]}",
                                "abcd"))
                .find("buffer 1"),
            std::string::npos);
  EXPECT_NE(
      error_of(Gltf::pack("{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":4}],"
                          "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":2,\"byteLength\":4}]}",
                          "abcd"))
          .find("buffer view 0"),
      std::string::npos);
  // JSON: invalid, and nested deep enough to exhaust a recursive parser.
  EXPECT_NE(error_of(Gltf::pack("{\"asset\":", "")).find("JSON"), std::string::npos);
  const std::string deep =
      "{\"asset\":{\"version\":\"2.0\"},\"extras\":" + std::string(100000, '[') +
      std::string(100000, ']') + "}";
  EXPECT_NE(error_of(Gltf::pack(deep, "")).find("nested"), std::string::npos);
}

TEST(ReadGlb, BadContainersAreInputErrorsNamingTheOffset) {
  const std::string good = cube_glb(kOneNode);
  for (std::size_t n = 0; n < good.size(); ++n) {
    EXPECT_THROW(read_mesh(good.substr(0, n)), InputError) << "prefix " << n;
  }
  std::string version = good;
  version[4] = 1;
  EXPECT_NE(error_of(version).find("GLB: byte offset 4"), std::string::npos);
  std::string length = good;
  length[10] = 0x7f;
  EXPECT_NE(error_of(length).find("truncated"), std::string::npos);
}

TEST(ReadGlb, RandomCorruptionGivesTypedErrorsOnly) {
  test_io::expect_only_typed_errors(cube_glb(kOneNode), 13, 400);
  test_io::expect_only_typed_errors(textured_glb("{\"wrapS\":33071}", ""), 14, 400);
}

TEST(ReadGlb, LimitsApply) {
  ReadOptions options;
  options.limits.max_vertices = 7;
  EXPECT_THROW(read_mesh(cube_glb(kOneNode), options), LimitError);
  options.limits.max_vertices = 8;
  options.limits.max_triangles = 11;
  EXPECT_THROW(read_mesh(cube_glb(kOneNode), options), LimitError);
}

}  // namespace
}  // namespace arg
