// The robustness benchmark's transformations: holes, noise, resampling, cuts and scaling.
#include "eval/perturbations.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>

#include "common/errors.hpp"
#include "common/random.hpp"
#include "eval/quadric_decimation.hpp"
#include "eval/refine_faces.hpp"
#include "gen/seeded_random.hpp"
#include "mesh/coincident_vertices.hpp"
#include "mesh/collapse_short_edges.hpp"

namespace arg {

namespace {

struct Entry {
  Perturbation kind;
  const char* name;
};
constexpr Entry kEntries[] = {
    {Perturbation::SmallHoles, "small_holes"},
    {Perturbation::LargeHoles, "large_holes"},
    {Perturbation::Noise, "noise"},
    {Perturbation::ShotNoise, "shot_noise"},
    {Perturbation::Decimate, "decimate"},
    {Perturbation::Remesh, "remesh"},
    {Perturbation::Split, "split"},
    {Perturbation::Partial, "partial"},
    {Perturbation::Scale, "scale"},
    {Perturbation::LocalScale, "local_scale"},
};

double diagonal(const Mesh& m) {
  return (m.V.colwise().maxCoeff() - m.V.colwise().minCoeff()).norm();
}

std::vector<double> face_areas(const Mesh& m) {
  std::vector<double> a(std::size_t(m.F.rows()));
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    a[std::size_t(f)] = 0.5 * (m.V.row(m.F(f, 1)) - m.V.row(m.F(f, 0)))
                                  .cross(m.V.row(m.F(f, 2)) - m.V.row(m.F(f, 0)))
                                  .norm();
  return a;
}

Eigen::RowVector3d centroid(const Mesh& m, Eigen::Index f) {
  return (m.V.row(m.F(f, 0)) + m.V.row(m.F(f, 1)) + m.V.row(m.F(f, 2))) / 3.0;
}

// A face drawn with probability proportional to its area.
Eigen::Index area_weighted_face(const std::vector<double>& area, SeededRandom& rng) {
  const double total = std::accumulate(area.begin(), area.end(), 0.0);
  double x = rng.unit() * total;
  for (std::size_t f = 0; f < area.size(); ++f) {
    x -= area[f];
    if (x <= 0) return Eigen::Index(f);
  }
  return Eigen::Index(area.size()) - 1;
}

// A point on the surface, area-weighted: the centroid of a face drawn by area.
Eigen::RowVector3d surface_point(const Mesh& m, const std::vector<double>& area,
                                 SeededRandom& rng) {
  return centroid(m, area_weighted_face(area, rng));
}

// A point drawn uniformly on the surface: a face drawn by area, then a point uniformly inside
// it. A hole centred there is as likely on any patch of the surface.
Eigen::RowVector3d uniform_surface_point(const Mesh& m, const std::vector<double>& area,
                                         SeededRandom& rng) {
  const Eigen::Index f = area_weighted_face(area, rng);
  double u = rng.unit(), v = rng.unit();
  if (u + v > 1) u = 1 - u, v = 1 - v;
  return m.V.row(m.F(f, 0)) + u * (m.V.row(m.F(f, 1)) - m.V.row(m.F(f, 0))) +
         v * (m.V.row(m.F(f, 2)) - m.V.row(m.F(f, 0)));
}

// The vertices that are the first at their position (mesh/coincident_vertices.hpp): the
// points of the surface, a soup's repeated corners counted once.
std::vector<int> surface_points(const std::vector<int>& first) {
  std::vector<int> out;
  for (std::size_t v = 0; v < first.size(); ++v)
    if (first[v] == int(v)) out.push_back(int(v));
  return out;
}

// The mesh with the vertices at one position merged into the first of them (the others stay,
// unused, so that vertex numbers and the random draws that follow them do not move).
Mesh joined_at_same_position(const Mesh& m, const std::vector<int>& first) {
  Mesh out = m;
  for (Eigen::Index f = 0; f < out.F.rows(); ++f)
    for (int c = 0; c < 3; ++c) out.F(f, c) = first[std::size_t(m.F(f, c))];
  return out;
}

// The faces for which keep(f) holds, their vertices renumbered in order of first use.
template <class Keep>
Mesh keep_faces(const Mesh& m, Keep&& keep) {
  std::vector<int> id(std::size_t(m.V.rows()), -1);
  std::vector<Eigen::Index> faces;
  int next = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    if (!keep(f)) continue;
    faces.push_back(f);
    for (int c = 0; c < 3; ++c)
      if (id[std::size_t(m.F(f, c))] < 0) id[std::size_t(m.F(f, c))] = next++;
  }
  if (faces.empty()) throw InputError("perturb: nothing of the mesh would be left");
  Mesh out;
  out.V.resize(next, 3);
  for (Eigen::Index v = 0; v < m.V.rows(); ++v)
    if (id[std::size_t(v)] >= 0) out.V.row(id[std::size_t(v)]) = m.V.row(v);
  out.F.resize(Eigen::Index(faces.size()), 3);
  if (m.has_colour()) out.C.resize(Eigen::Index(faces.size()), 3);
  for (std::size_t k = 0; k < faces.size(); ++k) {
    for (int c = 0; c < 3; ++c) out.F(Eigen::Index(k), c) = id[std::size_t(m.F(faces[k], c))];
    if (m.has_colour()) out.C.row(Eigen::Index(k)) = m.C.row(faces[k]);
  }
  return out;
}

// Distance from p to the triangle a, b, c (Ericson, Real-Time Collision Detection, 5.1.5).
double triangle_distance(const Eigen::RowVector3d& p, const Eigen::RowVector3d& a,
                         const Eigen::RowVector3d& b, const Eigen::RowVector3d& c) {
  const Eigen::RowVector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.norm();
  const Eigen::RowVector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const Eigen::RowVector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  const double sum = va + vb + vc;
  if (!(sum > 0)) return std::min({ap.norm(), bp.norm(), cp.norm()});  // degenerate
  return (p - (a + vb / sum * ab + vc / sum * ac)).norm();
}

// Removes the surface within `radius` of each of `count` points drawn uniformly on it: the
// faces whose centre lies within a radius of one go. Faces that the circle of a hole crosses
// (some of the face within the radius, some beyond) are first cut (conforming, the mesh left
// as it was elsewhere, eval/refine_faces.hpp) until their edges are at most a quarter of the
// radius, so that a hole takes about its own area on a coarse model too, not whole faces many
// times its size.
Mesh holes(const Mesh& m, int count, double radius, SeededRandom& rng) {
  const std::vector<double> area = face_areas(m);
  std::vector<Eigen::RowVector3d> centres;
  for (int k = 0; k < count; ++k) centres.push_back(uniform_surface_point(m, area, rng));
  const Mesh fine = refine_faces(
      m, 0.25 * radius,
      [&](const Eigen::RowVector3d& a, const Eigen::RowVector3d& b, const Eigen::RowVector3d& c) {
        for (const auto& p : centres) {
          const double farthest = std::max({(a - p).norm(), (b - p).norm(), (c - p).norm()});
          if (farthest > radius && triangle_distance(p, a, b, c) < radius) return true;
        }
        return false;
      },
      std::max<Eigen::Index>(4 * m.F.rows(), 200000));
  return keep_faces(fine, [&](Eigen::Index f) {
    const Eigen::RowVector3d c = centroid(fine, f);
    for (const auto& p : centres)
      if ((c - p).norm() < radius) return false;
    return true;
  });
}

double gaussian(SeededRandom& rng) {
  // Box-Muller; 1 - unit() lies in (0, 1], so the logarithm is finite.
  const double u = 1.0 - rng.unit(), v = rng.unit();
  return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * M_PI * v);
}

