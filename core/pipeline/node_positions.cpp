// Barycentres of Reeb graph nodes from the pieces of the sliced surface, level by level.
#include "pipeline/node_positions.hpp"

#include <algorithm>

#include "common/errors.hpp"
#include "mesh/mesh_edges.hpp"
#include "mu/mu_function.hpp"
#include "pipeline/prepare_surface.hpp"
#include "reeb/reeb_levels.hpp"
#include "reeb/slice_intervals.hpp"

namespace arg {

NodePositions node_positions(const Mesh& input, const BuildOptions& options,
                             const StopRequested& stop) {
  if (options.levels < kMinLevels || options.levels > kMaxLevels)
    throw InputError("build options: levels must be in [" + std::to_string(kMinLevels) + ", " +
                     std::to_string(kMaxLevels) + "]");
  NodePositions out;
  PreparedSurface prepared = prepare_surface(input, options, stop);
  out.mesh = prepared.proxy    ? std::move(*prepared.proxy)
             : prepared.coarse ? std::move(*prepared.coarse)
                               : std::move(prepared.posed);
  out.pose = prepared.pose;
  const MeshEdges edges = mesh_edges(out.mesh.F);
  out.mu = normalised_mu(out.mesh, edges, options, stop);
  const SlicedSurface sliced = slice_intervals(out.mesh, out.mu, 1 << options.levels, stop);
  const ReebGraph reeb = reeb_levels(sliced, edges, options.levels, stop);

  // Sums of area and area moment, finest level first, then each level into its parents: the
  // same order of additions as the ARG's own barycentres.
  const std::size_t level_count = reeb.levels.size();
  std::vector<std::vector<double>> area(level_count);
  std::vector<std::vector<Eigen::Vector3d>> moment(level_count);
  for (std::size_t r = 0; r < level_count; ++r) {
    area[r].assign(reeb.levels[r].interval.size(), 0.0);
    moment[r].assign(reeb.levels[r].interval.size(), Eigen::Vector3d::Zero());
  }
  for (std::size_t p = 0; p < sliced.pieces.size(); ++p) {
    const Piece& piece = sliced.pieces[p];
    const auto n = std::size_t(reeb.piece_node[p]);
    area.back()[n] += piece.area;
    moment.back()[n] += piece.area * piece.centroid;
  }
  for (std::size_t r = level_count - 1; r > 0; --r)
    for (std::size_t i = 0; i < reeb.levels[r].parent.size(); ++i) {
      const auto parent = std::size_t(reeb.levels[r].parent[i]);
      area[r - 1][parent] += area[r][i];
      moment[r - 1][parent] += moment[r][i];
    }

  out.levels.resize(level_count);
  for (std::size_t r = 0; r < level_count; ++r) {
    NodePlacementLevel& level = out.levels[r];
    double total = 0;
    for (double a : area[r]) total += a;
    for (std::size_t i = 0; i < area[r].size(); ++i) {
      level.centre.push_back(area[r][i] > 0 ? Eigen::Vector3d(moment[r][i] / area[r][i])
                                            : Eigen::Vector3d::Zero());
      level.area.push_back(total > 0 ? area[r][i] / total : 0.0);
    }
    level.interval = reeb.levels[r].interval;
    level.edges = reeb.levels[r].edges;
    level.parent = reeb.levels[r].parent;
  }
  out.face_first_interval = sliced.first_interval;
  out.face_piece_begin = sliced.piece_begin;
  out.piece_node = reeb.piece_node;
  return out;
}

int node_at(const NodePositions& positions, int level, int face, double mu) {
  if (level < 0 || level >= int(positions.levels.size()) || face < 0 ||
      std::size_t(face) + 1 >= positions.face_piece_begin.size())
    return -1;
  const int intervals = 1 << (int(positions.levels.size()) - 1);
  const int begin = positions.face_piece_begin[std::size_t(face)],
            end = positions.face_piece_begin[std::size_t(face) + 1];
  if (end <= begin) return -1;
  const int k =
      std::clamp(interval_of(mu, intervals) - positions.face_first_interval[std::size_t(face)], 0,
                 end - begin - 1);
  int node = positions.piece_node[std::size_t(begin + k)];
  for (int r = int(positions.levels.size()) - 1; r > level; --r)
    node = positions.levels[std::size_t(r)].parent[std::size_t(node)];
  return node;
}

}  // namespace arg
