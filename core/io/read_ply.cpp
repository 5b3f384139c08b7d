// Reading PLY meshes through OpenMesh's reader, for the layouts it handles correctly.
#include <string>
#include <vector>

#include "io/format_readers.hpp"
#include "io/memory_stream.hpp"
#include "io/openmesh_reader.hpp"
#include "io/ply_body.hpp"
#include "io/soup_importer.hpp"

namespace arg::io {

namespace {

bool is_real(PlyType t) {
  return !ply_type_is_integer(t);
}

bool one_of(const std::string& name, std::initializer_list<const char*> names) {
  for (const char* n : names) {
    if (name == n) return true;
  }
  return false;
}

// OpenMesh 9.0's PLY reader is correct only for part of what PLY allows; anything outside that
// part it misreads without an error. Returns an empty string when OpenMesh can read `header`,
// otherwise why not (and our own parser reads it):
// - element "tristrips" (triangle strips, as range scanners and igea.ply write) is skipped, so
//   the mesh would have no faces;
// - list properties other than the face's vertex indices are skipped as if they were a single
//   scalar, which shifts everything after them (MeshLab's per-corner "texcoord" lists);
// - list lengths of type other than uchar/uint8/uint16/int are refused;
// - coordinates, normals and texture coordinates of integer type, and colours of type double,
//   go through a conversion that reads nothing and yields 0, again shifting the rest;
// - face properties before "vertex_indices" are dropped from its layout;
// - it stops after the face element, so vertices stored after the faces are never read.
std::string openmesh_cannot_read(const PlyHeader& header) {
  const PlyElement* vertex = header.find("vertex");
  const PlyElement* face = header.find("face");
  if (!vertex) return "no vertex element";
  if (!face) return header.find("tristrips") ? "triangle strips" : "no face element";
  if (vertex > face) return "faces before vertices";
  int xyz = 0;
  for (const PlyProperty& p : vertex->properties) {
    if (p.is_list) return "list property in vertex";
    xyz += one_of(p.name, {"x", "y", "z"});
    if (one_of(p.name, {"x", "y", "z", "nx", "ny", "nz", "u", "v", "s", "t"}) && !is_real(p.type)) {
      return "integer vertex " + p.name;
    }
    if (one_of(p.name,
               {"red", "green", "blue", "alpha", "diffuse_red", "diffuse_green", "diffuse_blue"}) &&
        p.type == PlyType::Float64) {
      return "double colour";
    }
  }
  if (xyz != 3) return "vertex without x, y and z";
  if (face->properties.empty() || !face->properties[0].is_list ||
      !one_of(face->properties[0].name, {"vertex_indices", "vertex_index"})) {
    return "face layout";
  }
  const PlyProperty& indices = face->properties[0];
  if (!one_of(indices.count_type_name, {"uchar", "uint8", "uint16", "int"}) ||
      !ply_type_is_integer(indices.type)) {
    return "list type " + indices.count_type_name + " " + indices.type_name;
  }
  for (std::size_t i = 1; i < face->properties.size(); ++i) {
    const PlyProperty& p = face->properties[i];
    if (p.is_list) return "face list " + p.name;
    if (one_of(p.name, {"red", "green", "blue", "alpha"}) && p.type == PlyType::Float64) {
      return "double colour";
    }
  }
  for (const PlyElement& e : header.elements) {
    if (&e == face) break;
    for (const PlyProperty& p : e.properties) {
      if (p.is_list && &e != face) return "list in element " + e.name;
    }
  }
  return {};
}

}  // namespace

void read_ply(std::string_view bytes, SoupBuilder& out, ReadReport& report) {
  const PlyHeader header = parse_ply_header(bytes);
  report.variant = ply_encoding_name(header.encoding);
  check_ply_declared_counts(bytes, header, out);
  const std::string why_not = openmesh_cannot_read(header);
  if (!why_not.empty()) {
    read_ply_strict(bytes, header, out, report);
    return;
  }
  // OpenMesh stops at the end of the data without an error if the body is short, and follows
  // list lengths blindly; so walk the binary layout first (cheap: no conversions).
  if (header.binary()) check_ply_binary_layout(bytes, header, "face", out);

  const std::string canonical = canonical_ply_header(header);
  static constexpr std::string_view kNewline = "\n";
  std::vector<StreamPiece> pieces{{canonical, StreamPiece::npos},
                                  {bytes.substr(header.body_offset), header.body_offset}};
  // A last number right at the end of ASCII data would set eofbit and end OpenMesh's loops.
  if (!header.binary()) pieces.push_back({kNewline, StreamPiece::npos});
  MemoryStreamBuf buffer(std::move(pieces));
  auto where = [&] {
    const std::size_t pos = buffer.source_position();
    if (header.binary()) {
      return pos == StreamPiece::npos ? std::string("header")
                                      : "byte offset " + std::to_string(pos);
    }
    return describe_text_position(bytes, pos);
  };
  out.set_locator(where);
  out.set_immediate_index_check(true);  // the vertex element comes first (checked above)
  SoupImporter importer(out);
  const std::size_t nv = header.find("vertex")->count, nf = header.find("face")->count;
  const PolygonSoup& soup = out.soup();
  auto describe_failure = [&] {
    const std::string what =
        soup.vertex_count() < nv
            ? "vertex " + std::to_string(soup.vertex_count()) + " of " + std::to_string(nv)
            : "face " + std::to_string(soup.faces_seen) + " of " + std::to_string(nf);
    return "PLY: " + where() + ": could not read " + what;
  };
  OpenMesh::IO::Options options = OpenMesh::IO::Options::VertexColor;
  options += OpenMesh::IO::Options::FaceColor;
  options += OpenMesh::IO::Options::VertexTexCoord;
  const bool ok = run_openmesh_reader(OpenMeshReader::Ply, buffer, importer, options,
                                      /*fail_on_bad_read=*/true, describe_failure);
  out.set_locator({});
  if (!ok) throw_input_error("PLY", where(), "OpenMesh's reader rejected the data");
  if (soup.vertex_count() != nv || soup.faces_seen != nf) {
    throw_input_error("PLY", "end of data",
                      "file ends after " + std::to_string(soup.vertex_count()) + " of " +
                          std::to_string(nv) + " vertices and " + std::to_string(soup.faces_seen) +
                          " of " + std::to_string(nf) + " faces");
  }
}

}  // namespace arg::io
