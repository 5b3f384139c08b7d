// Reading Wavefront OBJ meshes through OpenMesh's reader, after a strict line-by-line check.
//
// OBJ has one parse path: OpenMesh's OBJ reader (Debian's libopenmesh), which handles what OBJ
// files carry (polygons, negative indices, per-corner texture coordinates, "v x y z r g b"
// colours). It skips what it cannot parse without an error, so scan_obj below reads every line
// it would act on first and rejects the file, with a line number, before OpenMesh sees it.
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <map>
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

// What the check saw, and the stream OpenMesh gets.
struct ObjScan {
  std::size_t vertices = 0;
  std::size_t coloured_vertices = 0;
  std::size_t texcoords = 0;
  std::size_t faces = 0;
  bool vc_lines = false;
  std::int64_t max_vertex_ref = 0, max_texcoord_ref = 0;
  std::size_t max_vertex_line = 0, max_texcoord_line = 0;
  std::vector<StreamPiece> pieces;
  // With `materials`: the usemtl names in order of first use, and per f line the index of the
  // last one before it (-1 before any).
  std::vector<std::string> material_names;
  std::vector<int> face_material;
};

// OpenMesh's OBJ reader silently skips what it cannot parse: a vertex line with a bad number is
// dropped (shifting every later index), a bad face index becomes vertex -1 or is ignored, and
// "mtllib" makes it open a file by name. So every line it would act on is checked here first,
// with its line number for the error, and mtllib/usemtl lines are cut from its stream; with
// `materials`, each face's material is recorded here instead.
ObjScan scan_obj(std::string_view bytes, const Limits& limits, bool materials) {
  ObjScan scan;
  std::map<std::string, int, std::less<>> material_index;
  int material = -1;
  LineScanner lines(bytes);
  std::vector<std::string_view> tokens;
  std::string_view raw;
  std::size_t kept_from = 0;
  auto fail = [&](const std::string& message) {
    throw_input_error("OBJ", "line " + std::to_string(lines.line_number()), message);
  };
  while (lines.next(raw)) {
    const std::string_view line = trim(raw);
    if (line.empty() || line[0] == '#') continue;
    const std::size_t count = split_tokens(line, tokens, 8);
    const std::string_view key = tokens[0];
    if (key == "mtllib" || key == "usemtl") {
      scan.pieces.push_back({bytes.substr(kept_from, lines.line_offset() - kept_from), kept_from});
      kept_from = lines.line_offset() + raw.size();
      if (materials && key == "usemtl") {
        // The whole rest of the line, as an MTL's newmtl names it (names may hold spaces).
        const std::string_view name = strip_comment(line.substr(key.size()));
        if (name.empty()) {
          material = -1;
        } else {
          auto found = material_index.find(name);
          if (found == material_index.end()) {
            found =
                material_index.emplace(std::string(name), int(scan.material_names.size())).first;
            scan.material_names.emplace_back(name);
          }
          material = found->second;
        }
      }
    } else if (key == "v") {
      double x[6];
      if (count < 4) fail("a vertex needs 3 coordinates");
      for (std::size_t k = 0; k < 3; ++k) {
        if (!parse_real(tokens[k + 1], x[k])) fail("a vertex needs 3 coordinates");
        if (!std::isfinite(x[k]) || std::fabs(x[k]) > FLT_MAX) {
          fail("vertex coordinate is not a finite single-precision number");
        }
      }
      bool coloured = count == 7;
      for (std::size_t k = 3; coloured && k < 6; ++k) coloured = parse_real(tokens[k + 1], x[k]);
      scan.coloured_vertices += coloured;
      ++scan.vertices;
    } else if (key == "vt") {
      double t[2];
      if (count < 3 || !parse_real(tokens[1], t[0]) || !parse_real(tokens[2], t[1]) ||
          !std::isfinite(t[0]) || !std::isfinite(t[1])) {
        fail("a texture coordinate needs 2 finite numbers");
      }
      ++scan.texcoords;
    } else if (key == "vc") {
      scan.vc_lines = true;
    } else if (key == "f") {
      if (count < 4) fail("a face needs 3 corners or more");
      if (count - 3 > limits.max_triangles) {
        throw LimitError("OBJ: line " + std::to_string(lines.line_number()) + ": a face with " +
                         std::to_string(count - 1) + " corners exceeds the triangle limit");
      }
      if (count > tokens.size()) split_tokens(line, tokens, count);
      for (std::size_t k = 1; k < count; ++k) {
        std::string_view corner = tokens[k];
        std::int64_t ref[3] = {0, 0, 0};
        for (int part = 0; part < 3 && !corner.empty(); ++part) {
          const std::size_t slash = corner.find('/');
          const std::string_view number = corner.substr(0, slash);
          if (!(number.empty() && part > 0)) {
            if (!parse_integer(number, ref[part]) || ref[part] == 0 ||
                std::llabs(ref[part]) > INT32_MAX / 2) {
              fail("corner '" + std::string(tokens[k]) + "' is not a valid index");
            }
          }
          corner = slash == std::string_view::npos ? std::string_view() : corner.substr(slash + 1);
          if (part == 2 && slash != std::string_view::npos) {
            fail("corner '" + std::string(tokens[k]) + "' has too many parts");
          }
        }
        if (ref[0] < 0 && std::size_t(-ref[0]) > scan.vertices) {
          fail("corner '" + std::string(tokens[k]) + "' refers to a vertex before the first");
        }
        if (ref[1] < 0 && std::size_t(-ref[1]) > scan.texcoords) {
          fail("corner '" + std::string(tokens[k]) +
               "' refers to a texture coordinate before the first");
        }
        if (ref[0] > scan.max_vertex_ref) {
          scan.max_vertex_ref = ref[0];
          scan.max_vertex_line = lines.line_number();
        }
        if (ref[1] > scan.max_texcoord_ref) {
          scan.max_texcoord_ref = ref[1];
          scan.max_texcoord_line = lines.line_number();
        }
      }
      ++scan.faces;
      if (materials) scan.face_material.push_back(material);
    }
  }
  if (scan.max_vertex_ref > std::int64_t(scan.vertices)) {
    throw_input_error("OBJ", "line " + std::to_string(scan.max_vertex_line),
                      "a face refers to vertex " + std::to_string(scan.max_vertex_ref) +
                          " but the file has " + std::to_string(scan.vertices) + " vertices");
  }
  if (scan.max_texcoord_ref > std::int64_t(scan.texcoords)) {
    throw_input_error("OBJ", "line " + std::to_string(scan.max_texcoord_line),
                      "a face refers to texture coordinate " +
                          std::to_string(scan.max_texcoord_ref) + " but the file has " +
                          std::to_string(scan.texcoords));
  }
  if (scan.vertices > limits.max_vertices) {
    throw LimitError("OBJ: " + std::to_string(scan.vertices) + " vertices, more than " +
                     std::to_string(limits.max_vertices));
  }
  static constexpr std::string_view kNewline = "\n";
  scan.pieces.push_back({bytes.substr(kept_from), kept_from});
  scan.pieces.push_back({kNewline, StreamPiece::npos});
  return scan;
}

}  // namespace

