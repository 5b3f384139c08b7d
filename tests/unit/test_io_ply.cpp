// Tests of reading PLY: ASCII and both binary byte orders, colours, strips, odd layouts, bad input.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "common/errors.hpp"
#include "input_error.hpp"
#include "io/read_mesh.hpp"
#include "test_io_support.hpp"

namespace arg {
namespace {

using test_io::Bytes;

struct PlyLayout {
  std::string encoding = "ascii";  // or binary_little_endian, binary_big_endian
  std::string coordinate = "float";
  std::string count_type = "uchar";
  std::string index_type = "int";
  bool vertex_colour = false;
  bool face_colour = false;
  bool faces_first = false;        // face element before the vertex element
  std::string comment_before_end;  // a header line just before end_header
};

// Writes one value of a PLY type in the layout's encoding.
void put(Bytes& b, const PlyLayout& l, const std::string& type, double value) {
  if (l.encoding == "ascii") {
    std::ostringstream s;
    s << value << ' ';
    b.text(s.str());
    return;
  }
  const bool be = l.encoding == "binary_big_endian";
  Bytes raw;
  if (type == "uchar" || type == "uint8") {
    raw.u8(std::uint8_t(value));
  } else if (type == "ushort" || type == "uint16") {
    raw.u16le(std::uint16_t(value));
  } else if (type == "int" || type == "int32" || type == "uint" || type == "uint32") {
    raw.i32le(std::int32_t(value));
  } else if (type == "float" || type == "float32") {
    raw.f32le(float(value));
  } else {
    raw.f64le(value);
  }
  std::string bytes = raw.str();
  if (be) bytes = std::string(bytes.rbegin(), bytes.rend());
  b.text(bytes);
}

std::string cube_ply(const PlyLayout& l) {
  Bytes b;
  b.text("ply\nformat " + l.encoding + " 1.0\ncomment a cube\n");
  const std::string vertex_header =
      "element vertex 8\nproperty " + l.coordinate + " x\nproperty " + l.coordinate +
      " y\nproperty " + l.coordinate + " z\n" +
      (l.vertex_colour ? "property uchar red\nproperty uchar green\nproperty uchar blue\n" : "");
  const std::string face_header =
      "element face 6\nproperty list " + l.count_type + " " + l.index_type + " vertex_indices\n" +
      (l.face_colour ? "property uchar red\nproperty uchar green\nproperty uchar blue\n" : "");
  b.text(l.faces_first ? face_header + vertex_header : vertex_header + face_header);
  if (!l.comment_before_end.empty()) b.text(l.comment_before_end + "\n");
  b.text("end_header\n");
  const bool ascii = l.encoding == "ascii";
  auto vertices = [&] {
    int i = 0;
    for (const auto& v : test_io::cube_vertices()) {
      for (double c : v) put(b, l, l.coordinate, c);
      if (l.vertex_colour) {
        put(b, l, "uchar", i < 4 ? 255 : 0);
        put(b, l, "uchar", 0);
        put(b, l, "uchar", i < 4 ? 0 : 255);
      }
      ++i;
      if (ascii) b.text("\n");
    }
  };
  auto faces = [&] {
    for (const auto& q : test_io::cube_quads()) {
      put(b, l, l.count_type, 4);
      for (int k : q) put(b, l, l.index_type, k);
      if (l.face_colour) {
        put(b, l, "uchar", 0);
        put(b, l, "uchar", 255);
        put(b, l, "uchar", 0);
      }
      if (ascii) b.text("\n");
    }
  };
  if (l.faces_first) {
    faces();
    vertices();
  } else {
    vertices();
    faces();
  }
  return b.str();
}

std::string error_of(const std::string& bytes) {
  return input_error_of([&] { read_mesh(bytes); });
}

const Mesh& off_cube() {
  static const Mesh mesh = read_mesh(test_io::cube_off());
  return mesh;
}

TEST(ReadPly, AsciiAndBothBinaryByteOrdersReadTheSameCube) {
  for (const char* encoding : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    PlyLayout layout;
    layout.encoding = encoding;
    ReadReport report;
    test_io::expect_same_shape(off_cube(), read_mesh(cube_ply(layout), {}, &report));
    EXPECT_EQ(report.variant, encoding);
    EXPECT_EQ(report.format, MeshFormat::Ply);
    EXPECT_EQ(report.faces_read, 6u);
    layout.coordinate = "double";
    layout.index_type = "uint";
    test_io::expect_same_shape(off_cube(), read_mesh(cube_ply(layout)));
  }
}

TEST(ReadPly, VertexColoursAndFaceColours) {
  for (const char* encoding : {"ascii", "binary_big_endian"}) {
    PlyLayout layout;
    layout.encoding = encoding;
    layout.vertex_colour = true;
    ReadReport report;
    Mesh mesh = read_mesh(cube_ply(layout), {}, &report);
    ASSERT_TRUE(mesh.has_colour()) << encoding;
    EXPECT_EQ(report.colour_source, "vertex");
    for (Eigen::Index t = 0; t < mesh.F.rows(); ++t) {
      const double z =
          (mesh.V(mesh.F(t, 0), 2) + mesh.V(mesh.F(t, 1), 2) + mesh.V(mesh.F(t, 2), 2)) / 3;
      EXPECT_NEAR(mesh.C(t, 0), 1 - z, 1e-6);
      EXPECT_NEAR(mesh.C(t, 2), z, 1e-6);
    }
    layout.face_colour = true;
    mesh = read_mesh(cube_ply(layout), {}, &report);
    EXPECT_EQ(report.colour_source, "face");
    EXPECT_NEAR(mesh.C(0, 1), 1.0, 1e-6);
  }
}

TEST(ReadPly, FloatVertexColours) {
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float "
      "z\n"
      "property float red\nproperty float green\nproperty float blue\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n"
      "0 0 0 0.5 0.25 1\n1 0 0 0.5 0.25 1\n0 1 0 0.5 0.25 1\n3 0 1 2\n";
  const Mesh mesh = read_mesh(ply);
  ASSERT_TRUE(mesh.has_colour());
  EXPECT_NEAR(mesh.C(0, 0), 0.5, 0.01);
  EXPECT_NEAR(mesh.C(0, 1), 0.25, 0.01);
  EXPECT_NEAR(mesh.C(0, 2), 1.0, 0.01);
}

TEST(ReadPly, AsciiValuesAreRoundedToTheDeclaredType) {
  // A float property is rounded once from the decimal, as a binary body stores it; a double one
  // keeps double precision (OpenMesh rounded both to float).
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty ";
  const std::string tail =
      " x\nproperty float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n"
      "-0.182252399623394 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_EQ(read_mesh(head + "float" + tail).V(0, 0),
            double(std::strtof("-0.182252399623394", nullptr)));
  EXPECT_EQ(read_mesh(head + "double" + tail).V(0, 0), -0.182252399623394);
}

TEST(ReadPly, LayoutsOpenMeshMisreadAreReadCorrectly) {
  PlyLayout layout;
  layout.encoding = "binary_little_endian";
  layout.count_type = "uint";  // OpenMesh refuses list lengths of type uint
  test_io::expect_same_shape(off_cube(), read_mesh(cube_ply(layout)));
  layout.count_type = "uchar";
  layout.coordinate = "int";  // OpenMesh would read integer coordinates as 0
  test_io::expect_same_shape(off_cube(), read_mesh(cube_ply(layout)));
  layout.coordinate = "float";
  // OpenMesh counts 12 bytes back from "end_header" to find a binary body: a comment line
  // there used to shift every value by a byte.
  layout.comment_before_end = "comment right before the end";
  test_io::expect_same_shape(off_cube(), read_mesh(cube_ply(layout)));
  layout.comment_before_end.clear();
  layout.faces_first = true;
  test_io::expect_same_shape(off_cube(), read_mesh(cube_ply(layout)));
}

std::string strips_ply(const std::string& encoding) {
  // The cube as triangle strips: each quad a b c d as the strip a b d c, strips separated by -1.
  PlyLayout l;
  l.encoding = encoding;
  Bytes b;
  b.text(
      "ply\nformat " + encoding +
      " 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
      "property float z\nelement tristrips 1\nproperty list int int vertex_indices\nend_header\n");
  for (const auto& v : test_io::cube_vertices()) {
    for (double c : v) put(b, l, "float", c);
  }
  put(b, l, "int", 6 * 5 - 1);
  bool first = true;
  for (const auto& q : test_io::cube_quads()) {
    if (!first) put(b, l, "int", -1);
    first = false;
    for (int k : {q[0], q[1], q[3], q[2]}) put(b, l, "int", k);
  }
  return b.str();
}

TEST(ReadPly, TriangleStripsAsInIgea) {
  for (const char* encoding : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    ReadReport report;
    test_io::expect_same_shape(off_cube(), read_mesh(strips_ply(encoding), {}, &report));
    EXPECT_NE(report.variant.find("triangle strips"), std::string::npos);
  }
}

TEST(ReadPly, PerCornerTextureCoordinatesWithASeparateTexture) {
  const std::string png = test_io::encode_image("png", 2, 2, [](int, int y) {
    return y == 0 ? std::array<std::uint8_t, 3>{0, 255, 0} : std::array<std::uint8_t, 3>{0, 0, 0};
  });
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float "
      "z\n"
      "element face 1\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 6 0.2 0.8 0.3 0.8 0.2 0.9\n";
  ReadOptions options;
  options.texture = png;
  ReadReport report;
  const Mesh mesh = read_mesh(ply, options, &report);
  ASSERT_TRUE(mesh.has_colour());
  EXPECT_EQ(report.colour_source, "texture");
  EXPECT_GT(mesh.C(0, 1), 0.6);
}

TEST(ReadPly, EveryTruncationIsAnInputError) {
  PlyLayout layout;
  for (const char* encoding : {"ascii", "binary_little_endian"}) {
    layout.encoding = encoding;
    const std::string full = cube_ply(layout);
    // Dropping only trailing blanks leaves a valid file.
    const std::size_t end = full.find_last_not_of(" \n") + 1;
    for (std::size_t n = 0; n < end; ++n) {
      EXPECT_THROW(read_mesh(full.substr(0, n)), InputError) << encoding << " prefix " << n;
    }
  }
  const std::string strips = strips_ply("binary_little_endian");
  for (std::size_t n = 0; n + 1 < strips.size(); ++n) {
    EXPECT_THROW(read_mesh(strips.substr(0, n)), InputError) << "strips prefix " << n;
  }
}

TEST(ReadPly, MalformedHeadersAreInputErrors) {
  // Each of these made OpenMesh's header parser loop forever or index an empty vector.
  EXPECT_NE(
      error_of("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n").find("end_header"),
      std::string::npos);
  EXPECT_NE(error_of("ply\nformat ascii 1.0\nproperty float x\nend_header\n").find("line 3"),
            std::string::npos);
  EXPECT_NE(error_of("ply\nformat ascii 1.0\ncomment x\n").find("PLY"), std::string::npos);
  EXPECT_NE(error_of("ply\nformat ascii 1.0\nelement vertex 3\nproperty quaternion x\nend_header\n")
                .find("line 4"),
            std::string::npos);
  EXPECT_NE(error_of("ply\nformat ebcdic 1.0\n").find("line 2"), std::string::npos);
  // Four billion entries of nothing would be a long loop over no data.
  EXPECT_NE(error_of("ply\nformat ascii 1.0\nelement junk 4000000000\nend_header\n").find("junk"),
            std::string::npos);
  EXPECT_NE(error_of("ply\nformat ascii 1.0\nelement vertex -3\nend_header\n").find("line 3"),
            std::string::npos);
}

TEST(ReadPly, MalformedBodiesAreInputErrorsNamingLineOrOffset) {
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float "
      "z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  EXPECT_NE(error_of(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n").find("vertex"), std::string::npos);
  EXPECT_NE(error_of(head + "0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n").find("PLY: line 11"),
            std::string::npos);
  Bytes nan;
  nan.text(
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n");
  for (int i = 0; i < 9; ++i) nan.f32le(i == 4 ? std::numeric_limits<float>::quiet_NaN() : 0.5f);
  nan.u8(3).i32le(0).i32le(1).i32le(2);
  EXPECT_NE(error_of(nan.str()).find("byte offset"), std::string::npos) << error_of(nan.str());
}

