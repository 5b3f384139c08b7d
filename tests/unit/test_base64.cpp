// Base64 of the text forms: RFC 4648's vectors, round trips, and strict decoding that names the
// first bad character wherever it lies (in the groups decoded four at a time or in the last).
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "common/base64.hpp"
#include "input_error.hpp"

namespace arg {
namespace {

TEST(Base64, TheStandardsVectors) {
  const std::pair<const char*, const char*> vectors[] = {
      {"", ""},
      {"f", "Zg=="},
      {"fo", "Zm8="},
      {"foo", "Zm9v"},
      {"foob", "Zm9vYg=="},
      {"fooba", "Zm9vYmE="},
      {"foobar", "Zm9vYmFy"},
  };
  for (auto [bytes, text] : vectors) {
    EXPECT_EQ(base64_encode(bytes), text);
    EXPECT_EQ(base64_decode(text), bytes);
  }
}

TEST(Base64, EveryLengthAndByteRoundTrips) {
  std::mt19937 random(7);
  for (std::size_t size = 0; size < 200; ++size) {
    std::string bytes(size, '\0');
    for (char& c : bytes) c = char(random() & 0xff);
    const std::string text = base64_encode(bytes);
    EXPECT_EQ(text.size(), (size + 2) / 3 * 4);
    EXPECT_EQ(base64_decode(text), bytes) << size;
  }
  std::string all;
  for (int c = 0; c < 256; ++c) all += char(c);
  EXPECT_EQ(base64_decode(base64_encode(all)), all);
}

TEST(Base64, TheFirstBadCharacterIsNamedWhereverItLies) {
  const std::string text = base64_encode(std::string(30, 'x')) + "QQ==";  // 44 characters
  for (std::size_t at = 0; at < text.size(); ++at)
    for (char bad : {'*', '=', ' ', char(0x80)}) {
      std::string changed = text;
      if (changed[at] == bad) continue;
      changed[at] = bad;
      // The padding's two places are PaddingAndLengthAreStrict's: a bad character in the
      // last makes the '=' before it the first bad one.
      if (at >= text.size() - 2) continue;
      const std::string message = input_error_of([&] { base64_decode(changed); }, "accepted");
      EXPECT_EQ(message, "base64: invalid character at offset " + std::to_string(at))
          << "at " << at << " bad " << int(bad);
      // A later bad character does not hide an earlier one.
      if (at + 5 < changed.size()) {
        changed[at + 5] = '*';
        EXPECT_EQ(input_error_of([&] { base64_decode(changed); }),
                  "base64: invalid character at offset " + std::to_string(at));
      }
    }
}

TEST(Base64, PaddingAndLengthAreStrict) {
  EXPECT_EQ(input_error_of([] { base64_decode("Zm9"); }),
            "base64: length 3 is not a multiple of 4");
  EXPECT_EQ(input_error_of([] { base64_decode("Zh=="); }),
            "base64: non-canonical padding at offset 0");
  EXPECT_EQ(input_error_of([] { base64_decode("Zm9vZm9="); }),
            "base64: non-canonical padding at offset 4");
  EXPECT_EQ(input_error_of([] { base64_decode("Zg==Zm9v"); }),
            "base64: invalid character at offset 2");
  EXPECT_EQ(input_error_of([] { base64_decode("Z=g="); }), "base64: invalid character at offset 1");
  EXPECT_EQ(base64_decode("Zg=="), "f");
}

}  // namespace
}  // namespace arg
