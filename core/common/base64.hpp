// Standard base64 (RFC 4648, padded) for the lossless text form of binary values.
#pragma once

#include <string>
#include <string_view>

namespace arg {

std::string base64_encode(std::string_view bytes);

// Strict: only the standard alphabet, length a multiple of 4, '=' only as final padding.
// Throws InputError naming the offset of the first bad character.
std::string base64_decode(std::string_view text);

}  // namespace arg