TEST(ReadPly, RandomCorruptionGivesTypedErrorsOnly) {
  PlyLayout layout;
  layout.vertex_colour = true;
  test_io::expect_only_typed_errors(cube_ply(layout), 6, 400);
  layout.encoding = "binary_little_endian";
  test_io::expect_only_typed_errors(cube_ply(layout), 7, 400);
  layout.encoding = "binary_big_endian";
  layout.count_type = "uint";
  test_io::expect_only_typed_errors(cube_ply(layout), 8, 400);
  test_io::expect_only_typed_errors(strips_ply("binary_little_endian"), 9, 400);
  test_io::expect_only_typed_errors(strips_ply("ascii"), 10, 400);
}

TEST(ReadPly, HugeDeclaredCountsFailFast) {
  const auto start = std::chrono::steady_clock::now();
  Bytes b;
  b.text(
      "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
      "end_header\n");
  for (int i = 0; i < 203; ++i) b.f32le(0);
  const std::string message = error_of(b.str());
  EXPECT_NE(message.find("header declares 1000000000 vertices"), std::string::npos) << message;
  EXPECT_NE(message.find("the body has 812 bytes"), std::string::npos) << message;
  // A face list claiming two billion corners.
  Bytes list;
  list.text(
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list int int vertex_indices\nend_header\n");
  for (int i = 0; i < 9; ++i) list.f32le(0);
  list.i32le(2000000000).i32le(0).i32le(1).i32le(2);
  EXPECT_THROW(read_mesh(list.str()), InputError);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
  ReadOptions options;
  options.limits.max_vertices = 7;
  EXPECT_THROW(read_mesh(cube_ply({}), options), LimitError);
}

}  // namespace
}  // namespace arg
