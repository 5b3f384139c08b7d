// Welding the corners of STL triangles into shared vertices, as both STL encodings need.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <unordered_map>

#include "common/hash.hpp"
#include "io/polygon_soup.hpp"

namespace arg::io {

// STL repeats every corner in every triangle; equal single-precision points become one vertex
// (0 and -0 alike), numbered in order of first appearance and stored as first seen. This is what
// OpenMesh's STL reader did, so binary STL models read before keep their vertices and bytes.
class StlWelder {
 public:
  int vertex(SoupBuilder& out, float x, float y, float z) {
    const Key key{x + 0.0f, y + 0.0f, z + 0.0f};  // + 0.0f turns -0 into 0
    auto it = index_.find(key);
    if (it == index_.end()) it = index_.emplace(key, out.add_vertex(x, y, z)).first;
    return it->second;
  }

 private:
  struct Key {
    float x, y, z;
    bool operator==(const Key& o) const { return x == o.x && y == o.y && z == o.z; }
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      char bits[12];  // the three bit patterns
      std::memcpy(bits, &k.x, 4);
      std::memcpy(bits + 4, &k.y, 4);
      std::memcpy(bits + 8, &k.z, 4);
      return static_cast<std::size_t>(fnv1a_64(std::string_view(bits, sizeof bits)));
    }
  };
  std::unordered_map<Key, int, Hash> index_;
};

// Adds a welded triangle, or counts it as skipped when two corners welded into one vertex.
inline void add_stl_triangle(SoupBuilder& out, const int corners[3]) {
  if (corners[0] == corners[1] || corners[1] == corners[2] || corners[0] == corners[2]) {
    ++out.soup().faces_seen;
    ++out.soup().faces_skipped;
    out.poll();
    return;
  }
  out.add_face(corners, 3);
}

}  // namespace arg::io
