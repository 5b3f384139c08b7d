// Half the cross product's length per triangle, summed.
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

}  // namespace arg
