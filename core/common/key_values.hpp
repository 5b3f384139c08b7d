// Splitting "key=value key=value" option texts (spaces or commas between pairs).
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace arg {

// Splits `text` into (key, value) pairs; a bare word comes back with an empty value.
// `what` names the text in error messages ("build options", "weights").
std::vector<std::pair<std::string, std::string>> split_key_values(std::string_view text,
                                                                  const char* what);

// Strict number parsing: the whole value must be a finite number.
double parse_finite_number(const std::string& value, const std::string& key, const char* what);
long parse_integer(const std::string& value, const std::string& key, const char* what, long lo,
                   long hi);

}  // namespace arg
