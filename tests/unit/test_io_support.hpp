// Helpers shared by the mesh input tests: byte writers, reference shapes, shape measures, data.
#pragma once

#include <gtest/gtest.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "io/read_mesh.hpp"
#include "mesh/mesh.hpp"

namespace arg::test_io {

// Builds binary inputs byte by byte.
class Bytes {
 public:
  Bytes& text(const std::string& s) {
    data_ += s;
    return *this;
  }
  Bytes& u8(std::uint8_t v) {
    data_.push_back(static_cast<char>(v));
    return *this;
  }
  Bytes& u16le(std::uint16_t v) { return u8(v & 0xff).u8(v >> 8); }
  Bytes& u32le(std::uint32_t v) { return u16le(v & 0xffff).u16le(v >> 16); }
  Bytes& u32be(std::uint32_t v) {
    return u8(v >> 24).u8((v >> 16) & 0xff).u8((v >> 8) & 0xff).u8(v & 0xff);
  }
  Bytes& i32le(std::int32_t v) { return u32le(static_cast<std::uint32_t>(v)); }
  Bytes& i32be(std::int32_t v) { return u32be(static_cast<std::uint32_t>(v)); }
  Bytes& f32le(float f) {
    std::uint32_t v;
    std::memcpy(&v, &f, 4);
    return u32le(v);
  }
  Bytes& f32be(float f) {
    std::uint32_t v;
    std::memcpy(&v, &f, 4);
    return u32be(v);
  }
  Bytes& f64le(double d) {
    std::uint64_t v;
    std::memcpy(&v, &d, 8);
    return u32le(static_cast<std::uint32_t>(v)).u32le(static_cast<std::uint32_t>(v >> 32));
  }
  Bytes& pad_to(std::size_t multiple, char fill) {
    while (data_.size() % multiple) data_.push_back(fill);
    return *this;
  }
  std::size_t size() const { return data_.size(); }
  const std::string& str() const { return data_; }

 private:
  std::string data_;
};

// The reference shape of every format test: the unit cube [0,1]^3, six quads (12 triangles,
// area 6), listed counter-clockwise seen from outside.
inline const std::array<std::array<double, 3>, 8>& cube_vertices() {
  static const std::array<std::array<double, 3>, 8> v{
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
  return v;
}
inline const std::array<std::array<int, 4>, 6>& cube_quads() {
  static const std::array<std::array<int, 4>, 6> f{
      {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};
  return f;
}
// The cube's twelve triangles (each quad split along its first diagonal).
inline std::vector<std::array<int, 3>> cube_triangles() {
  std::vector<std::array<int, 3>> t;
  for (const auto& q : cube_quads()) {
    t.push_back({q[0], q[1], q[2]});
    t.push_back({q[0], q[2], q[3]});
  }
  return t;
}

inline std::string cube_off() {
  std::ostringstream s;
  s << "OFF\n8 6 12\n";
  for (const auto& v : cube_vertices()) s << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
  for (const auto& q : cube_quads())
    s << "4 " << q[0] << ' ' << q[1] << ' ' << q[2] << ' ' << q[3] << '\n';
  return s.str();
}

inline double mesh_area(const Mesh& m) {
  double area = 0;
  for (Eigen::Index t = 0; t < m.F.rows(); ++t) {
    const Eigen::Vector3d a = m.V.row(m.F(t, 0)), b = m.V.row(m.F(t, 1)), c = m.V.row(m.F(t, 2));
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

// Signed volume (positive for outward-facing closed meshes).
inline double mesh_volume(const Mesh& m) {
  double volume = 0;
  for (Eigen::Index t = 0; t < m.F.rows(); ++t) {
    const Eigen::Vector3d a = m.V.row(m.F(t, 0)), b = m.V.row(m.F(t, 1)), c = m.V.row(m.F(t, 2));
    volume += a.dot(b.cross(c)) / 6;
  }
  return volume;
}

inline void expect_same_shape(const Mesh& expected, const Mesh& actual) {
  EXPECT_EQ(expected.F.rows(), actual.F.rows());
  EXPECT_NEAR(mesh_area(expected), mesh_area(actual), 1e-5);
  EXPECT_NEAR(mesh_volume(expected), mesh_volume(actual), 1e-5);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(expected.V.col(c).minCoeff(), actual.V.col(c).minCoeff(), 1e-6);
    EXPECT_NEAR(expected.V.col(c).maxCoeff(), actual.V.col(c).maxCoeff(), 1e-6);
  }
}

// An image encoded by OpenImageIO into memory; `format` is an OIIO plugin name ("png", "jpeg").
inline std::string encode_image(const char* format, int width, int height,
                                const std::function<std::array<std::uint8_t, 3>(int, int)>& rgb) {
  std::vector<unsigned char> out;
  OIIO::Filesystem::IOVecOutput proxy(out);
  auto writer = OIIO::ImageOutput::create(format);
  if (!writer) return {};
  writer->set_ioproxy(&proxy);
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  std::vector<std::uint8_t> pixels(std::size_t(3 * width * height));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const auto c = rgb(x, y);
      for (int k = 0; k < 3; ++k) pixels[std::size_t(3 * (y * width + x) + k)] = c[std::size_t(k)];
    }
  }
  if (!writer->open("/nonexistent/out." + std::string(format), spec) ||
      !writer->write_image(OIIO::TypeDesc::UINT8, pixels.data())) {
    return {};
  }
  writer->close();
  return std::string(out.begin(), out.end());
}

// Feeds `iterations` deterministic corruptions of `sample` (bytes overwritten, inserted, deleted,
// the data cut short or a slice repeated) to read_mesh; each must either read or throw one of
// the core's typed errors (never another exception, never a crash).
inline void expect_only_typed_errors(const std::string& sample, std::uint32_t seed, int iterations,
                                     const ReadOptions& options = {}) {
  std::uint32_t state = seed * 2654435761u + 1;
  auto next = [&state](std::uint32_t n) {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return n == 0 ? 0u : state % n;
  };
  for (int i = 0; i < iterations; ++i) {
    std::string bytes = sample;
    const int edits = 1 + int(next(4));
    for (int e = 0; e < edits && !bytes.empty(); ++e) {
      const std::size_t at = next(std::uint32_t(bytes.size()));
      switch (next(5)) {
        case 0:
          bytes[at] = char(next(256));
          break;
        case 1:
          bytes.insert(at, 1, "0123456789 -.\n\xff\x7f"[next(16)]);
          break;
        case 2:
          bytes.erase(at, 1 + next(8));
          break;
        case 3:
          bytes.resize(at);
          break;
        default:
          bytes.insert(at, bytes.substr(next(std::uint32_t(bytes.size())), 1 + next(16)));
          break;
      }
    }
    try {
      read_mesh(bytes, options);
    } catch (const Error&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << "seed " << seed << " iteration " << i << ": untyped exception " << e.what();
    }
  }
}

inline std::string shared_data_dir() {
  return ARG_SHARED_DATA;
}

inline bool read_file(const std::string& path, std::string& bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  bytes = s.str();
  return true;
}

}  // namespace arg::test_io
