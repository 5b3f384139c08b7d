// A z-buffer per axis: the nearest surface from each side, sampled at pixel centres.
#include "features/depth_images.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "features/triangle_pixels.hpp"

namespace arg {

DepthImages depth_images(const Mesh& mesh, int n) {
  DepthImages out;
  out.resolution = n;
  double h = 0;
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    h = std::max(h, mesh.V.row(v).cwiseAbs().maxCoeff());
  const float none = -std::numeric_limits<float>::infinity();
  for (auto& image : out.view) image.assign(std::size_t(n) * std::size_t(n), 0.0f);
  if (!(h > 0) || n <= 0) return out;
  const double pixel = 2.0 * h / n;
  std::vector<float> near(std::size_t(n) * std::size_t(n)), far(near.size());
  for (int a = 0; a < 3; ++a) {
    const int u = (a + 1) % 3, w = (a + 2) % 3;
    std::fill(near.begin(), near.end(), none);
    std::fill(far.begin(), far.end(), none);
    for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
      double px[3], py[3], pz[3];
      for (int c = 0; c < 3; ++c) {
        const auto p = mesh.V.row(mesh.F(f, c));
        px[c] = (p[u] + h) / pixel - 0.5;  // pixel i has its centre at px = i
        py[c] = (p[w] + h) / pixel - 0.5;
        pz[c] = p[a];
      }
      for_each_pixel_centre(
          px, py, 0, n - 1, 0, n - 1, [&](int i, int j, double b0, double b1, double b2) {
            const double z = b0 * pz[0] + b1 * pz[1] + b2 * pz[2];
            const std::size_t k = std::size_t(j) * std::size_t(n) + std::size_t(i);
            near[k] = std::max(near[k], float(z));  // seen from +a
            far[k] = std::max(far[k], float(-z));   // seen from -a
          });
    }
    for (std::size_t k = 0; k < near.size(); ++k) {
      if (near[k] == none) continue;
      out.view[std::size_t(2 * a)][k] = float(std::clamp((near[k] + h) / (2 * h), 0.0, 1.0));
      out.view[std::size_t(2 * a + 1)][k] = float(std::clamp((far[k] + h) / (2 * h), 0.0, 1.0));
    }
  }
  return out;
}

}  // namespace arg