Eigen::MatrixXd vertex_normals(const Mesh& m) {
  Eigen::MatrixXd n = Eigen::MatrixXd::Zero(m.V.rows(), 3);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const Eigen::RowVector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    const Eigen::RowVector3d area_normal = (b - a).cross(c - a);
    for (int k = 0; k < 3; ++k) n.row(m.F(f, k)) += area_normal;
  }
  for (Eigen::Index v = 0; v < n.rows(); ++v) {
    const double len = n.row(v).norm();
    if (len > 0) n.row(v) /= len;
  }
  return n;
}

// Vertex clustering (Rossignac and Borrel): vertices in one cell of a grid of step `cell`
// (shifted by `shift` cells) merge into their mean; faces that lose a corner are dropped.
Mesh cluster(const Mesh& m, double cell, const Eigen::RowVector3d& shift) {
  const Eigen::RowVector3d lo = m.V.colwise().minCoeff();
  std::map<std::array<long long, 3>, int> cell_id;
  std::vector<int> id(std::size_t(m.V.rows()));
  std::vector<Eigen::RowVector3d> sum;
  std::vector<int> count;
  for (Eigen::Index v = 0; v < m.V.rows(); ++v) {
    std::array<long long, 3> key;
    for (int a = 0; a < 3; ++a)
      key[std::size_t(a)] = (long long)std::floor((m.V(v, a) - lo[a]) / cell + shift[a]);
    auto [it, fresh] = cell_id.emplace(key, int(sum.size()));
    if (fresh) sum.emplace_back(0, 0, 0), count.push_back(0);
    id[std::size_t(v)] = it->second;
    sum[std::size_t(it->second)] += m.V.row(v);
    ++count[std::size_t(it->second)];
  }
  Mesh out;
  out.V.resize(Eigen::Index(sum.size()), 3);
  for (std::size_t k = 0; k < sum.size(); ++k) out.V.row(Eigen::Index(k)) = sum[k] / count[k];
  std::vector<std::array<int, 3>> faces;
  std::vector<Eigen::Index> source;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const int a = id[std::size_t(m.F(f, 0))], b = id[std::size_t(m.F(f, 1))],
              c = id[std::size_t(m.F(f, 2))];
    if (a == b || b == c || a == c) continue;
    faces.push_back({a, b, c});
    source.push_back(f);
  }
  if (faces.empty()) return Mesh{};  // cells too large: everything collapsed
  out.F.resize(Eigen::Index(faces.size()), 3);
  if (m.has_colour()) out.C.resize(Eigen::Index(faces.size()), 3);
  for (std::size_t k = 0; k < faces.size(); ++k) {
    for (int c = 0; c < 3; ++c) out.F(Eigen::Index(k), c) = faces[k][std::size_t(c)];
    if (m.has_colour()) out.C.row(Eigen::Index(k)) = m.C.row(source[k]);
  }
  // Clustering leaves vertices that no face uses when all their faces collapsed.
  return keep_faces(out, [](Eigen::Index) { return true; });
}

