// Tests of the mesh writers: OFF, binary PLY, binary STL and OBJ say what the mesh holds.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>

#include "io/write_mesh.hpp"

namespace arg {
namespace {

// A unit tetrahedron, outward oriented, optionally with one colour per face.
Mesh tetrahedron(bool colour) {
  Mesh m;
  m.V.resize(4, 3);
  m.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1.25;
  m.F.resize(4, 3);
  m.F << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
  if (colour) {
    m.C.resize(4, 3);
    m.C << 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5f, 0.25f, 1.0f / 3.0f;
  }
  return m;
}

// Just enough of an OFF reader to read back what write_off writes.
Mesh parse_off(const std::string& text, bool* had_colour) {
  std::istringstream in(text);
  std::string keyword;
  long nv = 0, nf = 0, ne = 0;
  in >> keyword >> nv >> nf >> ne;
  EXPECT_EQ(keyword, "OFF");
  Mesh m;
  m.V.resize(nv, 3);
  for (long v = 0; v < nv; ++v) in >> m.V(v, 0) >> m.V(v, 1) >> m.V(v, 2);
  m.F.resize(nf, 3);
  m.C.resize(nf, 3);
  std::string line;
  std::getline(in, line);
  *had_colour = false;
  for (long f = 0; f < nf; ++f) {
    std::getline(in, line);
    std::istringstream fl(line);
    int corners = 0;
    fl >> corners >> m.F(f, 0) >> m.F(f, 1) >> m.F(f, 2);
    EXPECT_EQ(corners, 3);
    int rgb[3];
    if (fl >> rgb[0] >> rgb[1] >> rgb[2]) {
      *had_colour = true;
      for (int c = 0; c < 3; ++c) m.C(f, c) = static_cast<float>(rgb[c] / 255.0);
    }
  }
  if (!*had_colour) m.C.resize(0, 3);
  return m;
}

std::uint32_t u32_at(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(s[at + i]);
  return v;
}

float f32_at(const std::string& s, std::size_t at) {
  const std::uint32_t bits = u32_at(s, at);
  float f = 0;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

TEST(WriteMesh, OffReadsBackToTheSameVerticesFacesAndColours) {
  const Mesh m = tetrahedron(true);
  bool had_colour = false;
  const Mesh back = parse_off(write_off(m), &had_colour);
  ASSERT_TRUE(had_colour);
  EXPECT_TRUE(back.F == m.F);
  EXPECT_TRUE(back.V.isApprox(m.V, 1e-9));
  EXPECT_LE((back.C - m.C).cwiseAbs().maxCoeff(), 0.5f / 255.0f + 1e-6f);
}

TEST(WriteMesh, OffWithoutColourHasBareFaceLinesAndHeaderCounts) {
  const std::string text = write_off(tetrahedron(false));
  EXPECT_EQ(text.substr(0, 12), "OFF\n4 4 0\n0 ");
  EXPECT_NE(text.find("\n3 0 2 1\n"), std::string::npos);
  bool had_colour = true;
  parse_off(text, &had_colour);
  EXPECT_FALSE(had_colour);
}

TEST(WriteMesh, OffKeepsNineSignificantDigits) {
  Mesh m = tetrahedron(false);
  m.V(1, 0) = 0.123456789123;
  const std::string text = write_off(m);
  EXPECT_NE(text.find("\n0.123456789 0 0\n"), std::string::npos) << text;
}

TEST(WriteMesh, PlyHeaderDeclaresCountsAndTheBodyHasExactlyThatSize) {
  for (bool colour : {false, true}) {
    const Mesh m = tetrahedron(colour);
    const std::string ply = write_ply_binary(m);
    const std::size_t end = ply.find("end_header\n");
    ASSERT_NE(end, std::string::npos);
    const std::string header = ply.substr(0, end);
    EXPECT_EQ(header.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
    EXPECT_NE(header.find("element vertex 4\n"), std::string::npos);
    EXPECT_NE(header.find("element face 4\n"), std::string::npos);
    EXPECT_EQ(header.find("property uchar red") != std::string::npos, colour);
    const std::size_t body = end + 11;
    EXPECT_EQ(ply.size(), body + 4 * 12 + 4 * (colour ? 16 : 13));
    EXPECT_EQ(f32_at(ply, body + 3 * 12 + 8), 1.25f);  // z of the fourth vertex
    const std::size_t last_face = body + 4 * 12 + 3 * (colour ? 16 : 13);
    EXPECT_EQ(ply[last_face], 3);
    EXPECT_EQ(u32_at(ply, last_face + 1), 1u);
    EXPECT_EQ(u32_at(ply, last_face + 9), 3u);
    if (colour) {
      EXPECT_EQ(static_cast<unsigned char>(ply[last_face + 14]), 64);  // 0.25 * 255
    }
  }
}

TEST(WriteMesh, StlHasAnEightyByteHeaderACountAndFiftyBytesPerTriangle) {
  const Mesh m = tetrahedron(true);
  const std::string stl = write_stl_binary(m);
  ASSERT_EQ(stl.size(), 84u + 4 * 50);
  EXPECT_NE(stl.substr(0, 5), "solid");  // would read as ASCII STL
  EXPECT_EQ(u32_at(stl, 80), 4u);
  // First facet (0, 2, 1) lies in z = 0 and faces down.
  EXPECT_EQ(f32_at(stl, 84 + 8), -1.0f);
  EXPECT_EQ(f32_at(stl, 84 + 12 + 12), 0.0f);  // second corner = vertex 2 = (0, 1, 0)
  EXPECT_EQ(f32_at(stl, 84 + 12 + 16), 1.0f);
}

TEST(WriteMesh, ObjHasOneLinePerVertexAndFaceWithOneBasedIndices) {
  const std::string obj = write_obj(tetrahedron(true));
  std::istringstream in(obj);
  std::string line;
  int v = 0, f = 0;
  while (std::getline(in, line)) {
    v += line.rfind("v ", 0) == 0;
    f += line.rfind("f ", 0) == 0;
  }
  EXPECT_EQ(v, 4);
  EXPECT_EQ(f, 4);
  EXPECT_NE(obj.find("\nf 1 3 2\n"), std::string::npos);
  EXPECT_NE(obj.find("\nv 0 0 1.25\n"), std::string::npos);
}

TEST(WriteMesh, WritersAreDeterministic) {
  const Mesh m = tetrahedron(true);
  EXPECT_EQ(write_off(m), write_off(m));
  EXPECT_EQ(write_ply_binary(m), write_ply_binary(m));
  EXPECT_EQ(write_stl_binary(m), write_stl_binary(m));
  EXPECT_EQ(write_obj(m), write_obj(m));
}

TEST(WriteMesh, AnEmptyMeshWritesValidEmptyFiles) {
  const Mesh empty;
  EXPECT_EQ(write_off(empty), "OFF\n0 0 0\n");
  EXPECT_EQ(write_stl_binary(empty).size(), 84u);
  EXPECT_NE(write_ply_binary(empty).find("element vertex 0\n"), std::string::npos);
}

}  // namespace
}  // namespace arg
