// The binary format: version 2 round trips byte for byte; version-1 values read and compare as
// before.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "common/errors.hpp"
#include "features/laplace_spectrum.hpp"
#include "features/panorama_descriptor.hpp"
#include "format1_fixtures.hpp"
#include "graph/serialize.hpp"
#include "match/similarity.hpp"
#include "pipeline/build_arg.hpp"
#include "test_shapes.hpp"

namespace arg {
namespace {

TEST(ArgFormat, VersionTwoRoundTripsBinaryAndTextByteForByte) {
  const ArgGraph g = build_arg(test::torus());
  ASSERT_EQ(g.format, 2);
  ASSERT_EQ(g.panorama.size(), std::size_t(kPanoramaSize));
  ASSERT_EQ(g.spectrum.size(), std::size_t(kSpectrumSize));
  const std::string bytes = serialize_arg(g);
  EXPECT_EQ(bytes.substr(4, 2), std::string("\x02\x00", 2));
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
  const std::string human = format1_fixture("human_l2"),
                    fourleg = format1_fixture("fourleg_l4_height"),
                    torus = format1_fixture("torus_l3_centroid");
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
  EXPECT_NEAR(arg_similarity(h, f), 0.712863, 5e-7);
  EXPECT_NEAR(arg_similarity(f, t), 0.634573, 5e-7);
  EXPECT_NEAR(arg_similarity(h, t), 0.686265, 5e-7);
  EXPECT_NEAR(arg_similarity(h, f, weights_preset("mrg")), 0.734950, 5e-7);
  EXPECT_NEAR(arg_similarity(f, t, weights_preset("mrg")), 0.527193, 5e-7);
  EXPECT_NEAR(arg_similarity(h, t, weights_preset("mrg")), 0.720556, 5e-7);
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
  // The last section is the panorama; cut one float off it.
  std::string shorter = good.substr(0, good.size() - 4);
  reseal_arg_digest(shorter);
  EXPECT_THROW(deserialize_arg(shorter), InputError);
  // Every panorama value must lie in [0, 1].
  std::string bad = good;
  const float big = 7.0f;
  std::memcpy(&bad[bad.size() - 4], &big, 4);
  reseal_arg_digest(bad);
  EXPECT_THROW(deserialize_arg(bad), InputError);
  // A format-1 value with a version-2 header size is refused.
  std::string mixed = good;
  mixed[4] = 1;
  reseal_arg_digest(mixed);
  EXPECT_THROW(deserialize_arg(mixed), InputError);
}

}  // namespace
}  // namespace arg
