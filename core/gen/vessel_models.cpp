// Vessels turned about the vertical axis: the vase, the cup with one handle, the amphora with two.
#include "common/strict_fp.hpp"  // first: it sets how arithmetic is compiled

#include <algorithm>
#include <cmath>
#include <vector>

#include "gen/model_blueprints.hpp"

namespace arg::gen {
namespace {

// Catmull-Rom through the control points, `per_span` samples a span, closed onto the axis at
// both ends so the chain bounds a solid of revolution.
std::vector<ProfilePoint> smooth_profile(const std::vector<ProfilePoint>& control, int per_span) {
  std::vector<ProfilePoint> chain;
  chain.push_back({0.0, control.front().z});
  const int n = static_cast<int>(control.size());
  for (int i = 0; i + 1 < n; ++i) {
    const ProfilePoint p0 = control[std::max(i - 1, 0)], p1 = control[i], p2 = control[i + 1],
                       p3 = control[std::min(i + 2, n - 1)];
    for (int s = 0; s < per_span; ++s) {
      const double t = static_cast<double>(s) / per_span, t2 = t * t, t3 = t2 * t;
      auto blend = [&](double a, double b, double c, double d) {
        return 0.5 * (2 * b + (-a + c) * t + (2 * a - 5 * b + 4 * c - d) * t2 +
                      (-a + 3 * b - 3 * c + d) * t3);
      };
      chain.push_back({blend(p0.rho, p1.rho, p2.rho, p3.rho), blend(p0.z, p1.z, p2.z, p3.z)});
    }
  }
  chain.push_back(control.back());
  chain.push_back({0.0, control.back().z});
  return chain;
}

// Extends the profile straight up by `rise` before closing it, so the body reaches well above
// the rim: the cut at the rim must meet the cavity, which ends `wall` below the body's top.
std::vector<ProfilePoint> raise_top(std::vector<ProfilePoint> chain, double rise) {
  const ProfilePoint top = chain[chain.size() - 2];
  chain.back() = {top.rho, top.z + rise};
  chain.push_back({0.0, top.z + rise});
  return chain;
}

// Outer radius of the profile chain at height z (the largest crossing).
double radius_at(const std::vector<ProfilePoint>& chain, double z) {
  double r = 0;
  for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
    const ProfilePoint a = chain[i], b = chain[i + 1];
    if ((a.z <= z) == (b.z <= z)) continue;
    r = std::max(r, a.rho + (b.rho - a.rho) * (z - a.z) / (b.z - a.z));
  }
  return r;
}

// Walking the profile chain from height z0 up (or down), the first point at distance r from
// the chain's point at z0. The chain rises monotonically between its axis ends.
ProfilePoint profile_point_at_distance(const std::vector<ProfilePoint>& chain, double z0, double r,
                                       bool upwards) {
  const int first = 1, last = static_cast<int>(chain.size()) - 2;  // skip the axis points
  int seg = first;
  while (seg + 1 < last && chain[seg + 1].z <= z0) ++seg;
  const ProfilePoint a = chain[seg], b = chain[seg + 1];
  const ProfilePoint centre{a.rho + (b.rho - a.rho) * (z0 - a.z) / (b.z - a.z), z0};
  ProfilePoint prev = centre;
  for (int i = upwards ? seg + 1 : seg; i >= first && i <= last; i += upwards ? 1 : -1) {
    const ProfilePoint q = chain[i];
    const double dx = q.rho - centre.rho, dz = q.z - centre.z;
    if (dx * dx + dz * dz >= r * r) {
      // |prev + t (q - prev) - centre| = r, the root in [0, 1].
      const double ex = q.rho - prev.rho, ez = q.z - prev.z;
      const double wx = prev.rho - centre.rho, wz = prev.z - centre.z;
      const double qa = ex * ex + ez * ez, qb = 2 * (ex * wx + ez * wz);
      const double qc = wx * wx + wz * wz - r * r;
      const double t = (-qb + std::sqrt(std::max(qb * qb - 4 * qa * qc, 0.0))) / (2 * qa);
      return {prev.rho + ex * t, prev.z + ez * t};
    }
    prev = q;
  }
  return prev;
}

constexpr double kRounding = 0.015;

// A solid of revolution hollowed to `wall` thickness above `floor_z` and cut open at `rim_z`.
// The cavity is the inward offset of the body, so walls are `wall` thick measured along the
// normal; the profile keeps its inner radius well above zero from floor to rim, so the cavity
// is one piece that opens at the rim and the vessel stays a (genus 0) ball.
Solid open_vessel(const std::vector<ProfilePoint>& chain, double wall, double floor_z,
                  double rim_z) {
  Solid body = revolved_profile(raise_top(chain, wall + 0.1), kRounding);
  Box bounds = body.bounds;
  bounds.hi.z = std::min(bounds.hi.z, rim_z);
  auto field = [outer = std::move(body.field), wall, floor_z, rim_z](const Vec3& p) {
    const double f = outer(p);
    const double cavity = std::max(f + wall, floor_z - p.z);
    return std::max(std::max(f, -cavity), p.z - rim_z);
  };
  return {std::move(field), bounds};
}

// A handle in the xz plane on the side `side` (+1 or -1), from height za to zb on the body
// surface, bulging out through the point at radius `out_rho`, height `out_z`. Its ends sit a
// little inside the wall so the tube joins it; the wall is thicker than the end caps reach, so
// the handle never pokes into the cavity.
Solid handle(const std::vector<ProfilePoint>& chain, double side, double za, double zb,
             double out_rho, double out_z, double radius) {
  const double inset = 0.3 * radius;
  const double ra = radius_at(chain, za) + kRounding - inset;
  const double rb = radius_at(chain, zb) + kRounding - inset;
  return torus_segment({side * ra, 0, za}, {side * out_rho, 0, out_z}, {side * rb, 0, zb}, radius);
}

}  // namespace

