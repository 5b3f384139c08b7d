// Collapsing short edges, topology kept: slivers of marching, coarser copies for the spectrum.
#include "common/strict_fp.hpp"  // first: it sets how arithmetic is compiled

#include "mesh/collapse_short_edges.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <tuple>
#include <vector>

#include "common/polled_sort.hpp"
#include "common/vec3.hpp"

namespace arg {
namespace {

struct Work {
  std::vector<Vec3> V;
  std::vector<std::array<int, 3>> F;
  std::vector<bool> face_alive, vertex_alive;
  std::vector<std::vector<int>> faces_of;  // live faces around each vertex
  std::vector<int> merged_into;            // the vertex a collapse moved each one into, or itself
};

bool has(const std::array<int, 3>& f, int v) {
  return f[0] == v || f[1] == v || f[2] == v;
}

int third(const std::array<int, 3>& f, int a, int b) {
  for (int v : f)
    if (v != a && v != b) return v;
  return -1;
}

Vec3 normal_of(const Vec3& a, const Vec3& b, const Vec3& c) {
  return cross(b - a, c - a);
}

void neighbours(const Work& w, int v, std::vector<int>& out) {
  out.clear();
  for (int f : w.faces_of[v])
    for (int u : w.F[f])
      if (u != v) out.push_back(u);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

// Whether every triangle around a and b is within `cosine` of their mean normal.
bool flat_around(const Work& w, int a, int b, double cosine) {
  Vec3 mean;
  static thread_local std::vector<Vec3> normals;
  normals.clear();
  for (int v : {a, b})
    for (int f : w.faces_of[v]) {
      const Vec3 n = normal_of(w.V[w.F[f][0]], w.V[w.F[f][1]], w.V[w.F[f][2]]);
      const double len = length(n);
      if (len == 0) return false;
      normals.push_back(n * (1.0 / len));
      mean = mean + normals.back();
    }
  const double len = length(mean);
  if (len == 0) return false;
  for (const Vec3& n : normals)
    if (dot(n, mean) < cosine * len) return false;
  return true;
}

// Tries to collapse edge (a, b) into its midpoint; returns whether it did.
bool try_collapse(Work& w, int a, int b, const CollapseOptions& options, double min_area2) {
  const Vec3 d = w.V[a] - w.V[b];
  const double len2 = dot(d, d);
  if (len2 >= options.min_length * options.min_length) {
    if (len2 >= options.flat_length * options.flat_length) return false;
    if (!flat_around(w, a, b, options.flat_cosine)) return false;
  }
  int shared[2], n_shared = 0;
  for (int f : w.faces_of[a])
    if (has(w.F[f], b)) {
      if (n_shared == 2) return false;
      shared[n_shared++] = f;
    }
  if (n_shared != 2) return false;
  const int c = third(w.F[shared[0]], a, b), e = third(w.F[shared[1]], a, b);

  // Link condition: a and b may share no neighbour but the two opposite corners, else the
  // collapse would pinch the surface (and change its topology).
  static thread_local std::vector<int> na, nb;
  neighbours(w, a, na);
  neighbours(w, b, nb);
  int common = 0;
  for (std::size_t i = 0, j = 0; i < na.size() && j < nb.size();) {
    if (na[i] < nb[j]) {
      ++i;
    } else if (nb[j] < na[i]) {
      ++j;
    } else {
      ++common, ++i, ++j;
    }
  }
  if (common != 2) return false;
  // Opposite corners of degree three would be left with two triangles folded onto each other.
  if (w.faces_of[c].size() <= 3 || w.faces_of[e].size() <= 3) return false;

  const Vec3 mid = (w.V[a] + w.V[b]) * 0.5;
  for (int v : {a, b})
    for (int f : w.faces_of[v]) {
      if (f == shared[0] || f == shared[1]) continue;
      std::array<Vec3, 3> p = {w.V[w.F[f][0]], w.V[w.F[f][1]], w.V[w.F[f][2]]};
      const Vec3 before = normal_of(p[0], p[1], p[2]);
      for (int k = 0; k < 3; ++k)
        if (w.F[f][k] == v) p[k] = mid;
      const Vec3 after = normal_of(p[0], p[1], p[2]);
      const double aa = dot(after, after);
      if (aa <= min_area2) return false;
      // Keep the turn of each triangle under 60 degrees: cos > 0.5.
      const double cosine = dot(before, after);
      if (cosine <= 0 || cosine * cosine <= 0.25 * dot(before, before) * aa) return false;
    }

  for (int f : shared) {
    w.face_alive[f] = false;
    for (int v : w.F[f]) {
      auto& list = w.faces_of[v];
      list.erase(std::remove(list.begin(), list.end(), f), list.end());
    }
  }
  for (int f : w.faces_of[b]) {
    for (int& v : w.F[f])
      if (v == b) v = a;
    w.faces_of[a].push_back(f);
  }
  std::sort(w.faces_of[a].begin(), w.faces_of[a].end());
  w.faces_of[b].clear();
  w.vertex_alive[b] = false;
  w.merged_into[b] = a;
  w.V[a] = mid;
  return true;
}

}  // namespace

Mesh collapse_short_edges(const Mesh& mesh, const CollapseOptions& options,
                          const StopRequested& stop, std::vector<int>* vertex_map) {
  Work w;
  const auto nv = static_cast<std::size_t>(mesh.V.rows());
  const auto nf = static_cast<std::size_t>(mesh.F.rows());
  w.V.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    poll_interrupt(v, stop);
    const auto r = static_cast<Eigen::Index>(v);
    w.V[v] = {mesh.V(r, 0), mesh.V(r, 1), mesh.V(r, 2)};
  }
  w.F.resize(nf);
  w.faces_of.resize(nv);
  for (std::size_t f = 0; f < nf; ++f) {
    poll_interrupt(f, stop);
    for (int k = 0; k < 3; ++k) {
      w.F[f][k] = mesh.F(static_cast<Eigen::Index>(f), k);
      w.faces_of[w.F[f][k]].push_back(static_cast<int>(f));
    }
  }
  w.face_alive.assign(nf, true);
  w.vertex_alive.assign(nv, true);
  w.merged_into.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) w.merged_into[v] = static_cast<int>(v);