// Edge collapse (topology kept, mesh/collapse_short_edges.hpp) with the shortest length that
// leaves at most `target` vertices (bisection on the length), as decimation tools do.
Mesh collapse_to(const Mesh& m, double target) {
  double lo = 0, hi = diagonal(m);
  Mesh best, fewest;
  for (int step = 0; step < 20; ++step) {
    CollapseOptions o;
    o.min_length = 0.5 * (lo + hi);
    Mesh trial = collapse_short_edges(m, o);
    if (trial.F.rows() > 0 && (fewest.F.rows() == 0 || trial.V.rows() < fewest.V.rows()))
      fewest = trial;
    if (double(trial.V.rows()) > target) {
      lo = o.min_length;
    } else {
      hi = o.min_length;
      if (trial.F.rows() > 0) best = std::move(trial);
    }
  }
  // A soup whose triangles share few edges cannot collapse down to the target (its loose
  // vertices have nothing to merge with): it is decimated as far as collapses go.
  if (best.F.rows() == 0) best = std::move(fewest);
  if (best.F.rows() == 0) throw InputError("perturb: nothing of the mesh would be left");
  if (m.has_colour()) best.C.resize(0, 3);  // collapses do not carry colour
  return best;
}

// Clustering with the cell size that leaves about `target` vertices (bisection on the size).
Mesh cluster_to(const Mesh& m, double target, const Eigen::RowVector3d& shift) {
  double lo = 0, hi = diagonal(m);
  Mesh best;
  for (int step = 0; step < 24 && hi - lo > 1e-6 * diagonal(m); ++step) {
    const double mid = 0.5 * (lo + hi);
    Mesh trial = cluster(m, mid, shift);
    if (double(trial.V.rows()) > target) {
      lo = mid;
    } else {
      hi = mid;
      if (trial.F.rows() > 0) best = std::move(trial);
    }
  }
  if (best.F.rows() == 0) throw InputError("perturb: nothing of the mesh would be left");
  return best;
}

