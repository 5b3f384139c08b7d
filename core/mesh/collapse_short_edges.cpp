// Collapsing short edges, topology kept: slivers of marching, coarser copies for the spectrum.
#include "common/strict_fp.hpp"  // first: it sets how arithmetic is compiled

#include "mesh/collapse_short_edges.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

#include "common/polled_sort.hpp"
#include "common/radix_sort.hpp"
#include "common/vec3.hpp"

namespace arg {
namespace {

// The live faces around each vertex, ascending (flat_around sums their normals in that order),
// in one pool: a vertex's list is a run of slots that moves to the pool's end, with twice the
// room, when a collapse outgrows it. One allocation instead of one a vertex, and neighbouring
// vertices' lists side by side.
struct FaceLists {
  std::vector<int> pool;
  std::vector<int> start, count, room;

  const int* begin(int v) const { return pool.data() + start[std::size_t(v)]; }
  const int* end(int v) const { return begin(v) + count[std::size_t(v)]; }
  int size(int v) const { return count[std::size_t(v)]; }
};

struct Work {
  std::vector<Vec3> V;
  std::vector<std::array<int, 3>> F;
  std::vector<bool> face_alive, vertex_alive;
  FaceLists faces_of;
  std::vector<int> merged_into;  // the vertex a collapse moved each one into, or itself
  // Per vertex, the last stamp that marked it as a neighbour of a collapse's first end.
  std::vector<std::uint32_t> mark;
  std::uint32_t stamp = 0;
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

// How many vertices are neighbours of both a and b (b and a themselves not counted), or 3
// once there are more than two: the link condition only asks whether it is exactly two.
int common_neighbours(Work& w, int a, int b) {
  if (w.stamp >= UINT32_MAX - 2) {
    std::fill(w.mark.begin(), w.mark.end(), 0u);
    w.stamp = 0;
  }
  const std::uint32_t of_a = ++w.stamp, counted = ++w.stamp;
  for (const int* f = w.faces_of.begin(a); f != w.faces_of.end(a); ++f)
    for (int u : w.F[std::size_t(*f)])
      if (u != a) w.mark[std::size_t(u)] = of_a;
  int common = 0;
  for (const int* f = w.faces_of.begin(b); f != w.faces_of.end(b); ++f)
    for (int u : w.F[std::size_t(*f)])
      if (u != b && w.mark[std::size_t(u)] == of_a) {
        w.mark[std::size_t(u)] = counted;
        if (++common > 2) return 3;
      }
  return common;
}

// Whether every triangle around a and b is within `cosine` of their mean normal.
bool flat_around(const Work& w, int a, int b, double cosine) {
  Vec3 mean;
  static thread_local std::vector<Vec3> normals;
  normals.clear();
  for (int v : {a, b})
    for (const int* f = w.faces_of.begin(v); f != w.faces_of.end(v); ++f) {
      const auto& t = w.F[std::size_t(*f)];
      const Vec3 n = normal_of(w.V[t[0]], w.V[t[1]], w.V[t[2]]);
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

// a's list becomes the ascending merge of a's and b's lists without the two shared faces.
void merge_lists(FaceLists& lists, int a, int b, const int shared[2]) {
  static thread_local std::vector<int> merged;
  merged.clear();
  const int *i = lists.begin(a), *ie = lists.end(a), *j = lists.begin(b), *je = lists.end(b);
  while (i != ie || j != je) {
    const int f = (j == je || (i != ie && *i < *j)) ? *i++ : *j++;
    if (f != shared[0] && f != shared[1]) merged.push_back(f);
  }
  const auto n = int(merged.size());
  auto ua = std::size_t(a);
  if (n > lists.room[ua]) {
    lists.room[ua] = std::max(2 * lists.room[ua], n);
    lists.start[ua] = int(lists.pool.size());
    lists.pool.resize(lists.pool.size() + std::size_t(lists.room[ua]));
  }
  std::copy(merged.begin(), merged.end(), lists.pool.begin() + lists.start[ua]);
  lists.count[ua] = n;
  lists.count[std::size_t(b)] = 0;
}

// Removes face f from v's list, keeping the rest in order.
void drop_face(FaceLists& lists, int v, int f) {
  int* first = lists.pool.data() + lists.start[std::size_t(v)];
  int* last = first + lists.count[std::size_t(v)];
  lists.count[std::size_t(v)] = int(std::remove(first, last, f) - first);
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
  for (const int* f = w.faces_of.begin(a); f != w.faces_of.end(a); ++f)
    if (has(w.F[std::size_t(*f)], b)) {
      if (n_shared == 2) return false;
      shared[n_shared++] = *f;
    }
  if (n_shared != 2) return false;
  const int c = third(w.F[std::size_t(shared[0])], a, b);
  const int e = third(w.F[std::size_t(shared[1])], a, b);

  // Link condition: a and b may share no neighbour but the two opposite corners, else the
  // collapse would pinch the surface (and change its topology).
  if (common_neighbours(w, a, b) != 2) return false;
  // Opposite corners of degree three would be left with two triangles folded onto each other.
  if (w.faces_of.size(c) <= 3 || w.faces_of.size(e) <= 3) return false;

  const Vec3 mid = (w.V[a] + w.V[b]) * 0.5;
  for (int v : {a, b})
    for (const int* fp = w.faces_of.begin(v); fp != w.faces_of.end(v); ++fp) {
      const int f = *fp;
      if (f == shared[0] || f == shared[1]) continue;
      const auto& t = w.F[std::size_t(f)];
      std::array<Vec3, 3> p = {w.V[t[0]], w.V[t[1]], w.V[t[2]]};
      const Vec3 before = normal_of(p[0], p[1], p[2]);
      for (int k = 0; k < 3; ++k)
        if (t[k] == v) p[k] = mid;
      const Vec3 after = normal_of(p[0], p[1], p[2]);
      const double aa = dot(after, after);
      if (aa <= min_area2) return false;
      // Keep the turn of each triangle under 60 degrees: cos > 0.5.
      const double cosine = dot(before, after);
      if (cosine <= 0 || cosine * cosine <= 0.25 * dot(before, before) * aa) return false;
    }

  for (int f : shared) {
    w.face_alive[std::size_t(f)] = false;
    for (int v : w.F[std::size_t(f)])
      if (v != a && v != b) drop_face(w.faces_of, v, f);
  }
  for (const int* f = w.faces_of.begin(b); f != w.faces_of.end(b); ++f)
    if (*f != shared[0] && *f != shared[1])
      for (int& v : w.F[std::size_t(*f)])
        if (v == b) v = a;
  merge_lists(w.faces_of, a, b, shared);
  w.vertex_alive[std::size_t(b)] = false;
  w.merged_into[std::size_t(b)] = a;
  w.V[std::size_t(a)] = mid;
  return true;
}

// An edge to try, ordered by length, then by its ends: a total order (each edge is listed
// once), so any sort gives the one order. Squared lengths are never negative, so their bits
// compare as the values do.
struct Candidate {
  std::uint64_t length_bits;
  std::uint64_t ends;  // a in the high half, b in the low: compares as the pair (a, b)
  bool operator<(const Candidate& o) const {
    return length_bits < o.length_bits || (length_bits == o.length_bits && ends < o.ends);
  }
};

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
  FaceLists& lists = w.faces_of;
  lists.count.assign(nv, 0);
  for (std::size_t f = 0; f < nf; ++f) {
    poll_interrupt(f, stop);
    for (int k = 0; k < 3; ++k) {
      w.F[f][k] = mesh.F(static_cast<Eigen::Index>(f), k);
      ++lists.count[std::size_t(w.F[f][k])];
    }
  }
  // Each list starts with room for two more faces than it holds: a collapse adds a few.
  lists.start.resize(nv);
  lists.room.resize(nv);
  std::size_t total = 0;
  for (std::size_t v = 0; v < nv; ++v) {
    lists.start[v] = int(total);
    lists.room[v] = lists.count[v] + 2;
    total += std::size_t(lists.room[v]);
    lists.count[v] = 0;
  }
  lists.pool.resize(total);
  for (std::size_t f = 0; f < nf; ++f) {
    poll_interrupt(f, stop);
    for (int v : w.F[f])
      lists.pool[std::size_t(lists.start[std::size_t(v)] + lists.count[std::size_t(v)]++)] = int(f);
  }
  w.face_alive.assign(nf, true);
  w.vertex_alive.assign(nv, true);
  w.mark.assign(nv, 0);
  w.merged_into.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) w.merged_into[v] = static_cast<int>(v);

  const double reach = std::max(options.min_length, options.flat_length);
  const double reach2 = reach * reach;
  // A triangle's doubled area must stay above a millionth of a short edge squared.
  const double min_area2 =
      1e-12 * options.min_length * options.min_length * options.min_length * options.min_length;
  std::vector<Candidate> candidates, sorted;
  for (int pass = 0; pass < 4; ++pass) {
    candidates.clear();
    for (std::size_t f = 0; f < nf; ++f) {
      poll_interrupt(f, stop);
      if (!w.face_alive[f]) continue;
      for (int k = 0; k < 3; ++k) {
        const int a = w.F[f][k], b = w.F[f][(k + 1) % 3];
        if (a > b) continue;  // each edge once (its other triangle lists it as b, a)
        const Vec3 d = w.V[std::size_t(a)] - w.V[std::size_t(b)];
        const double len2 = dot(d, d);
        if (len2 < reach2) {
          std::uint64_t bits;
          std::memcpy(&bits, &len2, sizeof bits);
          candidates.push_back({bits, std::uint64_t(a) << 32 | std::uint32_t(b)});
        }
      }
    }
    // By length in linear time, then each run of equal lengths (a regular mesh has many) by
    // its ends: the one order a sort by (length, ends) gives.
    radix_sort_by_key(
        candidates, [](const Candidate& c) { return c.length_bits; }, sorted, stop);
    for (std::size_t i = 0, runs = 0; i < candidates.size(); ++runs) {
      std::size_t j = i + 1;
      while (j < candidates.size() && candidates[j].length_bits == candidates[i].length_bits) ++j;
      if (j - i > 1)
        polled_sort(candidates.begin() + i, candidates.begin() + j, std::less<>(), stop);
      poll_interrupt(runs, stop);
      i = j;
    }
    int collapsed = 0;
    std::size_t tried = 0;
    for (const Candidate& edge : candidates) {
      // A collapse looks at two neighbourhoods (a few microseconds): poll every 256.
      if ((tried++ & 255u) == 0) check_interrupt(stop);
      const auto a = int(edge.ends >> 32), b = int(std::uint32_t(edge.ends));
      if (!w.vertex_alive[std::size_t(a)] || !w.vertex_alive[std::size_t(b)]) continue;
      collapsed += try_collapse(w, a, b, options, min_area2);
    }
    if (collapsed == 0) break;
  }

  std::vector<int> new_index(nv, -1);
  int next = 0;
  for (std::size_t v = 0; v < nv; ++v) {
    poll_interrupt(v, stop);
    if (w.vertex_alive[v] && lists.size(int(v)) > 0) new_index[v] = next++;
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
    for (int k = 0; k < 3; ++k) out.F(row, k) = new_index[std::size_t(w.F[f][k])];
    if (mesh.has_colour()) out.C.row(row) = mesh.C.row(static_cast<Eigen::Index>(f));
    ++row;
  }
  return out;
}

}  // namespace arg
