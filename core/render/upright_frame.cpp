// The resting-base rule for a canonical up, and a front from the principal axes.
#include "render/upright_frame.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "mesh/normalize_pose.hpp"

namespace arg {

namespace {

// The surface within this share of its extent above the floor touches it: thin enough that a
// table's legs touch and its rails do not, thick enough for a tessellated foot or rim.
constexpr double kContactBand = 0.02;
// A floor must be broad: its support polygon at least this share of the broadest side's.
constexpr double kBroadBase = 0.4;
// A file axis's floor must be this share of the broadest principal side's (standing below).
constexpr double kFileBase = 0.25;
// ... and hold the centroid this far (RMS radii) inside its edge: a bottle drawn lying along +x
// rests on its side with a margin of 0.06, figures and animals standing stand with 0.15 or more.
constexpr double kFileMargin = 0.1;
// The file's +z wins over its +y when both stand and +z holds the centroid this many times
// higher: a +z-up figure on its back is 7 times lower; a +y-up scorpion on its tail 2 times
// higher than on its legs.
constexpr double kFarHigher = 2.5;

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Counter-clockwise convex hull (Andrew's monotone chain); collinear points dropped.
std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> p) {
  std::sort(p.begin(), p.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<Eigen::Vector2d> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

double polygon_area(const std::vector<Eigen::Vector2d>& h) {
  double twice = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const Eigen::Vector2d& a = h[i];
    const Eigen::Vector2d& b = h[(i + 1) % h.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * std::fabs(twice);
}

// Signed distance from the origin to the boundary of a counter-clockwise convex polygon,
// positive inside; for fewer than three corners, minus the distance to the nearest.
double origin_margin(const std::vector<Eigen::Vector2d>& h) {
  if (h.size() < 3) {
    double nearest = h.empty() ? 1.0 : h[0].norm();
    for (const Eigen::Vector2d& p : h) nearest = std::min(nearest, p.norm());
    return -nearest;
  }
  double margin = INFINITY;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const Eigen::Vector2d edge = h[(i + 1) % h.size()] - h[i];
    const Eigen::Vector2d inward(-edge.y(), edge.x());
    margin = std::min(margin, -h[i].dot(inward) / inward.norm());
  }
  return margin;
}

// How the posed surface P would rest on a floor below it along `down` (unit, posed coordinates):
// the surface within the contact band above the floor, projected on it, makes the support polygon.
RestingSide measure_side(const Vertices& P, const Eigen::Vector3d& down,
                         const StopRequested& stop) {
  // Floor coordinates: for a principal direction the two other axes, as the sides were always
  // measured; else any orthonormal pair across `down`.
  Eigen::Vector3d e1, e2;
  Eigen::Index k = 0;
  if (down.cwiseAbs().maxCoeff(&k) > 1 - 1e-12) {
    e1 = Eigen::Vector3d::Unit((k + 1) % 3), e2 = Eigen::Vector3d::Unit((k + 2) % 3);
  } else {
    e1 = down.unitOrthogonal(), e2 = down.cross(e1);
  }
  RestingSide side;
  side.down = down;
  const Eigen::VectorXd depth = P * down;  // distance below the centroid, along `down`
  const double floor = depth.maxCoeff(), extent = floor - depth.minCoeff();
  std::vector<Eigen::Vector2d> touching;
  for (Eigen::Index i = 0; i < P.rows(); ++i) {
    poll_interrupt(std::size_t(i), stop);
    if (depth[i] >= floor - kContactBand * extent)
      touching.emplace_back(P.row(i).dot(e1), P.row(i).dot(e2));
  }
  const std::vector<Eigen::Vector2d> hull = convex_hull(touching);
  side.height = floor;  // the centroid is at the origin
  side.support = polygon_area(hull);
  side.margin = origin_margin(hull);
  side.tilt = std::atan2(side.margin, side.height);
  return side;
}

// The direction across `up` along which the surface is thinnest (its second moment there, from
// the pose's covariance), signed towards its heavier tail (positive third moment).
Eigen::Vector3d thinnest_across(const Mesh& mesh, const Pose& pose, const Eigen::Vector3d& up,
                                const StopRequested& stop) {
  const Eigen::Matrix3d cov =
      pose.rotation.transpose() * pose.eigenvalues.asDiagonal() * pose.rotation;
  const Eigen::Vector3d e1 = up.unitOrthogonal(), e2 = up.cross(e1);
  const double a = e1.dot(cov * e1), b = e1.dot(cov * e2), c = e2.dot(cov * e2);
  // The smaller eigenvalue's direction of the 2x2 matrix [a b; b c].
  const double angle = 0.5 * std::atan2(2 * b, a - c) + M_PI / 2;
  Eigen::Matrix3d axes;
  axes.row(0) = (std::cos(angle) * e1 + std::sin(angle) * e2).transpose();
  axes.row(1) = up.transpose();
  axes.row(2) = axes.row(0).cross(axes.row(1));
  orient_by_third_moment(mesh, pose.centre, pose.scale > 0 ? 1 / pose.scale : 1, axes, stop);
  return axes.row(0).transpose();
}

// Whether the surface stands on a floor below it along a file axis: its centroid is well inside
// a base that is not a point or a line (a share of the broadest principal side's; lower than
// kBroadBase, as a standing figure's feet make a narrower base than its side).
bool standing(const RestingSide& side, double broadest) {
  return side.margin >= kFileMargin && side.support >= kFileBase * broadest;
}

}  // namespace

Eigen::Vector3d parse_up_axis(const std::string& text) {
  std::string t;
  for (char c : text)
    if (!std::isspace(static_cast<unsigned char>(c)))
      t += char(std::tolower(static_cast<unsigned char>(c)));
  if (t.size() == 1) t = "+" + t;
  if (t.size() == 2 && (t[0] == '+' || t[0] == '-') && t[1] >= 'x' && t[1] <= 'z')
    return (t[0] == '-' ? -1.0 : 1.0) * Eigen::Vector3d::Unit(t[1] - 'x');
  throw std::invalid_argument("up axis '" + text +
                              "' is not one of +x, -x, +y, -y, +z, -z (the file axis that "
                              "points up)");
}

UprightFrame upright_frame(const Mesh& mesh, const UprightHint& hint, const StopRequested& stop) {
  UprightFrame frame;
  const Pose pose = surface_pose(mesh, stop);
  if (pose.area <= 0 || mesh.V.rows() == 0) return frame;
  // Posed coordinates: centroid at the origin, principal axes on x, y, z, unit RMS radius.
  Vertices P(mesh.V.rows(), 3);
  for (Eigen::Index i = 0; i < mesh.V.rows(); ++i)
    P.row(i) =
        (pose.scale * (pose.rotation * (mesh.V.row(i).transpose() - pose.centre))).transpose();
  for (int k = 0; k < 3; ++k)
    for (int s = 0; s < 2; ++s) {
      const double sign = s == 0 ? 1.0 : -1.0;
      RestingSide& side = frame.sides[std::size_t(2 * k + s)];
      side = measure_side(P, sign * Eigen::Vector3d::Unit(k), stop);
      side.down = sign * pose.rotation.row(k).transpose();
    }
  // Among the broad bases, the one that holds the centroid highest: an upright object carries
  // its mass above its base (a table's top, a bust's head, a standing figure's body), where
  // resting on its top or its side would lay most of its surface near the floor.
  double broadest = 0;
  for (const RestingSide& side : frame.sides) broadest = std::max(broadest, side.support);
  int best = 0;
  for (int i = 0; i < 6; ++i) {
    RestingSide& side = frame.sides[std::size_t(i)];
    side.score = side.support >= kBroadBase * broadest ? side.height : 0;
    if (side.score > frame.sides[std::size_t(best)].score) best = i;
  }
  // What the file says first; else a file axis the surface stands on as it is drawn.
  const auto in_mesh = [&](const Eigen::Vector3d& file_axis) {
    return (hint.file_axes * file_axis).normalized();
  };
  Eigen::Vector3d up = Eigen::Vector3d::Zero();
  if (!hint.up.isZero()) {
    up = in_mesh(hint.up);
  } else if (hint.prefer_file_axes) {
    // Files keep +y or +z up far more often than not: +y if the surface stands on it, unless
    // it stands on +z with its centroid far higher (a figure drawn +z up lies on its back
    // along -y). Where it stands on neither, the rule's up; but if the rule's side cannot hold
    // the centroid either and its up is the file's -y or -z, that axis the right way round
    // (a file is rarely drawn upside down; the rule's highest centroid is often a lying
    // animal's back).
    for (const int k : {1, 2}) {
      const Eigen::Vector3d u = in_mesh(Eigen::Vector3d::Unit(k));
      RestingSide side = measure_side(P, -(pose.rotation * u), stop);
      side.down = -u;
      side.score = standing(side, broadest) ? side.height : 0;
      frame.file_sides.push_back(side);
    }
    const RestingSide &y = frame.file_sides[0], &z = frame.file_sides[1];
    if (y.score > 0 && !(z.score > kFarHigher * y.score))
      up = -y.down;
    else if (z.score > 0)
      up = -z.down;
    const RestingSide& rule = frame.sides[std::size_t(best)];
    for (const int k : {1, 2})
      if (up.isZero() && rule.margin < 0 &&
          rule.down.dot(in_mesh(Eigen::Vector3d::Unit(k))) > std::sqrt(0.5))
        up = in_mesh(Eigen::Vector3d::Unit(k));
  }
  if (!up.isZero()) {
    frame.up = up;
    frame.front = thinnest_across(mesh, pose, up, stop);
    return frame;
  }
  const int up_axis = best / 2;
  frame.up = -frame.sides[std::size_t(best)].down;
  // Seen along the thinner of the two other axes, so the picture shows the wider one across,
  // from the side of its heavier tail (positive third moment, as the axes are signed): a
  // figure's or a bust's chest and face outweigh its back (docs/BENCHMARKS.md).
  const int front_axis = up_axis == 2 ? 1 : 2;
  frame.front = pose.rotation.row(front_axis).transpose();
  return frame;
}

UprightFrame upright_frame(const Mesh& mesh, const StopRequested& stop) {
  return upright_frame(mesh, UprightHint{}, stop);
}

Eigen::Matrix3d upright_view(const UprightFrame& frame) {
  Eigen::Matrix3d r;
  r.row(0) = frame.up.cross(frame.front).transpose();
  r.row(1) = frame.up.transpose();
  r.row(2) = frame.front.transpose();
  return r;
}

}  // namespace arg
