// Marching tetrahedra over a sampled grid: a closed, manifold, outward-oriented triangle mesh.
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
#include "common/strict_fp.hpp"  // first: the generator needs the same bits on every target

#include "mesh/marching_tetrahedra.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace arg {
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

// A point of the output, with its arithmetic spelled out (Eigen may reorder or fuse it).
struct Point {
  double x = 0, y = 0, z = 0;
};

// Bit mask of a corner offset -> index of the grid edge direction (1..7 -> 0..6).
constexpr int direction_index(int offset_bits) {
  return offset_bits - 1;
}

}  // namespace

Mesh marching_tetrahedra(const SampleGrid& g, const LayerSampler& sampler) {
  if (g.nx < 2 || g.ny < 2 || g.nz < 2)
    throw std::invalid_argument("marching_tetrahedra: fewer than two grid points along an axis");
  const std::size_t layer = static_cast<std::size_t>(g.nx) * g.ny;
  // Exact zeros become the smallest positive double (outside), so every edge has a strict sign
  // change or none; the border is forced outside so the surface closes.
  auto sample_layer = [&](int k, std::vector<double>& out) {
    sampler(k, out);
    if (out.size() != layer) throw std::invalid_argument("marching_tetrahedra: short layer");
    const bool border_layer = k == 0 || k == g.nz - 1;
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        double& f = out[static_cast<std::size_t>(j) * g.nx + i];
        if (std::isnan(f)) throw std::invalid_argument("marching_tetrahedra: NaN sample");
        if (f == 0) f = std::numeric_limits<double>::min();
        if (border_layer || i == 0 || j == 0 || i == g.nx - 1 || j == g.ny - 1)
          f = std::max(f, 1.0);
      }
  };

  // Two layers of samples and, for the grid points of each, the vertex on each of the seven
  // edges leaving it towards +x/+y/+z (-1 = none yet). A vertex is made once per edge, computed
  // from the edge's lower end, so every tetrahedron around the edge gets the same index.
  std::vector<double> values[2] = {std::vector<double>(layer), std::vector<double>(layer)};
  std::vector<int> edge_vertex[2] = {std::vector<int>(layer * 7, -1),
                                     std::vector<int>(layer * 7, -1)};
  std::vector<Point> vertices;
  std::vector<std::array<int, 3>> triangles;

  sample_layer(0, values[0]);
  for (int k = 0; k + 1 < g.nz; ++k) {
    const int lo = k & 1, hi = lo ^ 1;
    sample_layer(k + 1, values[hi]);
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
          const Point pa{g.origin[0] + (i + (a & 1)) * g.step,
                         g.origin[1] + (j + ((a >> 1) & 1)) * g.step,
                         g.origin[2] + (k + ((a >> 2) & 1)) * g.step};
          const Point pb{g.origin[0] + (i + (b & 1)) * g.step,
                         g.origin[1] + (j + ((b >> 1) & 1)) * g.step,
                         g.origin[2] + (k + ((b >> 2) & 1)) * g.step};
          slot = static_cast<int>(vertices.size());
          vertices.push_back(
              {pa.x + (pb.x - pa.x) * t, pa.y + (pb.y - pa.y) * t, pa.z + (pb.z - pa.z) * t});
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
            const auto squared = [&](int p, int q) {
              const double dx = vertices[p].x - vertices[q].x, dy = vertices[p].y - vertices[q].y,
                           dz = vertices[p].z - vertices[q].z;
              return dx * dx + dy * dy + dz * dz;
            };
            if (squared(ac, bd) <= squared(ad, bc)) {
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

}  // namespace arg