  const double reach = std::max(options.min_length, options.flat_length);
  const double reach2 = reach * reach;
  // A triangle's doubled area must stay above a millionth of a short edge squared.
  const double min_area2 =
      1e-12 * options.min_length * options.min_length * options.min_length * options.min_length;
  for (int pass = 0; pass < 4; ++pass) {
    std::vector<std::tuple<double, int, int>> candidates;
    for (std::size_t f = 0; f < nf; ++f) {
      poll_interrupt(f, stop);
      if (!w.face_alive[f]) continue;
      for (int k = 0; k < 3; ++k) {
        const int a = w.F[f][k], b = w.F[f][(k + 1) % 3];
        if (a > b) continue;  // each edge once (its other triangle lists it as b, a)
        const Vec3 d = w.V[a] - w.V[b];
        if (dot(d, d) < reach2) candidates.emplace_back(dot(d, d), a, b);
      }
    }
    polled_sort(candidates.begin(), candidates.end(), std::less<>(), stop);
    int collapsed = 0;
    std::size_t tried = 0;
    for (const auto& [len2, a, b] : candidates) {
      // A collapse looks at two neighbourhoods (a few microseconds): poll every 256.
      if ((tried++ & 255u) == 0) check_interrupt(stop);
      if (!w.vertex_alive[a] || !w.vertex_alive[b]) continue;
      collapsed += try_collapse(w, a, b, options, min_area2);
    }
    if (collapsed == 0) break;
  }

  std::vector<int> new_index(nv, -1);
  int next = 0;
  for (std::size_t v = 0; v < nv; ++v) {
    poll_interrupt(v, stop);
    if (w.vertex_alive[v] && !w.faces_of[v].empty()) new_index[v] = next++;
  }
  if (vertex_map) {
    // A merged vertex's target may itself have merged later: follow the chain to a survivor.
    vertex_map->assign(nv, -1);
    for (std::size_t v = 0; v < nv; ++v) {
      poll_interrupt(v, stop);
      int root = static_cast<int>(v);
      while (w.merged_into[std::size_t(root)] != root) root = w.merged_into[std::size_t(root)];
      for (int u = static_cast<int>(v); u != root;) {  // path compression: linear overall
        const int up = w.merged_into[std::size_t(u)];
        w.merged_into[std::size_t(u)] = root;
        u = up;
      }
      (*vertex_map)[v] = new_index[std::size_t(root)];
    }
  }
  Mesh out;
  out.V.resize(next, 3);
  for (std::size_t v = 0; v < nv; ++v) {
    if (new_index[v] < 0) continue;
    out.V(new_index[v], 0) = w.V[v].x;
    out.V(new_index[v], 1) = w.V[v].y;
    out.V(new_index[v], 2) = w.V[v].z;
  }
  const auto live =
      static_cast<Eigen::Index>(std::count(w.face_alive.begin(), w.face_alive.end(), true));
  out.F.resize(live, 3);
  if (mesh.has_colour()) out.C.resize(live, 3);
  Eigen::Index row = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    poll_interrupt(f, stop);
    if (!w.face_alive[f]) continue;
    for (int k = 0; k < 3; ++k) out.F(row, k) = new_index[w.F[f][k]];
    if (mesh.has_colour()) out.C.row(row) = mesh.C.row(static_cast<Eigen::Index>(f));
    ++row;
  }
  // Freed list by list, polling: a million small lists take a few hundred milliseconds to free.
  for (std::size_t v = 0; v < nv; ++v) {
    poll_interrupt(v, stop);
    std::vector<int>().swap(w.faces_of[v]);
  }
  return out;
}

}  // namespace arg
