// Encoding and strict decoding of format 3's node records, neighbour lists and colour.
#include "graph/compact_nodes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "common/errors.hpp"
#include "graph/quantise.hpp"

namespace arg {

namespace {

constexpr float kHalfPi = 1.57079632679f, kPi = 3.14159265359f;
constexpr std::uint16_t kNoParent = 0xffff;
using compact_detail::get16;

std::array<float, 256> byte_values(float lo, float hi) {
  std::array<float, 256> v;
  for (int q = 0; q < 256; ++q) v[std::size_t(q)] = byte_value(std::uint8_t(q), lo, hi);
  return v;
}

void put16(std::uint8_t* at, std::uint16_t x) {
  at[0] = std::uint8_t(x & 0xff), at[1] = std::uint8_t(x >> 8);
}

// Whether every bin is 0: a graph read row after row mostly holds no colour already, and not
// writing the zeros again spares a third of a node's bytes.
bool all_zero(const std::array<float, 3 * kColourBins>& bins) {
  std::uint32_t any = 0;
  for (float x : bins) {
    std::uint32_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    any |= bits;
  }
  return any == 0;
}

// The node's mu range as fractions of its interval's width.
float interval_fraction(float mu, const ArgNode& n) {
  return float(double(mu) * double(1u << n.level) - n.interval);
}
float mu_of_fraction(std::uint8_t q, const ArgNode& n) {
  return float((n.interval + q / 255.0) / double(1u << n.level));
}

// Histograms are stored as fractions of the area the reader will see: a node whose area
// rounds to 0 keeps empty histograms, as the reader requires.
float stored_area(const ArgNode& n) {
  return unit16_value(quantise_unit16(n.a));
}

// link_graph for pairs as read: (i, j) with j in i's next interval, sorted by i then j. A
// node's neighbours below it in mu come before those above (nodes are sorted by interval), and
// each group arrives sorted, so the lists fill in order without a sort; children likewise.
void link_read_graph(ArgGraph& g, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs,
                     std::vector<std::uint32_t>& fill) {
  const std::size_t n = g.nodes.size();
  fill.assign(n, 0);
  for (const ArgNode& node : g.nodes)
    if (node.parent >= 0) ++g.nodes[std::size_t(node.parent)].child_count;
  for (auto [a, b] : pairs) ++g.nodes[a].adj_count, ++g.nodes[b].adj_count;
  std::uint32_t child_at = 0, adj_at = 0;
  for (ArgNode& node : g.nodes) {
    node.child_begin = child_at, child_at += node.child_count, node.child_count = 0;
    node.adj_begin = adj_at, adj_at += node.adj_count;
  }
  g.children.resize(child_at);
  g.adjacency.resize(adj_at);
  for (std::size_t i = 0; i < n; ++i)
    if (g.nodes[i].parent >= 0) {
      ArgNode& p = g.nodes[std::size_t(g.nodes[i].parent)];
      g.children[p.child_begin + p.child_count++] = std::uint32_t(i);
    }
  // Neighbours below first: every pair's upper end, in the pairs' order (increasing lower end).
  for (auto [a, b] : pairs) g.adjacency[g.nodes[b].adj_begin + fill[b]++] = a;
  for (auto [a, b] : pairs) g.adjacency[g.nodes[a].adj_begin + fill[a]++] = b;
}

}  // namespace

const std::array<float, 256> compact_detail::theta_values = byte_values(-kHalfPi, kHalfPi),
                             compact_detail::phi_values = byte_values(0, kPi),
                             compact_detail::radius_values = byte_values(0, kMaxStoredRadius);

std::vector<std::uint32_t> up_neighbour_counts(const ArgGraph& g) {
  std::vector<std::uint32_t> up(g.nodes.size(), 0);
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const ArgNode& n = g.nodes[i];
    for (std::uint32_t k = 0; k < n.adj_count; ++k)
      up[i] += g.nodes[g.adjacency[n.adj_begin + k]].interval > n.interval;
  }
  return up;
}

