// What each model class builds before polygonisation: the solid, how to paint it, what it is.
#pragma once

#include <functional>
#include <string>

#include "gen/implicit_solid.hpp"
#include "gen/seeded_random.hpp"

namespace arg::gen {

struct Rgb {
  double r = 0, g = 0, b = 0;
};

// Colour of the surface around `point` (a triangle's centroid).
using Paint = std::function<Rgb(const Vec3& point)>;

struct Blueprint {
  Solid solid;
  Paint paint;
  std::string description;  // a short phrase, e.g. "cup with a high handle"
};

// One builder per class. Each draws all its choices from `rng` in a fixed order and keeps
// every part at least ~1.5 grid cells thick and every gap ~2.5 cells wide at resolution 32, so
// the built-in genus survives polygonisation at resolutions 32..64.
Blueprint vase_blueprint(SeededRandom& rng);
Blueprint cup_blueprint(SeededRandom& rng);
Blueprint amphora_blueprint(SeededRandom& rng);
Blueprint torus_blueprint(SeededRandom& rng);
Blueprint fourleg_blueprint(SeededRandom& rng);
Blueprint human_blueprint(SeededRandom& rng, int pose);
Blueprint table_blueprint(SeededRandom& rng);
Blueprint chair_blueprint(SeededRandom& rng);
Blueprint octopus_blueprint(SeededRandom& rng);

// Mixes two colours; t in [0, 1].
inline Rgb mix(Rgb a, Rgb b, double t) {
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}

// A colour from `palette` picked by rng, lightly jittered so no two variants match exactly.
Rgb pick_colour(SeededRandom& rng, std::initializer_list<Rgb> palette);

}  // namespace arg::gen
