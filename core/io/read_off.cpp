// Reading OFF meshes: plain OFF through OpenMesh's reader, COFF and binary OFF through our own.
#include <cstdint>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "io/format_readers.hpp"
#include "io/memory_stream.hpp"
#include "io/openmesh_reader.hpp"
#include "io/soup_importer.hpp"
#include "io/text_scan.hpp"

namespace arg::io {

namespace {

// The shortest text a vertex ("0 0 0\n") and a face ("3 0 1 2\n") can take.
constexpr std::size_t kMinVertexText = 6;
constexpr std::size_t kMinFaceText = 8;

// The stream OpenMesh gets: the keyword on its own line (OpenMesh's reader skips the whole first
// line, so counts written after the keyword would be lost), the rest with '#' comments cut out
// (OpenMesh does not know them) and a final newline (so a last number right at the end of the
// data does not set eofbit, which would make OpenMesh's loops stop early).
std::vector<StreamPiece> off_pieces(std::string_view bytes, const OffHeader& h) {
  static constexpr std::string_view kNewline = "\n";
  std::vector<StreamPiece> pieces;
  pieces.push_back(
      {bytes.substr(h.keyword_offset, h.keyword_end - h.keyword_offset), h.keyword_offset});
  pieces.push_back({kNewline, StreamPiece::npos});
  std::size_t i = h.counts_on_keyword_line ? h.keyword_end : h.line_end;
  while (i < bytes.size()) {
    std::size_t hash = bytes.find('#', i);
    if (hash == std::string_view::npos) hash = bytes.size();
    pieces.push_back({bytes.substr(i, hash - i), i});
    if (hash == bytes.size()) break;
    i = bytes.find('\n', hash);
    if (i == std::string_view::npos) break;
  }
  pieces.push_back({kNewline, StreamPiece::npos});
  return pieces;
}

// Whether the first face line carries a colour after its indices, which Geomview allows in plain
// OFF too; OpenMesh, not having seen a C in the header, would read the colour as the next face.
// Assumes one vertex per line, as OFF writers do (if not, OpenMesh's path reports the error).
bool first_face_has_colour(std::string_view bytes, const OffHeader& h) {
  LineScanner lines(bytes, h.counts_on_keyword_line ? h.keyword_end : h.line_end);
  std::string_view line;
  std::vector<std::string_view> tokens;
  std::int64_t nv = 0, nf = 0, corners = 0;
  if (h.counts_on_keyword_line) {
    lines.next(line);
    line = strip_comment(line);
  } else if (!lines.next_content(line, true)) {
    return false;
  }
  split_tokens(line, tokens, 3);
  if (tokens.size() < 2 || !parse_integer(tokens[0], nv) || !parse_integer(tokens[1], nf) ||
      nv < 0 || nf <= 0) {
    return false;
  }
  for (std::int64_t v = 0; v < nv; ++v) {
    if (!lines.next_content(line, true)) return false;
  }
  if (!lines.next_content(line, true)) return false;
  const std::size_t count = split_tokens(line, tokens, 1);
  return parse_integer(tokens[0], corners) && corners >= 0 &&
         count > static_cast<std::size_t>(corners) + 1;
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
  // OpenMesh 9.0 reads the header flags (C, N, ST, BINARY) only when it opens a file by name; its
  // std::istream entry point skips that step, so from memory it would ignore COFF colours and
  // parse binary OFF as text. Those variants, and faces with colours, go to our own parser.
  if (header->colours || header->binary || first_face_has_colour(bytes, *header)) {
    read_off_strict(bytes, *header, out, report);
    return;
  }
  report.variant = std::string(
      bytes.substr(header->keyword_offset, header->keyword_end - header->keyword_offset));

  MemoryStreamBuf buffer(off_pieces(bytes, *header));
  auto where = [&] { return describe_text_position(bytes, buffer.source_position()); };
  out.set_locator(where);
  out.set_immediate_index_check(true);
  SoupImporter importer(out);
  importer.on_declared([&](std::size_t vertices, std::size_t faces) {
    check_declared_counts(out, vertices, faces, kMinVertexText, kMinFaceText,
                          buffer.size() - buffer.position());
  });
  const PolygonSoup& soup = out.soup();
  auto describe_failure = [&] {
    std::string what;
    if (!importer.saw_declaration()) {
      what = "expected the vertex, face and edge counts";
    } else if (soup.vertex_count() < importer.declared_vertices()) {
      what = "could not read vertex " + std::to_string(soup.vertex_count()) + " of " +
             std::to_string(importer.declared_vertices()) + " (expected 3 coordinates)";
    } else {
      what = "could not read face " + std::to_string(soup.faces_seen) + " of " +
             std::to_string(importer.declared_faces()) + " (expected a corner count and indices)";
    }
    if (buffer.position() >= buffer.size() - 1) what = "unexpected end of data: " + what;
    return "OFF: " + where() + ": " + what;
  };
  OpenMesh::IO::Options options;  // geometry only; normals and texture coordinates are skipped
  const bool ok = run_openmesh_reader(OpenMeshReader::Off, buffer, importer, options,
                                      /*fail_on_bad_read=*/true, describe_failure);
  out.set_locator({});
  if (options.check(OpenMesh::IO::Options::Binary)) {
    // OpenMesh keeps the flags of the last OFF file it opened by name in its reader singleton.
    throw Error("OFF: OpenMesh's OFF reader was left in binary mode by an earlier file read");
  }
  if (!ok) throw_input_error("OFF", "", "OpenMesh's reader rejected the data");
  if (soup.vertex_count() != importer.declared_vertices() ||
      soup.faces_seen != importer.declared_faces()) {
    throw_input_error("OFF", "end of data",
                      "file ends after " + std::to_string(soup.vertex_count()) + " of " +
                          std::to_string(importer.declared_vertices()) + " vertices and " +
                          std::to_string(soup.faces_seen) + " of " +
                          std::to_string(importer.declared_faces()) + " faces");
  }
}

}  // namespace arg::io
