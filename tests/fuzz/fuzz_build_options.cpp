// libFuzzer target: parse_build_options; accepted options are in range and survive formatting.
#include "common/build_options.hpp"
#include "fuzz_support.hpp"

namespace arg::fuzz {

inline int fuzz_build_options(const std::uint8_t* data, std::size_t size) {
  try {
    const BuildOptions parsed = parse_build_options(as_bytes(data, size));
    ARG_FUZZ_CHECK(parsed.levels >= 1 && parsed.levels <= kMaxLevels);
    ARG_FUZZ_CHECK(parsed.base_points >= 8 && parsed.base_points <= 4096);
    ARG_FUZZ_CHECK(parsed.threads >= 1);
    ARG_FUZZ_CHECK(parsed.mu == MuKind::Geodesic || parsed.mu == MuKind::Height ||
                   parsed.mu == MuKind::Centroid);
    const std::string text = format_build_options(parsed);
    const BuildOptions again = parse_build_options(text);
    ARG_FUZZ_CHECK(again.levels == parsed.levels && again.mu == parsed.mu &&
                   again.base_points == parsed.base_points);
    ARG_FUZZ_CHECK(format_build_options(again) == text);
  } catch (const Error&) {
  }
  return 0;
}

}  // namespace arg::fuzz

ARG_FUZZ_ENTRY(arg::fuzz::fuzz_build_options)
