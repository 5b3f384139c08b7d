// The committed values of earlier formats (tests/unit/fixtures/formatN, see each README.md).
#pragma once

#include <fstream>
#include <iterator>
#include <string>

namespace arg {

// The bytes of fixtures/format<version>/NAME.arg.
inline std::string format_fixture(int version, const std::string& name) {
  std::ifstream in(
      ARG_SOURCE_DIR "/tests/unit/fixtures/format" + std::to_string(version) + "/" + name + ".arg",
      std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace arg
