// Pictures of models and matches: deterministic, not blank, every node drawn; the graph SVG.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "gen/generate_models.hpp"
#include "match/similarity.hpp"
#include "match/similarity_terms.hpp"
#include "oiio/write_png.hpp"
#include "pipeline/build_arg.hpp"
#include "pipeline/node_positions.hpp"
#include "reeb/slice_intervals.hpp"
#include "render/bitmap_font.hpp"
#include "render/colour_map.hpp"
#include "render/contact_sheet.hpp"
#include "render/graph_svg.hpp"
#include "render/match_picture.hpp"
#include "render/render_model.hpp"
#include "render/view_camera.hpp"

using namespace arg;

namespace {

// A generated model with its ARG and node positions, built once per test program.
struct Model {
  Mesh mesh;
  ArgGraph graph;
  NodePositions positions;
};

const Model& model(const std::string& label, int variant) {
  static std::map<std::pair<std::string, int>, Model> cache;
  auto it = cache.find({label, variant});
  if (it == cache.end()) {
    Model m;
    m.mesh = generate_model(label, variant, 40).mesh;
    m.graph = build_arg(m.mesh);
    m.positions = node_positions(m.mesh);
    it = cache.emplace(std::make_pair(label, variant), std::move(m)).first;
  }
  return it->second;
}

int nodes_at(const ArgGraph& g, int level) {
  return int(g.level_begin[std::size_t(level) + 1] - g.level_begin[std::size_t(level)]);
}

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

// A small well-formedness check of XML as the SVG writer produces it: one root element, tags
// balanced and properly nested, attributes quoted, no raw '<' in values, '&' only in entities.
// Returns an empty string when well formed, otherwise what is wrong.
std::string xml_problem(const std::string& xml) {
  std::vector<std::string> open;
  int roots = 0;
  auto name_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == ':' ||
           c == '.';
  };
  auto entity_ok = [&](std::size_t at) {
    for (const char* e : {"&lt;", "&gt;", "&amp;", "&quot;", "&apos;"})
      if (xml.compare(at, std::strlen(e), e) == 0) return true;
    if (xml.compare(at, 2, "&#") == 0) {
      const std::size_t end = xml.find(';', at);
      return end != std::string::npos && end > at + 2 && end < at + 10;
    }
    return false;
  };
  std::size_t i = 0;
  while (i < xml.size()) {
    if (xml[i] != '<') {
      if (open.empty() && !std::isspace(static_cast<unsigned char>(xml[i])))
        return "text outside the root element at " + std::to_string(i);
      if (xml[i] == '&' && !entity_ok(i)) return "bare '&' at " + std::to_string(i);
      if (xml[i] == '>') return "bare '>' at " + std::to_string(i);
      ++i;
      continue;
    }
    if (xml.compare(i, 4, "<!--") == 0) {
      const std::size_t end = xml.find("-->", i);
      if (end == std::string::npos) return "unterminated comment";
      i = end + 3;
      continue;
    }
    if (xml.compare(i, 2, "<?") == 0) {
      const std::size_t end = xml.find("?>", i);
      if (end == std::string::npos) return "unterminated declaration";
      i = end + 2;
      continue;
    }
    const bool closing = xml.compare(i, 2, "</") == 0;
    std::size_t j = i + (closing ? 2 : 1);
    const std::size_t name_start = j;
    while (j < xml.size() && name_char(xml[j])) ++j;
    const std::string name = xml.substr(name_start, j - name_start);
    if (name.empty()) return "tag without a name at " + std::to_string(i);
    bool self_closing = false;
    for (;;) {
      while (j < xml.size() && std::isspace(static_cast<unsigned char>(xml[j]))) ++j;
      if (j >= xml.size()) return "unterminated tag <" + name;
      if (xml[j] == '>') break;
      if (xml.compare(j, 2, "/>") == 0 && !closing) {
        self_closing = true;
        ++j;
        break;
      }
      if (closing) return "attributes in closing tag </" + name;
      const std::size_t attr_start = j;
      while (j < xml.size() && name_char(xml[j])) ++j;
      if (j == attr_start) return "bad attribute in <" + name + " at " + std::to_string(j);
      if (j >= xml.size() || xml[j] != '=') return "attribute without value in <" + name;
      ++j;
      if (j >= xml.size() || (xml[j] != '"' && xml[j] != '\'')) return "unquoted attribute";
      const char quote = xml[j++];
      for (; j < xml.size() && xml[j] != quote; ++j) {
        if (xml[j] == '<') return "'<' in an attribute value of <" + name;
        if (xml[j] == '&' && !entity_ok(j)) return "bare '&' in an attribute of <" + name;
      }
      if (j >= xml.size()) return "unterminated attribute value in <" + name;
      ++j;
    }
    i = j + 1;
    if (closing) {
      if (open.empty() || open.back() != name) return "</" + name + "> closes nothing open";
      open.pop_back();
    } else {
      if (open.empty() && ++roots > 1) return "more than one root element";
      if (!self_closing) open.push_back(name);
    }
  }
  if (!open.empty()) return "<" + open.back() + "> is never closed";
  if (roots != 1) return "no root element";
  return "";
}

