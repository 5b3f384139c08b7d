// Figures made of blended limbs: the four-legged animal, the standing human, the octopus.
#include "common/strict_fp.hpp"  // first: it sets how arithmetic is compiled

#include <algorithm>
#include <cmath>
#include <vector>

#include "gen/model_blueprints.hpp"
#include "gen/portable_math.hpp"

namespace arg::gen {
namespace {

// Unit vector at `elevation` above the horizontal, pointing along `heading` in the xy plane.
Vec3 direction(double heading, double elevation) {
  const double c = portable_cos(elevation);
  return {c * portable_cos(heading), c * portable_sin(heading), portable_sin(elevation)};
}

// A limb from `start` along `dir` bent by `bend` radians towards `bend_towards` at the middle
// joint: two tapered segments.
Solid limb(Vec3 start, Vec3 dir, double upper, double lower, double bend, Vec3 bend_towards,
           double r0, double r1, double r2) {
  const Vec3 joint = start + dir * upper;
  const Vec3 side = normalized(bend_towards - dir * dot(bend_towards, dir));
  const Vec3 dir2 = dir * portable_cos(bend) + side * portable_sin(bend);
  return tube({start, joint, joint + dir2 * lower}, {r0, r1, r2});
}

}  // namespace

Blueprint fourleg_blueprint(SeededRandom& rng) {
  const double length = rng.uniform(1.0, 1.35);
  const double width = rng.uniform(0.42, 0.5);
  const double depth = rng.uniform(0.36, 0.46);
  const double leg_len = rng.uniform(0.5, 0.72);
  const double leg_r = rng.uniform(0.095, 0.11);
  const double body_z = leg_len + 0.3 * depth;
  std::vector<Solid> parts;
  parts.push_back(ellipsoid({0, 0, body_z}, {0.5 * length, 0.5 * width, 0.5 * depth}));

  // Legs hang from the body's underside, splay a little outwards and swing fore or aft; the
  // front and hind swings are bounded so the feet never close the gap between the pairs.
  const double splay = degrees(rng.uniform(3, 8));
  for (int fore = 0; fore < 2; ++fore) {
    const double sx = fore ? 1.0 : -1.0;
    const double swing = degrees(fore ? rng.uniform(-10, 15) : rng.uniform(-15, 10));
    for (double sy : {1.0, -1.0}) {
      const Vec3 top{sx * (0.5 * length - 0.17), sy * (0.5 * width - 0.3 * leg_r),
                     body_z - 0.1 * depth};
      const double reach = top.z - 0.8 * leg_r;
      const Vec3 dir = normalized({portable_sin(swing), sy * portable_sin(splay), -1.0});
      const Vec3 foot = top + dir * (reach / -dir.z);
      parts.push_back(round_cone(top, foot, leg_r * 1.15, leg_r * 0.85));
    }
  }

  // Neck rises forward from the chest; the head is an egg along the muzzle.
  const Vec3 neck_base{0.5 * length - 0.12, 0, body_z + 0.15 * depth};
  const double neck_up = degrees(rng.uniform(25, 60));
  const Vec3 neck_dir = direction(0, neck_up);
  const Vec3 neck_top = neck_base + neck_dir * rng.uniform(0.3, 0.45);
  parts.push_back(round_cone(neck_base, neck_top, 0.14, 0.105));
  const double head_len = rng.uniform(0.17, 0.23);
  const double head_down = degrees(rng.uniform(-30, 0));
  const Vec3 muzzle = direction(0, head_down);
  parts.push_back(ellipsoid(neck_top + muzzle * (0.6 * head_len), {0.11, 0.11, head_len},
                            frame_with_axis(muzzle)));

  // Tail: a short curved tube leaving the rump backwards and curling up or down.
  const double tail_up = degrees(rng.uniform(-20, 45));
  const double tail_curl = degrees(rng.uniform(-30, 50));
  const double tail_len = rng.uniform(0.3, 0.5);
  std::vector<Vec3> tail{{-0.5 * length + 0.06, 0, body_z + 0.15 * depth}};
  std::vector<double> tail_r{0.09};
  for (int s = 1; s <= 6; ++s) {
    const double angle = tail_up + tail_curl * s / 6.0;
    tail.push_back(tail.back() + direction(kPi, angle) * (tail_len / 6.0));
    tail_r.push_back(0.09 - 0.015 * s / 6.0);
  }
  parts.push_back(tube(tail, tail_r));
  Solid solid = smooth_union(std::move(parts), 0.05);

  const Rgb coat = pick_colour(rng, {{0.55, 0.38, 0.22},
                                     {0.30, 0.25, 0.20},
                                     {0.85, 0.80, 0.70},
                                     {0.60, 0.60, 0.58},
                                     {0.75, 0.55, 0.30}});
  const Rgb socks = mix(coat, {0.1, 0.1, 0.1}, 0.5);
  const double sock_z = 0.35 * leg_len;
  Paint paint = [coat, socks, sock_z](const Vec3& p) { return p.z < sock_z ? socks : coat; };
  return {std::move(solid), std::move(paint),
          neck_up > degrees(45) ? "four-legged animal with a raised head" : "four-legged animal"};
}

Blueprint human_blueprint(SeededRandom& rng, int pose) {
  const double leg_len = rng.uniform(0.82, 0.95);
  const double torso_len = rng.uniform(0.55, 0.68);
  const double shoulder = rng.uniform(0.31, 0.36);
  const double head_r = rng.uniform(0.14, 0.165);
  const double hip_w = rng.uniform(0.11, 0.13);
  const double ankle_z = 0.1;
  const double hip_z = ankle_z + leg_len;
  const double shoulder_z = hip_z + torso_len - 0.05;

  // Arm elevation from hanging (0) through sideways (90) to raised (180 degrees), per side;
  // leg spread and the forward swing of legs (walking) per pose.
  double arm_left = 0, arm_right = 0, leg_spread = 0, stride = 0, arm_swing = 0;
  const char* description = "";
  switch (pose) {
    case 0:
      arm_left = rng.uniform(16, 24), arm_right = rng.uniform(16, 24);
      leg_spread = rng.uniform(3, 6), description = "standing figure with arms down";
      break;
    case 1:
      arm_left = rng.uniform(80, 100), arm_right = rng.uniform(80, 100);
      leg_spread = rng.uniform(3, 7), description = "standing figure with arms out";
      break;
    case 2:
      arm_left = rng.uniform(145, 162), arm_right = rng.uniform(145, 162);
      leg_spread = rng.uniform(3, 7), description = "standing figure with arms raised";
      break;
    case 3:
      arm_left = rng.uniform(145, 162), arm_right = rng.uniform(16, 24);
      leg_spread = rng.uniform(3, 7), description = "standing figure with one arm raised";
      break;
    case 4:
      arm_left = rng.uniform(35, 60), arm_right = rng.uniform(35, 60);
      leg_spread = rng.uniform(14, 22), description = "figure standing with legs apart";
      break;
    default:
      arm_left = rng.uniform(16, 22), arm_right = rng.uniform(16, 22);
      leg_spread = rng.uniform(3, 6), stride = rng.uniform(12, 20);
      arm_swing = rng.uniform(15, 30), description = "walking figure";
      break;
  }

  // The chest is widest a little below the shoulder joints, which sit on its surface: a joint
  // standing proud of a narrower torso would leave a crevice under the raised arm that the
  // grid can bridge into a tunnel.
  std::vector<Solid> parts;
  parts.push_back(
      ellipsoid({0, 0, hip_z + 0.45 * torso_len}, {0.14, 0.7 * shoulder, 0.45 * torso_len + 0.04}));
  parts.push_back(ellipsoid({0, 0, shoulder_z - 0.12}, {0.15, 0.9 * shoulder, 0.2}));
  parts.push_back(ellipsoid({0, 0, hip_z + 0.02}, {0.14, hip_w + 0.1, 0.13}));
  const Vec3 neck_base{0, 0, shoulder_z};
  parts.push_back(capsule(neck_base, {0, 0, shoulder_z + 0.12}, 0.08));
  parts.push_back(sphere({0.01, 0, shoulder_z + 0.1 + head_r}, head_r));

  for (double side : {1.0, -1.0}) {
    // Legs: hip to ankle with a slight knee bend forwards, then a short foot.
    const double swing = degrees(side * stride);
    const double spread = degrees(leg_spread);
    const Vec3 hip{0, side * hip_w, hip_z};
    const Vec3 leg_dir = normalized({portable_sin(swing), side * portable_sin(spread), -1.0});
    const Vec3 ankle = hip + leg_dir * ((hip_z - ankle_z) / -leg_dir.z);
    parts.push_back(
        tube({hip, lerp(hip, ankle, 0.5) + Vec3{0.02, 0, 0}, ankle}, {0.13, 0.11, 0.09}));
    parts.push_back(round_cone(ankle, ankle + Vec3{0.16, side * 0.02, -0.01}, 0.09, 0.08));

    // Arms: shoulder, elbow, hand; the forearm bends forwards or, when raised, upwards.
    const double lift = degrees(side > 0 ? arm_left : arm_right);
    const double forward = degrees(-side * arm_swing);
    const Vec3 shoulder_pt{0, side * 0.8 * shoulder, shoulder_z};
    const Vec3 arm_dir = normalized({portable_sin(forward), side * portable_sin(lift),
                                     -portable_cos(lift) * portable_cos(forward)});
    // Elbows bend forwards: bending raised arms inwards could bring the hands together.
    const Vec3 bend_to{1, 0, 0};
    const double bend = degrees(rng.uniform(5, 25));
    parts.push_back(limb(shoulder_pt, arm_dir, 0.32, 0.3, bend, bend_to, 0.1, 0.09, 0.085));
    const Vec3 elbow = shoulder_pt + arm_dir * 0.32;
    const Vec3 side_dir = normalized(bend_to - arm_dir * dot(bend_to, arm_dir));
    const Vec3 fore_dir = arm_dir * portable_cos(bend) + side_dir * portable_sin(bend);
    parts.push_back(sphere(elbow + fore_dir * 0.36, 0.095));
  }
  Solid solid = smooth_union(std::move(parts), 0.05);

  const Rgb skin = pick_colour(rng, {{0.90, 0.75, 0.62}, {0.65, 0.47, 0.35}, {0.45, 0.32, 0.24}});
  const Rgb shirt = pick_colour(
      rng, {{0.70, 0.15, 0.15}, {0.20, 0.35, 0.65}, {0.90, 0.90, 0.88}, {0.30, 0.50, 0.30}});
  const Rgb trousers = pick_colour(rng, {{0.15, 0.18, 0.30}, {0.35, 0.30, 0.25}, {0.2, 0.2, 0.2}});
  // Shirt over the chest and upper arms, trousers below the waist and inside the hands' reach.
  Paint paint = [=](const Vec3& p) {
    if (p.z > shoulder_z + 0.08) return skin;
    if (p.z > hip_z - 0.05 && std::fabs(p.y) < shoulder + 0.05) return shirt;
    if (p.z < hip_z + 0.05 && (std::fabs(p.y) < hip_w + 0.2 || p.z < hip_z - 0.35)) return trousers;
    return skin;
  };
  return {std::move(solid), std::move(paint), description};
}

Blueprint octopus_blueprint(SeededRandom& rng) {
  const double mantle_r = rng.uniform(0.3, 0.38);
  const double mantle_h = rng.uniform(0.38, 0.5);
  const double lean = degrees(rng.uniform(-15, 0));
  std::vector<Solid> parts;
  parts.push_back(ellipsoid({-0.05, 0, mantle_h + 0.05}, {mantle_r, mantle_r, mantle_h},
                            rotated_frame(1, lean)));
  // Eyes bulge from the front of the head at its widest, well above the web: an eye touching
  // both head and web would close a loop. The web joins the arms' roots (as in a real octopus)
  // so neighbouring arms only meet where they are already one piece.
  for (double side : {1.0, -1.0})
    parts.push_back(sphere({0.9 * mantle_r - 0.05, side * 0.16, mantle_h + 0.05}, 0.085));
  parts.push_back(ellipsoid({0, 0, -0.02}, {0.55, 0.55, 0.16}));

  // Each arm is a planar curve in its own vertical half plane: out and down, nearly straight,
  // then curling up at the tip by at most 130 degrees. With these ranges the arm's own parts
  // stay more than 0.2 apart (beyond their radii) and the curled half stays farther than 0.6
  // from the axis, where neighbouring arms are 0.4 apart, so no loop can close.
  const double arm_len = rng.uniform(0.85, 1.1);
  for (int k = 0; k < 8; ++k) {
    const double azimuth = degrees(45.0 * k + 22.5 + rng.uniform(-2, 2));
    const double droop = degrees(rng.uniform(15, 40));
    const double turn = degrees(rng.uniform(50, 130));
    const double len = arm_len * rng.uniform(0.88, 1.0);
    const int segments = 16;
    // Curvature grows along the arm (weight 0.3 + s^2), normalised to the total turn.
    const double weight_total = 0.3 + 1.0 / 3.0;
    double heading = -droop, u = 0.25, v = -0.05;
    std::vector<Vec3> points;
    std::vector<double> radii;
    const double base_r = 0.12;
    for (int s = 0; s <= segments; ++s) {
      const double t = static_cast<double>(s) / segments;
      points.push_back({u * portable_cos(azimuth), u * portable_sin(azimuth), v});
      radii.push_back(base_r * (1.0 - 0.33 * t));
      if (s == segments) break;
      const double tm = (s + 0.5) / segments;
      heading += turn * (0.3 + tm * tm) / weight_total / segments;
      u += portable_cos(heading) * len / segments;
      v += portable_sin(heading) * len / segments;
    }
    parts.push_back(tube(points, radii));
  }
  Solid solid = smooth_union(std::move(parts), 0.06);

  const Rgb skin = pick_colour(
      rng, {{0.75, 0.30, 0.25}, {0.85, 0.50, 0.30}, {0.55, 0.30, 0.50}, {0.80, 0.65, 0.55}});
  const Rgb under = mix(skin, {1, 1, 1}, 0.45);
  Paint paint = [skin, under](const Vec3& p) {
    return mix(skin, under, std::clamp((-0.1 - p.z) / 0.4, 0.0, 1.0));
  };
  return {std::move(solid), std::move(paint), "octopus with curling arms"};
}

}  // namespace arg::gen
