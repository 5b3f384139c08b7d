// Reading binary OFF (big-endian as Geomview writes it, or OpenMesh's little-endian dialect).
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "io/format_readers.hpp"

namespace arg::io {

// Binary OFF as Geomview specifies it: big-endian 32-bit integers and floats; each face is
// followed by a colour count and that many floats. OpenMesh writes a little-endian dialect
// without the colour count; it is accepted too when the big-endian counts make no sense.
void read_off_binary(std::string_view bytes, const OffHeader& h, SoupBuilder& out,
                     ReadReport& report) {
  std::size_t pos = h.line_end;
  bool big = true;
  out.set_locator([&] { return "byte offset " + std::to_string(pos); });
  auto u32 = [&](std::size_t at, bool be) {
    std::uint32_t x = 0;
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data() + at);
    x = be ? (std::uint32_t(b[0]) << 24 | std::uint32_t(b[1]) << 16 | std::uint32_t(b[2]) << 8 |
              b[3])
           : (std::uint32_t(b[3]) << 24 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[1]) << 8 |
              b[0]);
    return x;
  };
  auto need = [&](std::size_t n, const std::string& what) {
    if (bytes.size() - pos < n) out.fail("unexpected end of data: expected " + what);
  };
  need(12, "the vertex, face and edge counts");
  const std::size_t vertex_floats =
      3 + (h.normals ? 3 : 0) + (h.colours ? 4 : 0) + (h.texcoords ? 2 : 0);
  const std::size_t left = bytes.size() - pos - 12;
  auto plausible = [&](bool be) {
    const double nv = u32(pos, be), nf = u32(pos + 4, be);
    return nv * 4.0 * double(vertex_floats) + nf * 16.0 <= double(left);
  };
  if (!plausible(true) && plausible(false)) big = false;
  if (!big && h.colours) out.fail("little-endian binary COFF is not supported");
  report.variant = big ? "OFF BINARY (big endian)" : "OFF BINARY (little endian)";
  const std::size_t nv = u32(pos, big), nf = u32(pos + 4, big);
  pos += 12;
  check_declared_counts(out, nv, nf, 4 * vertex_floats, 16, left);
  auto f32 = [&](std::size_t at) {
    const std::uint32_t x = u32(at, big);
    float f;
    std::memcpy(&f, &x, 4);
    return f;
  };
  for (std::size_t v = 0; v < nv; ++v) {
    need(4 * vertex_floats, "vertex " + std::to_string(v));
    const int index = out.add_vertex(f32(pos), f32(pos + 4), f32(pos + 8));
    if (h.colours) {
      const std::size_t c = pos + 4 * (3 + (h.normals ? 3 : 0));
      out.set_vertex_colour(index, f32(c), f32(c + 4), f32(c + 8));
    }
    pos += 4 * vertex_floats;
  }
  std::vector<int> corners;
  for (std::size_t f = 0; f < nf; ++f) {
    need(4, "face " + std::to_string(f));
    const std::size_t n = u32(pos, big);
    if (n > (bytes.size() - pos - 4) / 4) {
      out.fail("face " + std::to_string(f) + " declares " + std::to_string(n) +
               " corners, more than the data holds");
    }
    pos += 4;
    corners.resize(n);
    for (std::size_t k = 0; k < n; ++k, pos += 4) {
      const std::uint32_t index = u32(pos, big);
      corners[k] = index > INT32_MAX ? -1 : static_cast<int>(index);
    }
    const int face = out.add_face(corners.data(), corners.size());
    if (big) {
      need(4, "the colour count of face " + std::to_string(f));
      const std::size_t nc = u32(pos, big);
      pos += 4;
      if (nc > 4)
        out.fail("face " + std::to_string(f) + " has " + std::to_string(nc) + " colour components");
      need(4 * nc, "the colour of face " + std::to_string(f));
      if (nc >= 3 && face >= 0) out.set_face_colour(face, f32(pos), f32(pos + 4), f32(pos + 8));
      pos += 4 * nc;
    }
  }
  out.set_locator({});
}

}  // namespace arg::io
