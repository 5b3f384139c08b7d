// Tests that the real meshes of ../shared/data read with plausible counts and colours.
#include <gtest/gtest.h>

#include <dirent.h>

#include <algorithm>
#include <chrono>

#include "common/errors.hpp"
#include "io/read_mesh.hpp"
#include "test_io_support.hpp"

namespace arg {
namespace {

Mesh read_shared(const std::string& relative, ReadReport* report,
                 const std::string& texture_relative = "") {
  std::string bytes, texture;
  EXPECT_TRUE(test_io::read_file(test_io::shared_data_dir() + "/" + relative, bytes)) << relative;
  if (!texture_relative.empty()) {
    EXPECT_TRUE(test_io::read_file(test_io::shared_data_dir() + "/" + texture_relative, texture));
  }
  ReadOptions options;
  options.texture = texture;
  return read_mesh(bytes, options, report);
}

bool shared_data_present(const std::string& relative) {
  std::string bytes;
  return test_io::read_file(test_io::shared_data_dir() + "/" + relative, bytes);
}

#define ARG_REQUIRE_SHARED(relative)                                                    \
  if (!shared_data_present(relative)) {                                                 \
    GTEST_SKIP() << "shared test data not found: " << test_io::shared_data_dir() << "/" \
                 << (relative);                                                         \
  }

// Colours that vary over the mesh (a texture was really sampled).
void expect_varied_colours(const Mesh& mesh) {
  ASSERT_TRUE(mesh.has_colour());
  const float spread = (mesh.C.colwise().maxCoeff() - mesh.C.colwise().minCoeff()).maxCoeff();
  EXPECT_GT(spread, 0.2f);
  EXPECT_GE(mesh.C.minCoeff(), 0.0f);
  EXPECT_LE(mesh.C.maxCoeff(), 1.0f);
}

TEST(ReadRealData, FoxGlbNonIndexedWithTexture) {
  ARG_REQUIRE_SHARED("textured/fox/Fox.glb");
  ReadReport report;
  const Mesh mesh = read_shared("textured/fox/Fox.glb", &report);
  EXPECT_EQ(report.format, MeshFormat::Glb);
  EXPECT_EQ(mesh.F.rows(), 576);
  EXPECT_EQ(mesh.V.rows(), 1728);  // non-indexed: three vertices per triangle
  EXPECT_EQ(report.colour_source, "texture");
  expect_varied_colours(mesh);
}

TEST(ReadRealData, BoxTexturedGlbHasColourFromItsTexture) {
  ARG_REQUIRE_SHARED("textured/box/BoxTextured.glb");
  ReadReport report;
  const Mesh mesh = read_shared("textured/box/BoxTextured.glb", &report);
  EXPECT_EQ(mesh.F.rows(), 12);
  EXPECT_EQ(mesh.V.rows(), 24);
  EXPECT_EQ(report.colour_source, "texture");
  ASSERT_TRUE(mesh.has_colour());
}

TEST(ReadRealData, DamagedHelmetGlbWithJpegAlbedo) {
  ARG_REQUIRE_SHARED("textured/helmet/DamagedHelmet.glb");
  ReadReport report;
  const Mesh mesh = read_shared("textured/helmet/DamagedHelmet.glb", &report);
  EXPECT_EQ(mesh.F.rows(), 15452);
  EXPECT_EQ(report.colour_source, "texture");
  expect_varied_colours(mesh);
}

TEST(ReadRealData, SpotObjWithPngTexture) {
  ARG_REQUIRE_SHARED("textured/spot/spot_triangulated.obj");
  ReadReport report;
  const Mesh mesh =
      read_shared("textured/spot/spot_triangulated.obj", &report, "textured/spot/spot_texture.png");
  EXPECT_EQ(mesh.F.rows(), 5856);
  EXPECT_EQ(report.colour_source, "texture");
  EXPECT_TRUE(report.warnings.empty());
  expect_varied_colours(mesh);
}

// The spider's five materials each name an image: every face maps its material's, each image
// once, and the mesh is the one read without them.
TEST(ReadRealData, SpiderObjMapsEachMaterialsTexture) {
  ARG_REQUIRE_SHARED("textured/spider/spider.obj");
  const std::string dir = test_io::shared_data_dir() + "/textured/spider/";
  std::string obj;
  ASSERT_TRUE(test_io::read_file(dir + "spider.obj", obj));
  const char* const materials[][2] = {{"Skin", "wal67ar_small.jpg"},
                                      {"Brusttex", "wal69ar_small.jpg"},
                                      {"HLeibTex", "SpiderTex.jpg"},
                                      {"BeinTex", "drkwood2.jpg"},
                                      {"Augentex", "engineflare1.jpg"}};
  std::vector<std::string> images(5);
  ReadOptions options;
  for (std::size_t i = 0; i < 5; ++i) {
    ASSERT_TRUE(test_io::read_file(dir + materials[i][1], images[i]));
    options.material_textures.push_back({materials[i][0], images[i]});
  }
  ReadReport report;
  MeshTexture texture;
  const Mesh mesh = read_mesh(obj, options, &report, &texture);
  EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();
  // Brusttex is in the MTL but no face uses it.
  EXPECT_EQ(texture.images.size(), 4u);
  ASSERT_EQ(texture.maps.size(), 4u);
  std::vector<std::size_t> per_map(4, 0);
  for (int map : texture.triangle_map) {
    ASSERT_GE(map, 0);
    ++per_map[std::size_t(map)];
  }
  for (std::size_t count : per_map) EXPECT_GT(count, 0u);
  const Mesh plain = read_mesh(obj);
  EXPECT_TRUE(mesh.V == plain.V && mesh.F == plain.F);
}

TEST(ReadRealData, AfricanHeadAndDiabloObjWithRleTga) {
  ARG_REQUIRE_SHARED("textured/african_head/african_head.obj");
  ReadReport report;
  Mesh mesh = read_shared("textured/african_head/african_head.obj", &report,
                          "textured/african_head/african_head_diffuse.tga");
  EXPECT_EQ(mesh.F.rows(), 2492);
  EXPECT_EQ(report.colour_source, "texture");
  expect_varied_colours(mesh);
  mesh = read_shared("textured/diablo/diablo3_pose.obj", &report,
                     "textured/diablo/diablo3_pose_diffuse.tga");
  EXPECT_EQ(mesh.F.rows(), 5022);
  expect_varied_colours(mesh);
}

TEST(ReadRealData, SpiderObjWithMaterialsReadsWithOrWithoutATexture) {
  ARG_REQUIRE_SHARED("textured/spider/spider.obj");
  ReadReport report;
  Mesh mesh = read_shared("textured/spider/spider.obj", &report);
  EXPECT_GT(mesh.F.rows(), 500);
  EXPECT_EQ(report.colour_source, "none");
  mesh = read_shared("textured/spider/spider.obj", &report, "textured/spider/SpiderTex.jpg");
  EXPECT_EQ(report.colour_source, "texture");
}

TEST(ReadRealData, IgeaPlyTriangleStrips) {
  ARG_REQUIRE_SHARED("museum/igea.ply");
  ReadReport report;
  const Mesh mesh = read_shared("museum/igea.ply", &report);
  EXPECT_EQ(mesh.V.rows(), 134345);
  // A closed-ish surface has about two triangles per vertex.
  EXPECT_GT(mesh.F.rows(), 250000);
  EXPECT_LT(mesh.F.rows(), 280000);
  EXPECT_NE(report.variant.find("triangle strips"), std::string::npos);
}

TEST(ReadRealData, Shrec07BinaryPly) {
  ARG_REQUIRE_SHARED("shrec07/Meshes/1.ply");
  ReadReport report;
  const Mesh mesh = read_shared("shrec07/Meshes/1.ply", &report);
  EXPECT_EQ(mesh.V.rows(), 4706);
  EXPECT_EQ(mesh.F.rows(), 9408);
  EXPECT_EQ(report.variant, "binary_little_endian");
}

TEST(ReadRealData, EveryMuseumMeshReads) {
  const std::string dir = test_io::shared_data_dir() + "/museum";
  DIR* d = opendir(dir.c_str());
  if (!d) GTEST_SKIP() << "shared test data not found: " << dir;
  std::vector<std::string> names;
  while (const dirent* e = readdir(d)) {
    const std::string name = e->d_name;
    for (const char* ext : {".obj", ".off", ".ply"}) {
      if (name.size() > 4 && name.substr(name.size() - 4) == ext) names.push_back(name);
    }
  }
  closedir(d);
  std::sort(names.begin(), names.end());
  EXPECT_GE(names.size(), 30u);
  for (const std::string& name : names) {
    ReadReport report;
    try {
      const Mesh mesh = read_shared("museum/" + name, &report);
      EXPECT_GT(mesh.F.rows(), 100) << name;
      EXPECT_TRUE(mesh.V.allFinite()) << name;
      EXPECT_GE(mesh.F.minCoeff(), 0) << name;
      EXPECT_LT(mesh.F.maxCoeff(), mesh.V.rows()) << name;
    } catch (const Error& e) {
      ADD_FAILURE() << name << ": " << e.what();
    }
  }
}

}  // namespace
}  // namespace arg
