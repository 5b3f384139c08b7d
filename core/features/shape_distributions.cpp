// D2 and cords histograms of a whole surface and the compact global descriptor built on them.
#include "features/shape_distributions.hpp"

#include <algorithm>
#include <cmath>

#include "common/random.hpp"

namespace arg {

namespace {

std::vector<double> area_cdf(const Mesh& mesh) {
  std::vector<double> cdf(std::size_t(mesh.F.rows()));
  double sum = 0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    Eigen::RowVector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)),
                       c = mesh.V.row(mesh.F(f, 2));
    sum += 0.5 * (b - a).cross(c - a).norm();
    cdf[f] = sum;
  }
  return cdf;
}

Eigen::Vector3d sample_point(const Mesh& mesh, const std::vector<double>& cdf, SeededRandom& rng) {
  double x = rng.unit() * cdf.back();
  std::size_t f = std::size_t(std::upper_bound(cdf.begin(), cdf.end(), x) - cdf.begin());
  f = std::min(f, cdf.size() - 1);
  double r1 = std::sqrt(rng.unit()), r2 = rng.unit();
  Eigen::Vector3d a = mesh.V.row(mesh.F(Eigen::Index(f), 0)).transpose(),
                  b = mesh.V.row(mesh.F(Eigen::Index(f), 1)).transpose(),
                  c = mesh.V.row(mesh.F(Eigen::Index(f), 2)).transpose();
  return (1 - r1) * a + r1 * (1 - r2) * b + r1 * r2 * c;
}

void normalise(std::vector<float>& h) {
  double sum = 0;
  for (float x : h) sum += x;
  if (sum > 0)
    for (float& x : h) x = float(x / sum);
}

}  // namespace

std::vector<Eigen::Vector3d> surface_samples(const Mesh& mesh, int count, std::uint64_t seed) {
  std::vector<Eigen::Vector3d> points;
  if (mesh.F.rows() == 0 || count <= 0) return points;
  const std::vector<double> cdf = area_cdf(mesh);
  if (!(cdf.back() > 0)) return points;
  SeededRandom rng(seed);
  points.reserve(std::size_t(count));
  for (int i = 0; i < count; ++i) points.push_back(sample_point(mesh, cdf, rng));
  return points;
}

std::vector<float> d2_histogram(const Mesh& mesh, int bins, int pairs, double max_distance) {
  std::vector<float> h(std::size_t(bins), 0.0f);
  if (mesh.F.rows() == 0) return h;
  std::vector<double> cdf = area_cdf(mesh);
  if (!(cdf.back() > 0)) return h;
  SeededRandom rng(0x0A5D2D2ull);
  for (int i = 0; i < pairs; ++i) {
    Eigen::Vector3d p = sample_point(mesh, cdf, rng), q = sample_point(mesh, cdf, rng);
    int b = int((p - q).norm() / max_distance * bins);
    h[std::size_t(std::clamp(b, 0, bins - 1))] += 1.0f;
  }
  normalise(h);
  return h;
}

std::vector<float> cords_histogram(const Mesh& mesh, int bins, double max_distance) {
  std::vector<float> h(std::size_t(bins), 0.0f);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)).transpose(),
                    b = mesh.V.row(mesh.F(f, 1)).transpose(),
                    c = mesh.V.row(mesh.F(f, 2)).transpose();
    double area = 0.5 * (b - a).cross(c - a).norm();
    int k = int(((a + b + c) / 3.0).norm() / max_distance * bins);
    h[std::size_t(std::clamp(k, 0, bins - 1))] += float(area);
  }
  normalise(h);
  return h;
}

std::array<float, kGlobalDims> global_descriptor(const Mesh& mesh, const Pose& pose,
                                                 const GraphCounts& counts, double volume,
                                                 const StopRequested& stop) {
  std::array<float, kGlobalDims> g{};
  std::vector<float> d2 = d2_histogram(mesh, 16, 4096);
  check_interrupt(stop);  // each of these is a pass over the faces
  std::vector<float> cords = cords_histogram(mesh, 16);
  check_interrupt(stop);
  std::copy(d2.begin(), d2.end(), g.begin());
  std::copy(cords.begin(), cords.end(), g.begin() + 16);
  float* stats = g.data() + 32;
  const double l1 = pose.eigenvalues[0];
  stats[0] = float(l1 > 0 ? pose.eigenvalues[1] / l1 : 0);
  stats[1] = float(l1 > 0 ? pose.eigenvalues[2] / l1 : 0);
  for (int r = 0; r <= kMaxLevels && r < 8; ++r)  // nodes per interval at each level
    stats[2 + r] = float(std::min(1.0, counts.nodes_per_level[std::size_t(r)] / double(4 << r)));
  stats[10] = float(counts.loops / (counts.loops + 1.0));
  stats[11] = float(1.0 / std::max(1, counts.components));
  // Compactness: 36 pi V^2 / A^3 is 1 for a sphere, smaller for everything else.
  double area = 0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    Eigen::RowVector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)),
                       c = mesh.V.row(mesh.F(f, 2));
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  stats[12] =
      float(area > 0 ? std::min(1.0, 36 * M_PI * volume * volume / (area * area * area)) : 0);
  return g;
}

}  // namespace arg