struct PixelStats {
  std::size_t colours = 0;
  double foreground = 0;  // share of pixels that differ from the background
};

PixelStats pixel_stats(const Image& image) {
  std::set<std::uint32_t> colours;
  std::size_t foreground = 0;
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
    const Rgb c{image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]};
    colours.insert(std::uint32_t(c.r) << 16 | std::uint32_t(c.g) << 8 | c.b);
    if (!(c == kRenderBackground)) ++foreground;
  }
  return {colours.size(), double(foreground) / double(image.rgb.size() / 3)};
}

}  // namespace

TEST(Render, TheSameModelGivesTheSameBytesTwice) {
  const Model& m = model("human", 0);
  RenderOptions o;
  o.title = "human_00";
  const RenderedModel first = render_model(m.positions, o);
  const RenderedModel second = render_model(node_positions(m.mesh), o);
  EXPECT_EQ(first.image.rgb, second.image.rgb);
  const auto dir = std::filesystem::temp_directory_path();
  const std::string a = (dir / "arg_test_render_a.png").string(),
                    b = (dir / "arg_test_render_b.png").string();
  write_png(first.image, a);
  write_png(second.image, b);
  const std::string bytes = file_bytes(a);
  EXPECT_GT(bytes.size(), 1000u);
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
  EXPECT_EQ(bytes, file_bytes(b));
  std::filesystem::remove(a);
  std::filesystem::remove(b);
}

TEST(Render, PictureIsNotBlank) {
  for (const char* label : {"human", "cup", "torus"}) {
    for (Shading shading : {Shading::Smooth, Shading::Flat}) {
      RenderOptions o;
      o.shading = shading;
      const PixelStats s = pixel_stats(render_model(model(label, 0).positions, o).image);
      EXPECT_GT(s.colours, 200u) << label;  // shading and the colour ramp give many colours
      EXPECT_GT(s.foreground, 0.12) << label;
      EXPECT_LT(s.foreground, 0.85) << label;
    }
  }
  // Without the graph and legend the surface alone still fills a plausible share.
  RenderOptions bare;
  bare.graph = bare.legend = false;
  const PixelStats s = pixel_stats(render_model(model("cup", 0).positions, bare).image);
  EXPECT_GT(s.foreground, 0.12);
}

TEST(Render, OwnColoursPaintEachFaceItsColourWithoutTheRamp) {
  // A red model: lit red is (r, s, s) with s the highlight, and the white background keeps
  // g = b where edges are averaged; mu's ramp would give pixels with g != b.
  NodePositions red = model("cup", 0).positions;
  red.mesh.C.setZero(red.mesh.F.rows(), 3);
  red.mesh.C.col(0).setOnes();
  RenderOptions o;
  o.graph = o.legend = false;
  o.own_colours = true;
  const Image own = render_model(red, o).image;
  std::size_t reddish = 0, unequal = 0;
  for (std::size_t i = 0; i < own.rgb.size(); i += 3) {
    if (own.rgb[i + 1] != own.rgb[i + 2]) ++unequal;
    if (own.rgb[i] > own.rgb[i + 1] + 60) ++reddish;
  }
  EXPECT_EQ(unequal, 0u);
  EXPECT_GT(double(reddish) / double(own.rgb.size() / 3), 0.1);
  o.own_colours = false;
  const Image mu = render_model(red, o).image;
  unequal = 0;
  for (std::size_t i = 0; i < mu.rgb.size(); i += 3) unequal += mu.rgb[i + 1] != mu.rgb[i + 2];
  EXPECT_GT(unequal, 1000u) << "mu's colours are not the model's";
}