// Every triangle into four at its edge midpoints (shared midpoints merged).
Mesh subdivide(const Mesh& m) {
  std::map<std::pair<int, int>, int> midpoint;
  std::vector<Eigen::RowVector3d> extra;
  const int nv = int(m.V.rows());
  auto mid = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    auto [it, fresh] = midpoint.emplace(key, nv + int(extra.size()));
    if (fresh) extra.push_back(0.5 * (m.V.row(a) + m.V.row(b)));
    return it->second;
  };
  Mesh out;
  out.F.resize(4 * m.F.rows(), 3);
  if (m.has_colour()) out.C.resize(4 * m.F.rows(), 3);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const int a = m.F(f, 0), b = m.F(f, 1), c = m.F(f, 2);
    const int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
    const int rows[4][3] = {{a, ab, ca}, {ab, b, bc}, {ca, bc, c}, {ab, bc, ca}};
    for (int k = 0; k < 4; ++k) {
      for (int j = 0; j < 3; ++j) out.F(4 * f + k, j) = rows[k][j];
      if (m.has_colour()) out.C.row(4 * f + k) = m.C.row(f);
    }
  }
  out.V.resize(nv + Eigen::Index(extra.size()), 3);
  out.V.topRows(nv) = m.V;
  for (std::size_t k = 0; k < extra.size(); ++k) out.V.row(nv + Eigen::Index(k)) = extra[k];
  return out;
}

Eigen::RowVector3d random_direction(SeededRandom& rng) {
  for (;;) {
    const Eigen::RowVector3d d(rng.signed_unit(), rng.signed_unit(), rng.signed_unit());
    const double n = d.norm();
    if (n > 1e-3 && n <= 1.0) return d / n;
  }
}

// Moves every point by up to 1% of the mean edge length (a random offset), so that a
// remeshing does not merely undo its own subdivision; corners at one position move together.
Mesh jitter(const Mesh& m, const std::vector<int>& first, SeededRandom& rng) {
  double sum = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int c = 0; c < 3; ++c) sum += (m.V.row(m.F(f, c)) - m.V.row(m.F(f, (c + 1) % 3))).norm();
  const double step = 0.01 * sum / double(std::max<Eigen::Index>(1, 3 * m.F.rows()));
  Eigen::MatrixXd offset(m.V.rows(), 3);
  for (Eigen::Index v = 0; v < m.V.rows(); ++v) offset.row(v) = step * random_direction(rng);
  Mesh out = m;
  for (Eigen::Index v = 0; v < out.V.rows(); ++v) out.V.row(v) += offset.row(first[std::size_t(v)]);
  return out;
}