void read_obj(std::string_view bytes, SoupBuilder& out, ReadReport& report) {
  PolygonSoup& soup = out.soup();
  ObjScan scan = scan_obj(bytes, out.limits(), soup.keep_face_materials);
  out.declared_counts(scan.vertices, scan.faces);
  report.variant = "text";
  MemoryStreamBuf buffer(std::move(scan.pieces));
  auto where = [&] {
    const std::size_t pos = buffer.source_position();
    if (pos == StreamPiece::npos || pos >= bytes.size()) return std::string("end of data");
    return "line " + std::to_string(line_of_offset(bytes, pos == 0 ? 0 : pos - 1));
  };
  out.set_locator(where);
  out.set_immediate_index_check(true);  // OpenMesh reads every vertex before the first face
  SoupImporter importer(out);
  if (soup.keep_face_materials) importer.set_call_materials(&scan.face_material);
  OpenMesh::IO::Options options;
  if (scan.texcoords > 0) options += OpenMesh::IO::Options::FaceTexCoord;
  // OpenMesh keeps "v x y z r g b" colours in a list of their own, indexed like the vertices,
  // so they line up only when every vertex has one.
  const bool colours =
      scan.vertices > 0 && scan.coloured_vertices == scan.vertices && !scan.vc_lines;
  if (colours) options += OpenMesh::IO::Options::VertexColor;
  auto describe_failure = [&] { return "OBJ: " + where() + ": could not read the data"; };
  const bool ok = run_openmesh_obj_reader(buffer, importer, options, describe_failure);
  out.set_locator({});
  if (!ok) throw_input_error("OBJ", "", "OpenMesh's reader rejected the data");
  if (out.soup().vertex_count() != scan.vertices) {
    throw_input_error("OBJ", "",
                      "OpenMesh read " + std::to_string(out.soup().vertex_count()) + " of " +
                          std::to_string(scan.vertices) + " vertices");
  }
  if (colours) report.variant = "text with vertex colours";
  if (soup.keep_face_materials) {
    // The faces' materials follow the f lines only if OpenMesh added each line as one face.
    if (soup.faces_seen == scan.faces) {
      soup.material_names = std::move(scan.material_names);
    } else {
      soup.face_material.clear();
      report.warnings.push_back("the materials' textures are not shown: OpenMesh added " +
                                std::to_string(soup.faces_seen) + " faces for " +
                                std::to_string(scan.faces) + " face lines");
    }
  }
}

}  // namespace arg::io
