// Choosing and normalising the function mu.
#include <algorithm>
#include <cmath>

#include "mu/mu_function.hpp"

namespace arg {

void normalise_min_max(std::vector<double>& mu) {
  if (mu.empty()) return;
  auto [lo, hi] = std::minmax_element(mu.begin(), mu.end());
  const double min = *lo, range = *hi - *lo;
  for (double& x : mu) x = range > 0 ? std::clamp((x - min) / range, 0.0, 1.0) : 0.0;
}

std::vector<double> normalised_mu(const Mesh& mesh, const MeshEdges& edges,
                                  const BuildOptions& options, const StopRequested& stop) {
  std::vector<double> mu;
  switch (options.mu) {
    case MuKind::Geodesic:
      mu = geodesic_integral(mesh, edges, options.base_points, options.threads, stop);
      break;
    case MuKind::Height:
      mu.resize(std::size_t(mesh.V.rows()));
      for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) mu[v] = mesh.V(v, 0);
      break;
    case MuKind::Centroid:
      mu.resize(std::size_t(mesh.V.rows()));
      for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) mu[v] = mesh.V.row(v).norm();
      break;
  }
  normalise_min_max(mu);
  return mu;
}

}  // namespace arg
