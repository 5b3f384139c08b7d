// Our own strict OFF parser for the variants OpenMesh cannot read from memory: COFF and binary.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "io/format_readers.hpp"
#include "io/memory_stream.hpp"
#include "io/text_scan.hpp"

namespace arg::io {

namespace {

bool looks_fractional(std::string_view token) {
  return token.find_first_of(".eE") != std::string_view::npos;
}

// Colour tokens of a COFF vertex or face: 3 or 4 numbers, floats in [0,1] or integers 0..255;
// a single token (a colour map index) or none means no colour.
bool parse_colour(const std::vector<std::string_view>& tokens, std::size_t first, float rgb[3]) {
  const std::size_t n = tokens.size() - first;
  if (n != 3 && n != 4) return false;
  bool fractional = false;
  for (std::size_t i = first; i < first + 3; ++i) fractional |= looks_fractional(tokens[i]);
  for (std::size_t i = 0; i < 3; ++i) {
    double c = 0;
    if (!parse_real(tokens[first + i], c) || !std::isfinite(c)) return false;
    rgb[i] = static_cast<float>(fractional ? c : c / 255.0);
  }
  return true;
}

void read_counts(const std::vector<std::string_view>& tokens, SoupBuilder& out,
                 std::size_t& vertices, std::size_t& faces) {
  std::int64_t nv = -1, nf = -1;
  if (tokens.size() < 2 || !parse_integer(tokens[0], nv) || !parse_integer(tokens[1], nf) ||
      nv < 0 || nf < 0) {
    out.fail("expected the vertex, face and edge counts");
  }
  vertices = static_cast<std::size_t>(nv);
  faces = static_cast<std::size_t>(nf);
}

void read_text(std::string_view bytes, const OffHeader& h, SoupBuilder& out) {
  LineScanner lines(bytes, h.counts_on_keyword_line ? h.keyword_end : h.line_end);
  std::size_t line_no = line_of_offset(bytes, h.keyword_offset);
  out.set_locator([&] { return "line " + std::to_string(line_no); });
  std::vector<std::string_view> tokens;
  std::string_view line;
  auto next = [&](const char* what) {
    if (!lines.next_content(line, true)) {
      line_no = lines.line_number() + 1;
      out.fail(std::string("unexpected end of data: expected ") + what);
    }
    line_no = lines.line_number();
    split_tokens(line, tokens);
  };
  if (h.counts_on_keyword_line) {
    lines.next(line);  // the rest of the keyword line
    line = strip_comment(line);
    split_tokens(line, tokens);
  } else {
    next("the vertex, face and edge counts");
  }
  std::size_t nv = 0, nf = 0;
  read_counts(tokens, out, nv, nf);
  check_declared_counts(out, nv, nf, 6, 8, bytes.size() - lines.offset());

  const std::size_t fixed = 3 + (h.normals ? 3 : 0);
  const std::size_t texture = h.texcoords ? 2 : 0;
  for (std::size_t v = 0; v < nv; ++v) {
    next("a vertex");
    if (tokens.size() < fixed + texture) {
      out.fail("vertex " + std::to_string(v) + ": expected " + std::to_string(fixed + texture) +
               " numbers or more, found " + std::to_string(tokens.size()));
    }
    double p[3];
    for (int k = 0; k < 3; ++k) {
      if (!parse_real(tokens[static_cast<std::size_t>(k)], p[k])) {
        out.fail("vertex " + std::to_string(v) + ": expected 3 coordinates");
      }
    }
    const int index = out.add_vertex(p[0], p[1], p[2]);
    // The colour sits between the coordinates (and normal) and the texture coordinates.
    std::vector<std::string_view> colour(tokens.begin(), tokens.end() - std::ptrdiff_t(texture));
    float rgb[3];
    if (parse_colour(colour, fixed, rgb)) out.set_vertex_colour(index, rgb[0], rgb[1], rgb[2]);
  }
  std::vector<int> corners;
  for (std::size_t f = 0; f < nf; ++f) {
    next("a face");
    std::int64_t n = -1;
    if (tokens.empty() || !parse_integer(tokens[0], n) || n < 0) {
      out.fail("face " + std::to_string(f) + ": expected a corner count");
    }
    if (static_cast<std::size_t>(n) + 1 > split_tokens(line, tokens, std::size_t(-1))) {
      out.fail("face " + std::to_string(f) + ": expected " + std::to_string(n) + " indices");
    }
    corners.resize(static_cast<std::size_t>(n));
    for (std::size_t k = 0; k < corners.size(); ++k) {
      std::int64_t index = -1;
      if (!parse_integer(tokens[k + 1], index) || index < 0 || index > INT32_MAX) {
        out.fail("face " + std::to_string(f) + ": corner " + std::to_string(k) +
                 " is not a vertex index");
      }
      corners[k] = static_cast<int>(index);
    }
    const int face = out.add_face(corners.data(), corners.size());
    float rgb[3];
    if (face >= 0 && parse_colour(tokens, corners.size() + 1, rgb)) {
      out.set_face_colour(face, rgb[0], rgb[1], rgb[2]);
    }
  }
  out.set_locator({});
}

// Binary OFF as Geomview specifies it: big-endian 32-bit integers and floats; each face is
// followed by a colour count and that many floats. OpenMesh writes a little-endian dialect
// without the colour count; it is accepted too when the big-endian counts make no sense.
void read_binary(std::string_view bytes, const OffHeader& h, SoupBuilder& out, ReadReport& report) {
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

}  // namespace

void read_off_strict(std::string_view bytes, const OffHeader& header, SoupBuilder& out,
                     ReadReport& report) {
  out.set_immediate_index_check(true);
  if (header.binary) {
    read_binary(bytes, header, out, report);
  } else {
    report.variant = std::string(
        bytes.substr(header.keyword_offset, header.keyword_end - header.keyword_offset));
    read_text(bytes, header, out);
  }
}

}  // namespace arg::io
