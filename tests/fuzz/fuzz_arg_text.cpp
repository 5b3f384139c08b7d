// libFuzzer target: arg_from_text; accepted text must be canonical (it prints back unchanged).
#include "fuzz_support.hpp"
#include "graph/serialize.hpp"

namespace arg::fuzz {

inline int fuzz_arg_text(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = as_bytes(data, size);
  try {
    const std::string bytes = arg_from_text(text);
    ARG_FUZZ_CHECK(arg_to_text(bytes) == text);
    ARG_FUZZ_CHECK(serialize_arg(deserialize_arg(bytes)) == bytes);
  } catch (const Error&) {
  }
  return 0;
}

}  // namespace arg::fuzz

ARG_FUZZ_ENTRY(arg::fuzz::fuzz_arg_text)
