// The committed format-1 values (tests/unit/fixtures/format1, made by arg 0.1.0's argtool).
#pragma once

#include <fstream>
#include <iterator>
#include <string>

namespace arg {

// The bytes of fixtures/format1/NAME.arg.
inline std::string format1_fixture(const std::string& name) {
  std::ifstream in(ARG_SOURCE_DIR "/tests/unit/fixtures/format1/" + name + ".arg",
                   std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace arg
