// Reading docs/REFERENCE.md as its coverage tests need it: sections, table rows, `code` spans.
#pragma once

#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace arg::test {

// The text of docs/REFERENCE.md in this source tree; empty when it cannot be read.
inline std::string read_reference() {
  std::ifstream in(ARG_SOURCE_DIR "/docs/REFERENCE.md", std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The number of #s of a heading line, 0 for any other line.
inline int heading_level(std::string_view line) {
  std::size_t n = 0;
  while (n < line.size() && line[n] == '#') ++n;
  return n > 0 && n < line.size() && line[n] == ' ' ? int(n) : 0;
}

// The lines under the heading whose text is `title` (at any level), up to the next heading of
// the same or a higher level; none when there is no such heading.
inline std::vector<std::string> section(const std::string& doc, std::string_view title) {
  std::vector<std::string> out;
  int level = 0;
  for (const std::string& line : lines_of(doc)) {
    const int h = heading_level(line);
    if (level > 0 && h > 0 && h <= level) break;
    if (level > 0) out.push_back(line);
    if (level == 0 && h > 0 && std::string_view(line).substr(std::size_t(h) + 1) == title)
      level = h;
  }
  return out;
}

// What the `code` spans of `text` hold, in order.
inline std::vector<std::string> code_spans(std::string_view text) {
  std::vector<std::string> spans;
  std::size_t at = 0;
  while ((at = text.find('`', at)) != std::string_view::npos) {
    const std::size_t end = text.find('`', at + 1);
    if (end == std::string_view::npos) break;
    spans.emplace_back(text.substr(at + 1, end - at - 1));
    at = end + 1;
  }
  return spans;
}

// The body rows of the tables among `lines` (header and separator rows left out), each as its
// cells without the spaces around them.
inline std::vector<std::vector<std::string>> table_rows(const std::vector<std::string>& lines) {
  auto is_row = [](const std::string& line) { return !line.empty() && line[0] == '|'; };
  auto is_separator = [&](const std::string& line) {
    return is_row(line) && line.find_first_not_of("|-: ") == std::string::npos;
  };
  std::vector<std::vector<std::string>> rows;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    if (!is_row(line) || is_separator(line)) continue;
    if (i + 1 < lines.size() && is_separator(lines[i + 1])) continue;  // a header
    std::vector<std::string> cells;
    std::string cell;
    for (std::size_t k = 1; k < line.size(); ++k) {
      if (line[k] == '|' && line[k - 1] != '\\') {
        const std::size_t first = cell.find_first_not_of(' ');
        cells.push_back(first == std::string::npos
                            ? std::string()
                            : cell.substr(first, cell.find_last_not_of(' ') - first + 1));
        cell.clear();
      } else {
        cell += line[k];
      }
    }
    rows.push_back(cells);
  }
  return rows;
}

}  // namespace arg::test
