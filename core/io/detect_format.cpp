// Recognising a mesh format from the content of its bytes (magic numbers and keywords).
#include <cstdint>

#include "io/format_readers.hpp"
#include "io/read_mesh.hpp"
#include "io/text_scan.hpp"

namespace arg {

const char* format_name(MeshFormat format) {
  switch (format) {
    case MeshFormat::Off:
      return "OFF";
    case MeshFormat::Obj:
      return "OBJ";
    case MeshFormat::Ply:
      return "PLY";
    case MeshFormat::Stl:
      return "STL";
    case MeshFormat::Glb:
      return "GLB";
    case MeshFormat::Unknown:
      break;
  }
  return "unknown";
}

namespace {

bool starts_with_word(std::string_view text, std::string_view word) {
  if (text.size() < word.size() || !io::iequals(text.substr(0, word.size()), word)) return false;
  return text.size() == word.size() || text[word.size()] == ' ' || text[word.size()] == '\t' ||
         text[word.size()] == '\r' || text[word.size()] == '\n';
}

bool is_obj_keyword(std::string_view w) {
  for (const char* k : {"v", "vt", "vn", "vp", "f", "o", "g", "s", "l", "p", "mtllib", "usemtl"}) {
    if (w == k) return true;
  }
  return false;
}

}  // namespace

MeshFormat detect_mesh_format(std::string_view bytes) {
  if (bytes.substr(0, 4) == "glTF") return MeshFormat::Glb;
  // Before any text test: the 80-byte header of a binary STL is free text (often "solid ...").
  if (io::stl_binary_size_matches(bytes)) return MeshFormat::Stl;
  const std::size_t skip = bytes.find_first_not_of(" \t\r\n");
  if (skip == std::string_view::npos) return MeshFormat::Unknown;
  const std::string_view text = bytes.substr(skip);
  if (text.substr(0, 3) == "ply" && text.size() > 3 && (text[3] == '\n' || text[3] == '\r')) {
    return MeshFormat::Ply;
  }
  if (starts_with_word(text, "solid")) return MeshFormat::Stl;
  if (io::find_off_header(bytes)) return MeshFormat::Off;
  // OBJ: the first line that is not blank or a comment starts with an OBJ keyword.
  io::LineScanner lines(bytes);
  std::string_view line;
  std::vector<std::string_view> tokens;
  for (int n = 0; n < 1000 && lines.next_content(line, true); ++n) {
    io::split_tokens(line, tokens, 1);
    return is_obj_keyword(tokens[0]) ? MeshFormat::Obj : MeshFormat::Unknown;
  }
  return MeshFormat::Unknown;
}

}  // namespace arg
