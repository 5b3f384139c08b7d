// Reading ASCII STL with a parser of our own, keyword by keyword.
//
// Not OpenMesh's reader: its read_stla looks for "outer" and "facet normal" anywhere in a line (a
// solid named "outer_shell" starts a bogus triangle) and never checks that a vertex line held
// three numbers (a malformed or NaN vertex silently repeats the previous one).
#include <cmath>
#include <string>
#include <vector>

#include "io/format_readers.hpp"
#include "io/stl_welder.hpp"
#include "io/text_scan.hpp"

namespace arg::io {

// The grammar: solid / facet normal / outer loop / vertex x3 / endloop / endfacet / endsolid,
// any number of solids; corners are welded as in binary STL, so both encodings read alike.
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
  StlWelder welded;
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
        float p[3];
        if (tokens.size() != 4 || !parse_real(tokens[1], p[0]) || !parse_real(tokens[2], p[1]) ||
            !parse_real(tokens[3], p[2])) {
          out.fail("a vertex needs 3 coordinates");
        }
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
          out.fail("vertex coordinate is not a finite number");
        }
        // Binary STL stores single precision: round the text once, straight to float.
        corners.push_back(welded.vertex(out, p[0], p[1], p[2]));
        if (corners.size() > out.limits().max_triangles + 2) out.fail_limit("a facet is too large");
      }
      expect("endfacet");
      if (corners.size() < 3) out.fail("a facet needs 3 vertices");
      if (corners.size() == 3) {
        add_stl_triangle(out, corners.data());
      } else {
        out.add_face(corners.data(), corners.size());  // a polygon, triangulated later
      }
    }
  }
  if (solids == 0) out.fail("expected 'solid'");
  out.set_locator({});
}

}  // namespace arg::io
