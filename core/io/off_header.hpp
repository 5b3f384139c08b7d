// The OFF header keyword ([ST][C][N][4][n]OFF [BINARY]) and where the data after it starts.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace arg::io {

struct OffHeader {
  bool texcoords = false;          // ST
  bool colours = false;            // C
  bool normals = false;            // N
  bool four_d = false;             // 4 (homogeneous coordinates)
  bool n_dim = false;              // n (dimension given in the file)
  bool binary = false;             // "OFF BINARY"
  std::size_t keyword_offset = 0;  // where the keyword starts
  std::size_t keyword_end = 0;     // just after the keyword
  std::size_t line_end = 0;        // just after the keyword line and its line ending
  bool counts_on_keyword_line = false;
};

// Finds the keyword after leading blank lines and '#' comments; nullopt when there is none.
std::optional<OffHeader> find_off_header(std::string_view bytes);

}  // namespace arg::io