TEST(Render, OverlayDrawsEveryNodeOfTheLevel) {
  for (const char* label : {"human", "fourleg", "cup"}) {
    const Model& m = model(label, 1);
    for (int level = 0; level <= 3; ++level) {
      RenderOptions o;
      o.level = level;
      o.width = 320, o.height = 256;
      const RenderedModel r = render_model(m.positions, o);
      ASSERT_EQ(int(r.nodes.size()), nodes_at(m.graph, level)) << label << " level " << level;
      for (const DrawnNode& d : r.nodes) {
        EXPECT_GE(d.x, 0);
        EXPECT_LT(d.x, o.width);
        EXPECT_GE(d.y, 0);
        EXPECT_LT(d.y, o.height);
        EXPECT_GE(d.radius, 3);
      }
    }
  }
  RenderOptions too_fine;
  too_fine.level = model("cup", 1).graph.levels() + 1;
  EXPECT_THROW(render_model(model("cup", 1).positions, too_fine), InputError);
}

TEST(Render, NodePositionsAgreeWithTheArgBarycentres) {
  const Model& m = model("fourleg", 0);
  ASSERT_EQ(int(m.positions.levels.size()), m.graph.levels() + 1);
  for (int level = 0; level <= m.graph.levels(); ++level) {
    const NodePlacementLevel& p = m.positions.levels[std::size_t(level)];
    ASSERT_EQ(int(p.centre.size()), nodes_at(m.graph, level));
    double area_sum = 0;
    for (std::size_t i = 0; i < p.centre.size(); ++i) {
      const ArgNode& n = m.graph.nodes[m.graph.level_begin[std::size_t(level)] + i];
      const Eigen::Vector3d& c = p.centre[i];
      // The ARG stores r, theta and phi in one byte each (format 3): half a step apart at most.
      EXPECT_NEAR(c.norm(), n.r, 0.5 * 4.0 / 255 + 1e-4);
      if (c.norm() > 1e-3) {
        EXPECT_NEAR(std::acos(c.z() / c.norm()), n.phi, 0.5 * M_PI / 255 + 1e-4);
      }
      if (std::fabs(c.x()) > 1e-3) {
        EXPECT_NEAR(std::atan(c.y() / c.x()), n.theta, 0.5 * M_PI / 255 + 1e-4);
      }
      EXPECT_NEAR(p.area[i], n.a * (m.graph.levels() + 1), 1e-4);
      EXPECT_EQ(p.interval[i], n.interval);
      area_sum += p.area[i];
    }
    EXPECT_NEAR(area_sum, 1.0, 1e-9);
  }
  // node_at: the centre of every triangle belongs to a node of its own interval.
  const Mesh& mesh = m.positions.mesh;
  for (Eigen::Index f = 0; f < mesh.F.rows(); f += 7) {
    const double mu =
        (m.positions.mu[std::size_t(mesh.F(f, 0))] + m.positions.mu[std::size_t(mesh.F(f, 1))] +
         m.positions.mu[std::size_t(mesh.F(f, 2))]) /
        3;
    const int node = node_at(m.positions, 2, int(f), mu);
    ASSERT_GE(node, 0);
    ASSERT_LT(node, nodes_at(m.graph, 2));
    EXPECT_EQ(m.positions.levels[2].interval[std::size_t(node)], interval_of(mu, 4));
  }
  EXPECT_EQ(node_at(m.positions, 9, 0, 0.5), -1);
  EXPECT_EQ(node_at(m.positions, 2, -1, 0.5), -1);
}

