// Checking a GLB file's header, chunks and JSON before tinygltf parses it.
#include "io/glb_container.hpp"

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "io/polygon_soup.hpp"

namespace arg::io {

namespace {

constexpr std::uint32_t kJson = 0x4E4F534A;
constexpr std::uint32_t kBin = 0x004E4942;
constexpr int kMaxJsonDepth = 64;

std::uint32_t le32(std::string_view b, std::size_t at) {
  const auto* p = reinterpret_cast<const unsigned char*>(b.data() + at);
  return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
         std::uint32_t(p[3]) << 24;
}

[[noreturn]] void fail_at(std::size_t offset, const std::string& message) {
  throw_input_error("GLB", "byte offset " + std::to_string(offset), message);
}

[[noreturn]] void fail_json(const std::string& message) {
  throw_input_error("GLB", "JSON chunk", message);
}

bool is_data_uri(const std::string& uri) {
  return uri.rfind("data:", 0) == 0;
}

// A non-negative integer member, or `fallback` when absent.
std::uint64_t unsigned_member(const nlohmann::json& o, const char* key, const std::string& what,
                              std::uint64_t fallback) {
  const auto it = o.find(key);
  if (it == o.end()) return fallback;
  if (!it->is_number_unsigned()) fail_json(what + ": '" + key + "' is not a non-negative integer");
  return it->get<std::uint64_t>();
}

}  // namespace

GlbChunks check_glb_container(std::string_view bytes) {
  if (bytes.size() < 20) fail_at(bytes.size(), "unexpected end of data: a GLB header has 20 bytes");
  if (bytes.substr(0, 4) != "glTF") fail_at(0, "expected the magic 'glTF'");
  const std::uint32_t version = le32(bytes, 4);
  if (version != 2) fail_at(4, "version " + std::to_string(version) + ", expected 2");
  const std::uint32_t length = le32(bytes, 8);
  if (length > bytes.size()) {
    fail_at(8, "header declares " + std::to_string(length) + " bytes but the data has " +
                   std::to_string(bytes.size()) + " (file truncated?)");
  }
  if (length < 20) fail_at(8, "declared length " + std::to_string(length) + " is too small");
  const std::uint32_t json_length = le32(bytes, 12);
  if (le32(bytes, 16) != kJson) fail_at(16, "the first chunk is not JSON");
  if (json_length == 0 || json_length % 4 != 0 || std::uint64_t(json_length) + 20 > length) {
    fail_at(12, "JSON chunk of " + std::to_string(json_length) + " bytes does not fit");
  }
  GlbChunks chunks;
  chunks.length = length;
  chunks.json = bytes.substr(20, json_length);
  // Chunk lengths include their padding, so the BIN chunk starts on a 4-byte boundary.
  const std::size_t at = 20 + std::size_t(json_length);
  if (at + 8 <= length) {
    const std::uint32_t bin_length = le32(bytes, at);
    if (le32(bytes, at + 4) != kBin) fail_at(at + 4, "the second chunk is not BIN");
    if (std::uint64_t(at) + 8 + bin_length > length) {
      fail_at(at, "BIN chunk of " + std::to_string(bin_length) + " bytes runs past the end");
    }
    chunks.bin = bytes.substr(at + 8, bin_length);
  }
  return chunks;
}

void check_gltf_json(const GlbChunks& chunks) {
  // Depth first, by scanning the text (strings skipped), before anything recurses on it.
  int depth = 0;
  bool in_string = false, escaped = false;
  for (const char c : chunks.json) {
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '{' || c == '[') {
      if (++depth > kMaxJsonDepth) fail_json("nested deeper than " + std::to_string(kMaxJsonDepth));
    } else if (c == '}' || c == ']') {
      --depth;
    }
  }
  const nlohmann::json doc = nlohmann::json::parse(chunks.json.begin(), chunks.json.end(), nullptr,
                                                   /*allow_exceptions=*/false);
  if (doc.is_discarded() || !doc.is_object()) fail_json("not a valid JSON object");
  std::vector<std::uint64_t> buffer_length;
  if (const auto buffers = doc.find("buffers"); buffers != doc.end()) {
    if (!buffers->is_array()) fail_json("'buffers' is not an array");
    for (std::size_t i = 0; i < buffers->size(); ++i) {
      const nlohmann::json& b = (*buffers)[i];
      const std::string what = "buffer " + std::to_string(i);
      if (!b.is_object()) fail_json(what + " is not an object");
      const std::uint64_t n = unsigned_member(b, "byteLength", what, UINT64_MAX);
      if (n == UINT64_MAX) fail_json(what + " has no byteLength");
      // The specification's minimum; tinygltf indexes the first byte of an embedded buffer.
      if (n == 0) fail_json(what + " has byteLength 0 (at least 1 is required)");
      const auto uri = b.find("uri");
      if (uri == b.end()) {
        if (i != 0) fail_json(what + " has no uri; only buffer 0 may refer to the BIN chunk");
        if (n > chunks.bin.size()) {
          fail_json(what + " declares " + std::to_string(n) + " bytes but the BIN chunk has " +
                    std::to_string(chunks.bin.size()));
        }
      } else if (!uri->is_string() || !is_data_uri(uri->get<std::string>())) {
        fail_json(what + " refers to an external file, which is not supported");
      } else if (n > uri->get<std::string>().size()) {
        fail_json(what + " declares more bytes than its data URI holds");
      }
      buffer_length.push_back(n);
    }
  }
  // An image is either in a buffer view or a data: URI; any other URI would be a file name
  // that tinygltf would try to open on the server.
  if (const auto images = doc.find("images"); images != doc.end()) {
    if (!images->is_array()) fail_json("'images' is not an array");
    for (std::size_t i = 0; i < images->size(); ++i) {
      const nlohmann::json& image = (*images)[i];
      const std::string what = "image " + std::to_string(i);
      if (!image.is_object()) fail_json(what + " is not an object");
      const auto uri = image.find("uri");
      if (uri != image.end() && (!uri->is_string() || !is_data_uri(uri->get<std::string>())))
        fail_json(what + " refers to an external file, which is not supported");
    }
  }
  if (const auto views = doc.find("bufferViews"); views != doc.end()) {
    if (!views->is_array()) fail_json("'bufferViews' is not an array");
    for (std::size_t i = 0; i < views->size(); ++i) {
      const nlohmann::json& v = (*views)[i];
      const std::string what = "buffer view " + std::to_string(i);
      if (!v.is_object()) fail_json(what + " is not an object");
      const std::uint64_t buffer = unsigned_member(v, "buffer", what, UINT64_MAX);
      const std::uint64_t offset = unsigned_member(v, "byteOffset", what, 0);
      const std::uint64_t length = unsigned_member(v, "byteLength", what, UINT64_MAX);
      if (buffer >= buffer_length.size()) fail_json(what + " refers to a missing buffer");
      if (length == UINT64_MAX || offset > buffer_length[buffer] ||
          length > buffer_length[buffer] - offset) {
        fail_json(what + " lies outside buffer " + std::to_string(buffer));
      }
    }
  }
}

}  // namespace arg::io
