// Our own strict parser for ASCII STL, which OpenMesh's reader parses too loosely.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>

#include "io/format_readers.hpp"
#include "io/text_scan.hpp"

namespace arg::io {

namespace {

struct CornerKey {
  float x, y, z;
  bool operator==(const CornerKey& o) const { return x == o.x && y == o.y && z == o.z; }
};

struct CornerHash {
  std::size_t operator()(const CornerKey& k) const {
    std::uint32_t b[3];
    std::memcpy(&b[0], &k.x, 4);
    std::memcpy(&b[1], &k.y, 4);
    std::memcpy(&b[2], &k.z, 4);
    std::uint64_t h = 1469598103934665603ull;
    for (std::uint32_t v : b) h = (h ^ v) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

}  // namespace

// OpenMesh's read_stla looks for "outer" and "facet normal" anywhere in a line (a solid named
// "outer_shell" starts a bogus triangle) and never checks that a vertex line held three numbers
// (a malformed or NaN vertex silently repeats the previous one). This parser follows the grammar
// solid / facet normal / outer loop / vertex x3 / endloop / endfacet / endsolid, keyword by
// keyword, and welds equal corners exactly as OpenMesh does for binary STL (so both read alike).
void read_stl_ascii(std::string_view bytes, SoupBuilder& out, ReadReport& report) {
  report.variant = "ascii";
  LineScanner lines(bytes);
  out.set_locator([&] { return "line " + std::to_string(lines.line_number()); });
  out.set_immediate_index_check(true);
  std::vector<std::string_view> tokens;
  std::string_view line;
  auto next = [&](const char* expected) {
    if (!lines.next_content(line, false)) {
      out.fail(std::string("unexpected end of data: expected ") + expected);
    }
    split_tokens(line, tokens, 8);
  };
  auto expect = [&](const char* keyword, const char* second = nullptr) {
    next(keyword);
    if (!iequals(tokens[0], keyword) ||
        (second && (tokens.size() < 2 || !iequals(tokens[1], second)))) {
      out.fail(std::string("expected '") + keyword + (second ? std::string(" ") + second : "") +
               "', found '" + std::string(tokens[0]) + "'");
    }
  };
  std::unordered_map<CornerKey, int, CornerHash> welded;
  std::vector<int> corners;
  std::size_t solids = 0;
  while (lines.next_content(line, false)) {
    split_tokens(line, tokens, 8);
    if (!iequals(tokens[0], "solid")) {
      out.fail("expected 'solid', found '" + std::string(tokens[0]) + "'");
    }
    ++solids;
    for (;;) {
      next("'facet' or 'endsolid'");
      if (iequals(tokens[0], "endsolid")) break;
      if (!iequals(tokens[0], "facet")) {
        out.fail("expected 'facet' or 'endsolid', found '" + std::string(tokens[0]) + "'");
      }
      expect("outer", "loop");
      corners.clear();
      for (;;) {
        next("'vertex' or 'endloop'");
        if (iequals(tokens[0], "endloop")) break;
        if (!iequals(tokens[0], "vertex")) {
          out.fail("expected 'vertex' or 'endloop', found '" + std::string(tokens[0]) + "'");
        }
        double p[3];
        if (tokens.size() != 4 || !parse_real(tokens[1], p[0]) || !parse_real(tokens[2], p[1]) ||
            !parse_real(tokens[3], p[2])) {
          out.fail("a vertex needs 3 coordinates");
        }
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
          out.fail("vertex coordinate is not a finite number");
        }
        // Binary STL stores single precision, and OpenMesh welds in single precision.
        CornerKey key{static_cast<float>(p[0]) + 0.0f, static_cast<float>(p[1]) + 0.0f,
                      static_cast<float>(p[2]) + 0.0f};
        auto it = welded.find(key);
        if (it == welded.end()) {
          it = welded.emplace(key, out.add_vertex(key.x, key.y, key.z)).first;
        }
        corners.push_back(it->second);
        if (corners.size() > out.limits().max_triangles + 2) out.fail_limit("a facet is too large");
      }
      expect("endfacet");
      if (corners.size() < 3) out.fail("a facet needs 3 vertices");
      // Like OpenMesh, drop triangles whose corners welded together.
      if (corners.size() == 3 &&
          (corners[0] == corners[1] || corners[1] == corners[2] || corners[0] == corners[2])) {
        ++out.soup().faces_seen;
        ++out.soup().faces_skipped;
        continue;
      }
      out.add_face(corners.data(), corners.size());
    }
  }
  if (solids == 0) out.fail("expected 'solid'");
  out.set_locator({});
}

}  // namespace arg::io
