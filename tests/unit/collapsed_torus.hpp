// A torus and its collapsed copy with the vertex map, for the tests of what the copy carries.
#pragma once

#include <vector>

#include "mesh/collapse_short_edges.hpp"
#include "test_shapes.hpp"

namespace arg::test {

struct Collapsed {
  Mesh fine, coarse;
  std::vector<int> map;  // each fine vertex's vertex of the copy (collapse_short_edges)
};

// A 120 x 45 torus collapsed to about a quarter of its vertices.
inline Collapsed collapsed_torus() {
  Collapsed c;
  c.fine = torus(2, 0.6, 120, 45);
  CollapseOptions o;
  o.min_length = 0.2;
  c.coarse = collapse_short_edges(c.fine, o, {}, &c.map);
  return c;
}

}  // namespace arg::test
