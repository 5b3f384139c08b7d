// Facing rim loops of different pieces, paired nearest first, joined by lerped rings.
#include "mesh/bridge_pieces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>

#include "mesh/append_faces.hpp"
#include "mesh/boundary_loops.hpp"
#include "mesh/connected_components.hpp"

namespace arg {

namespace {

using Point = Eigen::RowVector3d;

constexpr std::size_t kMaxLoops = 256;
constexpr double kRadiusRatio = 4.0;
constexpr double kFacing = 0.7;    // cosine between a loop's opening and the other's centre
constexpr int kMaxRings = 16;      // rings a tube gets at most (besides its two rims)
constexpr int kAlignSamples = 32;  // arc-length samples when turning one loop to the other

struct LoopShape {
  Point centre = Point::Zero(), opening = Point::Zero();  // opening: unit, out of the piece
  double radius = 0, edge = 0;                            // mean radius, mean rim edge length
  int piece = 0;
};

// A closed polyline with the arc-length position of each vertex, in [0, 1).
struct Ring {
  std::vector<Point> points;
  std::vector<double> at;

  Point point_at(double s) const {
    s -= std::floor(s);
    const std::size_t n = points.size();
    const std::size_t i = std::size_t(std::upper_bound(at.begin(), at.end(), s) - at.begin()) - 1;
    const double end = i + 1 < n ? at[i + 1] : 1.0;
    const double t = end > at[i] ? (s - at[i]) / (end - at[i]) : 0.0;
    return (1 - t) * points[i] + t * points[(i + 1) % n];
  }
};

Ring make_ring(std::vector<Point> points) {
  Ring r;
  const std::size_t n = points.size();
  r.at.assign(n, 0.0);
  double length = 0;
  for (std::size_t i = 0; i < n; ++i) {
    r.at[i] = length;
    length += (points[(i + 1) % n] - points[i]).norm();
  }
  if (length > 0)
    for (double& a : r.at) a /= length;
  else
    for (std::size_t i = 0; i < n; ++i) r.at[i] = double(i) / double(n);
  r.points = std::move(points);
  return r;
}

// Signed volume of each piece with its loops closed by fans: its sign says whether the piece's
// faces turn out (an open piece keeps whatever way clean_mesh left it). Measured about each
// piece's mean vertex, so that a model far from the origin keeps its sign.
std::vector<double> closed_volumes(const Mesh& mesh, const std::vector<int>& component,
                                   const std::vector<BoundaryLoop>& loops, int pieces) {
  std::vector<Point> origin(std::size_t(pieces), Point::Zero());
  std::vector<double> count(std::size_t(pieces), 0.0);
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
    origin[std::size_t(component[std::size_t(v)])] += mesh.V.row(v);
    count[std::size_t(component[std::size_t(v)])] += 1;
  }
  for (std::size_t p = 0; p < origin.size(); ++p)
    if (count[p] > 0) origin[p] /= count[p];
  std::vector<double> volume(std::size_t(pieces), 0.0);
  auto add = [&](int a, int b, const Point& c) {  // the triangle (a, b, c) of a's piece
    const std::size_t p = std::size_t(component[std::size_t(a)]);
    volume[p] += (Point(mesh.V.row(a)) - origin[p])
                     .dot((Point(mesh.V.row(b)) - origin[p]).cross(c - origin[p]));
  };
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    add(mesh.F(f, 0), mesh.F(f, 1), mesh.V.row(mesh.F(f, 2)));
  for (const BoundaryLoop& loop : loops) {
    const std::size_t n = loop.vertices.size();
    Point c = Point::Zero();
    for (int v : loop.vertices) c += mesh.V.row(v);
    c /= double(n);
    for (std::size_t i = 0; i < n; ++i)  // the fan face (to, from, centre)
      add(loop.vertices[(i + 1) % n], loop.vertices[i], c);
  }
  return volume;
}

struct TubeBuilder {
  const Mesh& mesh;
  std::vector<Point> vertices;  // added after mesh.V
  std::vector<Eigen::RowVector3i> faces;
  std::vector<Eigen::RowVector3f> colours;

