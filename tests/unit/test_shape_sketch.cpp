// Sketches: SIM's whole-shape terms to the bit, read strictly, compared as SIM weighs them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "common/errors.hpp"
#include "features/laplace_spectrum.hpp"
#include "features/panorama_descriptor.hpp"
#include "gen/generate_models.hpp"
#include "graph/panorama_codes.hpp"
#include "graph/serialize.hpp"
#include "match/similarity.hpp"
#include "pipeline/build_arg.hpp"
#include "search/shape_sketch.hpp"

using namespace arg;

namespace {

// Stored values (format 3, as a table holds them): two poses of a human and a cup.
const ArgGraph& stored(int which) {
  static const ArgGraph models[3] = {
      deserialize_arg(serialize_arg(build_arg(generate_model("human", 1, 32, false).mesh))),
      deserialize_arg(serialize_arg(build_arg(generate_model("human", 2, 32, false).mesh))),
      deserialize_arg(serialize_arg(build_arg(generate_model("cup", 1, 32, true).mesh)))};
  return models[which];
}

ShapeSketch read(const std::string& bytes) {
  ShapeSketch s;
  read_shape_sketch(bytes, s);
  return s;
}

void put_float(std::string& bytes, std::size_t at, float x) {
  std::uint32_t bits;
  std::memcpy(&bits, &x, 4);
  for (int i = 0; i < 4; ++i) bytes[at + std::size_t(i)] = char((bits >> (8 * i)) & 0xff);
}

// Bytes with `change` made and the digest sealed again, so that a check after the digest's sees
// the change.
template <typename Change>
std::string changed(const std::string& bytes, Change change) {
  std::string b = bytes;
  change(b);
  reseal_sketch_digest(b);
  return b;
}

// The same sketch in version 1 (arg 0.2.0's stored columns): no digest.
std::string as_version_1(const std::string& bytes) {
  std::string b = bytes.substr(0, 8) + bytes.substr(16);
  b[4] = 1;
  return b;
}

// Where the parts start in a sketch with every part.
constexpr std::size_t kGraphAt = 16, kPanoramaAt = kGraphAt + 4 * kSketchGraphDims,
                      kSpectrumAt = kPanoramaAt + kPanoramaCodesSize,
                      kFullSize = kSpectrumAt + 4 * kSpectrumSize;

}  // namespace

TEST(ShapeSketch, HoldsTheValuesWholeShapeSectionsToTheBit) {
  for (int m = 0; m < 3; ++m) {
    const ArgGraph& g = stored(m);
    ASSERT_EQ(g.panorama.size(), std::size_t(kPanoramaSize));
    ASSERT_EQ(g.spectrum.size(), std::size_t(kSpectrumSize));
    const std::string bytes = write_shape_sketch(shape_sketch(g));
    EXPECT_EQ(bytes.size(), kFullSize);
    const ShapeSketch s = read(bytes);
    ASSERT_TRUE(s.has_panorama && s.has_spectrum);
    // A format-3 panorama's codes are its sketch's.
    EXPECT_TRUE(std::equal(s.panorama.begin(), s.panorama.end(), g.panorama.begin()));
    EXPECT_TRUE(std::equal(s.spectrum.begin(), s.spectrum.end(), g.spectrum.begin()));
    EXPECT_EQ(s.flags, g.summary.flags);
    EXPECT_EQ(write_shape_sketch(s), bytes);  // read and written again: the same bytes
  }
}

TEST(ShapeSketch, GraphBlocksAreTheSearchDescriptorsOtherThanPanoramaAndEigenvalues) {
  const ArgGraph& g = stored(2);
  const auto d = search_descriptor(g);
  const ShapeSketch s = shape_sketch(g);
  std::size_t j = 0;
  for (int k = 0; k < kSearchDims; ++k)
    if (k < kSearchPanoramaAt || k >= kSearchColourAt) {
      EXPECT_EQ(s.graph[j++], d[std::size_t(k)]);
    }
  EXPECT_EQ(j, std::size_t(kSketchGraphDims));
}

