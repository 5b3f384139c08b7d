// Each vertex's offset from its neighbours' mean along its normal, in edge lengths.
#include "mesh/surface_roughness.hpp"

#include <cmath>

namespace arg {

std::vector<double> normal_offsets(const Mesh& mesh, const MeshEdges& edges,
                                   const StopRequested& stop) {
  const auto n = static_cast<std::size_t>(mesh.V.rows());
  Vertices normal = Vertices::Zero(mesh.V.rows(), 3), mean = Vertices::Zero(mesh.V.rows(), 3);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    poll_interrupt(std::size_t(f), stop);
    const Eigen::RowVector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)),
                             c = mesh.V.row(mesh.F(f, 2));
    const Eigen::RowVector3d twice_area_normal = (b - a).cross(c - a);
    for (int k = 0; k < 3; ++k) normal.row(mesh.F(f, k)) += twice_area_normal;
  }
  std::vector<double> length(n, 0.0), degree(n, 0.0);
  for (int e = 0; e < edges.count(); ++e) {
    poll_interrupt(std::size_t(e), stop);
    const int a = edges.v0[e], b = edges.v1[e];
    const double l = (mesh.V.row(a) - mesh.V.row(b)).norm();
    mean.row(a) += mesh.V.row(b), mean.row(b) += mesh.V.row(a);
    length[std::size_t(a)] += l, length[std::size_t(b)] += l;
    degree[std::size_t(a)] += 1, degree[std::size_t(b)] += 1;
  }
  std::vector<double> out(n, 0.0);
  for (std::size_t v = 0; v < n; ++v) {
    const auto r = static_cast<Eigen::Index>(v);
    const double norm = normal.row(r).norm();
    if (degree[v] == 0 || norm == 0 || length[v] == 0) continue;
    const Eigen::RowVector3d offset = mean.row(r) / degree[v] - mesh.V.row(r);
    out[v] = std::abs(offset.dot(normal.row(r))) / norm / (length[v] / degree[v]);
  }
  return out;
}

}  // namespace arg
