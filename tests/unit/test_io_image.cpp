// Tests of decoding texture images from memory and of sampling them.
#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "io/image.hpp"
#include "io/image_format_checks.hpp"
#include "io/texture_sampling.hpp"
#include "test_io_support.hpp"

namespace arg {
namespace {

using test_io::Bytes;

std::array<std::uint8_t, 3> pixel(const Image& image, int x, int y) {
  const std::size_t i = 3 * (std::size_t(y) * std::size_t(image.width) + std::size_t(x));
  return {image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]};
}

TEST(IoImage, DecodesPngFromMemory) {
  const std::string png = test_io::encode_image("png", 3, 2, [](int x, int y) {
    return std::array<std::uint8_t, 3>{std::uint8_t(100 * x), std::uint8_t(200 * y), 7};
  });
  const Image image = decode_image(png, {});
  ASSERT_EQ(image.width, 3);
  ASSERT_EQ(image.height, 2);
  EXPECT_EQ(pixel(image, 2, 1), (std::array<std::uint8_t, 3>{200, 200, 7}));
  EXPECT_EQ(pixel(image, 0, 0), (std::array<std::uint8_t, 3>{0, 0, 7}));
}

TEST(IoImage, DecodesJpegFromMemory) {
  const std::string jpeg = test_io::encode_image("jpeg", 16, 16, [](int, int) {
    return std::array<std::uint8_t, 3>{200, 100, 50};
  });
  ASSERT_FALSE(jpeg.empty());
  const Image image = decode_image(jpeg, {});
  EXPECT_EQ(image.width, 16);
  EXPECT_NEAR(pixel(image, 8, 8)[0], 200, 4);
  EXPECT_NEAR(pixel(image, 8, 8)[2], 50, 4);
}

// A 2x2 run-length encoded true-colour TGA stored bottom row first (the TGA default): the
// bottom row red, the top row one blue and one green pixel.
std::string rle_tga() {
  Bytes b;
  b.u8(0).u8(0).u8(10);                 // no id, no colour map, RLE true colour
  for (int i = 0; i < 5; ++i) b.u8(0);  // colour map spec
  b.u16le(0).u16le(0).u16le(2).u16le(2).u8(24).u8(0);
  b.u8(0x81).u8(0).u8(0).u8(255);                      // run of 2: red (BGR)
  b.u8(0x01).u8(255).u8(0).u8(0).u8(0).u8(255).u8(0);  // 2 raw: blue, green
  return b.str();
}

TEST(IoImage, DecodesRunLengthEncodedTgaWithTheTopRowFirst) {
  const Image image = decode_image(rle_tga(), {});
  ASSERT_EQ(image.width, 2);
  ASSERT_EQ(image.height, 2);
  EXPECT_EQ(pixel(image, 0, 1), (std::array<std::uint8_t, 3>{255, 0, 0}));
  EXPECT_EQ(pixel(image, 1, 1), (std::array<std::uint8_t, 3>{255, 0, 0}));
  EXPECT_EQ(pixel(image, 0, 0), (std::array<std::uint8_t, 3>{0, 0, 255}));
  EXPECT_EQ(pixel(image, 1, 0), (std::array<std::uint8_t, 3>{0, 255, 0}));
}

std::uint32_t crc32(const std::string& bytes) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (unsigned char c : bytes) {
    crc ^= c;
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

TEST(IoImage, PixelCountIsCheckedBeforeThePixelsAreRead) {
  // A valid 1x1 PNG whose header is rewritten to claim 100000 x 100000 pixels (with a correct
  // checksum): decoding them would need 30 GB; the limit must stop it before.
  std::string png = test_io::encode_image("png", 1, 1, [](int, int) {
    return std::array<std::uint8_t, 3>{0, 0, 0};
  });
  ASSERT_EQ(png.substr(12, 4), "IHDR");
  const char side[4] = {0x00, 0x01, char(0x86), char(0xA0)};  // 100000, big endian
  png.replace(16, 4, side, 4);
  png.replace(20, 4, side, 4);
  const std::uint32_t crc = crc32(png.substr(12, 17));
  const char crc_bytes[4] = {char(crc >> 24), char(crc >> 16), char(crc >> 8), char(crc)};
  png.replace(29, 4, crc_bytes, 4);
  EXPECT_THROW(decode_image(png, Limits{}), LimitError);
  Limits limits;
  const std::string ok = test_io::encode_image("png", 8, 8, [](int, int) {
    return std::array<std::uint8_t, 3>{0, 0, 0};
  });
  limits.max_image_pixels = 63;
  EXPECT_THROW(decode_image(ok, limits), LimitError);
  limits.max_image_pixels = 64;
  EXPECT_EQ(decode_image(ok, limits).width, 8);
}

// A progressive JPEG (SOF2) whose frame header declares 65000 x 65000 pixels, 183 bytes found
// by fuzz_decode_image: libjpeg asked for 8 GB of coefficients while OpenImageIO opened it,
// before the decoder's own pixel check. The frame header is read and refused first.
std::string progressive_jpeg_65000() {
  const unsigned char bytes[] = {
      0xff, 0xd8, 0xff, 0xdb, 0x00, 0x43, 0x00, 0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x01,
      0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x73, 0xff, 0xff, 0xff, 0xff, 0x01, 0x01, 0x01,
      0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x11, 0x00, 0xff, 0xc4, 0x00,
      0x26, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xf7, 0xda, 0x00, 0x08, 0x01, 0x01, 0x01,
      0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0xff, 0xc2, 0x00, 0x0b, 0x08, 0xfd, 0xe8,
      0xfd, 0xe8, 0x01, 0x01, 0x11, 0x00, 0xff, 0xc4, 0x00, 0x26, 0x00, 0x01, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x10, 0x01,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0xff, 0xda, 0x00, 0x08, 0x01, 0x01, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00, 0x3f, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x2c, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00};
  return std::string(reinterpret_cast<const char*>(bytes), sizeof bytes);
}

TEST(IoImage, AJpegFrameTooLargeIsRefusedBeforeTheDecoderOpensIt) {
  const std::string huge = progressive_jpeg_65000();
  ASSERT_EQ(huge.size(), 183u);
  const JpegFrameSize size = jpeg_frame_size(huge);
  EXPECT_EQ(size.width, 65000u);
  EXPECT_EQ(size.height, 65000u);
  try {
    decode_image(huge, Limits{});
    ADD_FAILURE() << "decoded";
  } catch (const LimitError& e) {
    EXPECT_NE(std::string(e.what()).find("65000x65000"), std::string::npos) << e.what();
  }
  // A real JPEG's frame is read as it was encoded, and the cap holds to the pixel.
  const std::string jpeg = test_io::encode_image("jpeg", 16, 12, [](int, int) {
    return std::array<std::uint8_t, 3>{10, 20, 30};
  });
  EXPECT_EQ(jpeg_frame_size(jpeg).width, 16u);
  EXPECT_EQ(jpeg_frame_size(jpeg).height, 12u);
  Limits limits;
  limits.max_image_pixels = 191;
  EXPECT_THROW(decode_image(jpeg, limits), LimitError);
  limits.max_image_pixels = 192;
  EXPECT_EQ(decode_image(jpeg, limits).height, 12);
}

TEST(IoImage, AJpegWithoutAReadableFrameHeaderIsAnInputError) {
  const std::string jpeg = test_io::encode_image("jpeg", 16, 16, [](int, int) {
    return std::array<std::uint8_t, 3>{0, 0, 0};
  });
  const std::size_t frame = jpeg.find("\xff\xc0");
  ASSERT_NE(frame, std::string::npos);
  // Every prefix that ends before the frame header's size is complete.
  for (std::size_t n = 0; n < frame + 9; ++n)
    EXPECT_THROW(jpeg_frame_size(jpeg.substr(0, n)), InputError) << "prefix " << n;
  // A segment length past the data, a scan before any frame, and a height left to a DNL marker.
  std::string long_segment = jpeg;
  long_segment[4] = char(0x7f);
  EXPECT_THROW(jpeg_frame_size(long_segment), InputError);
  EXPECT_THROW(jpeg_frame_size(std::string("\xff\xd8\xff\xda\x00\x02", 6)), InputError);
  std::string no_height = jpeg;
  no_height[frame + 5] = 0, no_height[frame + 6] = 0;
  EXPECT_THROW(decode_image(no_height, {}), InputError);
}

TEST(IoImage, GarbageAndTruncatedImagesAreInputErrors) {
  EXPECT_THROW(decode_image("", {}), InputError);
  EXPECT_THROW(decode_image("definitely not an image", {}), InputError);
  const std::string png = test_io::encode_image("png", 8, 8, [](int x, int) {
    return std::array<std::uint8_t, 3>{std::uint8_t(x), 0, 0};
  });
  for (std::size_t n = 0; n + 12 < png.size(); n += 7) {
    EXPECT_THROW(decode_image(png.substr(0, n), {}), InputError) << "prefix " << n;
  }
  const std::string tga = rle_tga();
  for (std::size_t n = 18; n < tga.size(); ++n) {
    EXPECT_THROW(decode_image(tga.substr(0, n), {}), InputError) << "tga prefix " << n;
  }
}

// OpenImageIO 2.4 crashed on this 20-byte colour-mapped RLE TGA with an empty colour map
// (found by fuzz_decode_image): colour-mapped TGA never reaches the decoder.
TEST(IoImage, ColourMappedTgaIsRejectedBeforeTheDecoder) {
  const std::string crash(
      "\x00\x01\x09\x14\xaf\x00\x00\x20\x60\x00\x00\x00\x01\x00\x00\x02"
      "\x08\x00\x00\x08",
      20);
  try {
    decode_image(crash, {});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("colour-mapped"), std::string::npos) << e.what();
  }
  std::string with_map = rle_tga();
  with_map[1] = 1;  // a colour map present in a true-colour image is refused too
  EXPECT_THROW(decode_image(with_map, {}), InputError);
}

std::string error_of(const std::string& bytes) {
  try {
    decode_image(bytes, {});
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// A 24-bit uncompressed BMP, bottom row first: row y holds (60 x, 100, 40 y) in RGB.
std::string bmp(int width, int height, std::uint32_t compression = 0) {
  const int row = (3 * width + 3) / 4 * 4;
  Bytes b;
  b.text("BM").u32le(54 + row * height).u32le(0).u32le(54);
  b.u32le(40).i32le(width).i32le(height).u16le(1).u16le(24).u32le(compression);
  b.u32le(row * height).i32le(2835).i32le(2835).u32le(0).u32le(0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) b.u8(std::uint8_t(40 * y)).u8(100).u8(std::uint8_t(60 * x));
    for (int pad = 3 * width; pad < row; ++pad) b.u8(0);
  }
  return b.str();
}

TEST(IoImage, DecodesAnUncompressedBmp) {
  const Image image = decode_image(bmp(3, 2), {});
  ASSERT_EQ(image.width, 3);
  ASSERT_EQ(image.height, 2);
  EXPECT_EQ(pixel(image, 2, 1), (std::array<std::uint8_t, 3>{120, 100, 0}));
  EXPECT_EQ(pixel(image, 1, 0), (std::array<std::uint8_t, 3>{60, 100, 40}));
}

// OpenImageIO 2.4 aborted the process (an uncaught std::length_error) on this run-length
// encoded BMP that claims 24 bits per pixel (found by fuzz_decode_image): the BMP header is
// checked first and only uncompressed bitmaps reach the decoder.
TEST(IoImage, BmpLayoutIsCheckedBeforeTheDecoder) {
  const std::string crash(
      "BMN\0\0\0\0\0\0\0\x08\0\0\0(\0\0\0\x03\0\0\0\x02\0\0\x40\x01\0\x18\0\x01\0"
      "\0\0\0\0\0\0\x80\x13\x0b\0\0\x13\x0b\0\0\0\0\0\0\0\0\0\0\0d\xc8<d\xc8xd\xc8"
      "\0\0\0\xc8xd\xc8\0\0\0",
      74);
  EXPECT_NE(error_of(crash).find("bmp: "), std::string::npos) << error_of(crash);
  EXPECT_NE(error_of(bmp(3, 2, 1)).find("compression method 1 is not supported"),
            std::string::npos);
  const std::string good = bmp(3, 2);
  EXPECT_NE(error_of(good.substr(0, good.size() - 1)).find("3x2 pixels do not fit in 77 bytes"),
            std::string::npos)
      << error_of(good.substr(0, good.size() - 1));
  std::string planes = good;
  planes[26] = 2;
  EXPECT_NE(error_of(planes).find("2 colour planes"), std::string::npos);
  std::string overlap = good;
  overlap[10] = 40;  // pixels said to start inside the info header
  EXPECT_NE(error_of(overlap).find("overlap"), std::string::npos);
  std::string height = good;
  height[22] = height[23] = height[24] = height[25] = 0;
  EXPECT_NE(error_of(height).find("no pixels"), std::string::npos);
}

// A 4 x 2 BMP of 8-bit palette indices with a palette of two colours (red, then blue).
std::string palette_bmp(std::uint8_t index) {
  Bytes b;
  b.text("BM").u32le(54 + 8 + 8).u32le(0).u32le(54 + 8);
  b.u32le(40).i32le(4).i32le(2).u16le(1).u16le(8).u32le(0);
  b.u32le(8).i32le(2835).i32le(2835).u32le(2).u32le(0);
  b.u8(0).u8(0).u8(255).u8(0).u8(255).u8(0).u8(0).u8(0);  // BGRA palette
  for (int i = 0; i < 7; ++i) b.u8(1);
  b.u8(index);
  return b.str();
}

// OpenImageIO reads palette entries without a bounds check, so every index is checked first.
TEST(IoImage, BmpPaletteIndicesMustNameAColour) {
  const Image image = decode_image(palette_bmp(0), {});
  ASSERT_EQ(image.width, 4);
  EXPECT_EQ(pixel(image, 0, 0), (std::array<std::uint8_t, 3>{0, 0, 255}));
  EXPECT_EQ(pixel(image, 3, 0), (std::array<std::uint8_t, 3>{255, 0, 0}));
  EXPECT_EQ(error_of(palette_bmp(200)), "image: bmp: pixel (3, 1) uses palette entry 200 of 2");
}

TEST(IoImage, PngWithAWrongChunkChecksumIsAnInputError) {
  std::string png = test_io::encode_image("png", 4, 4, [](int x, int y) {
    return std::array<std::uint8_t, 3>{std::uint8_t(x), std::uint8_t(y), 0};
  });
  ASSERT_EQ(decode_image(png, {}).width, 4);
  const std::size_t idat = png.find("IDAT");
  ASSERT_NE(idat, std::string::npos);
  png[idat + 6] = char(png[idat + 6] ^ 0x10);
  EXPECT_NE(error_of(png).find("wrong checksum"), std::string::npos) << error_of(png);
}

TEST(IoImage, UncompressedTgaMustHoldAllItsPixels) {
  Bytes b;
  b.u8(0).u8(0).u8(2);
  for (int i = 0; i < 5; ++i) b.u8(0);
  b.u16le(0).u16le(0).u16le(2).u16le(2).u8(24).u8(0);
  for (int i = 0; i < 4; ++i) b.u8(10).u8(20).u8(30);
  const std::string tga = b.str();
  EXPECT_EQ(decode_image(tga, {}).width, 2);
  EXPECT_NE(error_of(tga.substr(0, tga.size() - 1)).find("2x2 pixels do not fit in 29 bytes"),
            std::string::npos)
      << error_of(tga.substr(0, tga.size() - 1));
}

TEST(IoImage, SamplingWrapsAndFlipsAsAsked) {
  Image image;
  image.width = 2;
  image.height = 1;
  image.rgb = {255, 0, 0, 0, 0, 255};  // red | blue
  io::TextureSampler sampler;
  EXPECT_NEAR(io::sample_texture(image, 0.25, 0.5, sampler)[0], 1, 1e-6);
  EXPECT_NEAR(io::sample_texture(image, 0.75, 0.5, sampler)[2], 1, 1e-6);
  EXPECT_NEAR(io::sample_texture(image, 1.25, 0.5, sampler)[0], 1, 1e-6);  // repeat
  EXPECT_NEAR(io::sample_texture(image, -0.75, 0.5, sampler)[0], 1, 1e-6);
  EXPECT_NEAR(io::sample_texture(image, 0.5, 0.5, sampler)[0], 0.5, 1e-6);  // bilinear
  sampler.wrap_s = io::TextureWrap::ClampToEdge;
  EXPECT_NEAR(io::sample_texture(image, 7.0, 0.5, sampler)[2], 1, 1e-6);
  sampler.wrap_s = io::TextureWrap::MirroredRepeat;
  EXPECT_NEAR(io::sample_texture(image, 1.25, 0.5, sampler)[2], 1, 1e-6);
  Image column;
  column.width = 1;
  column.height = 2;
  column.rgb = {255, 0, 0, 0, 0, 255};  // top red, bottom blue
  io::TextureSampler obj;               // v = 0 at the bottom
  EXPECT_NEAR(io::sample_texture(column, 0.5, 0.75, obj)[0], 1, 1e-6);
  io::TextureSampler gltf;
  gltf.v_origin_bottom = false;
  EXPECT_NEAR(io::sample_texture(column, 0.5, 0.75, gltf)[2], 1, 1e-6);
}

}  // namespace
}  // namespace arg
