// Furniture from rounded slabs and legs: the table and the chair.
#include "common/strict_fp.hpp"  // first: it sets how arithmetic is compiled

#include <cmath>
#include <vector>

#include "gen/model_blueprints.hpp"
#include "gen/portable_math.hpp"

namespace arg::gen {
namespace {

// A leg from `top` down to the floor (z = 0), square (a rounded box along its axis) or turned
// (a tapered round cone).
Solid leg(Vec3 top, Vec3 foot, double half, bool turned) {
  if (turned) return round_cone(top, foot, half * 1.1, half * 0.8);
  const Vec3 axis = top - foot;
  const Frame frame = frame_with_axis(axis);
  return rounded_box((top + foot) * 0.5, {half, half, 0.5 * length(axis)}, 0.3 * half, frame);
}

const std::initializer_list<Rgb> kWoods = {
    {0.55, 0.36, 0.20}, {0.40, 0.26, 0.15}, {0.75, 0.60, 0.42}, {0.30, 0.20, 0.13}};

}  // namespace

Blueprint table_blueprint(SeededRandom& rng) {
  const double length = rng.uniform(1.2, 1.7);
  const double width = length * rng.uniform(0.5, 0.75);
  const double thick = rng.uniform(0.1, 0.13);
  const double height = rng.uniform(0.7, 0.85);
  const bool round_top = rng.chance(0.3);
  const bool turned = rng.chance(0.5);
  const double half = rng.uniform(0.055, 0.075);
  const double inset = rng.uniform(0.06, 0.14);
  const double splay = rng.uniform(0.0, 0.06);
  const double top_z = height - 0.5 * thick;

  std::vector<Solid> parts;
  double leg_x = 0.5 * length - inset - half, leg_y = 0.5 * width - inset - half;
  if (round_top) {
    // An elliptical disc: a squashed cylinder with rounded rim; legs stand on its inscribed box.
    const double r = 0.5 * length;
    const double squash = width / length;
    Solid disc = revolved_profile({{0, top_z - 0.5 * thick},
                                   {r - 0.02, top_z - 0.5 * thick},
                                   {r - 0.02, top_z + 0.5 * thick},
                                   {0, top_z + 0.5 * thick}},
                                  0.02);
    const double rz = disc.bounds.hi.z, lz = disc.bounds.lo.z;
    parts.push_back({[f = disc.field, squash](const Vec3& p) {
                       return f({p.x, p.y / squash, p.z}) * squash;
                     },
                     {{-r, -r * squash, lz}, {r, r * squash, rz}}});
    leg_x = 0.7071 * r - half - 0.5 * inset;
    leg_y = 0.7071 * r * squash - half - 0.5 * inset;
  } else {
    parts.push_back(rounded_box({0, 0, top_z}, {0.5 * length, 0.5 * width, 0.5 * thick}, 0.025));
  }
  for (double sx : {1.0, -1.0})
    for (double sy : {1.0, -1.0}) {
      const Vec3 top{sx * leg_x, sy * leg_y, top_z};
      const Vec3 foot{sx * (leg_x + splay), sy * (leg_y + splay), 0.0 + half};
      parts.push_back(leg(top, foot, half, turned));
    }
  Solid solid = smooth_union(std::move(parts), 0.03);

  const Rgb wood = pick_colour(rng, kWoods);
  const Rgb top_colour = mix(wood, {0.05, 0.03, 0.02}, 0.25);
  Paint paint = [wood, top_colour, top_z, thick](const Vec3& p) {
    return p.z > top_z - 0.5 * thick ? top_colour : wood;
  };
  std::string description = round_top ? "oval table" : "rectangular table";
  description += turned ? " on turned legs" : " on square legs";
  return {std::move(solid), std::move(paint), description};
}

Blueprint chair_blueprint(SeededRandom& rng) {
  const double width = rng.uniform(0.45, 0.55);
  const double depth = rng.uniform(0.42, 0.52);
  const double thick = rng.uniform(0.075, 0.09);
  const double seat_z = rng.uniform(0.43, 0.5);
  const double back_h = rng.uniform(0.45, 0.6);
  const double back_t = rng.uniform(0.075, 0.09);
  const double tilt = degrees(rng.uniform(0, 15));
  const double half = rng.uniform(0.045, 0.055);
  const bool turned = rng.chance(0.5);
  const double splay = rng.uniform(0.0, 0.04);

  std::vector<Solid> parts;
  parts.push_back(rounded_box({0, 0, seat_z}, {0.5 * depth, 0.5 * width, 0.5 * thick}, 0.02));
  // The back is one slab standing on the seat's rear edge along its whole width, leaning back
  // by `tilt`: slats or a top rail would add holes and change the genus.
  const Frame lean = rotated_frame(1, -tilt);
  const Vec3 up = lean.w;
  const Vec3 back_base{-0.5 * depth + 0.5 * back_t, 0, seat_z};
  parts.push_back(rounded_box(back_base + up * (0.5 * back_h),
                              {0.5 * back_t, 0.5 * width, 0.5 * back_h}, 0.02, lean));
  const double leg_x = 0.5 * depth - half - 0.02, leg_y = 0.5 * width - half - 0.02;
  for (double sx : {1.0, -1.0})
    for (double sy : {1.0, -1.0}) {
      const Vec3 top{sx * leg_x, sy * leg_y, seat_z};
      const Vec3 foot{sx * (leg_x + splay), sy * (leg_y + splay), half};
      parts.push_back(leg(top, foot, half, turned));
    }
  Solid solid = smooth_union(std::move(parts), 0.02);

  const Rgb wood = pick_colour(rng, kWoods);
  const Rgb cushion =
      pick_colour(rng, {{0.55, 0.15, 0.15}, {0.20, 0.30, 0.50}, {0.80, 0.75, 0.60}});
  const bool upholstered = rng.chance(0.5);
  Paint paint = [wood, cushion, upholstered, seat_z, thick](const Vec3& p) {
    return (upholstered && p.z > seat_z + 0.25 * thick) ? cushion : wood;
  };
  std::string description = upholstered ? "upholstered chair" : "wooden chair";
  if (tilt > degrees(8)) description += " with a reclining back";
  return {std::move(solid), std::move(paint), description};
}

}  // namespace arg::gen
