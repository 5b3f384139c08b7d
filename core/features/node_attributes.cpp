// Accumulating piece measures into finest nodes, summing up the levels, and normalising.
#include "features/node_attributes.hpp"

#include <algorithm>
#include <cmath>

#include "features/histogram_bins.hpp"

namespace arg {

namespace {

struct Accumulator {
  double area = 0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // area-weighted centroid sum
  double volume = 0;
  double mu_min = 1, mu_max = 0;
  std::array<double, kCurvatureBins> curv_mean{}, curv_gauss{};
  std::array<double, 3 * kColourBins> colour{};
  std::array<double, kCordBins> cords{};

  void add_children(const Accumulator& c) {
    area += c.area;
    moment += c.moment;
    volume += c.volume;
    mu_min = std::min(mu_min, c.mu_min), mu_max = std::max(mu_max, c.mu_max);
    for (int k = 0; k < kCurvatureBins; ++k)
      curv_mean[k] += c.curv_mean[k], curv_gauss[k] += c.curv_gauss[k];
    for (int k = 0; k < 3 * kColourBins; ++k) colour[k] += c.colour[k];
  }
};

// Finest level: pieces into nodes, then close each node with its caps to get its volume.
std::vector<Accumulator> finest_accumulators(const Mesh& mesh, const SlicedSurface& s,
                                             const ReebGraph& reeb, const TriangleCurvature& curv,
                                             const StopRequested& stop) {
  const std::size_t nodes = reeb.levels.back().interval.size();
  std::vector<Accumulator> acc(nodes);
  // One cap per contact between a node and a node of the next interval: the cut segments of
  // the triangles that have pieces in both.
  struct Cut {
    int lower, upper;
    std::size_t piece;
  };
  std::vector<Cut> cuts;
  const bool colour = mesh.has_colour();
  for (std::size_t p = 0; p < s.pieces.size(); ++p) {
    poll_interrupt(p, stop);
    const Piece& piece = s.pieces[p];
    const int n = reeb.piece_node[p];
    Accumulator& a = acc[std::size_t(n)];
    a.area += piece.area;
    a.moment += piece.area * piece.centroid;
    a.volume += piece.volume6 / 6.0;
    a.mu_min = std::min(a.mu_min, piece.mu_min), a.mu_max = std::max(a.mu_max, piece.mu_max);
    a.curv_mean[curvature_bin(curv.mean[piece.triangle])] += piece.area;
    a.curv_gauss[gaussian_bin(curv.gaussian[piece.triangle])] += piece.area;
    if (colour)
      for (int c = 0; c < 3; ++c)
        a.colour[c * kColourBins + colour_bin(mesh.C(piece.triangle, c))] += piece.area;
    if (piece.cap_length > 0 && p + 1 < s.pieces.size() &&
        s.pieces[p + 1].triangle == piece.triangle)
      cuts.push_back({n, reeb.piece_node[p + 1], p});
  }
  std::sort(cuts.begin(), cuts.end(), [](const Cut& x, const Cut& y) {
    return x.lower != y.lower ? x.lower < y.lower
                              : (x.upper != y.upper ? x.upper < y.upper : x.piece < y.piece);
  });
  // Each cap is a fan from the length-weighted centre of the contact's cut segments; its cone
  // from the origin adds c . sum(q1 x q0) / 6 to the lower node and takes it from the upper
  // one, so the volumes of neighbours add up exactly (paper figure 7).
  for (std::size_t i = 0; i < cuts.size();) {
    std::size_t j = i;
    Eigen::Vector3d cross = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
    double length = 0;
    for (; j < cuts.size() && cuts[j].lower == cuts[i].lower && cuts[j].upper == cuts[i].upper;
         ++j) {
      const Piece& piece = s.pieces[cuts[j].piece];
      cross += piece.cap_cross, moment += piece.cap_moment, length += piece.cap_length;
    }
    const double cap = (moment / length).dot(cross) / 6.0;
    acc[std::size_t(cuts[i].lower)].volume += cap;
    acc[std::size_t(cuts[i].upper)].volume -= cap;
    i = j;
  }
  return acc;
}

void spherical(const Eigen::Vector3d& p, float& r, float& theta, float& phi) {
  double radius = p.norm();
  r = float(radius);
  theta = float(p.x() != 0 ? std::atan(p.y() / p.x())
                           : (p.y() > 0   ? M_PI / 2
                              : p.y() < 0 ? -M_PI / 2
                                          : 0.0));
  phi = float(radius > 0 ? std::acos(std::clamp(p.z() / radius, -1.0, 1.0)) : M_PI / 2);
}

float unit(double x) {
  return float(std::clamp(x, 0.0, 1.0));
}

}  // namespace

std::vector<std::vector<ArgNode>> node_attributes(const Mesh& mesh, const SlicedSurface& s,
                                                  const ReebGraph& reeb,
                                                  const TriangleCurvature& curvature,
                                                  double* volume_out, const StopRequested& stop) {
  const int levels = int(reeb.levels.size()) - 1;
  std::vector<std::vector<Accumulator>> acc(reeb.levels.size());
  acc[std::size_t(levels)] = finest_accumulators(mesh, s, reeb, curvature, stop);
  for (int r = levels - 1; r >= 0; --r) {
    acc[std::size_t(r)].resize(reeb.levels[std::size_t(r)].interval.size());
    const ReebLevel& child = reeb.levels[std::size_t(r) + 1];
    for (std::size_t i = 0; i < child.parent.size(); ++i)
      acc[std::size_t(r)][std::size_t(child.parent[i])].add_children(acc[std::size_t(r) + 1][i]);
  }

  // Cords: area-weighted distances of the pieces to the barycentre of their node, per level.
  std::vector<int> node_of(s.pieces.size());
  for (std::size_t p = 0; p < s.pieces.size(); ++p) node_of[p] = reeb.piece_node[p];
  for (int r = levels; r >= 0; --r) {
    if (r < levels)
      for (int& n : node_of) n = reeb.levels[std::size_t(r) + 1].parent[std::size_t(n)];
    for (std::size_t p = 0; p < s.pieces.size(); ++p) {
      poll_interrupt(p, stop);
      Accumulator& a = acc[std::size_t(r)][std::size_t(node_of[p])];
      Eigen::Vector3d centre =
          a.area > 0 ? Eigen::Vector3d(a.moment / a.area) : Eigen::Vector3d::Zero();
      a.cords[cords_bin((s.pieces[p].centroid - centre).norm())] += s.pieces[p].area;
    }
  }

  double total_area = 0, total_volume = 0;
  for (const Accumulator& a : acc[0]) total_area += a.area;
  for (const Piece& piece : s.pieces) total_volume += piece.volume6 / 6.0;
  if (volume_out) *volume_out = std::max(total_volume, 0.0);
  const double per_level = 1.0 / (levels + 1);
  const double area_scale = total_area > 0 ? per_level / total_area : 0.0;
  // Volumes are only meaningful when the surface encloses a clear positive volume.
  const double volume_scale = total_volume > 1e-9 ? per_level / total_volume : 0.0;

  std::vector<std::vector<ArgNode>> out(reeb.levels.size());
  for (int r = 0; r <= levels; ++r) {
    const auto& level_acc = acc[std::size_t(r)];
    double length_sum = 0;
    for (const Accumulator& a : level_acc) length_sum += std::max(a.mu_max - a.mu_min, 0.0);
    auto& nodes = out[std::size_t(r)];
    nodes.resize(level_acc.size());
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const Accumulator& a = level_acc[i];
      ArgNode& n = nodes[i];
      n.level = std::uint16_t(r);
      n.interval = std::uint16_t(reeb.levels[std::size_t(r)].interval[i]);
      n.parent = r == 0 ? -1 : reeb.levels[std::size_t(r)].parent[i];
      n.a = unit(a.area * area_scale);
      n.l =
          unit(length_sum > 0 ? std::max(a.mu_max - a.mu_min, 0.0) / length_sum * per_level : 0.0);
      n.v = unit(a.volume * volume_scale);
      n.mu_min = unit(a.mu_min), n.mu_max = std::max(n.mu_min, unit(a.mu_max));
      spherical(a.area > 0 ? Eigen::Vector3d(a.moment / a.area) : Eigen::Vector3d::Zero(), n.r,
                n.theta, n.phi);
      for (int k = 0; k < kCordBins; ++k) n.cords[k] = unit(a.cords[k] * area_scale);
      for (int k = 0; k < kCurvatureBins; ++k) {
        n.curv_mean[k] = unit(a.curv_mean[k] * area_scale);
        n.curv_gauss[k] = unit(a.curv_gauss[k] * area_scale);
      }
      for (int k = 0; k < 3 * kColourBins; ++k) n.colour[k] = unit(a.colour[k] * area_scale);
    }
  }
  return out;
}

}  // namespace arg
