// The OFF header keyword ([ST][C][N][4][n]OFF [BINARY]) and where the data after it starts.
#include "io/off_header.hpp"

#include "io/text_scan.hpp"

namespace arg::io {

std::optional<OffHeader> find_off_header(std::string_view bytes) {
  std::size_t i = 0;
  // Skip whitespace and whole-line comments.
  while (i < bytes.size()) {
    const char c = bytes[i];
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
      ++i;
    } else if (c == '#') {
      while (i < bytes.size() && bytes[i] != '\n') ++i;
    } else {
      break;
    }
  }
  OffHeader h;
  h.keyword_offset = i;
  std::size_t end = i;
  while (end < bytes.size() && bytes[end] != ' ' && bytes[end] != '\t' && bytes[end] != '\r' &&
         bytes[end] != '\n' && bytes[end] != '#') {
    ++end;
  }
  std::string_view word = bytes.substr(i, end - i);
  if (word.substr(0, 2) == "ST") {
    h.texcoords = true;
    word.remove_prefix(2);
  }
  if (!word.empty() && word[0] == 'C') {
    h.colours = true;
    word.remove_prefix(1);
  }
  if (!word.empty() && word[0] == 'N') {
    h.normals = true;
    word.remove_prefix(1);
  }
  if (!word.empty() && word[0] == '4') {
    h.four_d = true;
    word.remove_prefix(1);
  }
  if (!word.empty() && word[0] == 'n') {
    h.n_dim = true;
    word.remove_prefix(1);
  }
  if (word != "OFF") return std::nullopt;
  h.keyword_end = end;
  std::size_t eol = end;
  while (eol < bytes.size() && bytes[eol] != '\n' && bytes[eol] != '\r') ++eol;
  const std::string_view rest = strip_comment(bytes.substr(end, eol - end));
  if (eol < bytes.size() && bytes[eol] == '\r') ++eol;
  if (eol < bytes.size() && bytes[eol] == '\n') ++eol;
  h.line_end = eol;
  if (rest == "BINARY") {
    h.binary = true;
  } else if (!rest.empty()) {
    h.counts_on_keyword_line = true;
  }
  return h;
}

}  // namespace arg::io
