// Dihedral-angle mean curvature and angle-defect Gaussian curvature on a triangle mesh.
#include "features/curvature.hpp"

#include <algorithm>
#include <cmath>

namespace arg {

TriangleCurvature triangle_curvature(const Mesh& mesh, const MeshEdges& E,
                                     const StopRequested& stop) {
  const int nv = int(mesh.V.rows()), m = int(mesh.F.rows());
  std::vector<Eigen::Vector3d> normal(static_cast<std::size_t>(m));
  std::vector<double> varea(static_cast<std::size_t>(nv), 0.0),
      angle_sum(static_cast<std::size_t>(nv), 0.0), dihedral(static_cast<std::size_t>(nv), 0.0);
  std::vector<char> on_boundary(std::size_t(nv), 0);
  for (int f = 0; f < m; ++f) {
    poll_interrupt(std::size_t(f), stop);
    Eigen::Vector3d p[3];
    for (int c = 0; c < 3; ++c) p[c] = mesh.V.row(mesh.F(f, c)).transpose();
    Eigen::Vector3d n = (p[1] - p[0]).cross(p[2] - p[0]);
    double twice = n.norm();
    normal[f] = twice > 0 ? Eigen::Vector3d(n / twice) : Eigen::Vector3d::Zero();
    for (int c = 0; c < 3; ++c) {
      varea[mesh.F(f, c)] += twice / 6.0;
      Eigen::Vector3d u = p[(c + 1) % 3] - p[c], w = p[(c + 2) % 3] - p[c];
      double denom = u.norm() * w.norm();
      if (denom > 0) angle_sum[mesh.F(f, c)] += std::acos(std::clamp(u.dot(w) / denom, -1.0, 1.0));
    }
  }
  for (int e = 0; e < E.count(); ++e) {
    poll_interrupt(std::size_t(e), stop);
    if (E.faces(e) != 2) {
      on_boundary[E.v0[e]] = on_boundary[E.v1[e]] = 1;
      continue;
    }
    int f = E.face_of[E.face_begin[e]], g = E.face_of[E.face_begin[e] + 1];
    double beta = std::acos(std::clamp(normal[f].dot(normal[g]), -1.0, 1.0));
    // Convex when g's far corner lies behind f's plane.
    int far = mesh.F(g, (E.corner_of[E.face_begin[e] + 1] + 2) % 3);
    Eigen::Vector3d d = mesh.V.row(far).transpose() - mesh.V.row(E.v0[e]).transpose();
    if (normal[f].dot(d) > 0) beta = -beta;
    double weighted = (mesh.V.row(E.v0[e]) - mesh.V.row(E.v1[e])).norm() * beta;
    dihedral[E.v0[e]] += weighted;
    dihedral[E.v1[e]] += weighted;
  }
  std::vector<double> H(static_cast<std::size_t>(nv)), K(static_cast<std::size_t>(nv));
  for (int v = 0; v < nv; ++v) {
    poll_interrupt(std::size_t(v), stop);
    double A = varea[v];
    H[v] = A > 0 ? dihedral[v] / (4.0 * A) : 0.0;
    K[v] = A > 0 ? ((on_boundary[v] ? M_PI : 2.0 * M_PI) - angle_sum[v]) / A : 0.0;
  }
  TriangleCurvature out;
  out.mean.resize(std::size_t(m));
  out.gaussian.resize(std::size_t(m));
  for (int f = 0; f < m; ++f) {
    poll_interrupt(std::size_t(f), stop);
    out.mean[f] = (H[mesh.F(f, 0)] + H[mesh.F(f, 1)] + H[mesh.F(f, 2)]) / 3.0;
    out.gaussian[f] = (K[mesh.F(f, 0)] + K[mesh.F(f, 1)] + K[mesh.F(f, 2)]) / 3.0;
  }
  return out;
}

}  // namespace arg
