// Turning an implicit solid into a closed, manifold, outward-oriented triangle mesh.
//
// Why this is watertight and manifold: every cube is cut into the six tetrahedra around its
// main diagonal (Freudenthal/Kuhn), which is the same pattern in every cube, so neighbouring
// cubes cut their shared face along the same diagonal and the grid is one tetrahedral complex.
// The surface is the zero set of the field interpolated linearly in each tetrahedron. No sample
// is exactly zero (zeros are nudged outwards), so each tetrahedron holds one triangle or one
// quad whose corners lie strictly inside its edges; a surface vertex belongs to one grid edge and
// is shared by every tetrahedron around that edge, whose pieces form a single disc about it.
// Samples on the grid's outer layer are forced outside, so the surface never reaches the border.
//
// Why no triangle has zero area: the edge parameter is clamped to [kEdgeMargin, 1 - kEdgeMargin]
// so corners stay strictly inside their edges. A triangle's corners then lie on three edges
// leaving one tetrahedron corner, and those edges are linearly independent; in a quad any three
// corners have two on one face of the tetrahedron and the third off that face's plane. So no
// three corners are collinear. Clamping moves a vertex by at most kEdgeMargin of a cell.
#include "gen/strict_fp.hpp"  // first: it sets how arithmetic is compiled

#include "gen/marching_tetrahedra.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace arg::gen {
namespace {

constexpr double kEdgeMargin = 1e-3;

// Corners of a cube as bits: 1 = +x, 2 = +y, 4 = +z. The six tetrahedra follow the monotone
// paths from corner 0 to corner 7, one per order of the axes; the odd orders are listed with
// their last two corners swapped so every tetrahedron has positive volume.
constexpr std::array<std::array<int, 4>, 6> kTetrahedra = {{
    {0, 1, 3, 7},  // x, y, z
    {0, 2, 7, 3},  // y, x, z (odd)
    {0, 2, 6, 7},  // y, z, x
    {0, 4, 7, 6},  // z, y, x (odd)
    {0, 4, 5, 7},  // z, x, y
    {0, 1, 7, 5},  // x, z, y (odd)
}};

struct Grid {
  Vec3 origin;
  double step = 0;
  int nx = 0, ny = 0, nz = 0;  // samples per axis (cells + 1)
};

Grid make_grid(const Box& bounds, int resolution) {
  const Vec3 extent = bounds.hi - bounds.lo;
  const double longest = std::max({extent.x, extent.y, extent.z});
  if (!(longest > 0) || !std::isfinite(longest))
    throw std::invalid_argument("marching_tetrahedra: empty or unbounded solid");
  Grid g;
  g.step = longest / resolution;
  const auto cells = [&](double e) { return static_cast<int>(std::ceil(e / g.step - 1e-9)) + 2; };
  const int cx = cells(extent.x), cy = cells(extent.y), cz = cells(extent.z);
  const Vec3 centre = (bounds.lo + bounds.hi) * 0.5;
  g.origin = {centre.x - 0.5 * cx * g.step, centre.y - 0.5 * cy * g.step,
              centre.z - 0.5 * cz * g.step};
  g.nx = cx + 1;
  g.ny = cy + 1;
  g.nz = cz + 1;
  return g;
}

// Samples one z layer. Exact zeros become the smallest positive double (outside), so every
// edge has a strict sign change or none; the border is forced outside so the surface closes.
void sample_layer(const Solid& solid, const Grid& g, int k, std::vector<double>& out) {
  const double z = g.origin.z + k * g.step;
  const bool border_layer = k == 0 || k == g.nz - 1;
  for (int j = 0; j < g.ny; ++j) {
    const double y = g.origin.y + j * g.step;
    for (int i = 0; i < g.nx; ++i) {
      double f = solid.field(Vec3{g.origin.x + i * g.step, y, z});
      if (std::isnan(f)) throw std::logic_error("marching_tetrahedra: field returned NaN");
      if (f == 0) f = std::numeric_limits<double>::min();
      if (border_layer || i == 0 || j == 0 || i == g.nx - 1 || j == g.ny - 1) f = std::max(f, 1.0);
      out[static_cast<std::size_t>(j) * g.nx + i] = f;
    }
  }
}

// Bit mask of a corner offset -> index of the grid edge direction (1..7 -> 0..6).
constexpr int direction_index(int offset_bits) {
  return offset_bits - 1;
}

}  // namespace

double marching_grid_step(const Box& bounds, int resolution) {
  return make_grid(bounds, resolution).step;
}

