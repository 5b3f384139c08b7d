// Barycentres of Reeb graph nodes from the pieces of the sliced surface, level by level.
#include "pipeline/node_positions.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>

#include "common/errors.hpp"
#include "mesh/mesh_edges.hpp"
#include "mesh/nearest_points.hpp"
#include "mu/mu_function.hpp"
#include "pipeline/prepare_surface.hpp"
#include "reeb/reeb_levels.hpp"
#include "reeb/slice_intervals.hpp"

namespace arg {

namespace {

// Another surface in place of the one the graph was built on: its mu per vertex and, per
// triangle, its first interval and its pieces' nodes (as SlicedSurface numbers them).
void show_surface(NodePositions& out, Mesh mesh, std::vector<double> mu,
                  std::vector<int> first_interval, std::vector<int> piece_begin,
                  std::vector<int> piece_node) {
  out.mesh = std::move(mesh);
  out.mu = std::move(mu);
  out.face_first_interval = std::move(first_interval);
  out.face_piece_begin = std::move(piece_begin);
  out.piece_node = std::move(piece_node);
}

// The fine surface in place of its collapsed copy (PreparedSurface::coarse): each fine vertex
// takes the mu of the copy's vertex it was collapsed into, and each fine triangle the pieces of
// the copy's triangle with the same corners after the collapse; a triangle the collapse removed
// takes those of a copy's triangle around its corners' images whose intervals hold its centre's
// mu. node_at then answers for the fine surface what it answers for the copy, and a picture
// shows the surface as read, with its texture coordinates on the triangles they were given on.
void show_fine_surface(NodePositions& out, Mesh fine, const std::vector<int>& coarse_vertex,
                       int intervals, const StopRequested& stop) {
  const Mesh& coarse = out.mesh;
  const auto corner_count = std::size_t(coarse.V.rows());
  std::map<std::array<int, 3>, int> face_of_corners;
  std::vector<int> around_begin(corner_count + 1, 0), around;
  for (Eigen::Index g = 0; g < coarse.F.rows(); ++g)
    for (int k = 0; k < 3; ++k) ++around_begin[std::size_t(coarse.F(g, k)) + 1];
  for (std::size_t v = 0; v < corner_count; ++v) around_begin[v + 1] += around_begin[v];
  around.resize(std::size_t(around_begin.back()));
  std::vector<int> fill(around_begin.begin(), around_begin.end() - 1);
  for (Eigen::Index g = 0; g < coarse.F.rows(); ++g) {
    poll_interrupt(std::size_t(g), stop);
    std::array<int, 3> corners = {coarse.F(g, 0), coarse.F(g, 1), coarse.F(g, 2)};
    for (int c : corners) around[std::size_t(fill[std::size_t(c)]++)] = int(g);
    std::sort(corners.begin(), corners.end());
    face_of_corners.emplace(corners, int(g));
  }
  std::vector<double> mu(std::size_t(fine.V.rows()), 0.0);
  for (Eigen::Index v = 0; v < fine.V.rows(); ++v) {
    const int to = coarse_vertex[std::size_t(v)];
    if (to >= 0) mu[std::size_t(v)] = out.mu[std::size_t(to)];
  }
  // A copy's triangle around `corner` whose pieces cover `interval` (-1 when none does).
  auto holding = [&](int corner, int interval) {
    const int b = around_begin[std::size_t(corner)], e = around_begin[std::size_t(corner) + 1];
    for (int i = b; i < e; ++i) {
      const auto g = std::size_t(around[std::size_t(i)]);
      const int first = out.face_first_interval[g];
      if (interval >= first &&
          interval < first + out.face_piece_begin[g + 1] - out.face_piece_begin[g])
        return int(g);
    }
    return -1;
  };
  std::vector<int> first_interval, piece_begin(1, 0), piece_node;
  first_interval.reserve(std::size_t(fine.F.rows()));
  piece_begin.reserve(std::size_t(fine.F.rows()) + 1);
  for (Eigen::Index f = 0; f < fine.F.rows(); ++f) {
    poll_interrupt(std::size_t(f), stop);
    std::array<int, 3> corners;
    double centre = 0;
    for (int k = 0; k < 3; ++k) {
      corners[std::size_t(k)] = coarse_vertex[std::size_t(fine.F(f, k))];
      centre += mu[std::size_t(fine.F(f, k))] / 3;
    }
    std::sort(corners.begin(), corners.end());
    const auto found = face_of_corners.find(corners);
    int g = found != face_of_corners.end() ? found->second : -1;
    for (int k = 0; g < 0 && k < 3; ++k)
      if (corners[std::size_t(k)] >= 0)
        g = holding(corners[std::size_t(k)], interval_of(centre, intervals));
    for (int k = 0; g < 0 && k < 3; ++k) {
      const int c = corners[std::size_t(k)];
      if (c >= 0 && around_begin[std::size_t(c)] < around_begin[std::size_t(c) + 1])
        g = around[std::size_t(around_begin[std::size_t(c)])];
    }
    if (g >= 0) {
      first_interval.push_back(out.face_first_interval[std::size_t(g)]);
      for (int p = out.face_piece_begin[std::size_t(g)];
           p < out.face_piece_begin[std::size_t(g) + 1]; ++p)
        piece_node.push_back(out.piece_node[std::size_t(p)]);
    } else {
      first_interval.push_back(0);
    }
    piece_begin.push_back(int(piece_node.size()));
  }
  show_surface(out, std::move(fine), std::move(mu), std::move(first_interval),
               std::move(piece_begin), std::move(piece_node));
}

// The model's own surface in place of its proxy (ShownSurface::Own): each vertex takes the mu
// of the proxy's nearest vertex, each triangle the pieces of the proxy triangle whose centre is
// nearest its own centre.
void show_own_surface(NodePositions& out, Mesh own, const StopRequested& stop) {
  const Mesh& proxy = out.mesh;
  const auto centre = [](const Mesh& m, Eigen::Index f) -> Eigen::Vector3d {
    return ((m.V.row(m.F(f, 0)) + m.V.row(m.F(f, 1)) + m.V.row(m.F(f, 2))) / 3).transpose();
  };
  Vertices centres(proxy.F.rows(), 3);
  for (Eigen::Index f = 0; f < proxy.F.rows(); ++f) centres.row(f) = centre(proxy, f).transpose();
  const NearestPoints vertex_index(proxy.V), face_index(centres);
  // clean_mesh refuses non-finite coordinates, so every query finds a point; -1 would mean a
  // broken invariant, not bad input.
  const auto nearest = [](const NearestPoints& index, const Eigen::Vector3d& q) {
    const int i = index.nearest(q);
    if (i < 0) throw std::logic_error("own surface: a point with no nearest proxy point");
    return std::size_t(i);
  };
  std::vector<double> mu(std::size_t(own.V.rows()));
  for (Eigen::Index v = 0; v < own.V.rows(); ++v) {
    poll_interrupt(std::size_t(v), stop);
    mu[std::size_t(v)] = out.mu[nearest(vertex_index, own.V.row(v).transpose())];
  }
  std::vector<int> first, begin{0}, node;
  first.reserve(std::size_t(own.F.rows()));
  begin.reserve(std::size_t(own.F.rows()) + 1);
  for (Eigen::Index f = 0; f < own.F.rows(); ++f) {
    poll_interrupt(std::size_t(f), stop);
    const std::size_t from = nearest(face_index, centre(own, f));
    first.push_back(out.face_first_interval[from]);
    for (int k = out.face_piece_begin[from]; k < out.face_piece_begin[from + 1]; ++k)
      node.push_back(out.piece_node[std::size_t(k)]);
    begin.push_back(int(node.size()));
  }
  show_surface(out, std::move(own), std::move(mu), std::move(first), std::move(begin),
               std::move(node));
}

}  // namespace

NodePositions node_positions(const Mesh& input, const BuildOptions& options,
                             const StopRequested& stop, ShownSurface shown) {
  if (options.levels < kMinLevels || options.levels > kMaxLevels)
    throw InputError("build options: levels must be in [" + std::to_string(kMinLevels) + ", " +
                     std::to_string(kMaxLevels) + "]");
  NodePositions out;
  PreparedSurface prepared = prepare_surface(input, options, stop);
  out.on_proxy = prepared.proxy.has_value();
  out.mesh = prepared.proxy    ? std::move(*prepared.proxy)
             : prepared.coarse ? std::move(*prepared.coarse)
                               : std::move(prepared.posed);
  out.pose = prepared.pose;
  // The edges prepare_surface found for the copy or the posed mesh; a proxy's are new.
  const MeshEdges edges = prepared.proxy    ? mesh_edges(out.mesh.F)
                          : prepared.coarse ? prepared.coarse_edges
                                            : prepared.posed_edges;
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
  if (prepared.coarse)
    show_fine_surface(out, std::move(prepared.posed), prepared.coarse_vertex, 1 << options.levels,
                      stop);
  else if (out.on_proxy && shown == ShownSurface::Own)
    show_own_surface(out, std::move(prepared.posed), stop);
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