TEST(Render, ViewsParseAndStayOrthonormal) {
  for (const char* view : {"front", "side", "top", "30,20", "-45,90", "10,20,180"}) {
    const Eigen::Matrix3d r = parse_view(view);
    EXPECT_TRUE((r * r.transpose()).isIdentity(1e-12)) << view;
    EXPECT_NEAR(r.determinant(), 1.0, 1e-12) << view;
  }
  // front looks along the smallest principal axis with the largest one up.
  const Eigen::Matrix3d front = parse_view("front");
  EXPECT_TRUE(front.row(1).isApprox(Eigen::RowVector3d(1, 0, 0)));
  EXPECT_TRUE(front.row(2).isApprox(Eigen::RowVector3d(0, 0, 1)));
  for (const char* bad : {"", "left", "10", "1,2,3,4", "a,b", "0,91", "10,20x", "nan,0"})
    EXPECT_THROW(parse_view(bad), InputError) << bad;
  EXPECT_EQ(parse_shading("flat"), Shading::Flat);
  EXPECT_THROW(parse_shading("gouraud"), InputError);
}

TEST(Render, BitmapFontDrawsTextOfTheExpectedWidth) {
  EXPECT_EQ(text_width("0.5", 1), 17);
  EXPECT_EQ(text_width("0.5", 2), 34);
  EXPECT_EQ(text_width("", 2), 0);
  Image image = make_canvas(80, 12, {255, 255, 255});
  draw_text(image, 1, 1, "SIM = 0.25", {0, 0, 0});
  const PixelStats s = pixel_stats(image);
  EXPECT_EQ(s.colours, 2u);
  EXPECT_GT(s.foreground, 0.03);
  // Glyphs differ from each other, and an unknown character draws as '?'.
  auto ink = [](const std::string& text) {
    Image i = make_canvas(8, 10, {255, 255, 255});
    draw_text(i, 1, 1, text, {0, 0, 0});
    return i.rgb;
  };
  std::set<std::vector<std::uint8_t>> glyphs;
  const std::string alphabet =
      "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz.-=_:,()/+%#";
  for (char c : alphabet) glyphs.insert(ink(std::string(1, c)));
  EXPECT_EQ(glyphs.size(), alphabet.size());
  EXPECT_EQ(ink("~"), ink("?"));
}

TEST(Render, ColourMapsAreOrderedAndDistinct) {
  // Blue at 0, red at 1, and different colours for the first dozen pairs.
  EXPECT_GT(mu_colour(0).b, mu_colour(0).r);
  EXPECT_GT(mu_colour(1).r, mu_colour(1).b);
  std::set<std::uint32_t> seen;
  for (int k = 0; k < 36; ++k) {
    const Rgb c = pair_colour(k);
    seen.insert(std::uint32_t(c.r) << 16 | std::uint32_t(c.g) << 8 | c.b);
  }
  EXPECT_EQ(seen.size(), 36u);
}

TEST(Render, SimilarityTermsAddUpToOneMinusTheGraphsSim) {
  const Model &a = model("human", 0), &b = model("human", 1), &c = model("cup", 0);
  for (const Weights& w : {Weights{}, parse_weights("arg level_ratio=0.5")})
    for (const auto& [x, y] : {std::make_pair(&a, &b), std::make_pair(&b, &a),
                               std::make_pair(&a, &c), std::make_pair(&a, &a)}) {
      std::vector<MatchPair> pairs;
      const double sim = graph_similarity(x->graph, y->graph, w, &pairs);
      const SimilarityTerms t = similarity_terms(x->graph, y->graph, w, pairs);
      // SIM of a graph with itself is 0 by definition; the terms sum byte-coded histograms whose
      // totals equal the node areas only to a code (1/255 of the area, format 3).
      EXPECT_NEAR(t.total(), 1 - sim, x == y ? 1e-3 : 1e-9);
      for (double term : {t.a, t.l, t.v, t.cords, t.curvature, t.colour}) EXPECT_GE(term, 0);
    }
  const Weights w;
  // Colour weighs nothing unless both models have colour.
  Model grey = model("human", 1);
  grey.graph.summary.has_colour = 0;
  std::vector<MatchPair> pairs;
  arg_similarity(a.graph, grey.graph, w, &pairs);
  EXPECT_EQ(similarity_terms(a.graph, grey.graph, w, pairs).colour, 0);
}

