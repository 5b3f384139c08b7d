// The PLY header: a strict parser and the element layout it declares.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace arg::io {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct PlyProperty {
  std::string name;
  std::string type_name;  // as written ("uchar", "float32", ...)
  PlyType type = PlyType::Float32;
  bool is_list = false;
  std::string count_type_name;  // lists only
  PlyType count_type = PlyType::UInt8;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

enum class PlyEncoding { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::Ascii;
  std::vector<PlyElement> elements;
  std::size_t body_offset = 0;  // first byte after the end_header line

  const PlyElement* find(std::string_view name) const;
  bool binary() const { return encoding != PlyEncoding::Ascii; }
};

// Parses the header strictly; InputError "PLY: line N: ..." on anything unexpected.
PlyHeader parse_ply_header(std::string_view bytes);

std::size_t ply_type_size(PlyType type);
bool ply_type_is_integer(PlyType type);
const char* ply_encoding_name(PlyEncoding encoding);

}  // namespace arg::io
