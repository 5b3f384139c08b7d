// Build options: every listed key parses over its whole range, and nothing else does.
#include <gtest/gtest.h>

#include "common/build_options.hpp"
#include "common/errors.hpp"
#include "input_error.hpp"

using namespace arg;

namespace {

std::string message(const std::string& text) {
  return input_error_of([&] { parse_build_options(text); }, "accepted");
}

}  // namespace

TEST(BuildOptions, EveryListedKeyTakesItsRangeOrItsWords) {
  ASSERT_EQ(build_option_keys().size(), 7u);
  for (const BuildOptionKey& k : build_option_keys()) {
    const std::string key(k.name);
    if (k.words.empty()) {
      EXPECT_EQ(message(key + "=" + std::to_string(k.lo)), "accepted") << key;
      EXPECT_EQ(message(key + "=" + std::to_string(k.hi)), "accepted") << key;
      EXPECT_NE(message(key + "=" + std::to_string(k.lo - 1)).find("must be an integer in ["),
                std::string::npos)
          << key;
      EXPECT_NE(message(key + "=" + std::to_string(k.hi + 1)).find(key), std::string::npos) << key;
    } else {
      for (std::string_view word : k.words)
        EXPECT_EQ(message(key + "=" + std::string(word)), "accepted") << key << "=" << word;
      EXPECT_NE(message(key + "=nothing").find("(expected "), std::string::npos) << key;
    }
  }
}

TEST(BuildOptions, WordsSetTheirEnumInOrder) {
  EXPECT_EQ(parse_build_options("mu=height").mu, MuKind::Height);
  EXPECT_EQ(parse_build_options("mu=centroid").mu, MuKind::Centroid);
  EXPECT_EQ(parse_build_options("surface=proxy").surface, SurfaceKind::Proxy);
  EXPECT_EQ(parse_build_options("surface=mesh").surface, SurfaceKind::Mesh);
  EXPECT_EQ(parse_build_options("holes=keep").holes, HoleKind::Keep);
  const BuildOptions o =
      parse_build_options("levels=3, base_points=64 proxy_resolution=32 threads=4");
  EXPECT_EQ(o.levels, 3);
  EXPECT_EQ(o.base_points, 64);
  EXPECT_EQ(o.proxy_resolution, 32);
  EXPECT_EQ(o.threads, 4);
  EXPECT_EQ(format_build_options(o),
            "levels=3 mu=geodesic base_points=64 surface=auto proxy_resolution=32 holes=fill");
}

TEST(BuildOptions, MessagesNameTheKeyAndWhatIsExpected) {
  EXPECT_EQ(message("levels=99"), "build options: levels=99 must be an integer in [1, 7]");
  EXPECT_EQ(message("mu=random"),
            "build options: mu=random (expected geodesic, height or centroid)");
  EXPECT_EQ(message("colour=1"),
            "build options: unknown key \"colour\" (expected levels, mu, base_points, surface, "
            "proxy_resolution, holes or threads)");
  EXPECT_EQ(parse_build_options("levels=2 levels=4").levels, 4) << "the last value counts";
}