// Cuts along random planes through points near the centre: every face goes to the side of
// each plane its centre lies on, its corners are copied per side, and each side moves 0.002 D
// away from the plane, so the sides become separate components.
Mesh split(const Mesh& m, int planes, SeededRandom& rng) {
  const double d = diagonal(m);
  const Eigen::RowVector3d middle = 0.5 * (m.V.colwise().minCoeff() + m.V.colwise().maxCoeff());
  std::vector<Eigen::RowVector3d> normal, point;
  for (int k = 0; k < planes; ++k) {
    normal.push_back(random_direction(rng));
    point.push_back(middle + 0.1 * d * random_direction(rng));
  }
  std::vector<int> side(std::size_t(m.F.rows()), 0);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < planes; ++k)
      if ((centroid(m, f) - point[std::size_t(k)]).dot(normal[std::size_t(k)]) > 0)
        side[std::size_t(f)] |= 1 << k;
  std::map<std::pair<int, int>, int> copy;  // (vertex, side) -> new vertex
  std::vector<Eigen::RowVector3d> vertices;
  Mesh out;
  out.F.resize(m.F.rows(), 3);
  if (m.has_colour()) out.C = m.C;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const int s = side[std::size_t(f)];
    Eigen::RowVector3d offset(0, 0, 0);
    for (int k = 0; k < planes; ++k)
      offset += ((s >> k) & 1 ? 0.002 : -0.002) * d * normal[std::size_t(k)];
    for (int c = 0; c < 3; ++c) {
      auto [it, fresh] = copy.emplace(std::make_pair(m.F(f, c), s), int(vertices.size()));
      if (fresh) vertices.push_back(m.V.row(m.F(f, c)) + offset);
      out.F(f, c) = it->second;
    }
  }
  out.V.resize(Eigen::Index(vertices.size()), 3);
  for (std::size_t k = 0; k < vertices.size(); ++k) out.V.row(Eigen::Index(k)) = vertices[k];
  return out;
}

// Removes the faces nearest a random surface point until `share` of the area is gone.
Mesh partial(const Mesh& m, double share, SeededRandom& rng) {
  const std::vector<double> area = face_areas(m);
  const Eigen::RowVector3d p = surface_point(m, area, rng);
  std::vector<Eigen::Index> order(std::size_t(m.F.rows()));
  std::iota(order.begin(), order.end(), 0);
  std::vector<double> gap(order.size());
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) gap[std::size_t(f)] = (centroid(m, f) - p).norm();
  std::stable_sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
    return gap[std::size_t(a)] < gap[std::size_t(b)];
  });
  const double total = std::accumulate(area.begin(), area.end(), 0.0);
  std::vector<char> removed(order.size(), 0);
  double gone = 0;
  for (Eigen::Index f : order) {
    if (gone >= share * total) break;
    removed[std::size_t(f)] = 1;
    gone += area[std::size_t(f)];
  }
  return keep_faces(m, [&](Eigen::Index f) { return !removed[std::size_t(f)]; });
}

Mesh local_scale(const Mesh& m, double growth, SeededRandom& rng) {
  const std::vector<double> area = face_areas(m);
  const Eigen::RowVector3d c = surface_point(m, area, rng);
  const double radius = 0.2 * diagonal(m);
  Mesh out = m;
  for (Eigen::Index v = 0; v < m.V.rows(); ++v) {
    const double t = (m.V.row(v) - c).norm() / radius;
    if (t < 1) out.V.row(v) = c + (m.V.row(v) - c) * (1.0 + growth * (1 - t) * (1 - t));
  }
  return out;
}

}  // namespace

const std::vector<Perturbation>& all_perturbations() {
  static const std::vector<Perturbation> kinds = [] {
    std::vector<Perturbation> k;
    for (const Entry& e : kEntries) k.push_back(e.kind);
    return k;
  }();
  return kinds;
}

const char* perturbation_name(Perturbation kind) {
  for (const Entry& e : kEntries)
    if (e.kind == kind) return e.name;
  return "unknown";
}

std::optional<Perturbation> parse_perturbation(std::string_view name) {
  for (const Entry& e : kEntries)
    if (name == e.name) return e.kind;
  return std::nullopt;
}

