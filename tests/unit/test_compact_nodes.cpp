// Format 3's node records: read back as written, and every field checked on the way in.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "common/errors.hpp"
#include "graph/compact_nodes.hpp"
#include "graph/serialize.hpp"
#include "input_error.hpp"
#include "pipeline/build_arg.hpp"
#include "test_shapes.hpp"

namespace arg {
namespace {

constexpr std::size_t kRecords = 304;  // format 3's header size: the first record's offset

const std::string& torus_bytes() {
  static const std::string bytes = serialize_arg(build_arg(test::torus()));
  return bytes;
}

// The torus's value with one change, resealed so that the structural checks see it.
std::string changed(const std::function<void(std::string&)>& change) {
  std::string bytes = torus_bytes();
  change(bytes);
  reseal_arg_digest(bytes);
  return bytes;
}

std::string error_of(const std::string& bytes) {
  return input_error_of([&] { deserialize_arg(bytes); }, "no error");
}

TEST(CompactNodes, RecordsReadBackAsTheGraphWasBuilt) {
  const ArgGraph g = build_arg(test::torus());
  const ArgGraph back = deserialize_arg(torus_bytes());
  ASSERT_EQ(back.nodes.size(), g.nodes.size());
  EXPECT_EQ(back.children, g.children);
  EXPECT_EQ(back.adjacency, g.adjacency);
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const ArgNode &x = g.nodes[i], &y = back.nodes[i];
    EXPECT_EQ(x.parent, y.parent);
    EXPECT_EQ(x.interval, y.interval);
    EXPECT_EQ(x.a, y.a);
    EXPECT_EQ(x.cords, y.cords);
    EXPECT_EQ(x.mu_min, y.mu_min);
    EXPECT_EQ(x.theta, y.theta);
  }
  EXPECT_EQ(torus_bytes().size(),
            kRecords + g.nodes.size() * kCompactNodeSize + g.adjacency.size() +  // 2 bytes an edge
                (8 + 4 * 24 + 2220) + (8 + 4 * 20));  // panorama, spectrum
}

TEST(CompactNodes, EveryFieldIsChecked) {
  const ArgGraph g = deserialize_arg(torus_bytes());
  const std::size_t last = g.nodes.size() - 1, second = 1;  // node 1 lies on level 1
  auto at = [](std::size_t node, std::size_t field) {
    return kRecords + node * kCompactNodeSize + field;
  };
  struct Case {
    const char* expect;
    std::function<void(std::string&)> change;
  };
  const Case cases[] = {
      {"level-0 node has a parent", [&](std::string& b) { b[at(0, 0)] = 0; }},
      {"parent out of range", [&](std::string& b) { b[at(second, 0)] = 9; }},
      {"interval out of range", [&](std::string& b) { b[at(second, 2)] = 2; }},
      {"mu range reversed",
       [&](std::string& b) { b[at(last, 4)] = char(255), b[at(last, 5)] = 0; }},
      {"neighbours", [&](std::string& b) { b[at(last, 3)] = 1; }},
      {"reserved header bytes", [&](std::string& b) { b[kRecords - 1] = 1; }},
      {"pooled flag", [&](std::string& b) { b[kRecords - 4] = 3; }},
      {"no children section", [&](std::string& b) { b[32] = 1; }},
  };
  for (const Case& c : cases) {
    const std::string message = error_of(changed(c.change));
    EXPECT_NE(message.find(c.expect), std::string::npos) << c.expect << ": " << message;
  }
  // A neighbour index pointing outside its level, and one pointing into the same interval.
  const std::size_t lists = kRecords + g.nodes.size() * kCompactNodeSize;
  for (char index : {char(120), char(0)}) {
    const std::string message = error_of(changed([&](std::string& b) { b[lists] = index; }));
    EXPECT_NE(message.find("neighbour"), std::string::npos) << message;
  }
}

TEST(CompactNodes, ALevelOverTheBoundIsRefused) {
  // Level table entries are not enough: the header's node count is checked against the bound.
  const std::string message = error_of(changed([](std::string& b) {
    b[28] = char(0xff), b[29] = char(0xff);  // node count 65,535
  }));
  EXPECT_NE(message.find("node count"), std::string::npos) << message;
}

// The input check of float records (check_node_values) is not run on format 3: no code may
// decode outside its ranges. Every scalar code, every histogram code under every area code,
// and mu ranges at both ends of every interval of the torus's levels.
TEST(CompactNodes, NoCodeDecodesOutsideTheRangesOfFloatRecords) {
  ArgNode n;
  for (int q = 0; q < 256; ++q) {
    n.theta = compact_detail::theta_values[std::size_t(q)];
    n.phi = compact_detail::phi_values[std::size_t(q)];
    n.r = compact_detail::radius_values[std::size_t(q)];
    EXPECT_NO_THROW(check_node_values(n, 0)) << "angle or radius code " << q;
  }
  n = ArgNode{};
  std::size_t out_of_range = 0;
  for (std::uint32_t area = 0; area <= 0xffff; ++area) {
    const float a = unit16_value(std::uint16_t(area));
    const float step = code_step(a);
    for (int code = 0; code < 256; ++code) {
      const float bin = float(code) * step;
      out_of_range += !(std::isfinite(bin) && bin >= 0.0f && bin <= 1.0001f);
    }
    // Through the check itself: the area as every unit value, and its largest bin.
    n.a = n.l = n.v = a;
    std::uint8_t codes[kCordBins] = {255};
    bins_values(codes, kCordBins, a, n.cords.data());
    n.curv_mean = n.curv_gauss = n.cords;
    std::copy(n.cords.begin(), n.cords.end(), n.colour.begin());
    if (area % 4096 == 0 || area == 0xffff) {
      EXPECT_NO_THROW(check_node_values(n, 0)) << area;
    }
    out_of_range += !(n.cords[0] <= 1.0001f && n.cords[0] >= 0.0f);
  }
  EXPECT_EQ(out_of_range, 0u);
  // Every node of the torus with the widest mu range, the largest codes and full histograms.
  const std::string wide = changed([](std::string& b) {
    const ArgGraph g = deserialize_arg(torus_bytes());
    for (std::size_t i = 0; i < g.nodes.size(); ++i) {
      char* rec = b.data() + kRecords + i * kCompactNodeSize;
      rec[4] = 0, rec[5] = char(255);                                         // the whole interval
      rec[6] = rec[7] = rec[8] = char(255);                                   // theta, phi, r
      rec[9] = rec[10] = rec[11] = rec[12] = rec[13] = rec[14] = char(0xff);  // a, l, v
      for (std::size_t h = 0; h < 3; ++h)
        for (std::size_t k = 0; k < kCordBins; ++k)
          rec[kCompactCodesAt + h * kCordBins + k] = char(k == 0 ? 255 : 0);
    }
  });
  const ArgGraph g = deserialize_arg(wide);
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    EXPECT_NO_THROW(check_node_values(g.nodes[i], i));
    EXPECT_EQ(g.nodes[i].mu_max, float((g.nodes[i].interval + 1.0) / (1u << g.nodes[i].level)));
  }
}

}  // namespace
}  // namespace arg