TEST(Render, MatchPictureLinksTheMatchedNodes) {
  const Model &a = model("human", 0), &b = model("human", 1);
  std::vector<MatchPair> pairs;
  arg_similarity(a.graph, b.graph, Weights{}, &pairs);
  MatchPictureOptions o;
  o.panel = 256;
  o.level = 2;
  o.notes = {"SIM = 0.5", "a second line"};
  const MatchPicture p = render_match_picture(a.positions, b.positions, pairs, o);
  EXPECT_EQ(p.image.width, 512);
  EXPECT_GT(p.image.height, 256);
  int rows = 0;
  std::set<int> in_a, in_b;
  for (const MatchPair& m : pairs)
    if (m.level == 2) ++rows, in_a.insert(m.a_node), in_b.insert(m.b_node);
  EXPECT_GT(p.links, 0);
  EXPECT_LE(p.links, rows);
  EXPECT_EQ(p.matched_a, int(in_a.size()));
  EXPECT_EQ(p.matched_b, int(in_b.size()));
  EXPECT_EQ(render_match_picture(a.positions, b.positions, pairs, o).image.rgb, p.image.rgb);
}

TEST(Render, ContactSheetPlacesEveryCell) {
  std::vector<SheetCell> cells(5);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    cells[k].picture = make_canvas(40, 30, pair_colour(int(k)));
    cells[k].caption = {"#" + std::to_string(k), "a long file name that will not fit"};
  }
  cells[0].framed = true;
  const Image sheet = contact_sheet(cells, 3, "title");
  EXPECT_GE(sheet.width, 3 * 40);
  EXPECT_GE(sheet.height, 2 * 30);
  // Every cell's colour shows somewhere.
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i < sheet.rgb.size(); i += 3)
    colours.insert(std::uint32_t(sheet.rgb[i]) << 16 | std::uint32_t(sheet.rgb[i + 1]) << 8 |
                   sheet.rgb[i + 2]);
  for (int k = 0; k < 5; ++k) {
    const Rgb c = pair_colour(k);
    EXPECT_TRUE(colours.count(std::uint32_t(c.r) << 16 | std::uint32_t(c.g) << 8 | c.b)) << k;
  }
}

TEST(Svg, GraphIsWellFormedWithOneCirclePerNodeAndOneLinePerEdge) {
  for (const char* label : {"human", "torus", "chair"}) {
    const ArgGraph& g = model(label, 0).graph;
    for (int level = 0; level <= g.levels(); ++level) {
      const std::string svg = arg_graph_svg(g, level);
      EXPECT_EQ(xml_problem(svg), "") << label << " level " << level;
      EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
      EXPECT_EQ(int(count_of(svg, "<circle ")), nodes_at(g, level)) << label << " " << level;
      std::size_t edges = 0;
      for (std::uint32_t i = g.level_begin[std::size_t(level)];
           i < g.level_begin[std::size_t(level) + 1]; ++i)
        for (std::uint32_t k = 0; k < g.nodes[i].adj_count; ++k)
          edges += g.adjacency[g.nodes[i].adj_begin + k] > i;
      EXPECT_EQ(count_of(svg, "<line "), edges) << label << " " << level;
      // Self-contained: no links, scripts or images.
      EXPECT_EQ(svg.find("href"), std::string::npos);
      EXPECT_EQ(svg.find("<script"), std::string::npos);
      EXPECT_EQ(svg, arg_graph_svg(g, level));
    }
  }
}

TEST(Svg, RejectsLevelsTheGraphDoesNotHave) {
  const ArgGraph& g = model("cup", 0).graph;
  EXPECT_THROW(arg_graph_svg(g, -1), InputError);
  EXPECT_THROW(arg_graph_svg(g, g.levels() + 1), InputError);
}

TEST(Svg, TheTestsXmlCheckerCatchesMalformedText) {
  EXPECT_EQ(xml_problem("<a><b x=\"1\"/>t &amp; u</a>"), "");
  EXPECT_NE(xml_problem("<a><b></a></b>"), "");
  EXPECT_NE(xml_problem("<a x=1/>"), "");
  EXPECT_NE(xml_problem("<a>R&D</a>"), "");
  EXPECT_NE(xml_problem("<a/><b/>"), "");
  EXPECT_NE(xml_problem("<a x=\"<\"/>"), "");
  EXPECT_NE(xml_problem("<a>"), "");
}