Blueprint vase_blueprint(SeededRandom& rng) {
  const double foot = rng.uniform(0.17, 0.25);
  const double belly = rng.uniform(0.27, 0.4);
  const double belly_z = rng.uniform(0.3, 0.5);
  const double neck = rng.uniform(0.17, 0.22);
  const double neck_z = rng.uniform(0.74, 0.84);
  const double lip = neck + rng.uniform(0.0, 0.09);
  const double wall = 0.08;
  const std::vector<ProfilePoint> control = {{foot, 0.0},      {foot + 0.01, 0.05},
                                             {belly, belly_z}, {neck, neck_z},
                                             {lip, 1.0},       {lip + 0.01, 1.05}};
  const auto chain = smooth_profile(control, 8);
  Solid solid = open_vessel(chain, wall, 0.1, 1.0);

  const Rgb glaze = pick_colour(rng, {{0.55, 0.70, 0.60},
                                      {0.15, 0.25, 0.60},
                                      {0.80, 0.55, 0.25},
                                      {0.90, 0.88, 0.82},
                                      {0.50, 0.15, 0.12}});
  const Rgb band = pick_colour(rng, {{0.10, 0.10, 0.12}, {0.85, 0.70, 0.30}, {0.95, 0.95, 0.92}});
  const double band_lo = belly_z + rng.uniform(-0.05, 0.05), band_hi = band_lo + 0.08;
  Paint paint = [glaze, band, band_lo, band_hi](const Vec3& p) {
    return (p.z > band_lo && p.z < band_hi) ? band : glaze;
  };
  const char* shape = belly_z < 0.4 ? "low-bellied vase" : "high-shouldered vase";
  return {std::move(solid), std::move(paint), shape};
}