Mesh marching_tetrahedra(const Solid& solid, int resolution) {
  if (resolution < 2) throw std::invalid_argument("marching_tetrahedra: resolution below 2");
  const Grid g = make_grid(solid.bounds, resolution);
  const std::size_t layer = static_cast<std::size_t>(g.nx) * g.ny;

  // Two layers of samples and, for the grid points of each, the vertex on each of the seven
  // edges leaving it towards +x/+y/+z (-1 = none yet). A vertex is made once per edge, computed
  // from the edge's lower end, so every tetrahedron around the edge gets the same index.
  std::vector<double> values[2] = {std::vector<double>(layer), std::vector<double>(layer)};
  std::vector<int> edge_vertex[2] = {std::vector<int>(layer * 7, -1),
                                     std::vector<int>(layer * 7, -1)};
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;

  sample_layer(solid, g, 0, values[0]);
  for (int k = 0; k + 1 < g.nz; ++k) {
    const int lo = k & 1, hi = lo ^ 1;
    sample_layer(solid, g, k + 1, values[hi]);
    std::fill(edge_vertex[hi].begin(), edge_vertex[hi].end(), -1);

    for (int j = 0; j + 1 < g.ny; ++j) {
      for (int i = 0; i + 1 < g.nx; ++i) {
        double f[8];
        for (int c = 0; c < 8; ++c) {
          const int layer_id = (c & 4) ? hi : lo;
          f[c] =
              values[layer_id][static_cast<std::size_t>(j + ((c >> 1) & 1)) * g.nx + i + (c & 1)];
        }
        int inside_mask = 0;
        for (int c = 0; c < 8; ++c) inside_mask |= (f[c] < 0) << c;
        if (inside_mask == 0 || inside_mask == 255) continue;

        // Vertex on the tetrahedron edge between cube corners c0 and c1.
        auto vertex_on = [&](int c0, int c1) {
          const int a = std::min(c0, c1), b = std::max(c0, c1);  // a's bits are a subset of b's
          const int layer_id = (a & 4) ? hi : lo;
          const std::size_t point =
              static_cast<std::size_t>(j + ((a >> 1) & 1)) * g.nx + i + (a & 1);
          int& slot = edge_vertex[layer_id][point * 7 + direction_index(b ^ a)];
          if (slot >= 0) return slot;
          const double fa = f[a], fb = f[b];
          const double t = std::clamp(fa / (fa - fb), kEdgeMargin, 1.0 - kEdgeMargin);
          const Vec3 pa{g.origin.x + (i + (a & 1)) * g.step,
                        g.origin.y + (j + ((a >> 1) & 1)) * g.step,
                        g.origin.z + (k + ((a >> 2) & 1)) * g.step};
          const Vec3 pb{g.origin.x + (i + (b & 1)) * g.step,
                        g.origin.y + (j + ((b >> 1) & 1)) * g.step,
                        g.origin.z + (k + ((b >> 2) & 1)) * g.step};
          slot = static_cast<int>(vertices.size());
          vertices.push_back(pa + (pb - pa) * t);
          return slot;
        };

        for (const auto& tet : kTetrahedra) {
          int in[4], out[4], n_in = 0, n_out = 0;
          for (int c : tet) (f[c] < 0 ? in[n_in++] : out[n_out++]) = c;
          if (n_in == 0 || n_out == 0) continue;
          // Reorder the corners as (a, b, c, d), an even permutation of tet (so still positively
          // oriented), with the lone or paired inside corners first; the orientations below were
          // derived for that order and point the normals from inside to outside.
          int order[4];
          if (n_in == 3) {
            order[0] = out[0];
            for (int m = 0; m < 3; ++m) order[m + 1] = in[m];
          } else {
            for (int m = 0; m < n_in; ++m) order[m] = in[m];
            for (int m = 0; m < n_out; ++m) order[n_in + m] = out[m];
          }
          int position[8];
          for (int m = 0; m < 4; ++m) position[tet[m]] = m;
          int inversions = 0;
          for (int p = 0; p < 4; ++p)
            for (int q = p + 1; q < 4; ++q) inversions += position[order[p]] > position[order[q]];
          if (inversions & 1) std::swap(order[2], order[3]);
          const int a = order[0], b = order[1], c = order[2], d = order[3];

          if (n_in == 1) {
            triangles.push_back({vertex_on(a, b), vertex_on(a, c), vertex_on(a, d)});
          } else if (n_in == 3) {
            triangles.push_back({vertex_on(a, b), vertex_on(a, d), vertex_on(a, c)});
          } else {
            // Quad ac, ad, bd, bc (in that cyclic order); split along its shorter diagonal.
            const int ac = vertex_on(a, c), ad = vertex_on(a, d);
            const int bd = vertex_on(b, d), bc = vertex_on(b, c);
            const Vec3 d1 = vertices[ac] - vertices[bd], d2 = vertices[ad] - vertices[bc];
            if (dot(d1, d1) <= dot(d2, d2)) {
              triangles.push_back({ac, ad, bd});
              triangles.push_back({ac, bd, bc});
            } else {
              triangles.push_back({ac, ad, bc});
              triangles.push_back({ad, bd, bc});
            }
          }
        }
      }
    }
    // The upper layer's in-plane edges were filled while processing this slab; its vertical
    // and diagonal edges will be filled by the next slab, which sees it as its lower layer.
  }

  Mesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(vertices.size()), 3);
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    const auto r = static_cast<Eigen::Index>(v);
    mesh.V(r, 0) = vertices[v].x;
    mesh.V(r, 1) = vertices[v].y;
    mesh.V(r, 2) = vertices[v].z;
  }
  mesh.F.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int c = 0; c < 3; ++c) mesh.F(static_cast<Eigen::Index>(t), c) = triangles[t][c];
  return mesh;
}

}  // namespace arg::gen