void write_compact_nodes(const ArgGraph& g, const std::vector<std::uint32_t>& up, ByteWriter& out) {
  std::uint8_t rec[kCompactNodeSize];
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const ArgNode& n = g.nodes[i];
    put16(rec, n.level == 0 ? kNoParent
                            : std::uint16_t(std::uint32_t(n.parent) - g.level_begin[n.level - 1]));
    rec[2] = std::uint8_t(n.interval), rec[3] = std::uint8_t(std::min<std::uint32_t>(up[i], 255));
    rec[4] = quantise_byte(interval_fraction(n.mu_min, n), 0, 1);
    rec[5] = quantise_byte(interval_fraction(n.mu_max, n), 0, 1);
    rec[6] = quantise_byte(n.theta, -kHalfPi, kHalfPi);
    rec[7] = quantise_byte(n.phi, 0, kPi);
    rec[8] = quantise_byte(n.r, 0, kMaxStoredRadius);
    put16(rec + 9, quantise_unit16(n.a));
    put16(rec + 11, quantise_unit16(n.l));
    put16(rec + 13, quantise_unit16(n.v));
    const float area = stored_area(n);
    quantise_bins(n.cords.data(), kCordBins, area, rec + kCompactCodesAt);
    quantise_bins(n.curv_mean.data(), kCurvatureBins, area, rec + kCompactCodesAt + kCordBins);
    quantise_bins(n.curv_gauss.data(), kCurvatureBins, area,
                  rec + kCompactCodesAt + kCordBins + kCurvatureBins);
    out.put_bytes(std::string_view(reinterpret_cast<const char*>(rec), kCompactNodeSize));
  }
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const ArgNode& n = g.nodes[i];
    const std::uint32_t first = g.level_begin[n.level];
    if (up[i] >= 255) out.put(std::uint16_t(up[i] - 255));
    for (std::uint32_t k = 0; k < n.adj_count; ++k) {
      const std::uint32_t j = g.adjacency[n.adj_begin + k];
      if (g.nodes[j].interval > n.interval) out.put(std::uint16_t(j - first));
    }
  }
}

namespace {

// Buffers of one reader, reused between calls: a ranking reads row after row.
struct ReadBuffers {
  CompactRecords records;
  std::vector<std::uint8_t> up;
  std::vector<std::uint32_t> fill;
};

// The calling thread's buffers, looked up once a call (see thread_scratch in mpair.cpp).
[[gnu::noinline]] ReadBuffers& thread_buffers() {
  thread_local ReadBuffers b;
  return b;
}

}  // namespace

