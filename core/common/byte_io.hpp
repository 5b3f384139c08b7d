// Little-endian writing and bounds-checked reading of fixed-width values.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>

#include "common/errors.hpp"

namespace arg {

class ByteWriter {
 public:
  template <class T>
  void put(T value) {
    static_assert(std::is_arithmetic_v<T>);
    using U = std::conditional_t<
        sizeof(T) == 8, std::uint64_t,
        std::conditional_t<sizeof(T) == 4, std::uint32_t,
                           std::conditional_t<sizeof(T) == 2, std::uint16_t, std::uint8_t>>>;
    U bits;
    std::memcpy(&bits, &value, sizeof(T));
    for (std::size_t i = 0; i < sizeof(T); ++i) out_ += char((bits >> (8 * i)) & 0xff);
  }
  void put_bytes(std::string_view bytes) { out_.append(bytes); }
  std::size_t size() const { return out_.size(); }
  std::string& bytes() { return out_; }

 private:
  std::string out_;
};

class ByteReader {
 public:
  // `what` prefixes error messages ("ARG", "PLY").
  ByteReader(std::string_view bytes, const char* what) : bytes_(bytes), what_(what) {}

  template <class T>
  T get() {
    static_assert(std::is_arithmetic_v<T>);
    using U = std::conditional_t<
        sizeof(T) == 8, std::uint64_t,
        std::conditional_t<sizeof(T) == 4, std::uint32_t,
                           std::conditional_t<sizeof(T) == 2, std::uint16_t, std::uint8_t>>>;
    need(sizeof(T));
    U bits = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i)
      bits |= U(static_cast<unsigned char>(bytes_[pos_ + i])) << (8 * i);
    pos_ += sizeof(T);
    T value;
    std::memcpy(&value, &bits, sizeof(T));
    return value;
  }
  std::string_view get_bytes(std::size_t n) {
    need(n);
    std::string_view s = bytes_.substr(pos_, n);
    pos_ += n;
    return s;
  }
  std::size_t offset() const { return pos_; }
  std::size_t remaining() const { return bytes_.size() - pos_; }

  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(std::string(what_) + ": " + message + " (at byte offset " +
                     std::to_string(pos_) + ")");
  }

 private:
  void need(std::size_t n) const {
    if (bytes_.size() - pos_ < n)
      fail("truncated: need " + std::to_string(n) + " more bytes, " +
           std::to_string(bytes_.size() - pos_) + " left");
  }
  std::string_view bytes_;
  std::size_t pos_ = 0;
  const char* what_;
};

}  // namespace arg
