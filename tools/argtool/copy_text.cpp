// Escaping for COPY's text format (the rows argtool ingest writes).
#include "copy_text.hpp"

#include <cctype>

namespace argtool {

void append_copy_field(std::string& row, std::string_view value) {
  for (const char c : value) {
    switch (c) {
      case '\\':
        row += "\\\\";
        break;
      case '\t':
        row += "\\t";
        break;
      case '\n':
        row += "\\n";
        break;
      case '\r':
        row += "\\r";
        break;
      default:
        row += c;
    }
  }
}

std::string copy_column_name(std::string_view name) {
  bool plain = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0]));
  for (const char c : name)
    plain = plain && (std::isalnum(static_cast<unsigned char>(c)) || c == '_') &&
            static_cast<unsigned char>(c) < 128;
  std::string out = "\"";
  for (const char c : name) {
    if (plain)
      out += char(std::tolower(static_cast<unsigned char>(c)));
    else
      out += c == '"' ? std::string("\"\"") : std::string(1, c);
  }
  return out + '"';
}

}  // namespace argtool