  // Triangles between two closed polylines of vertex ids (x runs as the faces along it must,
  // y the other way), both starting at arc-length 0, zipped by arc length.
  void zip(const std::vector<int>& x, const std::vector<double>& sx, const std::vector<int>& y,
           const std::vector<double>& sy, const Eigen::RowVector3f& colour) {
    const std::size_t nx = x.size(), ny = y.size();
    std::size_t i = 0, j = 0;
    while (i < nx || j < ny) {
      const double next_x = i + 1 < nx ? sx[i + 1] : 1.0, next_y = j + 1 < ny ? sy[j + 1] : 1.0;
      if (j == ny || (i < nx && next_x <= next_y)) {
        faces.emplace_back(x[i], x[(i + 1) % nx], y[j % ny]);
        ++i;
      } else {
        faces.emplace_back(y[(j + 1) % ny], y[j], x[i % nx]);
        ++j;
      }
      colours.push_back(colour);
    }
  }

  int add_vertex(const Point& p) {
    vertices.push_back(p);
    return int(mesh.V.rows() + Eigen::Index(vertices.size()) - 1);
  }
};

}  // namespace

Mesh bridge_pieces(const Mesh& mesh, const MeshEdges& edges, const std::vector<int>& component,
                   double max_gap, std::size_t* bridges, const StopRequested& stop) {
  if (bridges) *bridges = 0;
  const std::vector<BoundaryLoop> loops = boundary_loops(mesh, edges).loops;
  if (loops.size() < 2 || loops.size() > kMaxLoops || !(max_gap > 0) ||
      component.size() != std::size_t(mesh.V.rows()) ||
      *std::min_element(component.begin(), component.end()) < 0)
    return mesh;
  const int pieces = 1 + *std::max_element(component.begin(), component.end());
  const std::vector<double> volume = closed_volumes(mesh, component, loops, pieces);
  // Which way a piece is turned is known only from a closed fan surface that encloses some
  // volume: not for a piece with rim edges outside the simple loops (a rim that passes a vertex
  // twice), nor for a flat one (a lone triangle, a sheet), whose volume is rounding noise.
  // Their loops are not bridged.
  std::vector<long long> loose_rim(std::size_t(pieces), 0);
  for (int e = 0; e < edges.count(); ++e)
    if (edges.faces(e) == 1) ++loose_rim[std::size_t(component[std::size_t(edges.v0[e])])];
  for (const BoundaryLoop& loop : loops)
    loose_rim[std::size_t(component[std::size_t(loop.vertices[0])])] -=
        (long long)loop.vertices.size();
  const std::vector<double> area = component_areas(mesh, component, std::size_t(pieces));
  std::vector<char> turning_known(std::size_t(pieces), 0);
  for (std::size_t p = 0; p < turning_known.size(); ++p)
    turning_known[p] =
        loose_rim[p] == 0 && std::abs(volume[p]) > 1e-6 * area[p] * std::sqrt(area[p]);

  std::vector<LoopShape> shape(loops.size());
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const std::vector<int>& v = loops[l].vertices;
    const std::size_t n = v.size();
    LoopShape& s = shape[l];
    for (int u : v) s.centre += mesh.V.row(u);
    s.centre /= double(n);
    Point normal = Point::Zero();
    for (std::size_t i = 0; i < n; ++i) {
      const Point a = mesh.V.row(v[i]), b = mesh.V.row(v[(i + 1) % n]);
      s.radius += (a - s.centre).norm();
      s.edge += (b - a).norm();
      normal += (b - s.centre).cross(a - s.centre);
    }
    s.radius /= double(n);
    s.edge /= double(n);
    s.piece = component[std::size_t(v[0])];
    const double length = normal.norm();
    if (length > 0) s.opening = (volume[std::size_t(s.piece)] < 0 ? -1.0 : 1.0) * normal / length;
  }

  // Candidate pairs, nearest first, the gap counted longer as the sizes differ (where a hole
  // took a joint, two limb stumps facing each other are a better pair than either with the
  // body's wider rim); ties by loop index. Taken while they join pieces not yet joined.
  std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;
  for (std::size_t a = 0; a < loops.size(); ++a)
    for (std::size_t b = a + 1; b < loops.size(); ++b) {
      const LoopShape &p = shape[a], &q = shape[b];
      if (p.piece == q.piece || !turning_known[std::size_t(p.piece)] ||
          !turning_known[std::size_t(q.piece)])
        continue;
      const Point d = q.centre - p.centre;
      const double gap = d.norm();
      const double small = std::min(p.radius, q.radius), large = std::max(p.radius, q.radius);
      // Written so that a NaN fails each test.
      if (!(gap > 0 && gap <= max_gap && small > 0 && large <= kRadiusRatio * small)) continue;
      if (!(p.opening.dot(d) >= kFacing * gap && -q.opening.dot(d) >= kFacing * gap)) continue;
      pairs.emplace_back(gap * (1 + std::log(large / small)), a, b);
    }
  std::sort(pairs.begin(), pairs.end());
  std::vector<int> root(static_cast<std::size_t>(pieces));
  std::iota(root.begin(), root.end(), 0);
  auto find = [&](int x) {
    while (root[std::size_t(x)] != x)
      x = root[std::size_t(x)] = root[std::size_t(root[std::size_t(x)])];
    return x;
  };
  std::vector<char> used(loops.size(), 0);
  TubeBuilder tubes{mesh, {}, {}, {}};
  for (const auto& [order, a, b] : pairs) {
    check_interrupt(stop);
    if (used[a] || used[b]) continue;
    const int ra = find(shape[a].piece), rb = find(shape[b].piece);
    if (ra == rb) continue;
    root[std::size_t(ra)] = rb;
    used[a] = used[b] = 1;
    if (bridges) ++*bridges;

    // The faces along the tube run against both rims: loop a is walked backwards and loop b
    // forwards. When b's piece is turned the other way round, b is walked backwards too: the
    // tube then agrees with a's piece only, and clean_mesh turns b's piece over to match.
    const std::vector<int>& va = loops[a].vertices;
    std::vector<int> xa(va.size());
    for (std::size_t i = 0; i < va.size(); ++i) xa[i] = va[(va.size() - i) % va.size()];
    std::vector<int> yb = loops[b].vertices;
    if ((volume[std::size_t(shape[a].piece)] < 0) != (volume[std::size_t(shape[b].piece)] < 0))
      std::reverse(yb.begin(), yb.end());
    auto points = [&](const std::vector<int>& ids) {
      std::vector<Point> p;
      for (int v : ids) p.push_back(mesh.V.row(v));
      return make_ring(std::move(p));
    };
    const Ring ring_a = points(xa);
    Ring ring_b = points(yb);
    // The start of b that best fits a's (centred shapes, least squares over arc length).
    std::size_t best_start = 0;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t o = 0; o < yb.size(); ++o) {
      if ((o & 1023) == 1023) check_interrupt(stop);
      double cost = 0;
      for (int t = 0; t < kAlignSamples; ++t) {
        const double s = double(t) / kAlignSamples;
        cost += ((ring_a.point_at(s) - shape[a].centre) -
                 (ring_b.point_at(s + ring_b.at[o]) - shape[b].centre))
                    .squaredNorm();
      }
      if (cost < best) best = cost, best_start = o;
    }
    std::rotate(yb.begin(), yb.begin() + std::ptrdiff_t(best_start), yb.end());
    ring_b = points(yb);

    Eigen::RowVector3f colour(0, 0, 0);
    if (mesh.has_colour()) {
      for (int f : loops[a].faces) colour += mesh.C.row(f);
      for (int f : loops[b].faces) colour += mesh.C.row(f);
      colour /= float(loops[a].faces.size() + loops[b].faces.size());
    }
    const double gap = (shape[b].centre - shape[a].centre).norm();
    const double step = 0.5 * (shape[a].edge + shape[b].edge);
    const std::size_t count = std::max(xa.size(), yb.size());
    // No more rings than kMaxRings, and all tubes together add at most as many vertices as the
    // mesh has (a rim of millions of vertices would otherwise multiply them).
    const double budget =
        std::floor(double(mesh.V.rows() - Eigen::Index(tubes.vertices.size())) / double(count));
    const int rings = int(std::clamp(std::round(gap / std::max(step, 1e-12)) - 1.0, 0.0,
                                     std::min(double(kMaxRings), std::max(budget, 0.0))));
    std::vector<int> prev = xa, ring(count);
    std::vector<double> prev_at = ring_a.at, even(count);
    for (std::size_t t = 0; t < count; ++t) even[t] = double(t) / double(count);
    for (int k = 1; k <= rings; ++k) {
      const double w = double(k) / double(rings + 1);
      for (std::size_t t = 0; t < count; ++t)
        ring[t] =
            tubes.add_vertex((1 - w) * ring_a.point_at(even[t]) + w * ring_b.point_at(even[t]));
      tubes.zip(prev, prev_at, ring, even, colour);
      // The ring just made is the next zip's x side: the faces there walk its edges the other
      // way, as the two faces of an edge do.
      prev = ring;
      prev_at = even;
    }
    tubes.zip(prev, prev_at, yb, ring_b.at, colour);
  }
  if (tubes.faces.empty()) return mesh;

  return append_faces(mesh, tubes.vertices, tubes.faces, tubes.colours);
}

}  // namespace arg
