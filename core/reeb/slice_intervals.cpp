// Clipping each triangle against the mu slabs it spans (Sutherland-Hodgman on a linear field).
#include "reeb/slice_intervals.hpp"

#include <algorithm>
#include <cmath>

namespace arg {

namespace {

struct Corner {
  Eigen::Vector3d p;
  double mu;
  int plane;  // 0: an original corner, 1: on the lower cut, 2: on the upper cut
};

// Keeps the part of `poly` with sign * (mu - level) >= 0; new corners are tagged `plane`.
void clip(std::vector<Corner>& poly, std::vector<Corner>& out, double level, double sign,
          int plane) {
  out.clear();
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Corner& a = poly[i];
    const Corner& b = poly[(i + 1) % n];
    const bool a_in = sign * (a.mu - level) >= 0, b_in = sign * (b.mu - level) >= 0;
    if (a_in != b_in) {
      double t = (level - a.mu) / (b.mu - a.mu);
      out.push_back({a.p + t * (b.p - a.p), level, plane});
    }
    if (b_in) out.push_back(b);
  }
  poly.swap(out);
}

void measure(Piece& piece, const std::vector<Corner>& poly) {
  const std::size_t n = poly.size();
  Eigen::Vector3d area_vector = Eigen::Vector3d::Zero(), weighted = Eigen::Vector3d::Zero();
  double mu_lo = poly[0].mu, mu_hi = poly[0].mu;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    Eigen::Vector3d cross = (poly[i].p - poly[0].p).cross(poly[i + 1].p - poly[0].p);
    area_vector += cross;
    weighted += cross.norm() * (poly[0].p + poly[i].p + poly[i + 1].p) / 3.0;
    piece.volume6 += poly[0].p.dot(poly[i].p.cross(poly[i + 1].p));
  }
  double twice_area = 0;
  for (std::size_t i = 1; i + 1 < n; ++i)
    twice_area += (poly[i].p - poly[0].p).cross(poly[i + 1].p - poly[0].p).norm();
  piece.area = 0.5 * twice_area;
  piece.centroid = twice_area > 0 ? Eigen::Vector3d(weighted / twice_area) : poly[0].p;
  for (std::size_t i = 0; i < n; ++i) {
    const Corner& a = poly[i];
    const Corner& b = poly[(i + 1) % n];
    mu_lo = std::min(mu_lo, a.mu), mu_hi = std::max(mu_hi, a.mu);
    if (a.plane == 2 && b.plane == 2) {
      piece.cap_cross += b.p.cross(a.p);
      double len = (b.p - a.p).norm();
      piece.cap_moment += len * 0.5 * (a.p + b.p);
      piece.cap_length += len;
    }
  }
  piece.mu_min = mu_lo, piece.mu_max = mu_hi;
}

}  // namespace

SlicedSurface slice_intervals(const Mesh& mesh, const std::vector<double>& mu_in, int intervals,
                              const StopRequested& stop) {
  SlicedSurface s;
  s.intervals = intervals;
  s.mu = mu_in;
  for (double& x : s.mu) {
    double scaled = x * intervals;
    if (scaled > 0 && scaled < intervals && scaled == std::floor(scaled))
      x = std::nextafter(x, 2.0);
  }
  const Eigen::Index m = mesh.F.rows();
  s.first_interval.resize(std::size_t(m));
  s.piece_begin.assign(std::size_t(m) + 1, 0);
  for (Eigen::Index f = 0; f < m; ++f) {
    double lo = std::min({s.mu[mesh.F(f, 0)], s.mu[mesh.F(f, 1)], s.mu[mesh.F(f, 2)]});
    double hi = std::max({s.mu[mesh.F(f, 0)], s.mu[mesh.F(f, 1)], s.mu[mesh.F(f, 2)]});
    s.first_interval[f] = interval_of(lo, intervals);
    s.piece_begin[f + 1] = s.piece_begin[f] + interval_of(hi, intervals) - s.first_interval[f] + 1;
  }
  // Appended in order below, each piece once: none is zeroed first and then written again.
  s.pieces.reserve(std::size_t(s.piece_begin[m]));
  std::vector<Corner> triangle(3), poly, scratch;
  for (Eigen::Index f = 0; f < m; ++f) {
    if ((f & 4095) == 0) check_interrupt(stop);
    for (int c = 0; c < 3; ++c)
      triangle[c] = {mesh.V.row(mesh.F(f, c)).transpose(), s.mu[mesh.F(f, c)], 0};
    const int k0 = s.first_interval[f];
    const int k1 = k0 + s.piece_begin[f + 1] - s.piece_begin[f] - 1;
    for (int k = k0; k <= k1; ++k) {
      poly = triangle;
      if (k > k0) clip(poly, scratch, double(k) / intervals, +1.0, 1);
      if (k < k1) clip(poly, scratch, double(k + 1) / intervals, -1.0, 2);
      Piece& piece = s.pieces.emplace_back();  // at piece_begin[f] + k - k0
      piece.triangle = int(f);
      piece.interval = k;
      if (poly.size() >= 3) measure(piece, poly);
    }
  }
  return s;
}

}  // namespace arg
