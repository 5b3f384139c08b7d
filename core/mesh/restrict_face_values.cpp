// Area-weighted averages of a fine mesh's triangle values on its collapsed copy's triangles.
#include "mesh/restrict_face_values.hpp"

#include <Eigen/Geometry>

namespace arg {

std::vector<double> restrict_face_values(const Mesh& fine, const Mesh& coarse,
                                         const std::vector<int>& vertex_map,
                                         const std::vector<double>& fine_values,
                                         const StopRequested& stop) {
  const auto coarse_vertices = std::size_t(coarse.V.rows());
  std::vector<double> sum(coarse_vertices, 0.0), weight(coarse_vertices, 0.0);
  for (Eigen::Index f = 0; f < fine.F.rows(); ++f) {
    poll_interrupt(std::size_t(f), stop);
    const Eigen::Vector3d a = fine.V.row(fine.F(f, 0)), b = fine.V.row(fine.F(f, 1)),
                          c = fine.V.row(fine.F(f, 2));
    const double area = 0.5 * (b - a).cross(c - a).norm();
    const double value = fine_values[std::size_t(f)];
    for (int k = 0; k < 3; ++k) {
      const int to = vertex_map[std::size_t(fine.F(f, k))];
      if (to < 0) continue;
      sum[std::size_t(to)] += area * value;
      weight[std::size_t(to)] += area;
    }
  }
  for (std::size_t v = 0; v < coarse_vertices; ++v)
    if (weight[v] > 0) sum[v] /= weight[v];
  std::vector<double> out(std::size_t(coarse.F.rows()));
  for (Eigen::Index f = 0; f < coarse.F.rows(); ++f) {
    poll_interrupt(std::size_t(f), stop);
    out[std::size_t(f)] = (sum[std::size_t(coarse.F(f, 0))] + sum[std::size_t(coarse.F(f, 1))] +
                           sum[std::size_t(coarse.F(f, 2))]) /
                          3;
  }
  return out;
}

}  // namespace arg
