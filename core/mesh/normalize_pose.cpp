// Area-weighted centring, PCA alignment (Eigen) and RMS-radius scaling of a surface.
#include "mesh/normalize_pose.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace arg {

void orient_by_third_moment(const Mesh& mesh, const Eigen::Vector3d& centre, double rms,
                            Eigen::Matrix3d& axes, const StopRequested& stop) {
  const auto& V = mesh.V;
  const auto& F = mesh.F;
  // Third moments along each axis, from the triangle centroids (exact enough for a sign).
  Eigen::Vector3d third = Eigen::Vector3d::Zero();
  double area = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    poll_interrupt(std::size_t(f), stop);
    Eigen::Vector3d a = V.row(F(f, 0)).transpose(), b = V.row(F(f, 1)).transpose(),
                    c = V.row(F(f, 2)).transpose();
    double A = 0.5 * (b - a).cross(c - a).norm();
    Eigen::Vector3d p = axes * ((a + b + c) / 3.0 - centre);
    third += A * p.cwiseProduct(p).cwiseProduct(p);
    area += A;
  }
  for (int k = 0; k < 3; ++k)
    if (third[k] < -1e-9 * area * rms * rms * rms) axes.row(k) *= -1.0;
}

Pose surface_pose(const Mesh& mesh, const StopRequested& stop) {
  const auto& V = mesh.V;
  const auto& F = mesh.F;
  Pose pose;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  double area = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    poll_interrupt(std::size_t(f), stop);
    Eigen::Vector3d a = V.row(F(f, 0)).transpose(), b = V.row(F(f, 1)).transpose(),
                    c = V.row(F(f, 2)).transpose();
    double A = 0.5 * (b - a).cross(c - a).norm();
    Eigen::Vector3d s = a + b + c;
    area += A;
    first += A * s / 3.0;
    // Exact integral of x x^T over a triangle: A/12 (sum v v^T + s s^T).
    second +=
        A / 12.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  pose.area = area;
  if (area <= 0) return pose;
  pose.centre = first / area;
  Eigen::Matrix3d cov = second / area - pose.centre * pose.centre.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov);
  // Eigen sorts ascending; we want the largest spread on x.
  Eigen::Matrix3d axes;
  for (int k = 0; k < 3; ++k) {
    axes.row(k) = solver.eigenvectors().col(2 - k).transpose();
    pose.eigenvalues[k] = std::max(0.0, solver.eigenvalues()[2 - k]);
  }
  const double rms = std::sqrt(std::max(cov.trace(), 0.0));
  orient_by_third_moment(mesh, pose.centre, rms, axes, stop);
  pose.rotation = axes;
  pose.scale = rms > 0 ? 1.0 / rms : 1.0;
  return pose;
}

Mesh apply_pose(const Mesh& mesh, const Pose& pose) {
  Mesh out = mesh;
  for (Eigen::Index i = 0; i < out.V.rows(); ++i) {
    Eigen::Vector3d p = mesh.V.row(i).transpose() - pose.centre;
    out.V.row(i) = (pose.scale * (pose.rotation * p)).transpose();
  }
  // A mirroring frame turns every face inside out; turn them back so normals stay outward.
  if (pose.rotation.determinant() < 0) out.F.col(1).swap(out.F.col(2));
  return out;
}

}  // namespace arg
