// Area-weighted histograms of the displacement of each vertex by Taubin smoothing.
#include "features/surface_detail.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/mesh_edges.hpp"
#include "mesh/surface_area.hpp"
#include "mesh/taubin_smoothing.hpp"

namespace arg {

std::vector<float> surface_detail(const Mesh& posed, const DetailOptions& options) {
  const int bins = std::max(1, options.bins);
  std::vector<float> out(options.steps.size() * std::size_t(bins), 0.0f);
  const std::vector<double> area = vertex_areas(posed);
  double total = 0;
  for (double a : area) total += a;
  if (!(total > 0)) return out;
  const MeshEdges edges = mesh_edges(posed.F);
  const double width = (options.high - options.low) / bins;
  for (std::size_t s = 0; s < options.steps.size(); ++s) {
    const Mesh smooth = taubin_smoothing(posed, edges, options.steps[s], 0.5, -0.53);
    for (Eigen::Index v = 0; v < posed.V.rows(); ++v) {
      const double moved = (posed.V.row(v) - smooth.V.row(v)).norm();
      const double x = std::log10(std::max(moved, 1e-300));
      const int bin = std::clamp(int(std::floor((x - options.low) / width)), 0, bins - 1);
      out[s * std::size_t(bins) + std::size_t(bin)] += float(area[std::size_t(v)] / total);
    }
  }
  return out;
}

}  // namespace arg
