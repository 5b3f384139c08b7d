// Reading STL meshes, binary and ASCII, with parsers of our own (ASCII in read_stl_ascii.cpp).
//
// Not OpenMesh's reader: binary STL is 50-byte records that need no library, and OpenMesh welds
// corners through a std::map whose comparison is meaningless for NaN (a NaN corner silently
// became some other vertex); its ASCII reader is too loose (see read_stl_ascii.cpp). Both
// encodings weld corners with StlWelder, in OpenMesh's order, so the meshes read are the same.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "io/format_readers.hpp"
#include "io/stl_welder.hpp"

namespace arg::io {

namespace {

constexpr std::size_t kHeader = 84;  // 80 bytes of free text and the triangle count
constexpr std::size_t kRecord = 50;  // normal, three corners (12 floats) and 2 attribute bytes

std::uint32_t le32(const char* p) {
  const auto* b = reinterpret_cast<const unsigned char*>(p);
  return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 |
         std::uint32_t(b[3]) << 24;
}

float lef32(const char* p) {
  const std::uint32_t x = le32(p);
  float f;
  std::memcpy(&f, &x, 4);
  return f;
}

}  // namespace

bool stl_binary_size_matches(std::string_view bytes) {
  if (bytes.size() < kHeader) return false;
  const std::uint64_t n = le32(bytes.data() + 80);
  return kHeader + kRecord * n == bytes.size();
}

void read_stl(std::string_view bytes, SoupBuilder& out, ReadReport& report) {
  // A binary STL may begin with "solid" as ASCII STL does; only the size tells them apart.
  if (!stl_binary_size_matches(bytes)) {
    read_stl_ascii(bytes, out, report);
    return;
  }
  report.variant = "binary";
  const std::size_t triangles = le32(bytes.data() + 80);
  if (triangles > out.limits().max_triangles) {
    out.fail_limit("header declares " + std::to_string(triangles) + " triangles, more than " +
                   std::to_string(out.limits().max_triangles));
  }
  // Welding shares each corner among about six triangles: a closed surface's vertex count.
  out.declared_counts(triangles / 2, triangles);
  std::size_t at = kHeader;
  out.set_locator([&] { return "byte offset " + std::to_string(at); });
  out.set_immediate_index_check(true);
  StlWelder welder;
  for (std::size_t t = 0; t < triangles; ++t) {
    const char* record = bytes.data() + kHeader + kRecord * t;
    int corners[3];
    for (int c = 0; c < 3; ++c) {
      float p[3];
      for (int k = 0; k < 3; ++k) {
        at = kHeader + kRecord * t + 12 * std::size_t(c + 1) + 4 * std::size_t(k);
        p[k] = lef32(record + 12 * (c + 1) + 4 * k);
        if (!std::isfinite(p[k])) {
          out.fail("triangle " + std::to_string(t) +
                   " has a coordinate that is not a finite number");
        }
      }
      corners[c] = welder.vertex(out, p[0], p[1], p[2]);
    }
    add_stl_triangle(out, corners);
  }
  out.set_locator({});
}

}  // namespace arg::io
