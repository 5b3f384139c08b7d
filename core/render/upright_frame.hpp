// A canonical view of a surface: which way is up (the side it rests on is down) and which is front.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "common/limits.hpp"
#include "mesh/mesh.hpp"

namespace arg {

// How the surface would rest on a floor below it along one of its principal directions.
struct RestingSide {
  Eigen::Vector3d down = Eigen::Vector3d::Zero();  // unit, in the mesh's coordinates
  // Signed distance (RMS radius units) from the centroid's foot on the floor to the edge of the
  // support polygon (the 2D convex hull of the surface within a thin band above the floor):
  // positive inside, so a push of that size along the floor does not tip the object over.
  double margin = 0;
  double height = 0;   // of the centroid above the floor, RMS radius units
  double support = 0;  // area of the support polygon, RMS radius units squared
  double tilt = 0;     // atan2(margin, height): how far it may tilt before it tips (radians)
  double score = 0;    // what upright_frame ranks the sides by, larger is better
};

struct UprightFrame {
  // Unit and orthogonal, in the mesh's coordinates: `up` away from the side it rests on,
  // `front` towards a viewer who sees the object from the front.
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ(), front = Eigen::Vector3d::UnitY();
  // The six principal directions as floors, in the order +x0, -x0, +x1, -x1, +x2, -x2 of the
  // surface's principal axes (largest first, as surface_pose gives them).
  std::array<RestingSide, 6> sides;
  // The file axes tried as up (UprightHint::prefer_file_axes), in order, with the floor below
  // each: scored by its height when the surface stands on it, else 0.
  std::vector<RestingSide> file_sides;
};

// What is known of the file a surface came from.
struct UprightHint {
  // The file's x, y and z axes in the surface's coordinates (columns): the identity for a
  // surface as read, NodePositions::pose.rotation for the posed surface.
  Eigen::Matrix3d file_axes = Eigen::Matrix3d::Identity();
  // The file's own up as a file axis (parse_up_axis), when its format or its catalogue says it
  // (glTF: +y); zero when nothing does.
  Eigen::Vector3d up = Eigen::Vector3d::Zero();
  // Where nothing says: the file's +y, then +z, is up when the surface stands on it as drawn.
  bool prefer_file_axes = false;
};

// "+y", "-Z", "x" (case and spaces ignored, no sign is +) as a unit file axis; anything else
// throws std::invalid_argument saying what is accepted.
Eigen::Vector3d parse_up_axis(const std::string& text);

// The side the surface rests on, among its six principal directions: of the broad bases (a
// support polygon at least 0.4 of the broadest), the one that holds the centroid highest. The
// front is seen along the thinner remaining axis, from its heavier side. Depends on the surface
// only, not on its position, scale or rotation, except where two sides score alike; a surface
// without area gets the defaults. docs/BENCHMARKS.md ("Upright pictures") says how often it
// agrees with the labelled sets' own up.
UprightFrame upright_frame(const Mesh& mesh, const StopRequested& stop = {});

// The same, told what the file says or suggests: a known up is taken as it is, with the front
// seen along the surface's thinnest direction across it; else, with prefer_file_axes, the
// first of the file's +y and +z that the surface stands on (see standing_on in the source);
// else the rule above.
UprightFrame upright_frame(const Mesh& mesh, const UprightHint& hint,
                           const StopRequested& stop = {});

// The rotation whose rows are screen right, screen up and towards the viewer (ViewCamera's
// convention) for looking at `frame`'s front with its up upright.
Eigen::Matrix3d upright_view(const UprightFrame& frame);

}  // namespace arg
