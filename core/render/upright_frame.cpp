// The resting-base rule for a canonical up, and a front from the principal axes.
#include "render/upright_frame.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "mesh/normalize_pose.hpp"

namespace arg {

namespace {

// The surface within this share of its extent above the floor touches it: thin enough that a
// table's legs touch and its rails do not, thick enough for a tessellated foot or rim.
constexpr double kContactBand = 0.02;
// A floor must be broad: its support polygon at least this share of the broadest side's.
constexpr double kBroadBase = 0.4;

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

}  // namespace

UprightFrame upright_frame(const Mesh& mesh, const StopRequested& stop) {
  UprightFrame frame;
  const Pose pose = surface_pose(mesh, stop);
  if (pose.area <= 0 || mesh.V.rows() == 0) return frame;
  // Posed coordinates: centroid at the origin, principal axes on x, y, z, unit RMS radius.
  Vertices P(mesh.V.rows(), 3);
  for (Eigen::Index i = 0; i < mesh.V.rows(); ++i)
    P.row(i) =
        (pose.scale * (pose.rotation * (mesh.V.row(i).transpose() - pose.centre))).transpose();
  std::vector<Eigen::Vector2d> touching;
  for (int k = 0; k < 3; ++k) {
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    for (int s = 0; s < 2; ++s) {
      const double sign = s == 0 ? 1.0 : -1.0;
      RestingSide& side = frame.sides[std::size_t(2 * k + s)];
      side.down = sign * pose.rotation.row(k).transpose();
      const double floor = sign * (s == 0 ? P.col(k).maxCoeff() : P.col(k).minCoeff());
      const double extent = P.col(k).maxCoeff() - P.col(k).minCoeff();
      touching.clear();
      for (Eigen::Index i = 0; i < P.rows(); ++i) {
        poll_interrupt(std::size_t(i), stop);
        if (sign * P(i, k) >= floor - kContactBand * extent)
          touching.emplace_back(P(i, a), P(i, b));
      }
      const std::vector<Eigen::Vector2d> hull = convex_hull(touching);
      side.height = floor;  // the centroid is at the origin
      side.support = polygon_area(hull);
      side.margin = origin_margin(hull);
      side.tilt = std::atan2(side.margin, side.height);
    }
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
  const int up_axis = best / 2;
  frame.up = -frame.sides[std::size_t(best)].down;
  // Seen along the thinner of the two other axes, so the picture shows the wider one across,
  // from the side of its heavier tail (positive third moment, as the axes are signed): a
  // figure's or a bust's chest and face outweigh its back (docs/BENCHMARKS.md).
  const int front_axis = up_axis == 2 ? 1 : 2;
  frame.front = pose.rotation.row(front_axis).transpose();
  return frame;
}

Eigen::Matrix3d upright_view(const UprightFrame& frame) {
  Eigen::Matrix3d r;
  r.row(0) = frame.up.cross(frame.front).transpose();
  r.row(1) = frame.up.transpose();
  r.row(2) = frame.front.transpose();
  return r;
}

}  // namespace arg
