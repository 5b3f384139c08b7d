// NPCA: eigenvectors of the area-weighted covariance of unit face normals.
#include "mesh/normal_pose.hpp"

#include <Eigen/Eigenvalues>

namespace arg {

Pose normal_pose(const Mesh& mesh, const StopRequested& stop) {
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  double area = 0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    poll_interrupt(std::size_t(f), stop);
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)).transpose(),
                          b = mesh.V.row(mesh.F(f, 1)).transpose(),
                          c = mesh.V.row(mesh.F(f, 2)).transpose();
    const Eigen::Vector3d n = (b - a).cross(c - a);
    const double twice = n.norm();
    if (!(twice > 0)) continue;
    // (n / |n|) (n / |n|)^T weighted by the area |n| / 2.
    spread += (0.5 / twice) * (n * n.transpose());
    area += 0.5 * twice;
  }
  Pose pose;
  pose.area = area;
  if (!(area > 0)) return pose;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(spread / area);
  Eigen::Matrix3d axes;
  for (int k = 0; k < 3; ++k) {
    axes.row(k) = solver.eigenvectors().col(2 - k).transpose();
    pose.eigenvalues[k] = std::max(0.0, solver.eigenvalues()[2 - k]);
  }
  orient_by_third_moment(mesh, Eigen::Vector3d::Zero(), 1.0, axes, stop);
  pose.rotation = axes;
  return pose;
}

}  // namespace arg