Blueprint cup_blueprint(SeededRandom& rng) {
  const double height = rng.uniform(0.7, 0.95);
  const double base = rng.uniform(0.25, 0.32);
  const double top = rng.uniform(0.34, 0.42);
  const double waist = 0.5 * (base + top) + rng.uniform(-0.02, 0.04);
  const double wall = 0.09;
  const std::vector<ProfilePoint> control = {{base, 0.0},
                                             {base + 0.01, 0.04},
                                             {waist, 0.5 * height},
                                             {top, height},
                                             {top + 0.012, height + 0.05}};
  const auto chain = smooth_profile(control, 8);
  Solid body = open_vessel(chain, wall, 0.09, height);

  const double za = height * rng.uniform(0.2, 0.35);
  const double zb = height * rng.uniform(0.66, 0.8);
  const double reach = rng.uniform(0.26, 0.36);
  const double radius = rng.uniform(0.06, 0.075);
  const double out_z = 0.5 * (za + zb) + height * rng.uniform(-0.05, 0.08);
  const double out_rho = std::max(radius_at(chain, za), radius_at(chain, zb)) + reach;
  Solid solid =
      smooth_union(std::move(body), handle(chain, 1.0, za, zb, out_rho, out_z, radius), 0.04);

  const Rgb glaze = pick_colour(rng, {{0.95, 0.95, 0.93},
                                      {0.20, 0.35, 0.65},
                                      {0.70, 0.20, 0.18},
                                      {0.35, 0.55, 0.35},
                                      {0.15, 0.15, 0.15}});
  const Rgb rim = pick_colour(rng, {{0.85, 0.70, 0.30}, {0.95, 0.95, 0.95}, {0.10, 0.10, 0.30}});
  const double rim_from = height * 0.9;
  Paint paint = [glaze, rim, rim_from](const Vec3& p) { return p.z > rim_from ? rim : glaze; };
  const char* shape = (zb - za) > 0.45 * height ? "cup with a tall handle" : "cup with a handle";
  return {std::move(solid), std::move(paint), shape};
}

Blueprint amphora_blueprint(SeededRandom& rng) {
  const double toe = rng.uniform(0.07, 0.11);
  const double belly = rng.uniform(0.29, 0.35);
  const double belly_z = rng.uniform(0.38, 0.46);
  const double shoulder = belly - rng.uniform(0.01, 0.05);
  const double shoulder_z = rng.uniform(0.6, 0.64);
  const double neck = rng.uniform(0.16, 0.19);
  const double lip = neck + rng.uniform(0.03, 0.06);
  const double wall = 0.075;
  const std::vector<ProfilePoint> control = {{toe, 0.0},
                                             {toe + 0.02, 0.05},
                                             {0.55 * belly, 0.16},
                                             {belly, belly_z},
                                             {shoulder, shoulder_z},
                                             {neck, shoulder_z + 0.1},
                                             {neck, 0.9},
                                             {lip, 1.0},
                                             {lip + 0.01, 1.04}};
  const auto chain = smooth_profile(control, 8);
  Solid body = open_vessel(chain, wall, 0.2, 1.0);

  // Ear handles: arcs of radius r about the concave corner where neck meets shoulder, from
  // the neck down to the shoulder. A circle about a point of both surfaces meets each of them
  // square on, so the handle leaves the body steeply and the slot between them is never
  // narrower than the handle's own distance from the corner; r keeps the upper end below the
  // lip's flare.
  const double corner_z = shoulder_z + 0.08;
  const double r = std::min(0.9 - corner_z, rng.uniform(0.15, 0.2));
  const double radius = rng.uniform(0.048, 0.056);
  const ProfilePoint top = profile_point_at_distance(chain, corner_z, r, true);
  const ProfilePoint foot = profile_point_at_distance(chain, corner_z, r, false);
  const ProfilePoint corner{radius_at(chain, corner_z), corner_z};
  const double ux = top.rho - corner.rho, uz = top.z - corner.z;
  const double vx = foot.rho - corner.rho, vz = foot.z - corner.z;
  const double bx = ux + vx, bz = uz + vz, bl = std::sqrt(bx * bx + bz * bz);
  const double out_rho = corner.rho + kRounding + r * bx / bl, out_z = corner.z + r * bz / bl;
  Solid solid =
      smooth_union({std::move(body), handle(chain, 1.0, top.z, foot.z, out_rho, out_z, radius),
                    handle(chain, -1.0, top.z, foot.z, out_rho, out_z, radius)},
                   0.03);

  const Rgb clay = pick_colour(rng, {{0.78, 0.45, 0.25}, {0.70, 0.40, 0.22}, {0.82, 0.58, 0.38}});
  const Rgb slip = {0.08, 0.07, 0.06};
  const bool black_figure = rng.chance(0.5);
  const double band_lo = belly_z - 0.12, band_hi = belly_z + 0.12;
  Paint paint = [clay, slip, black_figure, band_lo, band_hi](const Vec3& p) {
    const bool in_band = p.z > band_lo && p.z < band_hi;
    return (in_band != black_figure) ? slip : clay;
  };
  return {std::move(solid), std::move(paint),
          black_figure ? "black-figure amphora with two handles"
                       : "red-figure amphora with two handles"};
}

}  // namespace arg::gen
