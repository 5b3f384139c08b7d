// The binary format: version 2 round trips byte for byte; version-1 values read and compare as
// before.
#include <gtest/gtest.h>

#include <array>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "common/errors.hpp"
#include "features/laplace_spectrum.hpp"
#include "features/panorama_descriptor.hpp"
#include "format_fixtures.hpp"
#include "graph/serialize.hpp"
#include "match/similarity.hpp"
#include "pipeline/build_arg.hpp"
#include "test_shapes.hpp"

namespace arg {
namespace {

// SIM of (x, y), (y, z) and (x, z) with the default and the mrg weights, as an earlier version's
// argtool printed them (six decimals). The defaults of 0.1.0 and 0.2.0 are the `part` preset now.
void expect_fixture_sims(const ArgGraph& x, const ArgGraph& y, const ArgGraph& z,
                         const std::array<double, 3>& arg, const std::array<double, 3>& mrg) {
  const std::pair<const ArgGraph*, const ArgGraph*> pairs[3] = {{&x, &y}, {&y, &z}, {&x, &z}};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(arg_similarity(*pairs[k].first, *pairs[k].second, weights_preset("part")), arg[k],
                5e-7)
        << k;
    EXPECT_NEAR(arg_similarity(*pairs[k].first, *pairs[k].second, weights_preset("mrg")), mrg[k],
                5e-7)
        << k;
  }
}

TEST(ArgFormat, VersionThreeRoundTripsBinaryAndTextByteForByte) {
  const ArgGraph g = build_arg(test::torus());
  ASSERT_EQ(g.format, 3);
  ASSERT_EQ(g.panorama.size(), std::size_t(kPanoramaSize));
  ASSERT_EQ(g.spectrum.size(), std::size_t(kSpectrumSize));
  const std::string bytes = serialize_arg(g);
  EXPECT_EQ(bytes.substr(4, 2), std::string("\x03\x00", 2));
  const ArgGraph back = deserialize_arg(bytes);
  EXPECT_EQ(back.panorama, g.panorama);
  EXPECT_EQ(back.spectrum, g.spectrum);
  EXPECT_EQ(back.options.surface, g.options.surface);
  EXPECT_EQ(back.options.proxy_resolution, g.options.proxy_resolution);
  EXPECT_EQ(back.options.holes, HoleKind::Fill);
  EXPECT_EQ(serialize_arg(back), bytes);
  EXPECT_EQ(arg_from_text(arg_to_text(bytes)), bytes);
  EXPECT_EQ(arg_similarity(g, back), 0.0);
}

TEST(ArgFormat, TheHoleOptionLivesInTheFormerlyReservedByte) {
  BuildOptions keep;
  keep.holes = HoleKind::Keep;
  std::string bytes = serialize_arg(build_arg(test::torus(), keep));
  EXPECT_EQ(deserialize_arg(bytes).options.holes, HoleKind::Keep) << "written before filling: 0";
  EXPECT_EQ(deserialize_arg(serialize_arg(build_arg(test::torus()))).options.holes, HoleKind::Fill);
  EXPECT_EQ(parse_build_options("holes=keep").holes, HoleKind::Keep);
  EXPECT_NE(format_build_options(BuildOptions{}).find("holes=fill"), std::string::npos);
  EXPECT_THROW(parse_build_options("holes=patch"), InputError);
}

TEST(ArgFormat, VersionOneValuesReadAndCompareAsIn010) {
  const std::string human = format_fixture(1, "human_l2"),
                    fourleg = format_fixture(1, "fourleg_l4_height"),
                    torus = format_fixture(1, "torus_l3_centroid");
  ASSERT_FALSE(human.empty());
  const ArgGraph h = deserialize_arg(human), f = deserialize_arg(fourleg),
                 t = deserialize_arg(torus);
  EXPECT_EQ(h.format, 1);
  EXPECT_TRUE(h.panorama.empty() && h.spectrum.empty());
  EXPECT_EQ(h.options.surface, SurfaceKind::Mesh);
  // Written back in the format they came in, byte for byte.
  EXPECT_EQ(serialize_arg(h), human);
  EXPECT_EQ(serialize_arg(t), torus);
  // Without whole-shape sections SIM is the graph's alone, as 0.1.0 computed it (README.md in
  // the fixtures folder has the values 0.1.0's argtool printed).
  expect_fixture_sims(h, f, t, {0.712863, 0.634573, 0.686265}, {0.734950, 0.527193, 0.720556});
  EXPECT_EQ(arg_similarity(h, h), 0.0);
  // A version-1 value against a version-2 one: the core shares the graph term only, and the SQL
  // surface refuses the pair as builds of builders 1.0 and 1.1 (test_comparable.cpp).
  const ArgGraph v2 = build_arg(test::torus());
  const SimilarityParts p = similarity_parts(h, v2, weights_preset("arg"));
  EXPECT_EQ(p.w_panorama, 0.0);
  EXPECT_EQ(p.w_spectrum, 0.0);
  EXPECT_DOUBLE_EQ(p.sim, p.graph);
}

TEST(ArgFormat, SectionsAreCheckedStrictly) {
  const std::string good = serialize_arg(build_arg(test::sphere(20, 24)));
  // The last section is the spectrum; cut one float off it.
  std::string shorter = good.substr(0, good.size() - 4);
  reseal_arg_digest(shorter);
  EXPECT_THROW(deserialize_arg(shorter), InputError);
  // Every spectrum value must lie in [1e-6, 1e3].
  std::string bad = good;
  const float big = 7e3f;
  std::memcpy(&bad[bad.size() - 4], &big, 4);
  reseal_arg_digest(bad);
  EXPECT_THROW(deserialize_arg(bad), InputError);
  // A format-1 or format-2 value with a version-3 header size is refused.
  for (char version : {1, 2}) {
    std::string mixed = good;
    mixed[4] = version;
    reseal_arg_digest(mixed);
    EXPECT_THROW(deserialize_arg(mixed), InputError);
  }
}

TEST(ArgFormat, VersionTwoValuesReadAndCompareAsIn020) {
  const std::string vase = format_fixture(2, "vase_colour"), human = format_fixture(2, "human_l4"),
                    chair = format_fixture(2, "chair_proxy");
  ASSERT_FALSE(vase.empty());
  const ArgGraph v = deserialize_arg(vase), h = deserialize_arg(human), c = deserialize_arg(chair);
  EXPECT_EQ(v.format, 2);
  EXPECT_EQ(v.summary.has_colour, 1);
  EXPECT_TRUE(c.summary.flags & kFlagProxy);
  // Written back in the format they came in, byte for byte.
  EXPECT_EQ(serialize_arg(v), vase);
  EXPECT_EQ(serialize_arg(h), human);
  EXPECT_EQ(serialize_arg(c), chair);
  // SIM as 0.2.0's argtool printed it (fixtures/format2/README.md).
  expect_fixture_sims(v, h, c, {0.471025, 0.408209, 0.502370}, {0.424559, 0.466277, 0.450499});
}

TEST(ArgFormat, VersionThreeIsAFractionOfVersionTwoAndRanksAlike) {
  for (const ArgGraph& built : {build_arg(test::torus()), build_arg(test::sphere(20, 24))}) {
    ArgGraph two = built;
    two.format = 2;
    const std::size_t v3 = serialize_arg(built).size(), v2 = serialize_arg(two).size();
    EXPECT_LT(v3 * 4, v2) << v3 << " bytes against " << v2;
  }
  // The graph a build returns is its stored form: storing it again changes nothing.
  const ArgGraph g = build_arg(test::torus());
  EXPECT_EQ(serialize_arg(stored_form(g)), serialize_arg(g));
  EXPECT_EQ(arg_similarity(g, stored_form(g)), 0.0);
}

TEST(ArgFormat, ColourIsStoredOnlyWhenTheModelHasColour) {
  const Mesh plain = test::torus();
  Mesh coloured = plain;
  coloured.C = FaceColours::Constant(coloured.F.rows(), 3, 0.25f);
  const std::string a = serialize_arg(build_arg(plain)), b = serialize_arg(build_arg(coloured));
  const ArgGraph gb = deserialize_arg(b);
  ASSERT_EQ(gb.summary.has_colour, 1);
  EXPECT_EQ(b.size() - a.size(), 8 + gb.nodes.size() * 24);
  // Every channel of every node still sums to the node's area, to a code (1/255 of it).
  for (const ArgNode& n : gb.nodes)
    for (int c = 0; c < 3; ++c) {
      double sum = 0;
      for (int k = 0; k < kColourBins; ++k) sum += n.colour[std::size_t(c * kColourBins + k)];
      EXPECT_NEAR(sum, n.a, n.a / 255 + 1e-7);
    }
  // The flag without the section, or the section without the flag, is refused.
  std::string flag_only = a;
  flag_only[52] = 1;  // summary.has_colour
  reseal_arg_digest(flag_only);
  EXPECT_THROW(deserialize_arg(flag_only), InputError);
  std::string section_only = b;
  section_only[52] = 0;
  reseal_arg_digest(section_only);
  EXPECT_THROW(deserialize_arg(section_only), InputError);
}

// Everything a reader fills, compared field by field (ArgNode has no padding).
void expect_same_graph(const ArgGraph& a, const ArgGraph& b, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(a.format, b.format);
  EXPECT_EQ(a.builder_version, b.builder_version);
  EXPECT_EQ(format_build_options(a.options), format_build_options(b.options));
  const ArgSummary &x = a.summary, &y = b.summary;
  EXPECT_EQ(std::tie(x.triangles, x.vertices, x.components, x.genus, x.has_colour, x.flags, x.area,
                     x.volume, x.scale, x.pooled),
            std::tie(y.triangles, y.vertices, y.components, y.genus, y.has_colour, y.flags, y.area,
                     y.volume, y.scale, y.pooled));
  EXPECT_EQ(a.global, b.global);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  EXPECT_EQ(std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(ArgNode)), 0);
  EXPECT_EQ(a.level_begin, b.level_begin);
  EXPECT_EQ(a.children, b.children);
  EXPECT_EQ(a.adjacency, b.adjacency);
  EXPECT_EQ(a.panorama, b.panorama);
  EXPECT_EQ(a.spectrum, b.spectrum);
}

