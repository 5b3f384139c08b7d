// Strict tokenising and number parsing for the short option texts of SQL and the CLI.
#include "common/key_values.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "common/errors.hpp"

namespace arg {

namespace {
bool is_separator(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',';
}
}  // namespace

std::vector<std::pair<std::string, std::string>> split_key_values(std::string_view text,
                                                                  const char* what) {
  if (text.size() > 4096) throw InputError(std::string(what) + ": text longer than 4096 bytes");
  std::vector<std::pair<std::string, std::string>> pairs;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && is_separator(text[i])) ++i;
    if (i == text.size()) break;
    std::size_t start = i;
    while (i < text.size() && !is_separator(text[i])) ++i;
    std::string_view token = text.substr(start, i - start);
    std::size_t eq = token.find('=');
    if (eq == std::string_view::npos) {
      pairs.emplace_back(std::string(token), std::string());
    } else {
      if (eq == 0 || eq + 1 == token.size())
        throw InputError(std::string(what) + ": malformed pair \"" + std::string(token) +
                         "\" (expected key=value)");
      pairs.emplace_back(std::string(token.substr(0, eq)), std::string(token.substr(eq + 1)));
    }
  }
  return pairs;
}

double parse_finite_number(const std::string& value, const std::string& key, const char* what) {
  const char* begin = value.c_str();
  char* end = nullptr;
  errno = 0;
  double x = std::strtod(begin, &end);
  if (value.empty() || end != begin + value.size() || errno == ERANGE || !std::isfinite(x))
    throw InputError(std::string(what) + ": " + key + "=" + value + " is not a finite number");
  return x;
}

long parse_integer(const std::string& value, const std::string& key, const char* what, long lo,
                   long hi) {
  const char* begin = value.c_str();
  char* end = nullptr;
  errno = 0;
  long x = std::strtol(begin, &end, 10);
  if (value.empty() || end != begin + value.size() || errno == ERANGE || x < lo || x > hi)
    throw InputError(std::string(what) + ": " + key + "=" + value + " must be an integer in [" +
                     std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return x;
}

}  // namespace arg
