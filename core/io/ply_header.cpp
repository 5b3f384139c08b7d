// The PLY header: a strict parser and the element layout it declares.
#include "io/ply_header.hpp"

#include <limits>
#include <optional>

#include "io/polygon_soup.hpp"
#include "io/text_scan.hpp"

namespace arg::io {

namespace {

constexpr std::size_t kMaxHeaderBytes = 1 << 20;
constexpr std::size_t kMaxProperties = 4096;

std::optional<PlyType> type_from_name(std::string_view name) {
  if (name == "char" || name == "int8") return PlyType::Int8;
  if (name == "uchar" || name == "uint8") return PlyType::UInt8;
  if (name == "short" || name == "int16") return PlyType::Int16;
  if (name == "ushort" || name == "uint16") return PlyType::UInt16;
  if (name == "int" || name == "int32") return PlyType::Int32;
  if (name == "uint" || name == "uint32") return PlyType::UInt32;
  if (name == "float" || name == "float32") return PlyType::Float32;
  if (name == "double" || name == "float64") return PlyType::Float64;
  return std::nullopt;
}

}  // namespace

const PlyElement* PlyHeader::find(std::string_view name) const {
  for (const PlyElement& e : elements) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

std::size_t ply_type_size(PlyType type) {
  switch (type) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 0;
}

bool ply_type_is_integer(PlyType type) {
  return type != PlyType::Float32 && type != PlyType::Float64;
}

const char* ply_encoding_name(PlyEncoding encoding) {
  switch (encoding) {
    case PlyEncoding::Ascii:
      return "ascii";
    case PlyEncoding::BinaryLittleEndian:
      return "binary_little_endian";
    case PlyEncoding::BinaryBigEndian:
      return "binary_big_endian";
  }
  return "";
}

PlyHeader parse_ply_header(std::string_view bytes) {
  PlyHeader header;
  LineScanner lines(bytes);
  std::vector<std::string_view> tokens;
  std::string_view line;
  auto fail = [&](const std::string& message) {
    throw_input_error("PLY", "line " + std::to_string(lines.line_number()), message);
  };
  if (!lines.next(line) || trim(line) != "ply") fail("expected 'ply' on the first line");
  bool have_format = false;
  std::size_t properties = 0;
  for (;;) {
    if (lines.offset() > kMaxHeaderBytes) fail("header longer than 1 MiB");
    if (!lines.next(line)) fail("unexpected end of data: no end_header line");
    const std::size_t count = split_tokens(line, tokens, 8);
    if (count == 0) continue;
    const std::string_view key = tokens[0];
    if (key == "comment" || key == "obj_info") continue;
    if (key == "end_header") {
      if (count != 1) fail("unexpected text after end_header");
      break;
    }
    if (key == "format") {
      if (have_format || !header.elements.empty()) fail("misplaced format line");
      if (count != 3) fail("expected 'format <encoding> 1.0'");
      if (tokens[1] == "ascii") {
        header.encoding = PlyEncoding::Ascii;
      } else if (tokens[1] == "binary_little_endian") {
        header.encoding = PlyEncoding::BinaryLittleEndian;
      } else if (tokens[1] == "binary_big_endian") {
        header.encoding = PlyEncoding::BinaryBigEndian;
      } else {
        fail("unknown encoding '" + std::string(tokens[1]) + "'");
      }
      have_format = true;
    } else if (key == "element") {
      if (!have_format) fail("element before the format line");
      std::int64_t n = -1;
      if (count != 3 || !parse_integer(tokens[2], n) || n < 0) {
        fail("expected 'element <name> <count>'");
      }
      if (n > std::numeric_limits<std::uint32_t>::max()) {
        fail("element count " + std::string(tokens[2]) + " is too large");
      }
      if (header.find(tokens[1]) != nullptr) {
        fail("element '" + std::string(tokens[1]) + "' declared twice");
      }
      header.elements.push_back({std::string(tokens[1]), static_cast<std::uint64_t>(n), {}});
    } else if (key == "property") {
      if (header.elements.empty()) fail("property before any element");
      if (++properties > kMaxProperties) fail("too many properties");
      PlyProperty p;
      if (count >= 2 && tokens[1] == "list") {
        if (count != 5) fail("expected 'property list <count type> <type> <name>'");
        const auto count_type = type_from_name(tokens[2]);
        const auto type = type_from_name(tokens[3]);
        if (!count_type || !ply_type_is_integer(*count_type)) {
          fail("list count type '" + std::string(tokens[2]) + "' is not an integer type");
        }
        if (!type) fail("unknown property type '" + std::string(tokens[3]) + "'");
        p.is_list = true;
        p.count_type_name = std::string(tokens[2]);
        p.count_type = *count_type;
        p.type_name = std::string(tokens[3]);
        p.type = *type;
        p.name = std::string(tokens[4]);
      } else {
        if (count != 3) fail("expected 'property <type> <name>'");
        const auto type = type_from_name(tokens[1]);
        if (!type) fail("unknown property type '" + std::string(tokens[1]) + "'");
        p.type_name = std::string(tokens[1]);
        p.type = *type;
        p.name = std::string(tokens[2]);
      }
      for (const PlyProperty& q : header.elements.back().properties) {
        if (q.name == p.name) fail("property '" + p.name + "' declared twice");
      }
      header.elements.back().properties.push_back(std::move(p));
    } else {
      fail("unknown header keyword '" + std::string(key) + "'");
    }
  }
  if (!have_format) fail("no format line");
  for (const PlyElement& e : header.elements) {
    // Reading such an element would loop `count` times over nothing.
    if (e.count > 0 && e.properties.empty()) {
      fail("element '" + e.name + "' has " + std::to_string(e.count) +
           " entries but no properties");
    }
  }
  header.body_offset = lines.offset();
  return header;
}

}  // namespace arg::io
