// libFuzzer target: parse_weights; accepted weights survive format_weights and a second parse.
#include "fuzz_support.hpp"
#include "match/weights.hpp"

namespace arg::fuzz {

inline int fuzz_weights(const std::uint8_t* data, std::size_t size) {
  try {
    const Weights parsed = parse_weights(as_bytes(data, size));
    const std::string text = format_weights(parsed);
    const Weights again = parse_weights(text);
    ARG_FUZZ_CHECK(again == parsed);
    ARG_FUZZ_CHECK(format_weights(again) == text);
  } catch (const Error&) {
  }
  return 0;
}

}  // namespace arg::fuzz

ARG_FUZZ_ENTRY(arg::fuzz::fuzz_weights)
