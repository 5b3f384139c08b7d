// The ring: a torus whose ring, tube and section vary by variant.
#include "common/strict_fp.hpp"  // first: it sets how arithmetic is compiled

#include <cmath>

#include "gen/model_blueprints.hpp"

namespace arg::gen {

Blueprint torus_blueprint(SeededRandom& rng) {
  const double major = rng.uniform(0.55, 0.75);
  const double minor = major * rng.uniform(0.28, 0.42);
  const double stretch = rng.uniform(1.0, 1.3);  // the ring is an ellipse in the xy plane
  const double swell = rng.uniform(0.0, 0.25);   // the tube thickens along x, thins along y
  const double flatten = rng.uniform(0.8, 1.0);  // the tube's section is squashed in z
  auto field = [=](const Vec3& p) {
    const double x = p.x / stretch, y = p.y;
    const double rho = std::sqrt(x * x + y * y);
    const double c = rho > 0 ? (x * x - y * y) / (rho * rho) : 0.0;  // cos of twice the angle
    const double tube = minor * (1.0 + swell * c);
    const double ring = rho - major;
    const double z = p.z / flatten;
    // Dividing x by stretch >= 1 only flattens the field, dividing z by flatten <= 1 steepens
    // it by up to 1/flatten; the factor flatten keeps it no steeper than a distance.
    return (std::sqrt(ring * ring + z * z) - tube) * flatten;
  };
  const double out = major + minor * (1.0 + swell);
  Solid solid{field,
              {{-out * stretch, -out, -minor * (1.0 + swell) * flatten},
               {out * stretch, out, minor * (1.0 + swell) * flatten}}};
  const Rgb metal = pick_colour(
      rng, {{0.72, 0.52, 0.20}, {0.85, 0.70, 0.25}, {0.35, 0.60, 0.40}, {0.85, 0.85, 0.82}});
  Paint paint = [metal](const Vec3& p) { return mix(metal, {1, 1, 1}, p.z > 0 ? 0.15 : 0.0); };
  return {std::move(solid), std::move(paint), stretch > 1.15 ? "oval ring" : "ring"};
}

}  // namespace arg::gen