void read_compact_records(ByteReader& in, const std::vector<std::uint32_t>& level_begin,
                          std::size_t count, std::uint32_t edges, CompactRecords& out) {
  std::vector<std::uint8_t>& up = thread_buffers().up;
  const auto* rec =
      reinterpret_cast<const unsigned char*>(in.get_bytes(count * kCompactNodeSize).data());
  out.records = rec;
  out.parent.resize(count);
  out.interval.resize(count);
  up.resize(count);
  // One pass: a node's parent lies in the level above, so its interval is known by then.
  for (std::size_t r = 0, i = 0; i < count; ++i, rec += kCompactNodeSize) {
    while (i >= level_begin[r + 1]) ++r;
    auto bad = [&](const char* what) { in.fail("node " + std::to_string(i) + ": " + what); };
    const std::uint16_t parent = get16(rec);
    const std::uint16_t interval = rec[2];
    if (r == 0) {
      if (parent != kNoParent) bad("level-0 node has a parent");
      out.parent[i] = -1;
    } else {
      if (parent >= level_begin[r] - level_begin[r - 1]) bad("parent out of range");
      out.parent[i] = std::int32_t(level_begin[r - 1] + parent);
    }
    out.interval[i] = interval;
    if (interval >= (1u << r)) bad("interval out of range");
    up[i] = rec[3];
    if (rec[4] > rec[5]) bad("mu range reversed");
    const std::uint16_t area = get16(rec + 9);
    static_assert(kCordBins == 8 && kCurvatureBins == 8, "three histograms of eight codes");
    if (!canonical_bins_3x8(rec + kCompactCodesAt, area))
      bad("histogram codes sum over 255, or fill a node without area");
    // Nodes sorted by interval within a level, each a child of a node of its interval's half:
    // what check_structure would ask, checked here so that format 3 can skip it.
    if (i > level_begin[r] && interval < out.interval[i - 1]) bad("nodes not sorted by interval");
    if (r > 0 && out.interval[std::size_t(out.parent[i])] != interval / 2)
      bad("parent lies in another mu interval");
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs = out.pairs;
  pairs.resize(edges);
  std::size_t read = 0;
  for (std::size_t r = 0, i = 0; i < count; ++i) {
    while (i >= level_begin[r + 1]) ++r;
    const std::uint32_t first = level_begin[r], size = level_begin[r + 1] - first;
    // 255 in the record: the count goes on in a 2-byte number before the list.
    const std::uint32_t up_count = up[i] < 255 ? up[i] : 255u + in.get<std::uint16_t>();
    if (up_count > edges - read)
      in.fail("node " + std::to_string(i) + ": more neighbours than the header's " +
              std::to_string(edges));
    if (up_count == 0) continue;
    const auto* list = reinterpret_cast<const unsigned char*>(in.get_bytes(2 * up_count).data());
    const std::uint32_t above = out.interval[i] + 1u;
    std::uint32_t last = 0;
    for (std::uint32_t k = 0; k < up_count; ++k) {
      const std::uint32_t j = get16(list + 2 * k);
      if (j >= size || out.interval[first + j] != above)
        in.fail("node " + std::to_string(i) + ": neighbour " + std::to_string(j) +
                " is not in the next interval of its level");
      if (k > 0 && j <= last)
        in.fail("node " + std::to_string(i) + ": neighbours not sorted or repeated");
      last = j;
      pairs[read++] = {std::uint32_t(i), first + j};
    }
  }
  if (read != edges)
    in.fail("nodes list " + std::to_string(read) + " neighbours, header says " +
            std::to_string(edges));
}

void read_compact_nodes(ByteReader& in, ArgGraph& g, std::uint32_t edges) {
  ReadBuffers& b = thread_buffers();
  CompactRecords& records = b.records;
  const std::size_t count = g.nodes.size();
  read_compact_records(in, g.level_begin, count, edges, records);
  const unsigned char* rec = records.records;
  for (std::size_t r = 0, i = 0; i < count; ++i, rec += kCompactNodeSize) {
    while (i >= g.level_begin[r + 1]) ++r;
    ArgNode& n = g.nodes[i];
    n.level = std::uint16_t(r);
    // The graph may hold an earlier value's nodes: link_read_graph counts from zero, and
    // the colour section (when there is one) fills the colour.
    n.child_count = n.adj_count = 0;
    if (!g.summary.has_colour && !all_zero(n.colour)) n.colour.fill(0.0f);
    n.parent = records.parent[i];
    n.interval = records.interval[i];
    n.mu_min = mu_of_fraction(rec[4], n), n.mu_max = mu_of_fraction(rec[5], n);
    const CompactScalars s = compact_scalars(rec);
    n.theta = s.theta, n.phi = s.phi, n.r = s.r;
    n.a = s.a, n.l = s.l, n.v = s.v;
    bins_values(rec + kCompactCodesAt, kCordBins, n.a, n.cords.data());
    bins_values(rec + kCompactCodesAt + kCordBins, kCurvatureBins, n.a, n.curv_mean.data());
    bins_values(rec + kCompactCodesAt + kCordBins + kCurvatureBins, kCurvatureBins, n.a,
                n.curv_gauss.data());
  }
  link_read_graph(g, records.pairs, b.fill);
  records.records = nullptr;  // it pointed into the value read
}

void write_compact_colour(const ArgGraph& g, ByteWriter& out) {
  std::uint8_t rec[kCompactColourSize];
  for (const ArgNode& n : g.nodes) {
    for (int c = 0; c < 3; ++c)
      quantise_bins(n.colour.data() + c * kColourBins, kColourBins, stored_area(n),
                    rec + c * kColourBins);
    out.put_bytes(std::string_view(reinterpret_cast<const char*>(rec), kCompactColourSize));
  }
}

void read_compact_colour(std::string_view payload, ArgGraph& g) {
  const auto* rec = reinterpret_cast<const unsigned char*>(payload.data());
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    ArgNode& n = g.nodes[i];
    for (int c = 0; c < 3; ++c) {
      if (!canonical_bins(rec + c * kColourBins, kColourBins, quantise_unit16(n.a)))
        throw InputError("ARG: node " + std::to_string(i) +
                         ": colour codes sum over 255, or fill a node without area");
      bins_values(rec + c * kColourBins, kColourBins, n.a, n.colour.data() + c * kColourBins);
    }
    rec += kCompactColourSize;
  }
}

}  // namespace arg
