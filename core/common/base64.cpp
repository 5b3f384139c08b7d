// Standard padded base64, strict on decode so text input cannot smuggle odd bytes.
#include "common/base64.hpp"

#include <array>
#include <cstdint>

#include "common/errors.hpp"

namespace arg {

namespace {
constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

constexpr std::array<std::int8_t, 256> make_decode_table() {
  std::array<std::int8_t, 256> table{};
  for (auto& x : table) x = -1;
  for (int i = 0; i < 64; ++i) table[static_cast<unsigned char>(kAlphabet[i])] = std::int8_t(i);
  return table;
}
constexpr auto kDecode = make_decode_table();
}  // namespace

std::string base64_encode(std::string_view bytes) {
  // Written in place: appending a character at a time was most of a value's output (COPY TO,
  // pg_dump).
  std::string out((bytes.size() + 2) / 3 * 4, '=');
  char* at = out.data();
  std::size_t i = 0;
  auto byte = [&](std::size_t k) { return std::uint32_t(static_cast<unsigned char>(bytes[k])); };
  for (; i + 3 <= bytes.size(); i += 3, at += 4) {
    const std::uint32_t v = byte(i) << 16 | byte(i + 1) << 8 | byte(i + 2);
    at[0] = kAlphabet[v >> 18 & 63];
    at[1] = kAlphabet[v >> 12 & 63];
    at[2] = kAlphabet[v >> 6 & 63];
    at[3] = kAlphabet[v & 63];
  }
  const std::size_t rest = bytes.size() - i;
  if (rest > 0) {  // one or two bytes: the rest of the group stays '='
    const std::uint32_t v = byte(i) << 16 | (rest == 2 ? byte(i + 1) << 8 : 0);
    at[0] = kAlphabet[v >> 18 & 63];
    at[1] = kAlphabet[v >> 12 & 63];
    if (rest == 2) at[2] = kAlphabet[v >> 6 & 63];
  }
  return out;
}

namespace {

// Decodes groups [from, text.size()) one character at a time, naming the first bad one; the
// last group may carry padding. Appends to `out`.
void decode_checked(std::string_view text, std::size_t from, std::string& out) {
  for (std::size_t i = from; i < text.size(); i += 4) {
    const bool last = i + 4 == text.size();
    int pad = 0;
    std::uint32_t v = 0;
    for (std::size_t k = 0; k < 4; ++k) {
      char c = text[i + k];
      std::int8_t d = kDecode[static_cast<unsigned char>(c)];
      if (c == '=' && last && k >= 2 && (k == 3 || text[i + 3] == '=')) {
        ++pad;
        d = 0;
      } else if (d < 0 || pad > 0) {
        throw InputError("base64: invalid character at offset " + std::to_string(i + k));
      }
      v = v << 6 | std::uint32_t(d);
    }
    // Canonical form: the bits dropped by padding must be zero.
    if ((pad == 1 && (v & 0xff) != 0) || (pad == 2 && (v & 0xffff) != 0))
      throw InputError("base64: non-canonical padding at offset " + std::to_string(i));
    out += char(v >> 16 & 0xff);
    if (pad < 2) out += char(v >> 8 & 0xff);
    if (pad < 1) out += char(v & 0xff);
  }
}

}  // namespace

std::string base64_decode(std::string_view text) {
  if (text.size() % 4 != 0)
    throw InputError("base64: length " + std::to_string(text.size()) + " is not a multiple of 4");
  // Every group but the last has no padding: decoded four characters at a time with one test
  // for a character outside the alphabet (its table entry is -1, so the OR of the four is
  // negative). Character by character, this was a third of reading a value's text (COPY).
  const std::size_t body = text.empty() ? 0 : text.size() - 4;
  std::string out(body / 4 * 3, '\0');
  const auto* in = reinterpret_cast<const unsigned char*>(text.data());
  char* at = out.data();
  std::size_t i = 0;
  for (; i < body; i += 4, at += 3) {
    const std::int32_t a = kDecode[in[i]], b = kDecode[in[i + 1]], c = kDecode[in[i + 2]],
                       d = kDecode[in[i + 3]];
    if ((a | b | c | d) < 0) break;  // decode_checked names it
    const std::uint32_t v =
        std::uint32_t(a) << 18 | std::uint32_t(b) << 12 | std::uint32_t(c) << 6 | std::uint32_t(d);
    at[0] = char(v >> 16), at[1] = char(v >> 8 & 0xff), at[2] = char(v & 0xff);
  }
  out.resize(i / 4 * 3);
  decode_checked(text, i, out);
  return out;
}

}  // namespace arg
