// Line and token scanning with strict number parsing, for the hand-written text parsers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace arg::io {

// Walks a text line by line ('\n', '\r\n' or '\r' endings), tracking 1-based line numbers.
class LineScanner {
 public:
  explicit LineScanner(std::string_view text, std::size_t start = 0);

  // The next line without its ending; false at the end of the text.
  bool next(std::string_view& line);
  // The next line that has a token once '#' comments are cut off (when `hash_comments`).
  bool next_content(std::string_view& line, bool hash_comments);
  std::size_t line_number() const { return line_number_; }  // of the line last returned
  std::size_t offset() const { return pos_; }               // where the next line starts
  std::size_t line_offset() const { return line_start_; }   // where the last line started

 private:
  std::string_view text_;
  std::size_t pos_;
  std::size_t line_start_ = 0;
  std::size_t line_number_ = 0;
};

// Splits on spaces and tabs (and stray '\r'); keeps at most `max_tokens` (the rest is dropped
// and the return value says how many there were in all).
std::size_t split_tokens(std::string_view line, std::vector<std::string_view>& tokens,
                         std::size_t max_tokens = 64);

// Whole-token parses; a leading '+' is allowed. parse_real accepts "nan"/"inf" spellings, so
// callers check std::isfinite where they need to.
bool parse_real(std::string_view token, double& value);
// Rounds the decimal straight to single precision (never through double, which can round a
// halfway case differently); a value too small for a float becomes a signed zero, as strtof makes
// it, and one too large fails.
bool parse_real(std::string_view token, float& value);
bool parse_integer(std::string_view token, std::int64_t& value);

// Cuts `line` at a '#' comment and trims spaces.
std::string_view strip_comment(std::string_view line);
std::string_view trim(std::string_view s);

bool iequals(std::string_view a, std::string_view b);

}  // namespace arg::io
