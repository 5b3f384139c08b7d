// Seeds for the generator's random streams, one per class and variant.
#pragma once

#include <cstdint>
#include <string_view>

#include "common/random.hpp"

namespace arg::gen {

using arg::SeededRandom;

// Mixes a name and a number into a seed (FNV-1a, then the splitmix64 finaliser), so nearby
// variants and classes get unrelated streams.
std::uint64_t mix_seed(std::string_view name, std::uint64_t number);

}  // namespace arg::gen