TEST(ShapeSketch, DistanceIsSimWithTheGraphTermReplaced) {
  const Weights w;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const ShapeSketch sa = shape_sketch(stored(a)), sb = shape_sketch(stored(b));
      const SimilarityParts p = similarity_parts(stored(a), stored(b), w);
      // Colour (the last 12 values) counts only between two coloured models, as in SIM.
      const int end = sa.has_colour && sb.has_colour ? kSketchGraphDims : kSketchGraphDims - 12;
      double l1 = 0;
      for (int k = 0; k < end; ++k)
        l1 += std::fabs(double(sa.graph[std::size_t(k)]) - sb.graph[std::size_t(k)]);
      const double expected = (p.w_graph * kSketchGraphMix * l1 + p.w_panorama * p.panorama +
                               p.w_spectrum * p.spectrum) /
                              (p.w_graph + p.w_panorama + p.w_spectrum);
      EXPECT_DOUBLE_EQ(sketch_distance(sa, sb, w), expected) << a << " " << b;
      EXPECT_EQ(sketch_distance(sa, sb, w), sketch_distance(sb, sa, w));
      if (a == b) {
        EXPECT_EQ(sketch_distance(sa, sb, w), 0.0);
      }
    }
  // A pose of a human is nearer the other pose than a cup.
  const ShapeSketch h1 = shape_sketch(stored(0)), h2 = shape_sketch(stored(1)),
                    cup = shape_sketch(stored(2));
  EXPECT_LT(sketch_distance(h1, h2), sketch_distance(h1, cup));
}

TEST(ShapeSketch, LeavesOutTheTermsSimLeavesOut) {
  const ShapeSketch a = shape_sketch(stored(0));
  ShapeSketch b = shape_sketch(stored(1));
  // A proxy's spectrum counts for nothing: changing it changes nothing.
  ShapeSketch proxy = b;
  proxy.flags |= kFlagProxy;
  const double d = sketch_distance(a, proxy);
  for (float& x : proxy.spectrum) x *= 2;
  EXPECT_EQ(sketch_distance(a, proxy), d);
  // Without a panorama on one side, the panorama counts for nothing either.
  ShapeSketch bare = b;
  bare.has_panorama = false;
  Weights only_views;
  only_views.spectrum = 0;
  double l1 = 0;
  for (int k = 0; k < kSketchGraphDims; ++k)
    l1 += std::fabs(double(a.graph[std::size_t(k)]) - bare.graph[std::size_t(k)]);
  EXPECT_DOUBLE_EQ(sketch_distance(a, bare, only_views), kSketchGraphMix * l1)
      << "the graph blocks alone, as SIM falls back on the graph";
  const ShapeSketch back = read(write_shape_sketch(bare));
  EXPECT_FALSE(back.has_panorama);
  EXPECT_TRUE(back.has_spectrum && back.spectrum == b.spectrum);
}

TEST(ShapeSketch, RefusesEveryMalformedByte) {
  const std::string good = write_shape_sketch(shape_sketch(stored(0)));
  auto refused = [](std::string bytes, const char* what) {
    ShapeSketch s;
    EXPECT_THROW(read_shape_sketch(bytes, s), InputError) << what;
  };
  for (std::size_t n = 0; n < good.size(); ++n) refused(good.substr(0, n), "truncated");
  refused(good + '\0', "a byte after the end");
  std::string b = good;
  b[0] = 'X', refused(b, "magic");
  b = good, b[4] = 3, refused(b, "version");
  refused(changed(good, [](std::string& x) { x[5] |= 8; }), "unknown part");
  refused(changed(good, [](std::string& x) { x[7] = char(0x80); }), "unknown flag");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  auto with_float = [&](std::size_t at, float x) {
    return changed(good, [&](std::string& y) { put_float(y, at, x); });
  };
  refused(with_float(kGraphAt + 8, nan), "NaN graph value");
  refused(with_float(kGraphAt, -1.0f), "negative graph value");
  refused(with_float(kPanoramaAt, 2.0f), "panorama scale above 1");
  refused(with_float(kPanoramaAt, nan), "NaN panorama scale");
  refused(with_float(kSpectrumAt, 0.0f), "zero eigenvalue");
  refused(with_float(kSpectrumAt + 4, std::numeric_limits<float>::infinity()),
          "infinite eigenvalue");
  // A block whose largest code is not 255 is not what the writer makes.
  refused(changed(good,
                  [](std::string& x) {
                    for (std::size_t k = kPanoramaAt + 4 * kPanoramaBlocks;
                         k < kPanoramaAt + 4 * kPanoramaBlocks + kPanoramaPerView; ++k)
                      if (static_cast<unsigned char>(x[k]) == 255) x[k] = char(254);
                  }),
          "non-canonical codes");
  // Without the panorama part, its bytes are trailing bytes.
  refused(changed(good, [](std::string& x) { x[5] = 2; }), "parts say no panorama");
  EXPECT_NO_THROW(read(good));
}

