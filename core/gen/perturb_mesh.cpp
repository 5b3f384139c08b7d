// A seeded random rotation, scale and jitter of a mesh, for invariance and robustness tests.
#include "common/strict_fp.hpp"  // first: it sets how arithmetic is compiled

#include "gen/perturb_mesh.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "common/vec3.hpp"
#include "gen/seeded_random.hpp"

namespace arg {
namespace {

Vec3 row(const Mesh& m, Eigen::Index v) {
  return {m.V(v, 0), m.V(v, 1), m.V(v, 2)};
}

// A point uniform in the unit ball of dimension 3, by rejection from the cube (no
// transcendental functions, so no libm differences).
Vec3 in_unit_ball(gen::SeededRandom& rng) {
  for (;;) {
    const Vec3 p{rng.signed_unit(), rng.signed_unit(), rng.signed_unit()};
    if (dot(p, p) <= 1.0) return p;
  }
}

}  // namespace

Mesh perturb_mesh(const Mesh& mesh, std::uint64_t seed, double noise) {
  if (!(noise >= 0) || !std::isfinite(noise))
    throw InputError("perturb_mesh: noise must be a finite number >= 0");
  gen::SeededRandom rng(gen::mix_seed("perturb_mesh", seed));

  // A uniform rotation is a uniform unit quaternion: normalise a point drawn uniformly in the
  // 4-ball (rejecting ones too near the centre to normalise accurately).
  double q[4];
  for (;;) {
    double n2 = 0;
    for (double& c : q) {
      c = rng.signed_unit();
      n2 += c * c;
    }
    if (n2 <= 1.0 && n2 > 1e-4) {
      const double inv = 1.0 / std::sqrt(n2);
      for (double& c : q) c *= inv;
      break;
    }
  }
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                          {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                          {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  const double scale = rng.uniform(0.5, 2.0);

  Vec3 lo{0, 0, 0}, hi{0, 0, 0};
  if (mesh.V.rows() > 0) lo = hi = row(mesh, 0);
  for (Eigen::Index v = 1; v < mesh.V.rows(); ++v) {
    const Vec3 p = row(mesh, v);
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const Vec3 centre = (lo + hi) * 0.5;

  double edge_sum = 0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int c = 0; c < 3; ++c)
      edge_sum += length(row(mesh, mesh.F(f, c)) - row(mesh, mesh.F(f, (c + 1) % 3)));
  const double mean_edge = mesh.F.rows() > 0 ? edge_sum / (3.0 * mesh.F.rows()) : 0.0;
  const double jitter = noise * mean_edge * scale;

  Mesh out = mesh;
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
    const Vec3 p = row(mesh, v) - centre;
    Vec3 t{(r[0][0] * p.x + r[0][1] * p.y + r[0][2] * p.z) * scale,
           (r[1][0] * p.x + r[1][1] * p.y + r[1][2] * p.z) * scale,
           (r[2][0] * p.x + r[2][1] * p.y + r[2][2] * p.z) * scale};
    if (jitter > 0) t = t + in_unit_ball(rng) * jitter;
    t = t + centre;
    out.V(v, 0) = t.x;
    out.V(v, 1) = t.y;
    out.V(v, 2) = t.z;
  }
  return out;
}

}  // namespace arg
