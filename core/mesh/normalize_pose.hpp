// Pose normalisation: centre of mass at the origin, principal axes on x, y, z, unit RMS radius.
#pragma once

#include <Eigen/Core>

#include "common/limits.hpp"
#include "mesh/mesh.hpp"

namespace arg {

struct Pose {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();        // area-weighted centre of mass
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // rows: principal axes, largest first
  Eigen::Vector3d eigenvalues = Eigen::Vector3d::Zero();   // surface covariance, descending
  double scale = 1;  // multiply by this to reach unit RMS distance from the centre
  double area = 0;   // surface area before scaling
};

// Computes the pose of a surface from exact area integrals over its triangles. Axis signs follow
// the third moment (the heavier tail of the surface along each axis points to +), so mirror
// images get the same frame; an axis with a vanishing third moment keeps the solver's sign.
Pose surface_pose(const Mesh& mesh, const StopRequested& stop = {});

// Flips the rows of `axes` so that the surface's third moment about `centre` along each is not
// negative (below -1e-9 area rms^3 counts as negative); the rule surface_pose uses.
void orient_by_third_moment(const Mesh& mesh, const Eigen::Vector3d& centre, double rms,
                            Eigen::Matrix3d& axes, const StopRequested& stop = {});

// Applies a pose: V' = scale * rotation * (V - centre).
Mesh apply_pose(const Mesh& mesh, const Pose& pose);

}  // namespace arg
