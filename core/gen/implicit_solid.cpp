// Solids given by signed distance fields (negative inside), their primitives and blends.
#include "common/strict_fp.hpp"  // first: it sets how arithmetic is compiled

#include "gen/implicit_solid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "gen/portable_math.hpp"

namespace arg::gen {
namespace {

Box box_around(Vec3 c, double r) {
  return {{c.x - r, c.y - r, c.z - r}, {c.x + r, c.y + r, c.z + r}};
}

Box merge(const Box& a, const Box& b) {
  return {{std::min(a.lo.x, b.lo.x), std::min(a.lo.y, b.lo.y), std::min(a.lo.z, b.lo.z)},
          {std::max(a.hi.x, b.hi.x), std::max(a.hi.y, b.hi.y), std::max(a.hi.z, b.hi.z)}};
}

Box grow(const Box& b, double r) {
  return {{b.lo.x - r, b.lo.y - r, b.lo.z - r}, {b.hi.x + r, b.hi.y + r, b.hi.z + r}};
}

// Distance from p to the box, zero inside: a lower bound of any exact field inside the box.
double box_distance(const Box& b, Vec3 p) {
  const double dx = std::max({b.lo.x - p.x, 0.0, p.x - b.hi.x});
  const double dy = std::max({b.lo.y - p.y, 0.0, p.y - b.hi.y});
  const double dz = std::max({b.lo.z - p.z, 0.0, p.z - b.hi.z});
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// Bounds of a frame-aligned box with half-sizes h, turned into world axes.
Box oriented_bounds(Vec3 c, Vec3 h, const Frame& f) {
  const Vec3 e{std::fabs(f.u.x) * h.x + std::fabs(f.v.x) * h.y + std::fabs(f.w.x) * h.z,
               std::fabs(f.u.y) * h.x + std::fabs(f.v.y) * h.y + std::fabs(f.w.y) * h.z,
               std::fabs(f.u.z) * h.x + std::fabs(f.v.z) * h.y + std::fabs(f.w.z) * h.z};
  return {c - e, c + e};
}

Vec3 to_local(Vec3 p, Vec3 c, const Frame& f) {
  const Vec3 d = p - c;
  return {dot(d, f.u), dot(d, f.v), dot(d, f.w)};
}

double sign_of(double x) {
  return x > 0 ? 1.0 : (x < 0 ? -1.0 : 0.0);
}

// Exact distance to a round cone (after Inigo Quilez), with the shape constants precomputed.
struct RoundCone {
  Vec3 a, ba;
  double r1, r2, l2, rr, a2, il2;

  RoundCone(Vec3 a_, Vec3 b, double ra, double rb)
      : a(a_),
        ba(b - a_),
        r1(ra),
        r2(rb),
        l2(dot(ba, ba)),
        rr(ra - rb),
        a2(l2 - rr * rr),
        il2(1.0 / l2) {}

  double operator()(Vec3 p) const {
    const Vec3 pa = p - a;
    const double y = dot(pa, ba);
    const double z = y - l2;
    const Vec3 w = pa * l2 - ba * y;
    const double x2 = dot(w, w);
    const double y2 = y * y * l2;
    const double z2 = z * z * l2;
    const double k = sign_of(rr) * rr * rr * x2;
    if (sign_of(z) * a2 * z2 > k) return std::sqrt(x2 + z2) * il2 - r2;
    if (sign_of(y) * a2 * y2 < k) return std::sqrt(x2 + y2) * il2 - r1;
    return (std::sqrt(x2 * a2 * il2) + y * rr) * il2 - r1;
  }
};

// A cone is only defined while one end sphere does not swallow the other; then the bigger
// sphere is the whole solid.
bool cone_is_proper(Vec3 a, Vec3 b, double ra, double rb) {
  const double l = length(b - a);
  return l > std::fabs(ra - rb) * (1.0 + 1e-9) && l > 1e-12;
}

// A monotone stand-in for the angle of (x, y) in [0, 4), free of atan2.
double pseudo_angle(double x, double y) {
  if (x == 0 && y == 0) return 0;
  if (y >= 0) return x >= 0 ? y / (x + y) : 1 - x / (-x + y);
  return x < 0 ? 2 - y / (-x - y) : 3 + x / (x - y);
}

double smooth_min(double a, double b, double k) {
  if (k <= 0) return std::min(a, b);
  const double h = std::max(k - std::fabs(a - b), 0.0) / k;
  return std::min(a, b) - h * h * k * 0.25;
}

}  // namespace

Frame frame_with_axis(Vec3 w) {
  Frame f;
  f.w = normalized(w);
  // Any vector not parallel to w gives the first axis; pick the world axis least aligned.
  const Vec3 seed = std::fabs(f.w.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  f.u = normalized(seed - f.w * dot(seed, f.w));
  f.v = cross(f.w, f.u);
  return f;
}

Frame rotated_frame(int axis, double angle) {
  const double c = portable_cos(angle), s = portable_sin(angle);
  Frame f;
  if (axis == 0) {
    f.v = {0, c, s};
    f.w = {0, -s, c};
  } else if (axis == 1) {
    f.u = {c, 0, -s};
    f.w = {s, 0, c};
  } else {
    f.u = {c, s, 0};
    f.v = {-s, c, 0};
  }
  return f;
}

Solid sphere(Vec3 centre, double radius) {
  return {[centre, radius](const Vec3& p) { return length(p - centre) - radius; },
          box_around(centre, radius)};
}

Solid round_cone(Vec3 a, Vec3 b, double ra, double rb) {
  if (!cone_is_proper(a, b, ra, rb)) return ra >= rb ? sphere(a, ra) : sphere(b, rb);
  return {[cone = RoundCone(a, b, ra, rb)](const Vec3& p) { return cone(p); },
          merge(box_around(a, ra), box_around(b, rb))};
}

Solid tube(std::vector<Vec3> points, std::vector<double> radii) {
  if (points.size() < 2 || radii.size() != points.size())
    throw std::invalid_argument("tube needs matching points and radii, at least two");
  std::vector<RoundCone> cones;
  std::vector<Box> boxes;
  std::vector<Solid> spheres;
  Box bounds = box_around(points[0], radii[0]);
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const Box b = merge(box_around(points[i], radii[i]), box_around(points[i + 1], radii[i + 1]));
    bounds = merge(bounds, b);
    if (cone_is_proper(points[i], points[i + 1], radii[i], radii[i + 1])) {
      cones.emplace_back(points[i], points[i + 1], radii[i], radii[i + 1]);
      boxes.push_back(b);
    } else {
      const std::size_t big = radii[i] >= radii[i + 1] ? i : i + 1;
      spheres.push_back(sphere(points[big], radii[big]));
    }
  }
  auto field = [cones = std::move(cones), boxes = std::move(boxes),
                spheres = std::move(spheres)](const Vec3& p) {
    double d = 1e300;
    // Segments are exact distances, so a segment whose box is farther than the best so far
    // cannot win; skipping it keeps long tentacles cheap.
    for (std::size_t i = 0; i < cones.size(); ++i)
      if (box_distance(boxes[i], p) < d) d = std::min(d, cones[i](p));
    for (const auto& s : spheres) d = std::min(d, s.field(p));
    return d;
  };
  return {std::move(field), bounds};
}

Solid ellipsoid(Vec3 centre, Vec3 radii, Frame frame) {
  // Quilez's bound k0 (k0 - 1) / k1: exact on the surface, close to a distance nearby.
  auto field = [centre, radii, frame](const Vec3& p) {
    const Vec3 q = to_local(p, centre, frame);
    const Vec3 s{q.x / radii.x, q.y / radii.y, q.z / radii.z};
    const Vec3 s2{s.x / radii.x, s.y / radii.y, s.z / radii.z};
    const double k0 = length(s);
    const double k1 = length(s2);
    if (k1 == 0) return -std::min({radii.x, radii.y, radii.z});
    return k0 * (k0 - 1.0) / k1;
  };
  return {std::move(field), oriented_bounds(centre, radii, frame)};
}

Solid rounded_box(Vec3 centre, Vec3 half, double rounding, Frame frame) {
  const Vec3 inner{half.x - rounding, half.y - rounding, half.z - rounding};
  auto field = [centre, inner, rounding, frame](const Vec3& p) {
    const Vec3 q = to_local(p, centre, frame);
    const Vec3 d{std::fabs(q.x) - inner.x, std::fabs(q.y) - inner.y, std::fabs(q.z) - inner.z};
    const Vec3 out{std::max(d.x, 0.0), std::max(d.y, 0.0), std::max(d.z, 0.0)};
    return length(out) + std::min(std::max({d.x, d.y, d.z}), 0.0) - rounding;
  };
  return {std::move(field), oriented_bounds(centre, half, frame)};
}

Solid torus(Vec3 centre, double major, double minor, Frame frame) {
  auto field = [centre, major, minor, frame](const Vec3& p) {
    const Vec3 q = to_local(p, centre, frame);
    const double ring = std::sqrt(q.x * q.x + q.y * q.y) - major;
    return std::sqrt(ring * ring + q.z * q.z) - minor;
  };
  const double r = major + minor;
  return {std::move(field), oriented_bounds(centre, {r, r, minor}, frame)};
}

Solid torus_segment(Vec3 a, Vec3 through, Vec3 b, double radius) {
  // Circumcircle of the three points; walking a -> through -> b turns left about n.
  const Vec3 ab = through - a, ac = b - a;
  const Vec3 abxac = cross(ab, ac);
  const double den = 2.0 * dot(abxac, abxac);
  if (den < 1e-24) throw std::invalid_argument("torus_segment: the three points are collinear");
  const Vec3 centre =
      a + (cross(abxac, ab) * dot(ac, ac) + cross(ac, abxac) * dot(ab, ab)) * (1.0 / den);
  const double big_r = length(a - centre);
  const Vec3 n = normalized(cross(through - a, b - through));
  const Vec3 e1 = normalized(a - centre);
  const Vec3 e2 = cross(n, e1);
  const Vec3 eb = b - centre;
  const double end_angle = pseudo_angle(dot(eb, e1), dot(eb, e2));
  auto on_arc = [e1, e2, end_angle](Vec3 d) {
    return pseudo_angle(dot(d, e1), dot(d, e2)) <= end_angle;
  };
  auto field = [=](const Vec3& p) {
    const Vec3 q = p - centre;
    const double h = dot(q, n);
    const Vec3 d = q - n * h;
    if (on_arc(d)) {
      const double ring = length(d) - big_r;
      return std::sqrt(ring * ring + h * h) - radius;
    }
    return std::min(length(p - a), length(p - b)) - radius;
  };
  // The arc's box: its ends plus those extreme points of the full circle that lie on the arc.
  Box bounds = merge(box_around(a, radius), box_around(b, radius));
  const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const Vec3& e : axes) {
    const Vec3 in_plane = e - n * dot(e, n);
    if (length(in_plane) < 1e-12) continue;
    const Vec3 dir = normalized(in_plane);
    for (double s : {1.0, -1.0}) {
      if (on_arc(dir * s)) bounds = merge(bounds, box_around(centre + dir * (s * big_r), radius));
    }
  }
  return {std::move(field), bounds};
}

Solid revolved_profile(std::vector<ProfilePoint> chain, double rounding, Vec3 axis_xy) {
  if (chain.size() < 3) throw std::invalid_argument("revolved_profile needs three points");
  double rho_max = 0, z_lo = chain[0].z, z_hi = chain[0].z;
  for (const auto& q : chain) {
    rho_max = std::max(rho_max, q.rho);
    z_lo = std::min(z_lo, q.z);
    z_hi = std::max(z_hi, q.z);
  }
  const double cx = axis_xy.x, cy = axis_xy.y;
  auto field = [chain = std::move(chain), rounding, cx, cy](const Vec3& p) {
    const double dx = p.x - cx, dy = p.y - cy;
    const double rho = std::sqrt(dx * dx + dy * dy), z = p.z;
    double best = 1e300;
    bool inside = false;
    // The closing edge along the axis is no surface once turned, so it only counts for the
    // inside test, and a ray towards +rho never crosses it.
    for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
      const ProfilePoint s = chain[i], e = chain[i + 1];
      const double ex = e.rho - s.rho, ez = e.z - s.z;
      const double wx = rho - s.rho, wz = z - s.z;
      const double len2 = ex * ex + ez * ez;
      const double t = len2 > 0 ? std::clamp((wx * ex + wz * ez) / len2, 0.0, 1.0) : 0.0;
      const double qx = wx - ex * t, qz = wz - ez * t;
      best = std::min(best, qx * qx + qz * qz);
      if ((s.z > z) != (e.z > z) && rho < s.rho + ex * (z - s.z) / ez) inside = !inside;
    }
    const double d = std::sqrt(best);
    return (inside ? -d : d) - rounding;
  };
  const double r = rho_max + rounding;
  return {std::move(field), {{cx - r, cy - r, z_lo - rounding}, {cx + r, cy + r, z_hi + rounding}}};
}

