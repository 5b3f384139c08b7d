// The radius of a posed surface along each principal axis, and its symmetry about that axis.
#include "features/vessel_profile.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include "features/shape_distributions.hpp"

namespace arg {

namespace {

constexpr std::uint64_t kProfileSeed = 0x5E55E1ull;

VesselProfile profile_of_points(const std::vector<Eigen::Vector3d>& points, int axis,
                                const ProfileOptions& o) {
  const int bins = std::max(1, o.bins);
  VesselProfile p;
  p.axis = axis;
  p.area.assign(std::size_t(bins), 0.0);
  p.radius.assign(std::size_t(bins), 0.0);
  p.spread.assign(std::size_t(bins), 0.0);
  if (points.empty()) return p;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  // The bins span the surface's height between its `tail` quantiles, so that a thin lip or a
  // stray fragment does not squeeze the body into a few bins; beyond them go to the end bins.
  std::vector<double> heights;
  heights.reserve(points.size());
  for (const Eigen::Vector3d& q : points) heights.push_back(q[axis]);
  const std::size_t cut = std::size_t(std::clamp(o.tail, 0.0, 0.49) * double(heights.size()));
  std::nth_element(heights.begin(), heights.begin() + long(cut), heights.end());
  const double lo = heights[cut];
  std::nth_element(heights.begin(), heights.end() - 1 - long(cut), heights.end());
  const double hi = heights[heights.size() - 1 - cut];
  p.low = lo;
  p.high = hi;
  const double span = hi > lo ? hi - lo : 1.0;
  // Per bin and harmonic k = 1..H: sums of r e^{ik theta} and of e^{ik theta}, so that the
  // harmonics of r - mean(r) about the axis come out in one pass.
  using Complex = std::complex<double>;
  const std::size_t harmonics = std::size_t(std::max(1, o.harmonics));
  std::vector<Complex> wave_r(std::size_t(bins) * harmonics), wave(wave_r.size());
  std::vector<double> r2(std::size_t(bins), 0.0);
  for (const Eigen::Vector3d& q : points) {
    const double h = q[axis], r = std::hypot(q[u], q[v]);
    const std::size_t b =
        std::size_t(std::clamp(int(std::floor((h - lo) / span * bins)), 0, bins - 1));
    p.area[b] += 1;
    p.radius[b] += r;
    r2[b] += r * r;
    if (!(r > 0)) continue;  // a point on the axis faces no direction
    const Complex turn(q[u] / r, q[v] / r);
    Complex power = turn;
    for (std::size_t k = 0; k < harmonics; ++k, power *= turn) {
      wave_r[b * harmonics + k] += r * power;
      wave[b * harmonics + k] += power;
    }
  }
  const double total = double(points.size());
  double asymmetry = 0;
  for (std::size_t b = 0; b < std::size_t(bins); ++b) {
    const double n = p.area[b];
    if (n == 0) continue;
    const double mean = p.radius[b] / n;
    p.radius[b] = mean;
    p.spread[b] = std::sqrt(std::max(0.0, r2[b] / n - mean * mean));
    p.area[b] = n / total;
    // The RMS of the radius's first H harmonics about the axis, relative to the mean: r =
    // mean (1 + e cos k theta) gives e / sqrt 2. Zero when every direction reaches as far,
    // whatever walls inside do (they differ in radius, not by direction).
    double power = 0;
    for (std::size_t k = 0; k < harmonics; ++k)
      power += std::norm(wave_r[b * harmonics + k] - mean * wave[b * harmonics + k]);
    const double relative = mean > 0 ? std::sqrt(2 * power) / (n * mean) : 1.0;
    asymmetry += p.area[b] * std::min(1.0, relative);
  }
  p.symmetry = std::clamp(1.0 - asymmetry, 0.0, 1.0);
  return p;
}

}  // namespace

VesselProfile profile_about_axis(const Mesh& posed, int axis, const ProfileOptions& options) {
  return profile_of_points(surface_samples(posed, options.samples, kProfileSeed),
                           std::clamp(axis, 0, 2), options);
}

VesselProfile vessel_profile(const Mesh& posed, const ProfileOptions& options) {
  const std::vector<Eigen::Vector3d> points = surface_samples(posed, options.samples, kProfileSeed);
  VesselProfile best = profile_of_points(points, 0, options);
  for (int axis = 1; axis < 3; ++axis) {
    VesselProfile p = profile_of_points(points, axis, options);
    if (p.symmetry > best.symmetry) best = std::move(p);
  }
  return best;
}

std::vector<float> profile_vector(const VesselProfile& p) {
  std::vector<float> out{float(p.symmetry), float(p.high - p.low)};
  for (double x : p.area) out.push_back(float(x));
  // The radii relative to their area-weighted mean: the profile's shape, not its girth, which
  // the height (in units of the posed surface's RMS radius) already tells.
  double mean = 0;
  for (std::size_t b = 0; b < p.area.size(); ++b) mean += p.area[b] * p.radius[b];
  const double unit = mean > 0 ? 1 / mean : 0;
  for (const auto* part : {&p.radius, &p.spread})
    for (double x : *part) out.push_back(float(x * unit));
  return out;
}

double profile_distance(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size() || a.size() < 2 || (a.size() - 2) % 3 != 0) {
    double s = 0;
    for (float x : a) s += std::fabs(x);
    for (float x : b) s += std::fabs(x);
    return s;
  }
  const std::size_t bins = (a.size() - 2) / 3;
  double same = 0, flipped = 0;
  for (std::size_t part = 0; part < 3; ++part) {
    const std::size_t at = 2 + part * bins;
    for (std::size_t k = 0; k < bins; ++k) {
      same += std::fabs(double(a[at + k]) - b[at + k]);
      flipped += std::fabs(double(a[at + k]) - b[at + bins - 1 - k]);
    }
  }
  return std::fabs(double(a[1]) - b[1]) + std::min(same, flipped);
}

}  // namespace arg
