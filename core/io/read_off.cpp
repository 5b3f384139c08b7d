// Reading OFF meshes (OFF, COFF, NOFF, STOFF and binary OFF) with a parser of our own.
//
// Not OpenMesh's reader: OpenMesh 9.0 takes the header flags (C, N, ST, BINARY) only when it opens
// a file by name, so from memory it reads COFF without its colours and binary OFF as text; it
// knows no '#' comments, reads a face colour in plain OFF as the next face, and stops without an
// error when the last number ends the data. This parser reads one element per line, names the
// line of every error, and rounds text coordinates to single precision: what OpenMesh stored for
// plain OFF (the ARGs built from it keep their bytes), and what binary OFF and STL hold.
#include <cmath>
#include <cstdint>
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
  // The shortest vertex is "0 0 0\n"; the shortest face "0\n" (skipped, but counted).
  check_declared_counts(out, nv, nf, 6, 2, bytes.size() - lines.offset());

  const std::size_t fixed = 3 + (h.normals ? 3 : 0);
  const std::size_t texture = h.texcoords ? 2 : 0;
  for (std::size_t v = 0; v < nv; ++v) {
    next("a vertex");
    if (tokens.size() < fixed + texture) {
      out.fail("vertex " + std::to_string(v) + ": expected " + std::to_string(fixed + texture) +
               " numbers or more, found " + std::to_string(tokens.size()));
    }
    float p[3];
    for (int k = 0; k < 3; ++k) {
      if (!parse_real(tokens[static_cast<std::size_t>(k)], p[k])) {
        out.fail("vertex " + std::to_string(v) + ": expected 3 coordinates");
      }
    }
    const int index = out.add_vertex(p[0], p[1], p[2]);
    if (!h.colours) continue;  // numbers after a vertex are a colour only in COFF
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

}  // namespace

void read_off(std::string_view bytes, SoupBuilder& out, ReadReport& report) {
  const std::optional<OffHeader> header = find_off_header(bytes);
  if (!header) throw_input_error("OFF", "line 1", "expected the keyword OFF");
  if (header->four_d || header->n_dim) {
    throw_input_error("OFF",
                      "line " + std::to_string(line_of_offset(bytes, header->keyword_offset)),
                      "4OFF and nOFF (not three-dimensional) are not supported");
  }
  out.set_immediate_index_check(true);  // the vertices come before the faces
  if (header->binary) {
    read_off_binary(bytes, *header, out, report);
    return;
  }
  report.variant = std::string(
      bytes.substr(header->keyword_offset, header->keyword_end - header->keyword_offset));
  read_text(bytes, *header, out);
}

}  // namespace arg::io
