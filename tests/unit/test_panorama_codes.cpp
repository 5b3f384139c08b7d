// The panorama's byte codec: values read and written again keep their bytes; bad ones refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "common/byte_io.hpp"
#include "common/errors.hpp"
#include "graph/panorama_codes.hpp"

using namespace arg;

namespace {

// A panorama with a heavy tail in every block, some blocks all zero.
std::vector<float> sample_panorama() {
  std::vector<float> p(kPanoramaSize);
  for (std::size_t k = 0; k < p.size(); ++k)
    p[k] = (k / 97) % 5 == 3 ? 0.0f : float(0.3 / (1.0 + double(k % 53)) + 1e-4 * double(k % 7));
  return p;
}

std::vector<float> read_back(const std::string& bytes) {
  ByteReader in(bytes, "test");
  std::vector<float> out(kPanoramaSize);
  read_panorama_codes(in, out.data());
  EXPECT_EQ(in.remaining(), 0u);
  return out;
}

}  // namespace

TEST(PanoramaCodes, SizeIsAScaleABlockAndAByteAValue) {
  ByteWriter out;
  write_panorama_codes(sample_panorama().data(), out);
  EXPECT_EQ(out.size(), kPanoramaCodesSize);
  EXPECT_EQ(kPanoramaCodesSize, 4 * kPanoramaBlocks + std::size_t(kPanoramaSize));
}

TEST(PanoramaCodes, ReadValuesWriteTheSameBytes) {
  const std::vector<float> p = sample_panorama();
  ByteWriter first;
  write_panorama_codes(p.data(), first);
  const std::vector<float> decoded = read_back(first.bytes());
  ByteWriter second;
  write_panorama_codes(decoded.data(), second);
  EXPECT_EQ(second.bytes(), first.bytes());
  EXPECT_EQ(read_back(second.bytes()), decoded);
  // Each value within one code step of its block's scale (sqrt codes: finer near zero).
  for (std::size_t k = 0; k < p.size(); ++k) EXPECT_NEAR(decoded[k], p[k], 0.3 * 2.0 / 255.0) << k;
}

TEST(PanoramaCodes, RefusesBadScalesAndCodes) {
  ByteWriter out;
  write_panorama_codes(sample_panorama().data(), out);
  const std::string good = out.bytes();
  auto refused = [](const std::string& bytes, const char* what) {
    ByteReader in(bytes, "test");
    std::vector<float> p(kPanoramaSize);
    EXPECT_THROW(read_panorama_codes(in, p.data()), InputError) << what;
  };
  auto with_scale = [&](float x) {
    std::string b = good;
    std::memcpy(&b[0], &x, 4);  // the tests run on little-endian machines, as ByteWriter writes
    return b;
  };
  refused(with_scale(std::numeric_limits<float>::quiet_NaN()), "NaN scale");
  refused(with_scale(-0.5f), "negative scale");
  refused(with_scale(1.5f), "scale above 1");
  refused(good.substr(0, good.size() - 1), "one byte short");
  // The first block (the first view's Fourier features) with a scale but no code 255: not
  // what the writer makes.
  std::string b = good;
  for (std::size_t k = 0; k < std::size_t(kPanoramaPerView); ++k)
    b[4 * kPanoramaBlocks + k] = char(3);
  refused(b, "codes that do not reach their scale");
  EXPECT_NO_THROW(read_back(good));
}
