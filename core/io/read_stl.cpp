// Reading STL meshes: binary STL through OpenMesh's reader (ASCII STL has its own parser).
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "io/format_readers.hpp"
#include "io/memory_stream.hpp"
#include "io/openmesh_reader.hpp"
#include "io/soup_importer.hpp"

namespace arg::io {

namespace {

constexpr std::size_t kHeader = 84;
constexpr std::size_t kRecord = 50;

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
  // OpenMesh welds equal corners through a std::map whose comparison is meaningless for NaN (a
  // NaN corner would silently become some other vertex), so check every number first.
  for (std::size_t t = 0; t < triangles; ++t) {
    const char* record = bytes.data() + kHeader + kRecord * t;
    for (int k = 3; k < 12; ++k) {
      if (!std::isfinite(lef32(record + 4 * k))) {
        throw_input_error(
            "STL", "byte offset " + std::to_string(kHeader + kRecord * t + 4 * k),
            "triangle " + std::to_string(t) + " has a coordinate that is not a finite number");
      }
    }
  }
  MemoryStreamBuf buffer(bytes);
  out.set_locator([&] { return "byte offset " + std::to_string(buffer.position()); });
  out.set_immediate_index_check(true);
  SoupImporter importer(out);
  OpenMesh::IO::Options options = OpenMesh::IO::Options::Binary;
  auto describe_failure = [&] {
    return "STL: byte offset " + std::to_string(buffer.position()) + ": unexpected end of data";
  };
  const bool ok = run_openmesh_reader(OpenMeshReader::Stl, buffer, importer, options,
                                      /*fail_on_bad_read=*/true, describe_failure);
  out.set_locator({});
  if (!ok) throw_input_error("STL", "", "OpenMesh's reader rejected the data");
  // OpenMesh drops triangles whose corners weld into fewer than three vertices.
  out.soup().faces_skipped += triangles - out.soup().faces_seen;
  out.soup().faces_seen = triangles;
}

}  // namespace arg::io
