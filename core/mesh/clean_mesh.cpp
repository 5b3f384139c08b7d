// Mesh cleaning: weld, drop degenerate/duplicate faces and unused vertices, orient consistently.
#include "mesh/clean_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numeric>
#include <utility>
#include <vector>

#include "common/errors.hpp"
#include "common/polled_sort.hpp"
#include "mesh/mesh_edges.hpp"

namespace arg {

namespace {

// Maps every vertex to the first vertex with the same coordinates up to a relative tolerance.
std::vector<int> weld_map(const Vertices& V, std::size_t* welded, const StopRequested& stop) {
  const Eigen::Index n = V.rows();
  Eigen::RowVector3d lo = V.colwise().minCoeff(), hi = V.colwise().maxCoeff();
  const double eps = std::max((hi - lo).norm() * 1e-10, 1e-300);
  // Sorted by value, not through an index: each comparison reads its two keys in place.
  struct Key {
    std::array<long long, 3> at;
    int vertex;
    bool operator<(const Key& o) const {
      if (at[0] != o.at[0]) return at[0] < o.at[0];
      if (at[1] != o.at[1]) return at[1] < o.at[1];
      if (at[2] != o.at[2]) return at[2] < o.at[2];
      return vertex < o.vertex;
    }
  };
  std::vector<Key> key(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    poll_interrupt(std::size_t(i), stop);
    for (int c = 0; c < 3; ++c) key[std::size_t(i)].at[c] = std::llround((V(i, c) - lo[c]) / eps);
    key[std::size_t(i)].vertex = int(i);
  }
  polled_sort(key.begin(), key.end(), std::less<>(), stop);
  std::vector<int> map(static_cast<std::size_t>(n));
  *welded = 0;
  for (std::size_t k = 0; k < key.size(); ++k) {
    poll_interrupt(k, stop);
    if (k > 0 && key[k].at == key[k - 1].at) {
      map[std::size_t(key[k].vertex)] = map[std::size_t(key[k - 1].vertex)];
      ++*welded;
    } else {
      map[std::size_t(key[k].vertex)] = key[k].vertex;
    }
  }
  return map;
}

// Which faces repeat the corner set of a face before them (`corners`: each face's corners
// ascending). Faces are bucketed by their smallest corner, in order (a counting sort), and each
// bucket, the few faces whose smallest corner is one vertex, is searched for an earlier equal
// pair of the other two; a bucket too large for that (the centre of a fan) is sorted. Linear,
// where a sort of every face's corners took n log n, and the same faces come out.
std::vector<char> repeated_faces(const std::vector<std::array<int, 3>>& corners,
                                 std::size_t vertices, const StopRequested& stop) {
  std::vector<int> start(vertices + 1, 0);
  for (const auto& c : corners) ++start[std::size_t(c[0]) + 1];
  for (std::size_t v = 0; v < vertices; ++v) start[v + 1] += start[v];
  std::vector<int> order(corners.size());
  {
    std::vector<int> next(start.begin(), start.end() - 1);
    for (std::size_t k = 0; k < corners.size(); ++k) {
      poll_interrupt(k, stop);
      order[std::size_t(next[std::size_t(corners[k][0])]++)] = int(k);
    }
  }
  std::vector<char> repeated(corners.size(), 0);
  // The other two corners packed into one word, then the face's place: pairs compare as words.
  const auto pair_of = [&](int k) {
    const auto& c = corners[std::size_t(k)];
    return std::uint64_t(std::uint32_t(c[1])) << 32 | std::uint32_t(c[2]);
  };
  std::vector<std::pair<std::uint64_t, int>> large;
  // Indices, not pointers: with no face kept, order.data() may be null.
  for (std::size_t v = 0; v < vertices; ++v) {
    poll_interrupt(v, stop);
    const auto first = std::size_t(start[v]), last = std::size_t(start[v + 1]);
    if (last - first <= 32) {
      for (std::size_t i = first + 1; i < last; ++i)
        for (std::size_t j = first; j < i; ++j)
          if (pair_of(order[j]) == pair_of(order[i])) {
            repeated[std::size_t(order[i])] = 1;
            break;
          }
      continue;
    }
    large.clear();
    for (std::size_t i = first; i < last; ++i) large.emplace_back(pair_of(order[i]), order[i]);
    polled_sort(large.begin(), large.end(), std::less<>(), stop);
    for (std::size_t k = 1; k < large.size(); ++k)
      if (large[k].first == large[k - 1].first) repeated[std::size_t(large[k].second)] = 1;
  }
  return repeated;
}

double triangle_area(const Vertices& V, int a, int b, int c) {
  Eigen::Vector3d u = (V.row(b) - V.row(a)).transpose(), w = (V.row(c) - V.row(a)).transpose();
  return 0.5 * u.cross(w).norm();
}

// Flips faces so that faces sharing a manifold edge traverse it in opposite directions.
// Returns, per face, the orientation patch it belongs to.
// `turned` toggles for each face flipped.
std::vector<int> orient_patches(Triangles& F, const MeshEdges& E, std::size_t* flipped,
                                std::vector<char>& turned, const StopRequested& stop) {
  const int m = int(F.rows());
  // face -> its three edges, for the traversal
  std::vector<std::array<int, 3>> face_edges(std::size_t(m), {-1, -1, -1});
  for (int e = 0; e < E.count(); ++e) {
    poll_interrupt(std::size_t(e), stop);
    for (int k = E.face_begin[e]; k < E.face_begin[e + 1]; ++k)
      face_edges[E.face_of[k]][E.corner_of[k]] = e;
  }
  auto direction = [&](int f, int a, int b) {  // +1 if f walks a->b, -1 if b->a
    for (int c = 0; c < 3; ++c) {
      if (F(f, c) == a && F(f, (c + 1) % 3) == b) return 1;
      if (F(f, c) == b && F(f, (c + 1) % 3) == a) return -1;
    }
    return 0;
  };
  std::vector<int> patch(std::size_t(m), -1);
  std::vector<int> queue;
  int patches = 0;
  *flipped = 0;
  for (int seed = 0; seed < m; ++seed) {
    if (patch[seed] >= 0) continue;
    patch[seed] = patches;
    queue.assign(1, seed);
    for (std::size_t q = 0; q < queue.size(); ++q) {
      if ((q & 4095) == 0) check_interrupt(stop);
      int f = queue[q];
      for (int c = 0; c < 3; ++c) {
        int e = face_edges[f][c];
        if (e < 0 || E.faces(e) != 2) continue;
        int g = E.face_of[E.face_begin[e]] == f ? E.face_of[E.face_begin[e] + 1]
                                                : E.face_of[E.face_begin[e]];
        if (patch[g] >= 0) continue;
        if (direction(f, E.v0[e], E.v1[e]) == direction(g, E.v0[e], E.v1[e])) {
          std::swap(F(g, 1), F(g, 2));
          turned[std::size_t(g)] ^= 1;
          ++*flipped;
          // the flipped face's corner numbering changed: recompute its edge slots
          std::array<int, 3> slots = face_edges[g];
          face_edges[g] = {slots[2], slots[1], slots[0]};
        }
        patch[g] = patches;
        queue.push_back(g);
      }
    }
    ++patches;
  }
  return patch;
}

}  // namespace

Mesh clean_mesh(const Mesh& in, CleanReport* report, const StopRequested& stop, MeshEdges* edges) {
  CleanReport local;
  CleanReport& r = report ? *report : local;
  r = CleanReport{};
  if (in.V.rows() == 0 || in.F.rows() == 0) throw InputError("mesh has no faces");
  if (!in.V.allFinite()) throw InputError("mesh has a NaN or infinite vertex coordinate");
  for (Eigen::Index f = 0; f < in.F.rows(); ++f)
    for (int c = 0; c < 3; ++c)
      if (in.F(f, c) < 0 || in.F(f, c) >= in.V.rows())
        throw InputError("face " + std::to_string(f) + " refers to vertex " +
                         std::to_string(in.F(f, c)) + " of " + std::to_string(in.V.rows()));

  std::vector<int> map = weld_map(in.V, &r.welded_vertices, stop);
  check_interrupt(stop);
  Eigen::RowVector3d lo = in.V.colwise().minCoeff(), hi = in.V.colwise().maxCoeff();
  const double min_area = 1e-14 * (hi - lo).squaredNorm();

  // Keep faces with three distinct corners, positive area and a corner set not seen before.
  std::vector<std::array<int, 3>> corners;
  std::vector<int> kept;
  corners.reserve(std::size_t(in.F.rows()));
  for (Eigen::Index f = 0; f < in.F.rows(); ++f) {
    poll_interrupt(std::size_t(f), stop);
    int a = map[in.F(f, 0)], b = map[in.F(f, 1)], c = map[in.F(f, 2)];
    if (a == b || b == c || a == c || triangle_area(in.V, a, b, c) <= min_area) {
      ++r.dropped_degenerate;
      continue;
    }
    std::array<int, 3> key{a, b, c};
    std::sort(key.begin(), key.end());
    corners.push_back(key);
    kept.push_back(int(f));
  }
  const std::vector<char> duplicate = repeated_faces(corners, std::size_t(in.V.rows()), stop);
  r.dropped_duplicate = std::size_t(std::count(duplicate.begin(), duplicate.end(), 1));
  check_interrupt(stop);

  // Compact: new vertex ids in order of first use by a kept face's original index.
  std::vector<int> new_id(std::size_t(in.V.rows()), -1);
  int nv = 0, nf = 0;
  for (std::size_t k = 0; k < kept.size(); ++k) {
    poll_interrupt(k, stop);
    if (duplicate[k]) continue;
    ++nf;
    for (int c = 0; c < 3; ++c) {
      int v = map[in.F(kept[k], c)];
      if (new_id[v] < 0) new_id[v] = nv++;
    }
  }
  if (nf == 0) throw InputError("mesh has no face with positive area");
  Mesh out;
  out.V.resize(nv, 3);
  for (Eigen::Index v = 0; v < in.V.rows(); ++v) {
    poll_interrupt(std::size_t(v), stop);
    if (new_id[v] >= 0) out.V.row(new_id[v]) = in.V.row(v);
  }
  r.unused_vertices = std::size_t(in.V.rows()) - std::size_t(nv) - r.welded_vertices;
  out.F.resize(nf, 3);
  const bool colour = in.has_colour();
  if (colour) out.C.resize(nf, 3);
  nf = 0;
  for (std::size_t k = 0; k < kept.size(); ++k) {
    poll_interrupt(k, stop);
    if (duplicate[k]) continue;
    for (int c = 0; c < 3; ++c) out.F(nf, c) = new_id[map[in.F(kept[k], c)]];
    if (colour) out.C.row(nf) = in.C.row(kept[k]);
    ++nf;
  }

  MeshEdges E = mesh_edges(out.F, stop);
  for (int e = 0; e < E.count(); ++e) {
    poll_interrupt(std::size_t(e), stop);
    if (E.faces(e) == 1) ++r.boundary_edges;
    if (E.faces(e) > 2) ++r.nonmanifold_edges;
  }
  std::vector<char> turned(std::size_t(out.F.rows()), 0);
  std::vector<int> patch = orient_patches(out.F, E, &r.flipped_faces, turned, stop);

  // Turn each patch so that it encloses positive volume about its own centroid.
  const int patches = patch.empty() ? 0 : *std::max_element(patch.begin(), patch.end()) + 1;
  std::vector<Eigen::Vector3d> centre(std::size_t(patches), Eigen::Vector3d::Zero());
  std::vector<double> area(std::size_t(patches), 0.0), volume(std::size_t(patches), 0.0);
  for (int f = 0; f < out.F.rows(); ++f) {
    poll_interrupt(std::size_t(f), stop);
    double A = triangle_area(out.V, out.F(f, 0), out.F(f, 1), out.F(f, 2));
    Eigen::Vector3d c =
        (out.V.row(out.F(f, 0)) + out.V.row(out.F(f, 1)) + out.V.row(out.F(f, 2))).transpose() /
        3.0;
    centre[patch[f]] += A * c;
    area[patch[f]] += A;
  }
  for (int p = 0; p < patches; ++p)
    if (area[p] > 0) centre[p] /= area[p];
  for (int f = 0; f < out.F.rows(); ++f) {
    poll_interrupt(std::size_t(f), stop);
    const Eigen::Vector3d& o = centre[patch[f]];
    Eigen::Vector3d a = out.V.row(out.F(f, 0)).transpose() - o;
    Eigen::Vector3d b = out.V.row(out.F(f, 1)).transpose() - o;
    Eigen::Vector3d c = out.V.row(out.F(f, 2)).transpose() - o;
    volume[patch[f]] += a.dot(b.cross(c));
  }
  for (int f = 0; f < out.F.rows(); ++f)
    if (volume[patch[f]] < 0) {
      std::swap(out.F(f, 1), out.F(f, 2));
      turned[std::size_t(f)] ^= 1;
      ++r.flipped_faces;
    }
  if (edges) {
    // A turned face (corners 1 and 2 swapped) calls its first edge its third and the other way
    // round. The table's order is unchanged: within an edge, faces are listed by id, and a face
    // with three distinct corners holds each edge once.
    for (std::size_t k = 0; k < E.face_of.size(); ++k) {
      poll_interrupt(k, stop);
      std::int8_t& c = E.corner_of[k];
      if (turned[std::size_t(E.face_of[k])]) c = std::int8_t(c == 1 ? 1 : 2 - c);
    }
    *edges = std::move(E);
  }
  return out;
}

}  // namespace arg
