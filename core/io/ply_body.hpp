// Walking a PLY body value by value (ASCII tokens or binary numbers), with bounds and positions.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "io/ply_header.hpp"
#include "io/polygon_soup.hpp"

namespace arg::io {

// Reads the values of a PLY body in order; every read is bounds-checked and failures name the
// byte offset (binary) or line (ASCII).
class PlyBodyCursor {
 public:
  PlyBodyCursor(std::string_view bytes, const PlyHeader& header);

  double read(PlyType type);
  // A list length, checked against what the rest of the body can hold.
  std::size_t read_count(PlyType count_type, PlyType entry_type);
  // Skips a value without converting it (binary: just advances).
  void skip(PlyType type);
  // Binary only: skips `n` bytes known to be there.
  void advance(std::size_t n) { pos_ += n; }
  std::string where() const;
  std::size_t offset() const { return pos_; }
  std::size_t remaining() const { return bytes_.size() - pos_; }
  [[noreturn]] void fail(const std::string& message) const;

 private:
  std::string_view token();

  std::string_view bytes_;
  std::size_t pos_;
  bool binary_;
  bool big_endian_;
  std::size_t line_ = 1;  // ASCII only: line of pos_
};

// Fail-fast checks of the declared element counts against the body size and the Limits, before
// any element is read: InputError "PLY: header declares N vertices (at least B bytes each) but
// the body has K bytes", or LimitError.
void check_ply_declared_counts(std::string_view bytes, const PlyHeader& header, SoupBuilder& out);

}  // namespace arg::io
