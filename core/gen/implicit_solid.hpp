// Solids given by signed distance fields (negative inside), their primitives and blends.
#pragma once

#include <functional>
#include <vector>

#include "common/vec3.hpp"

namespace arg::gen {

struct Box {
  Vec3 lo, hi;
};

// `bounds` must contain the whole solid: the polygoniser samples only there. Fields are exact
// distances where cheap and otherwise distance-like (same sign, close to 1-Lipschitz), which is
// what the smooth blends and the marching need.
struct Solid {
  std::function<double(const Vec3&)> field;
  Box bounds;
};

// An orthonormal frame; `w` is the axis of tori and the third half-size of boxes.
struct Frame {
  Vec3 u{1, 0, 0}, v{0, 1, 0}, w{0, 0, 1};
};

// A frame whose third axis is `w` (need not be unit); the other two are chosen from it.
Frame frame_with_axis(Vec3 w);
// The standard frame turned by `angle` radians about the world axis 0 (x), 1 (y) or 2 (z).
Frame rotated_frame(int axis, double angle);

Solid sphere(Vec3 centre, double radius);
// A cone with spherical ends: radius ra around a, rb around b.
Solid round_cone(Vec3 a, Vec3 b, double ra, double rb);
inline Solid capsule(Vec3 a, Vec3 b, double radius) {
  return round_cone(a, b, radius, radius);
}
// A tube through `points` whose radius goes linearly from radii[i] to radii[i + 1].
Solid tube(std::vector<Vec3> points, std::vector<double> radii);
Solid ellipsoid(Vec3 centre, Vec3 radii, Frame frame = {});
// A box of half-sizes `half` whose edges are rounded by `rounding` (included in `half`).
Solid rounded_box(Vec3 centre, Vec3 half, double rounding, Frame frame = {});
// Ring of radius `major` around frame.w with a tube of radius `minor`.
Solid torus(Vec3 centre, double major, double minor, Frame frame = {});
// A tube of radius `radius` along the circular arc from a through `through` to b: a torus
// segment with round ends, as for handles.
Solid torus_segment(Vec3 a, Vec3 through, Vec3 b, double radius);

// A point (rho, z) of a profile in the half plane rho >= 0 of a solid of revolution.
struct ProfilePoint {
  double rho = 0, z = 0;
};
// The solid swept by turning the polygon `chain` (from the axis, out and back to the axis, not
// crossing itself) about the vertical axis through `axis_xy`, then grown by `rounding`.
Solid revolved_profile(std::vector<ProfilePoint> chain, double rounding, Vec3 axis_xy = {});

// Blend with a fillet of size about k (polynomial smooth minimum); k = 0 is a plain union.
Solid smooth_union(Solid a, Solid b, double k);
Solid smooth_union(std::vector<Solid> parts, double k);
Solid subtract(Solid a, Solid b);
Solid intersect(Solid a, Solid b);
// The part of `a` below the plane z = height (to open a vessel at its rim).
Solid cut_above(Solid a, double height);

}  // namespace arg::gen