TEST(ShapeSketch, ItsDigestRefusesAnyChangedByte) {
  const std::string good = write_shape_sketch(shape_sketch(stored(2)));
  ASSERT_EQ(good.size(), kFullSize);
  EXPECT_EQ(good[4], char(kSketchVersion));
  for (std::size_t at = 0; at < good.size(); ++at)
    for (unsigned char flip : {0x01, 0x80}) {
      std::string b = good;
      b[at] = char(static_cast<unsigned char>(b[at]) ^ flip);
      ShapeSketch s;
      EXPECT_THROW(read_shape_sketch(b, s), InputError) << "byte " << at << " ^ " << int(flip);
    }
  std::string b = good;
  b[kSpectrumAt] = char(static_cast<unsigned char>(b[kSpectrumAt]) ^ 1);
  try {
    read(b);
    ADD_FAILURE() << "a changed eigenvalue was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("digest mismatch"), std::string::npos) << e.what();
  }
}

TEST(ShapeSketch, Version1SketchesStillReadAsTheSameSketch) {
  for (int which : {0, 2}) {
    const ShapeSketch s = shape_sketch(stored(which));
    const std::string v2 = write_shape_sketch(s), v1 = as_version_1(v2);
    EXPECT_EQ(v1.size() + 8, v2.size());
    EXPECT_EQ(write_shape_sketch(read(v1)), v2);  // read, then written as version 2
    EXPECT_EQ(sketch_distance(read(v1), s), 0.0);
    EXPECT_EQ(sketch_from_text(sketch_to_text(v1)), v1);
  }
}

TEST(ShapeSketch, TextFormRoundTripsAndIsChecked) {
  const std::string bytes = write_shape_sketch(shape_sketch(stored(2)));
  const std::string text = sketch_to_text(bytes);
  EXPECT_EQ(text.rfind("sketch1:", 0), 0u);
  EXPECT_EQ(sketch_from_text(text), bytes);
  EXPECT_THROW(sketch_from_text("arg1:" + text.substr(8)), InputError);
  EXPECT_THROW(sketch_from_text("sketch1:QUJD"), InputError);  // base64 of "ABC": no sketch
  EXPECT_THROW(sketch_from_text(text.substr(0, text.size() - 4)), InputError);
}

TEST(ShapeSketch, AValueOutOfRangeLeavesItsPartOutSoTheSketchReadsBack) {
  // Rankings read stored values unchecked: a forged NaN, a panorama value above 1 or a zero
  // eigenvalue must not make a sketch that its own reader refuses.
  for (int bad = 0; bad < 4; ++bad) {
    ArgGraph g = stored(1);
    if (bad == 0) g.panorama[17] = std::numeric_limits<float>::quiet_NaN();
    if (bad == 1) g.panorama[900] = 2.0f;
    if (bad == 2) g.spectrum[3] = 0.0f;
    if (bad == 3) g.spectrum[0] = std::numeric_limits<float>::infinity();
    const ShapeSketch s = shape_sketch(g);
    EXPECT_EQ(s.has_panorama, bad >= 2) << bad;
    EXPECT_EQ(s.has_spectrum, bad < 2) << bad;
    EXPECT_NO_THROW(read(write_shape_sketch(s))) << bad;
  }
}

TEST(ShapeSketch, ColourCountsOnlyBetweenTwoColouredModels) {
  const ShapeSketch cup = shape_sketch(stored(2)), human = shape_sketch(stored(0));
  ASSERT_TRUE(cup.has_colour);
  ASSERT_FALSE(human.has_colour);
  // Against a model without colour, the cup's colour values change nothing (SIM's rule).
  ShapeSketch recoloured = cup;
  for (std::size_t k = recoloured.graph.size() - 12; k < recoloured.graph.size(); ++k)
    recoloured.graph[k] *= 3;
  EXPECT_EQ(sketch_distance(human, recoloured), sketch_distance(human, cup));
  // Between two coloured models they count.
  EXPECT_GT(sketch_distance(cup, recoloured), 0.0);
  // A sketch that says it has no colour but carries colour values is refused.
  ShapeSketch forged = human;
  forged.graph.back() = 1.0f;
  ShapeSketch out;
  EXPECT_THROW(read_shape_sketch(write_shape_sketch(forged), out), InputError);
  EXPECT_TRUE(read(write_shape_sketch(cup)).has_colour);
}