// A ranking reads row after row into one graph: whatever the graph held before (more nodes,
// colour, another format, a value refused halfway), it ends as a fresh read of the new value.
TEST(ArgFormat, ReadingIntoAGraphInUseGivesWhatAFreshReadGives) {
  Mesh coloured = test::torus();
  coloured.C = FaceColours::Constant(coloured.F.rows(), 3, 0.25f);
  const std::vector<std::pair<std::string, std::string>> values = {
      {"coloured torus", serialize_arg(build_arg(coloured))},
      {"capsule", serialize_arg(build_arg(test::capsule()))},
      {"format-2 coloured vase", format_fixture(2, "vase_colour")},
      {"format-1 human", format_fixture(1, "human_l2")},
      {"format-2 chair on a proxy", format_fixture(2, "chair_proxy")},
      {"sphere", serialize_arg(build_arg(test::sphere()))},
  };
  ArgGraph g;
  for (int pass = 0; pass < 2; ++pass)
    for (const auto& [name, bytes] : values) {
      ASSERT_FALSE(bytes.empty()) << name;
      if (pass == 1) {
        // A value refused partway leaves the graph to be read again.
        std::string broken = bytes.substr(0, bytes.size() - 1);
        EXPECT_THROW(deserialize_arg_into(broken, g, false), InputError);
      }
      deserialize_arg_into(bytes, g, /*check_digest=*/false);
      expect_same_graph(g, deserialize_arg(bytes), name);
    }
}

}  // namespace
}  // namespace arg
