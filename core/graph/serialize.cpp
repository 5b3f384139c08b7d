// Binary and text forms of an ARG: deterministic writer, strict validating reader.
#include "graph/serialize.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "common/base64.hpp"
#include "common/byte_io.hpp"
#include "common/errors.hpp"
#include "common/hash.hpp"
#include "graph/compact_nodes.hpp"
#include "graph/node_bound.hpp"
#include "graph/panorama_codes.hpp"
#include "graph/quantise.hpp"
#include "graph/whole_shape_layout.hpp"

namespace arg {

namespace {

constexpr char kMagic[4] = {'A', 'R', 'G', 'R'};
constexpr std::size_t kLevelSlots = kMaxLevels + 2;
constexpr std::size_t kHeaderSize1 =
    4 + 2 + 2 + 4 + 4 + 8 + 4 + 4 + 4 + 4 + 28 + 4 * kLevelSlots + 4 * kGlobalDims;
// Format 2 adds the surface option (1 byte, 1 reserved) and the proxy resolution (2 bytes).
constexpr std::size_t kHeaderSize2 = kHeaderSize1 + 4;
// Format 3 adds the number of pooled components (2 bytes, 2 reserved).
constexpr std::size_t kHeaderSize3 = kHeaderSize2 + 4;
constexpr std::size_t kNodeSize =
    2 + 2 + 4 * 5 + 4 * 8 + 4 * (kCordBins + 2 * kCurvatureBins + 3 * kColourBins);
constexpr std::uint32_t kMaxNodes = 1u << 20;
constexpr char kTextTag[] = "arg1:";

// Format 2 ends with tagged sections, in increasing tag order, each at most once: a 4-byte tag,
// the payload's length in bytes (uint32) and the payload. A later feature is a new tag; the
// reader knows every tag it accepts and the exact length each must have.
constexpr std::uint32_t tag_of(const char (&name)[5]) {
  return std::uint32_t(std::uint8_t(name[0])) | std::uint32_t(std::uint8_t(name[1])) << 8 |
         std::uint32_t(std::uint8_t(name[2])) << 16 | std::uint32_t(std::uint8_t(name[3])) << 24;
}
constexpr std::uint32_t kTagPanorama = tag_of("PANO");
constexpr std::uint32_t kTagSpectrum = tag_of("SPEC");
// Format 3: the panorama in bytes (sqrt codes by block, quantise.hpp) and the nodes' colour.
constexpr std::uint32_t kTagPanoramaBytes = tag_of("PNQ8");
constexpr std::uint32_t kTagColour = tag_of("COLR");
std::size_t header_size(std::uint16_t version) {
  return version == 1 ? kHeaderSize1 : version == 2 ? kHeaderSize2 : kHeaderSize3;
}

// Calls f on every field of a node, in the order of the binary form.
template <class Node, class F>
void for_each_field(Node& n, F&& f) {
  f(n.level), f(n.interval), f(n.parent), f(n.child_begin), f(n.child_count), f(n.adj_begin),
      f(n.adj_count);
  f(n.a), f(n.l), f(n.r), f(n.theta), f(n.phi), f(n.v), f(n.mu_min), f(n.mu_max);
  for (auto& x : n.cords) f(x);
  for (auto& x : n.curv_mean) f(x);
  for (auto& x : n.curv_gauss) f(x);
  for (auto& x : n.colour) f(x);
}

// FNV-1a over every byte but the digest's own eight.
std::uint64_t content_digest(std::string_view bytes) {
  return fnv1a_64(bytes.substr(kDigestOffset + kDigestSize),
                  fnv1a_64(bytes.substr(0, kDigestOffset)));
}

struct Header {
  std::uint16_t version = 0, header_size = 0;
  std::uint32_t total_size = 0, builder_version = 0;
  std::uint64_t digest = 0;
  std::uint8_t levels = 0, mu_kind = 0;
  std::uint16_t base_points = 0;
  std::uint32_t node_count = 0, child_count = 0, adjacency_count = 0;
};

[[noreturn]] void fail(const std::string& message) {
  throw InputError("ARG: " + message);
}

bool finite(float x) {
  return std::isfinite(x);
}

// Reads and checks the header; fills graph's scalar parts.
Header read_header(ByteReader& in, std::string_view bytes, ArgGraph& g, bool check_digest) {
  Header h;
  std::string_view magic = in.get_bytes(4);
  if (magic != std::string_view(kMagic, 4)) in.fail("bad magic (not an ARG value)");
  h.version = in.get<std::uint16_t>();
  if (h.version < 1 || h.version > kFormatVersion)
    in.fail("unsupported format version " + std::to_string(h.version) + " (this build reads 1 to " +
            std::to_string(kFormatVersion) + ")");
  h.header_size = in.get<std::uint16_t>();
  if (h.header_size != header_size(h.version))
    in.fail("header size " + std::to_string(h.header_size));
  if (bytes.size() < h.header_size)
    in.fail("value of " + std::to_string(bytes.size()) + " bytes is shorter than its header");
  h.total_size = in.get<std::uint32_t>();
  if (h.total_size != bytes.size())
    in.fail("declared size " + std::to_string(h.total_size) + " but value has " +
            std::to_string(bytes.size()) + " bytes");
  h.builder_version = in.get<std::uint32_t>();
  h.digest = in.get<std::uint64_t>();
  if (check_digest && h.digest != content_digest(bytes))
    in.fail("digest mismatch (corrupted value)");
  h.levels = in.get<std::uint8_t>();
  h.mu_kind = in.get<std::uint8_t>();
  h.base_points = in.get<std::uint16_t>();
  if (h.levels < kMinLevels || h.levels > kMaxLevels) in.fail("levels " + std::to_string(h.levels));
  if (h.mu_kind > 2) in.fail("mu kind " + std::to_string(h.mu_kind));
  if (h.base_points < kMinBasePoints || h.base_points > kMaxBasePoints)
    in.fail("base points " + std::to_string(h.base_points));
  h.node_count = in.get<std::uint32_t>();
  h.child_count = in.get<std::uint32_t>();
  h.adjacency_count = in.get<std::uint32_t>();
  if (h.node_count < 1 || h.node_count > (h.version < 3 ? kMaxNodes : kMaxGraphNodes))
    in.fail("node count " + std::to_string(h.node_count));
  // Format 3 stores no children (parents say it all) and each undirected edge once, in 2 bytes.
  if (h.version >= 3 && h.child_count != 0) in.fail("a format-3 value has no children section");
  if (h.version >= 3 && h.adjacency_count > kMaxGraphNodes)
    in.fail("edge count " + std::to_string(h.adjacency_count));
  const std::uint64_t expected =
      h.version < 3 ? h.header_size + std::uint64_t(h.node_count) * kNodeSize +
                          4 * (std::uint64_t(h.child_count) + h.adjacency_count)
                    : h.header_size + std::uint64_t(h.node_count) * kCompactNodeSize +
                          2 * std::uint64_t(h.adjacency_count);
  // Format 1 ends with the adjacency; format 2 has its sections after it.
  if (h.version == 1 ? expected != bytes.size() : expected > bytes.size())
    in.fail("counts (" + std::to_string(h.node_count) + " nodes, " + std::to_string(h.child_count) +
            " links, " + std::to_string(h.adjacency_count) + " adjacencies) need " +
            std::to_string(expected) + " bytes, value has " + std::to_string(bytes.size()));

  g.options.levels = h.levels;
  g.options.mu = MuKind(h.mu_kind);
  g.options.base_points = h.base_points;
  g.builder_version = h.builder_version;
  ArgSummary& s = g.summary;
  s.triangles = in.get<std::uint32_t>();
  s.vertices = in.get<std::uint32_t>();
  s.components = in.get<std::uint16_t>();
  s.genus = in.get<std::uint16_t>();
  s.has_colour = in.get<std::uint16_t>();
  s.flags = in.get<std::uint16_t>();
  s.area = in.get<float>();
  s.volume = in.get<float>();
  s.scale = in.get<float>();
  if (s.has_colour > 1) in.fail("colour flag " + std::to_string(s.has_colour));
  if (!finite(s.area) || !finite(s.volume) || !finite(s.scale) || s.area < 0 || s.scale < 0)
    in.fail("summary holds a non-finite or negative measure");
  g.level_begin.assign(kLevelSlots, 0);
  for (auto& x : g.level_begin) x = in.get<std::uint32_t>();
  for (auto& x : g.global) {
    x = in.get<float>();
    if (!finite(x)) in.fail("global descriptor holds a non-finite value");
  }
  g.format = h.version;
  if (h.version == 1) {
    g.options.surface = SurfaceKind::Mesh;  // format 1 predates the proxy and hole filling
    g.options.holes = HoleKind::Keep;
  } else {
    const std::uint8_t surface = in.get<std::uint8_t>();
    if (surface > 2) in.fail("surface kind " + std::to_string(surface));
    // Values written before holes could be filled have 0 here, which reads as holes=keep.
    const std::uint8_t holes = in.get<std::uint8_t>();
    if (holes > 1) in.fail("hole kind " + std::to_string(holes));
    g.options.surface = SurfaceKind(surface);
    g.options.holes = HoleKind(holes);
    g.options.proxy_resolution = in.get<std::uint16_t>();
    if (g.options.proxy_resolution < kMinProxyResolution ||
        g.options.proxy_resolution > kMaxProxyResolution)
      in.fail("proxy resolution " + std::to_string(g.options.proxy_resolution));
  }
  if (h.version >= 3) {
    s.pooled = in.get<std::uint16_t>();
    if (in.get<std::uint16_t>() != 0) in.fail("reserved header bytes are not zero");
  }
  const std::uint16_t known = h.version == 1 ? kFlagOpen
                              : h.version == 2
                                  ? kFlagOpen | kFlagProxy | kFlagWideOpen
                                  : kFlagOpen | kFlagProxy | kFlagWideOpen | kFlagPooled;
  if (s.flags & ~known) in.fail("unknown summary flags " + std::to_string(s.flags));
  if ((s.pooled > 0) != bool(s.flags & kFlagPooled))
    in.fail("pooled flag and pooled component count disagree");
  return h;
}

// The level table: every level present, in order, covering every node; format 3 also bounds
// the nodes of a level.
void check_level_table(const ArgGraph& g, std::size_t n) {
  const int levels = g.levels();
  if (g.level_begin[0] != 0) fail("level table does not start at node 0");
  for (std::size_t r = 1; r < kLevelSlots; ++r) {
    std::uint32_t want = r <= std::size_t(levels) + 1 ? g.level_begin[r] : n;
    if (g.level_begin[r] < g.level_begin[r - 1] || g.level_begin[r] > n || g.level_begin[r] != want)
      fail("level table entry " + std::to_string(r) + " is inconsistent");
    if (r <= std::size_t(levels) + 1 && g.level_begin[r] == g.level_begin[r - 1])
      fail("level " + std::to_string(r - 1) + " has no node");
  }
  if (g.level_begin[levels + 1] != n) fail("level table does not cover every node");
  if (g.format >= 3)
    if (const int r = level_over_node_bound(g); r >= 0)
      fail("level " + std::to_string(r) + " holds more than " +
           std::to_string(max_nodes_per_level(levels)) + " nodes");
}

// Structural checks: levels, ordering, parent/child links both ways, adjacency symmetry.
void check_structure(const ArgGraph& g) {
  const std::size_t n = g.nodes.size();
  const int levels = g.levels();
  check_level_table(g, n);

  std::uint32_t child_cursor = 0, adj_cursor = 0;
  std::vector<std::uint8_t> seen_as_child(n, 0);
  for (int r = 0; r <= levels; ++r) {
    for (std::uint32_t i = g.level_begin[r]; i < g.level_begin[r + 1]; ++i) {
      const ArgNode& node = g.nodes[i];
      // The message prefix is only built when a check fails: this loop runs on every read.
      auto at = [i] { return "node " + std::to_string(i); };
      if (node.level != r)
        fail(at() + ": level " + std::to_string(node.level) + " in level " + std::to_string(r) +
             "'s range");
      if (node.interval >= (1u << r)) fail(at() + ": interval out of range");
      if (i > g.level_begin[r] && g.nodes[i - 1].interval > node.interval)
        fail(at() + ": nodes not sorted by interval");
      if (r == 0) {
        if (node.parent != -1) fail(at() + ": level-0 node has a parent");
      } else {
        if (node.parent < std::int32_t(g.level_begin[r - 1]) ||
            node.parent >= std::int32_t(g.level_begin[r]))
          fail(at() + ": parent out of range");
        if (g.nodes[node.parent].interval != node.interval / 2)
          fail(at() + ": parent lies in another mu interval");
      }
      if (node.child_begin != child_cursor || node.child_count > g.children.size() - child_cursor)
        fail(at() + ": children range out of order or out of bounds");
      for (std::uint32_t k = 0; k < node.child_count; ++k) {
        std::uint32_t c = g.children[child_cursor + k];
        if (c >= n || g.nodes[c].parent != std::int32_t(i) || seen_as_child[c])
          fail(at() + ": child " + std::to_string(c) + " does not point back or is listed twice");
        seen_as_child[c] = 1;
      }
      child_cursor += node.child_count;
      if (node.adj_begin != adj_cursor || node.adj_count > g.adjacency.size() - adj_cursor)
        fail(at() + ": adjacency range out of order or out of bounds");
      for (std::uint32_t k = 0; k < node.adj_count; ++k) {
        std::uint32_t j = g.adjacency[adj_cursor + k];
        if (j < g.level_begin[r] || j >= g.level_begin[r + 1])
          fail(at() + ": neighbour " + std::to_string(j) + " is not on the same level");
        int gap = int(g.nodes[j].interval) - int(node.interval);
        if (gap != 1 && gap != -1) fail(at() + ": neighbour not in an adjacent interval");
        if (k > 0 && g.adjacency[adj_cursor + k - 1] >= j)
          fail(at() + ": neighbours not sorted or repeated");
      }
      adj_cursor += node.adj_count;
    }
  }
  if (child_cursor != g.children.size()) fail("unused entries in the children section");
  if (adj_cursor != g.adjacency.size()) fail("unused entries in the adjacency section");
  // Symmetry, once every node's neighbour range is known to lie inside the section and be
  // sorted (a later node's range is not checked yet while an earlier one is walked).
  for (std::uint32_t i = 0; i < n; ++i) {
    const ArgNode& node = g.nodes[i];
    for (std::uint32_t k = 0; k < node.adj_count; ++k) {
      const std::uint32_t j = g.adjacency[node.adj_begin + k];
      const auto begin = g.adjacency.begin() + g.nodes[j].adj_begin;
      if (!std::binary_search(begin, begin + g.nodes[j].adj_count, i))
        fail("node " + std::to_string(i) + ": adjacency to " + std::to_string(j) +
             " is not symmetric");
    }
  }
  for (std::uint32_t i = g.level_begin[1]; i < n; ++i)
    if (!seen_as_child[i]) fail("node " + std::to_string(i) + " is not a child of its parent");
}

const bool kLittleEndianHost = [] {
  const std::uint32_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}();
static_assert(sizeof(ArgNode) == kNodeSize, "ArgNode records are copied as they are stored");

void copy_section(ByteReader& in, void* to, std::size_t bytes) {
  if (bytes) std::memcpy(to, in.get_bytes(bytes).data(), bytes);
}

// A section of `count` floats, every value finite and in [lo, hi].
void read_floats(ByteReader& in, std::uint32_t length, std::size_t count, const char* what,
                 float lo, float hi, bool check_values, std::vector<float>& out) {
  if (length != 4 * count)
    in.fail(std::string(what) + " section of " + std::to_string(length) + " bytes, expected " +
            std::to_string(4 * count));
  out.resize(count);
  if (kLittleEndianHost)
    copy_section(in, out.data(), 4 * count);
  else
    for (float& x : out) x = in.get<float>();
  if (check_values)
    for (float x : out)
      if (!std::isfinite(x) || x < lo || x > hi)
        fail(std::string(what) + " holds a value out of range or not finite");
}

// Format 3's panorama (graph/panorama_codes.hpp).
void read_panorama_bytes(ByteReader& in, std::uint32_t length, ArgGraph& g) {
  if (length != kPanoramaCodesSize)
    in.fail("panorama section of " + std::to_string(length) + " bytes, expected " +
            std::to_string(kPanoramaCodesSize));
  g.panorama.resize(kPanoramaSize);
  read_panorama_codes(in, g.panorama.data());
}

void read_sections(ByteReader& in, std::size_t end, ArgGraph& g, bool check_values) {
  std::uint32_t last = 0;
  bool colour = false, panorama = false, spectrum = false;
  while (in.offset() < end) {
    const std::uint32_t tag = in.get<std::uint32_t>();
    const std::uint32_t length = in.get<std::uint32_t>();
    if (tag <= last) in.fail("sections out of order or repeated");
    last = tag;
    if (length > end - in.offset()) in.fail("section runs past the end of the value");
    // Panorama features are means of values in [0, 1]; the spectrum is clamped to [1e-6, 1e3].
    if (tag == kTagPanorama && g.format == 2)
      read_floats(in, length, kPanoramaSize, "panorama", 0.0f, 1.0001f, check_values, g.panorama),
          panorama = true;
    else if (tag == kTagSpectrum)
      read_floats(in, length, kSpectrumSize, "spectrum", 1e-6f, 1e3f, check_values, g.spectrum),
          spectrum = true;
    else if (tag == kTagPanoramaBytes && g.format >= 3)
      read_panorama_bytes(in, length, g), panorama = true;
    else if (tag == kTagColour && g.format >= 3 && g.summary.has_colour) {
      if (length != g.nodes.size() * kCompactColourSize)
        in.fail("colour section of " + std::to_string(length) + " bytes, expected " +
                std::to_string(g.nodes.size() * kCompactColourSize));
      read_compact_colour(in.get_bytes(length), g);
      colour = true;
    } else
      in.fail("unknown section tag " + std::to_string(tag) + " in a format-" +
              std::to_string(g.format) + " value" +
              (tag == kTagColour ? " (colour section without the colour flag)" : ""));
  }
  if (g.format >= 3 && g.summary.has_colour && !colour)
    in.fail("colour flag set but no colour section");
  if (!panorama) g.panorama.clear();
  if (!spectrum) g.spectrum.clear();
}

// Formats 1 and 2: the records, children and adjacency as they lie in memory.
void read_float_records(ByteReader& in, ArgGraph& g, const Header& h) {
  g.children.resize(h.child_count);
  g.adjacency.resize(h.adjacency_count);
  if (kLittleEndianHost) {
    // The records are stored exactly as they lie in memory here: one copy per section.
    copy_section(in, g.nodes.data(), g.nodes.size() * kNodeSize);
    copy_section(in, g.children.data(), g.children.size() * 4);
    copy_section(in, g.adjacency.data(), g.adjacency.size() * 4);
  } else {
    for (ArgNode& node : g.nodes)
      for_each_field(node, [&](auto& x) { x = in.get<std::remove_reference_t<decltype(x)>>(); });
    for (auto& c : g.children) c = in.get<std::uint32_t>();
    for (auto& j : g.adjacency) j = in.get<std::uint32_t>();
  }
}

}  // namespace

std::string serialize_arg(const ArgGraph& g) {
  const bool first = g.format == 1;
  if (first && (!g.panorama.empty() || !g.spectrum.empty() || g.summary.flags > kFlagOpen))
    throw InputError("ARG: a format-1 value cannot hold whole-shape sections or a proxy");
  if (g.format < 1 || g.format > kFormatVersion)
    throw InputError("ARG: cannot write format " + std::to_string(g.format));
  if (g.format < 3 && g.summary.flags & kFlagPooled)
    throw InputError("ARG: a pooled graph needs format 3");
  const bool compact = g.format >= 3;
  std::uint32_t edges = 0;
  std::vector<std::uint32_t> up;  // format 3: each node's neighbours in the next interval
  if (compact) {
    // Two-byte indices and the reader's bound: a graph over it is pooled first (build_arg does).
    if (const int r = level_over_node_bound(g); r >= 0)
      throw InputError("ARG: level " + std::to_string(r) +
                       " holds more nodes than format 3 keeps (pool_fragments first)");
    up = up_neighbour_counts(g);
    for (std::uint32_t count : up) edges += count;
  }
  ByteWriter out;
  out.put_bytes(std::string_view(kMagic, 4));
  out.put(g.format);
  out.put(std::uint16_t(header_size(g.format)));
  out.put(std::uint32_t(0));  // total size, patched below
  out.put(g.builder_version);
  out.put(std::uint64_t(0));  // digest, patched below
  out.put(std::uint8_t(g.options.levels));
  out.put(std::uint8_t(g.options.mu));
  out.put(std::uint16_t(g.options.base_points));
  out.put(std::uint32_t(g.nodes.size()));
  out.put(std::uint32_t(compact ? 0 : g.children.size()));
  out.put(std::uint32_t(compact ? edges : g.adjacency.size()));
  const ArgSummary& s = g.summary;
  out.put(s.triangles), out.put(s.vertices), out.put(s.components), out.put(s.genus);
  out.put(s.has_colour), out.put(s.flags), out.put(s.area), out.put(s.volume), out.put(s.scale);
  for (std::size_t r = 0; r < kLevelSlots; ++r)
    out.put(r < g.level_begin.size() ? g.level_begin[r] : std::uint32_t(g.nodes.size()));
  for (float x : g.global) out.put(x);
  if (!first) {
    out.put(std::uint8_t(g.options.surface));
    out.put(std::uint8_t(g.options.holes));
    out.put(std::uint16_t(g.options.proxy_resolution));
  }
  if (compact) {
    out.put(std::uint16_t(g.summary.pooled));
    out.put(std::uint16_t(0));
    write_compact_nodes(g, up, out);
  } else {
    for (const ArgNode& node : g.nodes) for_each_field(node, [&](auto x) { out.put(x); });
    for (auto c : g.children) out.put(c);
    for (auto j : g.adjacency) out.put(j);
  }
  auto section = [&](std::uint32_t tag, const std::vector<float>& values) {
    if (values.empty()) return;
    out.put(tag);
    out.put(std::uint32_t(4 * values.size()));
    for (float x : values) out.put(x);
  };
  // Tags in increasing order as little-endian uint32 (the last letter weighs most): format 2
  // "SPEC" < "PANO", format 3 "PNQ8" < "SPEC" < "COLR".
  if (!compact) {
    section(kTagSpectrum, g.spectrum);
    section(kTagPanorama, g.panorama);
  } else {
    if (!g.panorama.empty()) {
      if (g.panorama.size() != std::size_t(kPanoramaSize))
        throw InputError("ARG: panorama of " + std::to_string(g.panorama.size()) + " values");
      out.put(kTagPanoramaBytes);
      out.put(std::uint32_t(kPanoramaCodesSize));
      write_panorama_codes(g.panorama.data(), out);
    }
    section(kTagSpectrum, g.spectrum);
    if (g.summary.has_colour) {
      out.put(kTagColour);
      out.put(std::uint32_t(g.nodes.size() * kCompactColourSize));
      write_compact_colour(g, out);
    }
  }

  std::string& bytes = out.bytes();
  ByteWriter size;
  size.put(std::uint32_t(bytes.size()));
  bytes.replace(8, 4, size.bytes());
  ByteWriter digest;
  digest.put(content_digest(bytes));
  bytes.replace(kDigestOffset, kDigestSize, digest.bytes());
  return std::move(bytes);
}

namespace {

// The start of every read: the length checked, what the reader does not overwrite back to its
// default (the vectors keep their storage), the header read.
Header begin_read(ByteReader& in, std::string_view bytes, ArgGraph& g, bool check_digest) {
  if (bytes.size() < kHeaderSize1)
    fail("value of " + std::to_string(bytes.size()) + " bytes is shorter than the header (" +
         std::to_string(kHeaderSize1) + ")");
  g.options = BuildOptions{};
  g.summary = ArgSummary{};
  // The panorama and spectrum keep their storage until read_sections (or a format-1 value)
  // has found whether the value holds them: emptied first, they were zero-filled again on
  // every row of a ranking before being read over.
  return read_header(in, bytes, g, check_digest);
}

}  // namespace

void deserialize_arg_into(std::string_view bytes, ArgGraph& g, bool check_digest) {
  ByteReader in(bytes, "ARG");
  const Header h = begin_read(in, bytes, g, check_digest);
  g.nodes.resize(h.node_count);
  if (h.version >= 3) {
    // Decoding needs each node's level: the level table first.
    check_level_table(g, g.nodes.size());
    read_compact_nodes(in, g, h.adjacency_count);
  } else {
    read_float_records(in, g, h);
  }
  if (h.version != 1) {
    read_sections(in, bytes.size(), g, check_digest);
  } else {
    g.panorama.clear();
    g.spectrum.clear();
  }
  // Values out of range cannot make anything read out of bounds; a value that passed the full
  // check on input only needs the structural one. Format 3's values are decoded from codes
  // into their ranges, so no code can fail this (tests/unit/test_compact_nodes.cpp tries every
  // code): it checks float records only.
  if (check_digest && h.version < 3)
    for (std::size_t i = 0; i < g.nodes.size(); ++i) check_node_values(g.nodes[i], i);
  // Format 3's reader checks every link as it reads it and builds the rest consistent.
  if (h.version < 3) check_structure(g);
  g.level_begin.resize(std::size_t(g.levels()) + 2);
}

bool read_compact_value(std::string_view bytes, ArgGraph& head, CompactRecords& nodes) {
  head.nodes.clear();
  head.children.clear();
  head.adjacency.clear();
  ByteReader in(bytes, "ARG");
  const Header h = begin_read(in, bytes, head, /*check_digest=*/false);
  if (h.version < 3 || head.summary.has_colour) return false;
  check_level_table(head, h.node_count);
  read_compact_records(in, head.level_begin, h.node_count, h.adjacency_count, nodes);
  // No colour, so read_sections needs no node records (a colour section is refused).
  read_sections(in, bytes.size(), head, /*check_values=*/false);
  head.level_begin.resize(std::size_t(head.levels()) + 2);
  return true;
}

ArgGraph deserialize_arg(std::string_view bytes, bool check_digest) {
  ArgGraph g;
  deserialize_arg_into(bytes, g, check_digest);
  return g;
}

ArgGraph stored_form(const ArgGraph& graph) {
  return deserialize_arg(serialize_arg(graph), /*check_digest=*/false);
}

void check_node_values(const ArgNode& n, std::size_t i) {
  auto bad = [&](const char* what) {
    fail("node " + std::to_string(i) + ": " + what + " out of range or not finite");
  };
  auto unit = [](float x) { return std::isfinite(x) && x >= 0.0f && x <= 1.0001f; };
  if (!unit(n.a)) bad("area");
  if (!unit(n.l)) bad("length");
  if (!unit(n.v)) bad("volume");
  if (!std::isfinite(n.r) || n.r < 0 || n.r > 1e6f) bad("r");
  if (!std::isfinite(n.theta) || std::fabs(n.theta) > 1.5708f) bad("theta");
  if (!std::isfinite(n.phi) || n.phi < 0 || n.phi > 3.1416f) bad("phi");
  if (!unit(n.mu_min) || !unit(n.mu_max) || n.mu_min > n.mu_max) bad("mu range");
  auto hist = [&](const float* x, std::size_t count, const char* what) {
    for (std::size_t k = 0; k < count; ++k)
      if (!unit(x[k])) bad(what);
  };
  hist(n.cords.data(), n.cords.size(), "cords histogram");
  hist(n.curv_mean.data(), n.curv_mean.size(), "mean curvature histogram");
  hist(n.curv_gauss.data(), n.curv_gauss.size(), "Gaussian curvature histogram");
  hist(n.colour.data(), n.colour.size(), "colour histogram");
}

void validate_arg_bytes(std::string_view bytes) {
  // One graph a thread, its vectors kept: a COPY validates row after row, and a new graph's
  // node records (248 bytes a node, zeroed) cost more than the checks of a format-3 value.
  thread_local ArgGraph g;
  if (g.nodes.capacity() > kMaxGraphNodes) g = ArgGraph{};  // an old value's many nodes
  deserialize_arg_into(bytes, g, /*check_digest=*/true);
}

std::uint64_t arg_digest(std::string_view bytes) {
  if (bytes.size() < kDigestOffset + kDigestSize) fail("value too short for a digest");
  ByteReader in(bytes.substr(kDigestOffset, kDigestSize), "ARG");
  return in.get<std::uint64_t>();
}

void reseal_arg_digest(std::string& bytes) {
  if (bytes.size() < kHeaderSize1) fail("value too short for a header");
  ByteWriter digest;
  digest.put(content_digest(bytes));
  bytes.replace(kDigestOffset, kDigestSize, digest.bytes());
}

std::string arg_to_text(std::string_view bytes) {
  return kTextTag + base64_encode(bytes);
}

std::string arg_from_text(std::string_view text) {
  const std::string_view tag(kTextTag);
  if (text.substr(0, tag.size()) != tag) {
    std::size_t colon = text.find(':');
    if (colon != std::string_view::npos && colon < 16 && text.substr(0, 3) == "arg")
      fail("unsupported text version tag \"" + std::string(text.substr(0, colon + 1)) +
           "\" (expected \"arg1:\")");
    fail("text form must start with \"arg1:\"");
  }
  std::string bytes = base64_decode(text.substr(tag.size()));
  validate_arg_bytes(bytes);
  return bytes;
}

}  // namespace arg
