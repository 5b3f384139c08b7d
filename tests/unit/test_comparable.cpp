// Which ARGs compare: one builder major and minor version and the same build options; and which
// values a rebuild would change.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "common/errors.hpp"
#include "format_fixtures.hpp"
#include "graph/comparable.hpp"
#include "graph/serialize.hpp"
#include "pipeline/build_arg.hpp"
#include "test_shapes.hpp"

namespace arg {
namespace {

// The stored bytes of `bytes` with another builder version, digest resealed.
std::string with_builder(std::string bytes, std::uint32_t version) {
  std::memcpy(&bytes[12], &version, 4);
  reseal_arg_digest(bytes);
  return bytes;
}

TEST(Comparable, SameBuilderAndOptionsCompareAPatchApart) {
  const ArgGraph a = build_arg(test::torus());
  ArgGraph patched = a;
  patched.builder_version = current_builder_version() + 1;
  EXPECT_TRUE(comparable(a, a));
  EXPECT_TRUE(comparable(a, patched));
  EXPECT_EQ(incomparable_reason(a, patched), "");
  EXPECT_NO_THROW(require_comparable(patched, a));
}

TEST(Comparable, AnotherMinorOrMajorVersionIsRefusedNamingBoth) {
  const ArgGraph a = build_arg(test::torus());
  ArgGraph minor = a, major = a;
  minor.builder_version = current_builder_version() + 100;
  major.builder_version = current_builder_version() + 10000;
  EXPECT_FALSE(comparable(a, minor));
  EXPECT_FALSE(comparable(major, a));
  const std::string reason = incomparable_reason(a, minor);
  EXPECT_NE(reason.find("builder " + builder_version_text(a.builder_version)), std::string::npos)
      << reason;
  EXPECT_NE(reason.find("builder " + builder_version_text(minor.builder_version)),
            std::string::npos)
      << reason;
  EXPECT_THROW(require_comparable(a, major), Incomparable);
}

TEST(Comparable, OtherBuildOptionsAreRefusedNamingBoth) {
  BuildOptions keep;
  keep.holes = HoleKind::Keep;
  BuildOptions coarse;
  coarse.levels = 3;
  const ArgGraph a = build_arg(test::torus()), b = build_arg(test::torus(), keep),
                 c = build_arg(test::torus(), coarse);
  EXPECT_FALSE(comparable(a, b));
  EXPECT_FALSE(comparable(a, c));
  const std::string reason = incomparable_reason(a, b);
  EXPECT_NE(reason.find("holes=fill"), std::string::npos) << reason;
  EXPECT_NE(reason.find("holes=keep"), std::string::npos) << reason;
  // threads never changes the result, so it is no build option that matters.
  BuildOptions threads;
  threads.threads = 2;
  EXPECT_TRUE(comparable(a, build_arg(test::torus(), threads)));
}

TEST(Comparable, EveryBuildOptionButThreadsCounts) {
  // A key added to the parser and forgotten by the rule would compare builds it changes.
  ArgGraph x, y;
  for (const BuildOptionKey& key : build_option_keys()) {
    const std::string name(key.name);
    const std::string lo = key.words.empty() ? std::to_string(key.lo) : std::string(key.words[0]);
    const std::string hi = key.words.empty() ? std::to_string(key.hi) : std::string(key.words[1]);
    x.options = parse_build_options(name + "=" + lo);
    y.options = parse_build_options(name + "=" + hi);
    EXPECT_EQ(comparable(x, y), name == "threads") << name;
    EXPECT_EQ(comparable(x, y), format_build_options(x.options) == format_build_options(y.options))
        << name;
  }
}

TEST(Comparable, VersionOneValuesCompareWithTheirOwnKindOnly) {
  const std::string human = format_fixture(1, "human_l2");
  ASSERT_FALSE(human.empty());
  const ArgGraph h = deserialize_arg(human);
  EXPECT_EQ(builder_version_text(h.builder_version), "1.0.0");
  EXPECT_TRUE(comparable(h, h));
  // A patch of builder 1.0 compares with it, builder 1.1 (holes filled, smoothed curvature) not.
  EXPECT_TRUE(comparable(h, deserialize_arg(with_builder(human, 10003))));
  EXPECT_FALSE(comparable(h, deserialize_arg(with_builder(human, 10100))));
  BuildOptions same = h.options;
  same.holes = HoleKind::Keep;
  const ArgGraph now = build_arg(test::torus(), same);
  EXPECT_FALSE(comparable(h, now));
  const std::string reason = incomparable_reason(h, now);
  EXPECT_NE(reason.find("builder 1.0.0"), std::string::npos) << reason;
  EXPECT_NE(reason.find("builder 1.8.0"), std::string::npos) << reason;
  // Values of other options, as the fixtures are, do not compare either.
  EXPECT_FALSE(comparable(h, deserialize_arg(format_fixture(1, "torus_l3_centroid"))));
}

TEST(Comparable, RebuildIsNeededForOlderFormatsAndOtherMinorVersions) {
  const ArgGraph now = build_arg(test::torus());
  EXPECT_FALSE(rebuild_needed(now));
  ArgGraph patched = now, minor = now;
  patched.builder_version += 1;
  minor.builder_version += 100;
  EXPECT_FALSE(rebuild_needed(patched));
  EXPECT_TRUE(rebuild_needed(minor));
  EXPECT_TRUE(rebuild_needed(deserialize_arg(format_fixture(1, "fourleg_l4_height"))));
  // 0.2.0's values: format 2, builder 1.1 (before byte-coded records and pooled fragments).
  const ArgGraph v2 = deserialize_arg(format_fixture(2, "vase_colour"));
  EXPECT_TRUE(rebuild_needed(v2));
  EXPECT_FALSE(comparable(v2, build_arg(test::torus())));
  EXPECT_TRUE(comparable(v2, deserialize_arg(format_fixture(2, "chair_proxy"))) ==
              (format_build_options(v2.options) ==
               format_build_options(deserialize_arg(format_fixture(2, "chair_proxy")).options)));
}

TEST(Comparable, BuilderVersionText) {
  EXPECT_EQ(builder_version_text(10100), "1.1.0");
  EXPECT_EQ(builder_version_text(20304), "2.3.4");
}

}  // namespace
}  // namespace arg
