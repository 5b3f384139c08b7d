// Line and token scanning with strict number parsing, for the hand-written text parsers.
#include "io/text_scan.hpp"

#include <cctype>
#include <charconv>
#include <cmath>

namespace arg::io {

namespace {
bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}
}  // namespace

LineScanner::LineScanner(std::string_view text, std::size_t start)
    : text_(text), pos_(start), line_start_(start) {
  for (std::size_t i = 0; i < start && i < text.size(); ++i) {
    if (text[i] == '\n' || (text[i] == '\r' && (i + 1 >= text.size() || text[i + 1] != '\n'))) {
      ++line_number_;
    }
  }
}

bool LineScanner::next(std::string_view& line) {
  if (pos_ >= text_.size()) return false;
  line_start_ = pos_;
  std::size_t end = pos_;
  while (end < text_.size() && text_[end] != '\n' && text_[end] != '\r') ++end;
  line = text_.substr(pos_, end - pos_);
  if (end < text_.size() && text_[end] == '\r') ++end;
  if (end < text_.size() && text_[end] == '\n') ++end;
  pos_ = end;
  ++line_number_;
  return true;
}

bool LineScanner::next_content(std::string_view& line, bool hash_comments) {
  std::string_view raw;
  while (next(raw)) {
    line = hash_comments ? strip_comment(raw) : trim(raw);
    if (!line.empty()) return true;
  }
  return false;
}

std::size_t split_tokens(std::string_view line, std::vector<std::string_view>& tokens,
                         std::size_t max_tokens) {
  tokens.clear();
  std::size_t count = 0;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_blank(line[i])) ++i;
    if (i >= line.size()) break;
    std::size_t j = i;
    while (j < line.size() && !is_blank(line[j])) ++j;
    if (tokens.size() < max_tokens) tokens.push_back(line.substr(i, j - i));
    ++count;
    i = j;
  }
  return count;
}

bool parse_real(std::string_view token, double& value) {
  if (!token.empty() && token[0] == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  return result.ec == std::errc() && result.ptr == end;
}

bool parse_real(std::string_view token, float& value) {
  if (!token.empty() && token[0] == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  if (result.ec == std::errc::result_out_of_range && result.ptr == end) {
    double wide = 0;
    if (!parse_real(token, wide) || std::fabs(wide) >= 1.0) return false;
    value = static_cast<float>(wide);
    return true;
  }
  return result.ec == std::errc() && result.ptr == end;
}

bool parse_integer(std::string_view token, std::int64_t& value) {
  if (!token.empty() && token[0] == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  return result.ec == std::errc() && result.ptr == end;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (is_blank(s.front()) || s.front() == '\n')) s.remove_prefix(1);
  while (!s.empty() && (is_blank(s.back()) || s.back() == '\n')) s.remove_suffix(1);
  return s;
}

std::string_view strip_comment(std::string_view line) {
  const std::size_t hash = line.find('#');
  if (hash != std::string_view::npos) line = line.substr(0, hash);
  return trim(line);
}

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) !=
        std::tolower(static_cast<unsigned char>(b[i]))) {
      return false;
    }
  }
  return true;
}

}  // namespace arg::io
