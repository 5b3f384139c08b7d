// PostgreSQL COPY's text format: fields escaped as COPY reads them back, names as SQL reads them.
#pragma once

#include <string>
#include <string_view>

namespace argtool {

// COPY's NULL in the text format.
inline constexpr std::string_view kCopyNull = "\\N";

// Appends `value` to `row` as one field of COPY's text format: backslash, tab, line feed and
// carriage return escaped, so COPY reads back exactly `value`.
void append_copy_field(std::string& row, std::string_view value);

// `name` as a column of a COPY column list: a plain name ([A-Za-z_][A-Za-z0-9_]*) folded to
// lower case as SQL folds unquoted names, anything else kept as written; either way in double
// quotes, so that a keyword (order, user) is a column too.
std::string copy_column_name(std::string_view name);

}  // namespace argtool
