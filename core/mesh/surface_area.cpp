// Half the cross product's length per triangle, summed, or a third of it to each corner.
#include "mesh/surface_area.hpp"

namespace arg {

double surface_area(const Mesh& m) {
  double a = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    a += 0.5 * (m.V.row(m.F(f, 1)) - m.V.row(m.F(f, 0)))
                   .cross(m.V.row(m.F(f, 2)) - m.V.row(m.F(f, 0)))
                   .norm();
  return a;
}

std::vector<double> vertex_areas(const Mesh& mesh) {
  std::vector<double> area(std::size_t(mesh.V.rows()), 0.0);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    Eigen::RowVector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)),
                       c = mesh.V.row(mesh.F(f, 2));
    double third = 0.5 * (b - a).cross(c - a).norm() / 3.0;
    for (int k = 0; k < 3; ++k) area[std::size_t(mesh.F(f, k))] += third;
  }
  return area;
}

}  // namespace arg
