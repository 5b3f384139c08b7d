// Walking a PLY body value by value (ASCII tokens or binary numbers), with bounds and positions.
#include "io/ply_body.hpp"

#include <cmath>
#include <cstring>

#include "io/memory_stream.hpp"
#include "io/text_scan.hpp"

namespace arg::io {

namespace {

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

// The minimum bytes one element takes in a binary body (lists counted as empty).
std::size_t min_binary_size(const PlyElement& e) {
  std::size_t size = 0;
  for (const PlyProperty& p : e.properties)
    size += ply_type_size(p.is_list ? p.count_type : p.type);
  return size;
}

std::string plural(const std::string& name, std::uint64_t count) {
  if (count == 1) return name;
  if (name == "vertex") return "vertices";
  if (!name.empty() && name.back() == 's') return name;
  return name + "s";
}

}  // namespace

PlyBodyCursor::PlyBodyCursor(std::string_view bytes, const PlyHeader& header)
    : bytes_(bytes),
      pos_(header.body_offset),
      binary_(header.binary()),
      big_endian_(header.encoding == PlyEncoding::BinaryBigEndian) {
  if (!binary_) line_ = line_of_offset(bytes, pos_);
}

std::string PlyBodyCursor::where() const {
  if (binary_) return "byte offset " + std::to_string(pos_);
  return pos_ >= bytes_.size() ? std::string("end of data") : "line " + std::to_string(line_);
}

void PlyBodyCursor::fail(const std::string& message) const {
  throw_input_error("PLY", where(), message);
}

std::string_view PlyBodyCursor::token() {
  while (pos_ < bytes_.size() && is_space(bytes_[pos_])) {
    if (bytes_[pos_] == '\n') ++line_;
    ++pos_;
  }
  if (pos_ >= bytes_.size()) fail("unexpected end of data (file truncated?)");
  const std::size_t begin = pos_;
  while (pos_ < bytes_.size() && !is_space(bytes_[pos_])) ++pos_;
  return bytes_.substr(begin, pos_ - begin);
}

double PlyBodyCursor::read(PlyType type) {
  if (!binary_) {
    const std::size_t at = pos_;
    const std::string_view t = token();
    double value = 0;
    float single = 0;
    std::int64_t integer = 0;
    // A float property is rounded once, from the decimal, as a binary body would store it.
    const bool ok = ply_type_is_integer(type)  ? parse_integer(t, integer)
                    : type == PlyType::Float32 ? parse_real(t, single)
                                               : parse_real(t, value);
    if (type == PlyType::Float32) value = single;
    if (!ok) {
      pos_ = at;
      token();  // re-read so that where() points at the token's line
      fail("'" + std::string(t.substr(0, 32)) + "' is not a valid " +
           (ply_type_is_integer(type) ? "integer" : "number"));
    }
    return ply_type_is_integer(type) ? static_cast<double>(integer) : value;
  }
  const std::size_t size = ply_type_size(type);
  if (bytes_.size() - pos_ < size) fail("unexpected end of data (file truncated?)");
  unsigned char b[8];
  std::memcpy(b, bytes_.data() + pos_, size);
  pos_ += size;
  if (big_endian_) {
    for (std::size_t i = 0; i < size / 2; ++i) std::swap(b[i], b[size - 1 - i]);
  }
  switch (type) {
    case PlyType::Int8: {
      std::int8_t v;
      std::memcpy(&v, b, 1);
      return v;
    }
    case PlyType::UInt8:
      return b[0];
    case PlyType::Int16: {
      std::int16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case PlyType::UInt16: {
      std::uint16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case PlyType::Int32: {
      std::int32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
    case PlyType::UInt32: {
      std::uint32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
    case PlyType::Float32: {
      float v;
      std::memcpy(&v, b, 4);
      return v;
    }
    case PlyType::Float64: {
      double v;
      std::memcpy(&v, b, 8);
      return v;
    }
  }
  return 0;
}

std::size_t PlyBodyCursor::read_count(PlyType count_type, PlyType entry_type) {
  const std::size_t at = pos_;
  const double n = read(count_type);
  // Each entry takes its binary size, or at least two bytes ("0 ") in ASCII.
  const std::size_t entry = binary_ ? ply_type_size(entry_type) : 2;
  if (n < 0 || n > double(remaining()) / double(entry) + 1) {
    pos_ = at;
    fail("list length " + std::to_string(static_cast<long long>(n)) +
         " is negative or longer than the rest of the data");
  }
  return static_cast<std::size_t>(n);
}

void PlyBodyCursor::skip(PlyType type) {
  if (!binary_) {
    token();
    return;
  }
  const std::size_t size = ply_type_size(type);
  if (bytes_.size() - pos_ < size) fail("unexpected end of data (file truncated?)");
  pos_ += size;
}

void check_ply_declared_counts(std::string_view bytes, const PlyHeader& header, SoupBuilder& out) {
  const std::size_t body = bytes.size() - header.body_offset;
  // Counts are below 2^32 and an element is at most 4096 properties of 8 bytes: no overflow.
  std::uint64_t needed = 0;
  std::string what;
  for (const PlyElement& e : header.elements) {
    // ASCII: every value takes a character and a separator.
    const std::size_t each = header.binary() ? min_binary_size(e) : 2 * e.properties.size();
    needed += e.count * each;
    if (!what.empty()) what += ", ";
    what += std::to_string(e.count) + " " + plural(e.name, e.count);
    if (e.count > 0 && needed > body + 1) {
      throw_input_error("PLY", "",
                        "header declares " + what + " (at least " + std::to_string(needed) +
                            " bytes) but the body has " + std::to_string(body) + " bytes");
    }
  }
  const PlyElement* v = header.find("vertex");
  const PlyElement* f = header.find("face");
  if (v && v->count > out.limits().max_vertices) {
    out.fail_limit("header declares " + std::to_string(v->count) + " vertices, more than " +
                   std::to_string(out.limits().max_vertices));
  }
  if (f && f->count > out.limits().max_triangles) {
    out.fail_limit("header declares " + std::to_string(f->count) + " faces, more than " +
                   std::to_string(out.limits().max_triangles) + " triangles");
  }
  out.declared_counts(v ? v->count : 0, f ? f->count : 0);
}

}  // namespace arg::io
