// What each model class builds before polygonisation: the solid, how to paint it, what it is.
#include "common/strict_fp.hpp"  // first: it sets how arithmetic is compiled

#include "gen/model_blueprints.hpp"

#include <algorithm>

namespace arg::gen {

Rgb pick_colour(SeededRandom& rng, std::initializer_list<Rgb> palette) {
  const Rgb base = *(palette.begin() + rng.below(static_cast<int>(palette.size())));
  const double jitter = rng.uniform(-0.06, 0.06);
  auto clamp01 = [](double v) { return std::clamp(v, 0.0, 1.0); };
  return {clamp01(base.r + jitter), clamp01(base.g + jitter), clamp01(base.b + jitter)};
}

}  // namespace arg::gen