Mesh perturb(const Mesh& mesh, Perturbation kind, int s, std::uint64_t seed) {
  if (s < 1 || s > 5) throw InputError("perturb: strength must be in 1..5");
  if (mesh.V.rows() == 0 || mesh.F.rows() == 0) throw InputError("perturb: mesh has no faces");
  SeededRandom rng(gen::mix_seed(perturbation_name(kind), seed * 8 + std::uint64_t(s)));
  const double d = diagonal(mesh);
  switch (kind) {
    case Perturbation::SmallHoles:
      return holes(mesh, 4 * s, 0.02 * d, rng);
    case Perturbation::LargeHoles:
      return holes(mesh, s, 0.06 * d, rng);
    case Perturbation::Noise: {
      // Noise moves points of the surface: a soup's corners at one position move together.
      // Every vertex still draws its offset, so a mesh without coincident vertices gets the
      // offsets it always had.
      const std::vector<int> first = first_at_same_position(mesh);
      Eigen::MatrixXd offset(mesh.V.rows(), 3);
      for (Eigen::Index v = 0; v < offset.rows(); ++v)
        for (int a = 0; a < 3; ++a) offset(v, a) = 0.001 * s * d * gaussian(rng);
      Mesh out = mesh;
      for (Eigen::Index v = 0; v < out.V.rows(); ++v)
        out.V.row(v) += offset.row(first[std::size_t(v)]);
      return out;
    }
    case Perturbation::ShotNoise: {
      // As for noise, a shot moves a point of the surface, with every corner there, along the
      // normal of all the faces that meet at it; the shots are counted and drawn among points.
      const std::vector<int> first = first_at_same_position(mesh);
      const std::vector<int> points = surface_points(first);
      const Eigen::MatrixXd n = vertex_normals(joined_at_same_position(mesh, first));
      Eigen::MatrixXd shift = Eigen::MatrixXd::Zero(mesh.V.rows(), 3);
      const std::size_t count =
          std::max<std::size_t>(1, std::size_t(0.002 * s * double(points.size())));
      for (std::size_t k = 0; k < count; ++k) {
        const int v = points[std::size_t(rng.bits() % std::uint64_t(points.size()))];
        shift.row(v) += (rng.chance(0.5) ? 0.02 : -0.02) * d * n.row(v);
      }
      Mesh out = mesh;
      for (Eigen::Index v = 0; v < out.V.rows(); ++v)
        out.V.row(v) += shift.row(first[std::size_t(v)]);
      return out;
    }
    case Perturbation::Decimate: {
      // The budget counts points of the surface, not a soup's repeated corners.
      const std::size_t points = surface_points(first_at_same_position(mesh)).size();
      return quadric_decimation(mesh, std::size_t((0.5 - 0.075 * (s - 1)) * double(points)));
    }
    case Perturbation::Remesh: {
      // On the points of the surface, so that a soup is subdivided and collapsed as one surface.
      const std::vector<int> first = first_at_same_position(mesh);
      const std::size_t points = surface_points(first).size();
      Mesh jittered = jitter(joined_at_same_position(mesh, first), first, rng);
      // A soup's merged corners would count against the vertex budget: drop them.
      if (points < std::size_t(mesh.V.rows()))
        jittered = keep_faces(jittered, [](Eigen::Index) { return true; });
      return collapse_to(subdivide(jittered), (0.75 + 0.25 * s) * double(points));
    }
    case Perturbation::Cluster: {
      const Eigen::RowVector3d shift(rng.unit(), rng.unit(), rng.unit());
      return cluster_to(mesh, (0.5 - 0.075 * (s - 1)) * double(mesh.V.rows()), shift);
    }
    case Perturbation::Split:
      return split(mesh, s, rng);
    case Perturbation::Partial:
      return partial(mesh, 0.05 * s, rng);
    case Perturbation::Scale: {
      Mesh out = mesh;
      out.V *= std::ldexp(1.0, s);
      return out;
    }
    case Perturbation::LocalScale:
      return local_scale(mesh, 0.15 * s, rng);
  }
  return mesh;
}

}  // namespace arg
