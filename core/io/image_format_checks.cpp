// Checks of PNG, BMP, TGA and JPEG byte layouts done before OpenImageIO decodes the image.
#include "io/image_format_checks.hpp"

#include <zlib.h>

#include <cstdint>
#include <string>

#include "common/byte_io.hpp"
#include "common/errors.hpp"

namespace arg {

namespace {

[[noreturn]] void fail(const std::string& what) {
  throw InputError("image: " + what);
}

// PNG stores lengths and checksums big-endian (ByteReader reads little-endian).
std::uint32_t u32be(std::string_view b, std::size_t i) {
  const auto u8 = [&](std::size_t k) { return std::uint32_t(static_cast<unsigned char>(b[k])); };
  return u8(i) << 24 | u8(i + 1) << 16 | u8(i + 2) << 8 | u8(i + 3);
}

// OpenImageIO 2.4's PNG reader leaks its error message whenever libpng long-jumps out of a read
// past the end of the data, so every chunk must lie inside the data; a corrupt chunk (wrong CRC)
// is refused here too, with its offset, instead of by a long jump through OpenImageIO's frames.
void check_png(std::string_view b) {
  std::size_t at = 8;
  for (;;) {
    if (b.size() - at < 12) fail("png: truncated data (no IEND chunk)");
    const std::uint32_t length = u32be(b, at);
    if (length > b.size() - at - 12) {
      fail("png: the chunk at byte offset " + std::to_string(at) +
           " runs past the end of the data");
    }
    const auto* type = reinterpret_cast<const Bytef*>(b.data() + at + 4);
    const uLong crc = crc32(crc32(0L, Z_NULL, 0), type, uInt(4 + length));
    if (crc != u32be(b, at + 8 + length)) {
      fail("png: the chunk at byte offset " + std::to_string(at) + " has a wrong checksum");
    }
    const bool end = b.substr(at + 4, 4) == "IEND";
    at += 12 + std::size_t(length);
    if (end) return;
  }
}

// Windows and OS/2 bitmaps, uncompressed (or with bit-field masks): OpenImageIO 2.4's run-length
// decoder throws std::length_error through a C++ frame that cannot pass it on, which aborts.
void check_bmp(std::string_view b) {
  ByteReader in(b.substr(10), "image: bmp");
  const std::uint64_t offset = in.get<std::uint32_t>();
  const std::uint32_t header = in.get<std::uint32_t>();
  const bool os2 = header == 12;
  if (!os2 && header != 40 && header != 52 && header != 56 && header != 108 && header != 124) {
    fail("bmp: unknown info header size " + std::to_string(header));
  }
  if (b.size() < 14 + std::size_t(header)) fail("bmp: truncated header");
  std::int64_t width, height;
  std::uint32_t planes, bits, compression = 0, colours = 0;
  if (os2) {
    width = in.get<std::uint16_t>();
    height = in.get<std::uint16_t>();
    planes = in.get<std::uint16_t>();
    bits = in.get<std::uint16_t>();
  } else {
    width = in.get<std::int32_t>();
    height = in.get<std::int32_t>();
    planes = in.get<std::uint16_t>();
    bits = in.get<std::uint16_t>();
    compression = in.get<std::uint32_t>();
    in.get_bytes(12);  // image size, pixels per metre
    colours = in.get<std::uint32_t>();
  }
  if (height < 0) height = -height;  // rows stored top first
  if (width <= 0 || height <= 0) fail("bmp: no pixels");
  if (planes != 1) fail("bmp: " + std::to_string(planes) + " colour planes (must be 1)");
  if (bits != 1 && bits != 4 && bits != 8 && bits != 16 && bits != 24 && bits != 32) {
    fail("bmp: " + std::to_string(bits) + " bits per pixel");
  }
  const bool masks = compression == 3 && (bits == 16 || bits == 32);
  if (compression != 0 && !masks) {
    fail("bmp: compression method " + std::to_string(compression) +
         " is not supported (save the texture as uncompressed BMP, PNG or JPEG)");
  }
  std::uint64_t table = masks && header == 40 ? 12 : 0;
  if (bits <= 8) {
    const std::uint32_t most = 1u << bits;
    if (colours > most) fail("bmp: " + std::to_string(colours) + " palette colours");
    table += std::uint64_t(colours ? colours : most) * (os2 ? 3 : 4);
  }
  if (offset < 14 + header + table) fail("bmp: the pixels overlap the header or the palette");
  const std::uint64_t row = (std::uint64_t(width) * bits + 31) / 32 * 4;
  if (offset > b.size() || row * std::uint64_t(height) > b.size() - offset) {
    fail("bmp: " + std::to_string(width) + "x" + std::to_string(height) + " pixels do not fit in " +
         std::to_string(b.size()) + " bytes");
  }
  // OpenImageIO looks palette indices up without a bounds check: with a short palette, every
  // index must name one of its colours.
  if (bits <= 8 && colours != 0 && colours < (1u << bits)) {
    for (std::uint64_t y = 0; y < std::uint64_t(height); ++y) {
      for (std::uint64_t x = 0; x < std::uint64_t(width); ++x) {
        const std::uint64_t bit = x * bits;
        const unsigned byte =
            static_cast<unsigned char>(b[std::size_t(offset + y * row + bit / 8)]);
        const unsigned index = (byte >> (8 - bits - bit % 8)) & ((1u << bits) - 1);
        if (index >= colours) {
          fail("bmp: pixel (" + std::to_string(x) + ", " + std::to_string(y) +
               ") uses palette entry " + std::to_string(index) + " of " + std::to_string(colours));
        }
      }
    }
  }
}

// OpenImageIO 2.4's TGA reader indexes the colour map with unchecked values (a colour-mapped
// image with an empty map crashes it), so only true-colour and greyscale TGA reach it.
void check_tga(std::string_view b) {
  ByteReader in(b, "image: tga");
  const unsigned id_length = in.get<std::uint8_t>(), colour_map = in.get<std::uint8_t>();
  const unsigned type = in.get<std::uint8_t>();
  if (colour_map != 0 || type == 1 || type == 9) {
    fail(
        "tga: colour-mapped images are not supported (save the texture as true-colour TGA, PNG "
        "or JPEG)");
  }
  in.get_bytes(9);  // colour map specification, origin
  const std::uint64_t width = in.get<std::uint16_t>(), height = in.get<std::uint16_t>();
  const std::uint64_t bits = in.get<std::uint8_t>();
  if (width == 0 || height == 0) fail("tga: no pixels");
  if (type == 2 || type == 3) {
    const std::uint64_t pixels = width * height * ((bits + 7) / 8);
    if (18 + id_length + pixels > b.size()) {
      fail("tga: " + std::to_string(width) + "x" + std::to_string(height) +
           " pixels do not fit in " + std::to_string(b.size()) + " bytes");
    }
  }
}

// The JPEG markers that begin a frame header: SOF0-SOF15 but DHT (C4), JPG (C8) and DAC (CC).
bool frame_marker(unsigned m) {
  return m >= 0xC0 && m <= 0xCF && m != 0xC4 && m != 0xC8 && m != 0xCC;
}

}  // namespace

JpegFrameSize jpeg_frame_size(std::string_view b) {
  const auto u8 = [&](std::size_t i) { return unsigned(static_cast<unsigned char>(b[i])); };
  if (b.size() < 2 || u8(0) != 0xFF || u8(1) != 0xD8) fail("jpeg: no start-of-image marker");
  std::size_t at = 2;
  for (;;) {
    // The next marker as libjpeg finds it (jdmarker.c, next_marker): bytes before a 0xFF are
    // skipped (extraneous data, a warning there), then fill bytes 0xFF, and a 0xFF 0x00 pair is
    // stuffed data, not a marker. Standalone markers (TEM, RSTn) carry no segment, every other
    // one a big-endian length that counts itself.
    unsigned marker = 0;
    while (marker == 0) {
      while (at < b.size() && u8(at) != 0xFF) ++at;
      while (at < b.size() && u8(at) == 0xFF) ++at;
      if (at >= b.size()) fail("jpeg: truncated data before the frame header");
      marker = u8(at++);
    }
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) continue;
    if (marker == 0xD9 || marker == 0xDA)
      fail("jpeg: the image data starts before any frame header");
    if (marker == 0xD8) fail("jpeg: a second start-of-image marker");
    if (b.size() - at < 2)
      fail("jpeg: truncated marker segment at byte offset " + std::to_string(at - 2));
    const std::size_t length = u8(at) << 8 | u8(at + 1);
    if (length < 2 || length > b.size() - at) {
      fail("jpeg: the marker segment at byte offset " + std::to_string(at - 2) +
           " runs past the end of the data");
    }
    if (frame_marker(marker)) {
      // Precision (1 byte), then the number of lines and of samples per line, big-endian.
      if (length < 7) fail("jpeg: a frame header too short to hold its size");
      JpegFrameSize size;
      size.height = u8(at + 3) << 8 | u8(at + 4);
      size.width = u8(at + 5) << 8 | u8(at + 6);
      if (size.height == 0 || size.width == 0) {
        fail("jpeg: the frame header declares " + std::to_string(size.width) + "x" +
             std::to_string(size.height) + " pixels (a height given later by a DNL marker is " +
             "not supported)");
      }
      return size;
    }
    at += length;
  }
}

const char* sniff_image_format(std::string_view b) {
  auto starts = [&](std::string_view magic) { return b.substr(0, magic.size()) == magic; };
  if (starts("\x89PNG\r\n\x1a\n")) return "png";
  if (starts("\xFF\xD8\xFF")) return "jpeg";
  if (starts("BM") && b.size() >= 26) return "bmp";
  // TGA has no magic number: check the header fields that have only a few legal values.
  if (b.size() >= 18) {
    const auto u8 = [&](std::size_t i) { return unsigned(static_cast<unsigned char>(b[i])); };
    const unsigned type = u8(2), colour_map = u8(1), bits = u8(16);
    const bool type_ok =
        type == 1 || type == 2 || type == 3 || type == 9 || type == 10 || type == 11;
    const bool bits_ok = bits == 8 || bits == 15 || bits == 16 || bits == 24 || bits == 32;
    if (colour_map <= 1 && type_ok && bits_ok) return "targa";
  }
  return nullptr;
}

void check_image_layout(std::string_view bytes, std::string_view format) {
  if (format == "png") check_png(bytes);
  if (format == "bmp") check_bmp(bytes);
  if (format == "targa") check_tga(bytes);
}

}  // namespace arg