Solid smooth_union(Solid a, Solid b, double k) {
  const Box bounds = grow(merge(a.bounds, b.bounds), std::max(k, 0.0) * 0.25);
  auto field = [fa = std::move(a.field), fb = std::move(b.field), k](const Vec3& p) {
    return smooth_min(fa(p), fb(p), k);
  };
  return {std::move(field), bounds};
}

Solid smooth_union(std::vector<Solid> parts, double k) {
  if (parts.empty()) throw std::invalid_argument("smooth_union of nothing");
  Solid result = std::move(parts[0]);
  for (std::size_t i = 1; i < parts.size(); ++i)
    result = smooth_union(std::move(result), std::move(parts[i]), k);
  return result;
}

Solid subtract(Solid a, Solid b) {
  const Box bounds = a.bounds;
  auto field = [fa = std::move(a.field), fb = std::move(b.field)](const Vec3& p) {
    return std::max(fa(p), -fb(p));
  };
  return {std::move(field), bounds};
}

Solid intersect(Solid a, Solid b) {
  const Box bounds{{std::max(a.bounds.lo.x, b.bounds.lo.x), std::max(a.bounds.lo.y, b.bounds.lo.y),
                    std::max(a.bounds.lo.z, b.bounds.lo.z)},
                   {std::min(a.bounds.hi.x, b.bounds.hi.x), std::min(a.bounds.hi.y, b.bounds.hi.y),
                    std::min(a.bounds.hi.z, b.bounds.hi.z)}};
  auto field = [fa = std::move(a.field), fb = std::move(b.field)](const Vec3& p) {
    return std::max(fa(p), fb(p));
  };
  return {std::move(field), bounds};
}

Solid cut_above(Solid a, double height) {
  Box bounds = a.bounds;
  bounds.hi.z = std::min(bounds.hi.z, height);
  auto field = [fa = std::move(a.field), height](const Vec3& p) {
    return std::max(fa(p), p.z - height);
  };
  return {std::move(field), bounds};
}

}  // namespace arg::gen
