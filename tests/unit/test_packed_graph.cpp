// A row read straight into its keys: the same prep as the decoded graph's, the same SIM to the
// bit, the same checks; what it cannot do it leaves to the decoded path.
#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "gen/generate_models.hpp"
#include "graph/serialize.hpp"
#include "match/match_prep.hpp"
#include "match/mpair.hpp"
#include "match/packed_graph.hpp"
#include "match/similarity.hpp"
#include "pipeline/build_arg.hpp"
#include "test_stored_graphs.hpp"

using namespace arg;

namespace {

// Branching models without colour as a ranking stores them.
const std::vector<std::string>& plain_values() {
  static const std::vector<std::string> all = [] {
    std::vector<std::string> v;
    const char* classes[] = {"human", "human", "fourleg", "octopus", "cup", "chair"};
    for (int k = 0; k < 6; ++k)
      v.push_back(serialize_arg(build_arg(generate_model(classes[k], k, 32, false).mesh)));
    return v;
  }();
  return all;
}

template <class T>
bool same_bytes(const std::vector<T>& x, const std::vector<T>& y) {
  return x.size() == y.size() &&
         (x.empty() || std::memcmp(x.data(), y.data(), sizeof(T) * x.size()) == 0);
}

bool same_bits(double x, double y) {
  return std::memcmp(&x, &y, sizeof x) == 0;
}

const char* kPresets[] = {"arg", "mrg", "graph", "shape", "colour", "arg level_ratio=0.6"};

}  // namespace

TEST(PackedGraph, PrepIsTheDecodedGraphsPrepByteForByte) {
  PackedGraph row;  // reused row after row, as a ranking does
  for (const char* preset : kPresets)
    for (const std::string& bytes : plain_values()) {
      const Weights w = parse_weights(preset);
      ASSERT_TRUE(read_packed_graph(bytes, w, row));
      const ArgGraph g = deserialize_arg(bytes, false);
      MatchPrep full;
      prepare_match(g, w, full);
      const MatchPrep& p = row.prep;
      EXPECT_TRUE(prep_fits(&p, row.head, w));
      EXPECT_TRUE(row.head.nodes.empty());
      EXPECT_EQ(row.adjacency, g.adjacency.size());
      EXPECT_EQ(row.head.level_begin, g.level_begin);
      EXPECT_EQ(std::memcmp(row.head.global.data(), g.global.data(), sizeof g.global), 0);
      EXPECT_TRUE(same_bytes(row.head.panorama, g.panorama));
      EXPECT_TRUE(same_bytes(row.head.spectrum, g.spectrum));
      EXPECT_EQ(row.head.summary.flags, g.summary.flags);
      EXPECT_EQ(row.head.builder_version, g.builder_version);
      EXPECT_TRUE(same_bytes(p.keys, full.keys)) << preset;
      EXPECT_EQ(p.branches, full.branches);
      ASSERT_FALSE(full.sim_keys.empty());
      EXPECT_TRUE(same_bytes(p.sim_keys, full.sim_keys));
      EXPECT_EQ(p.interval_begin, full.interval_begin);
      EXPECT_EQ(p.neighbour_begin, full.neighbour_begin);
      EXPECT_EQ(p.neighbour_split, full.neighbour_split);
      EXPECT_EQ(p.neighbours, full.neighbours);
      ASSERT_FALSE(full.child_begin.empty());
      EXPECT_EQ(p.child_begin, full.child_begin);
      EXPECT_EQ(p.child_mid, full.child_mid);
      EXPECT_EQ(p.children, full.children);
      EXPECT_TRUE(same_bytes(p.plain.self, full.plain.self));
      EXPECT_TRUE(same_bits(p.plain.total, full.plain.total));
      EXPECT_TRUE(p.plain.order.empty());  // until the row is matched first
      order_packed_graph(row);
      EXPECT_EQ(p.plain.order, full.plain.order);
      EXPECT_TRUE(p.coloured.self.empty());
    }
}

TEST(PackedGraph, SimilarityIsArgSimilarityBitForBit) {
  // Queries with and without colour against rows without: every ordered pair but a model
  // with its own geometry, which packed_similarity leaves to the decoded graphs.
  std::vector<ArgGraph> queries;
  for (const std::string& bytes : plain_values()) queries.push_back(deserialize_arg(bytes));
  for (const ArgGraph& g : test::stored_graphs()) queries.push_back(g);
  PackedGraph row;
  int compared = 0;
  for (const char* preset : kPresets) {
    const Weights w = parse_weights(preset);
    if (w.groups) continue;
    for (const ArgGraph& q : queries) {
      MatchPrep prep;
      prepare_match(q, w, prep);
      for (const std::string& bytes : plain_values()) {
        ASSERT_TRUE(read_packed_graph(bytes, w, row));
        const ArgGraph b = deserialize_arg(bytes, false);
        double sim = -1;
        // The same geometry (with colour or not) ties on everything before the node records.
        const bool same = q.nodes.size() == b.nodes.size() &&
                          q.adjacency.size() == b.adjacency.size() &&
                          std::memcmp(q.global.data(), b.global.data(), sizeof q.global) == 0;
        ASSERT_EQ(packed_similarity(q, &prep, row, w, sim), !same) << preset;
        if (same) continue;
        EXPECT_TRUE(same_bits(sim, arg_similarity(q, b, w, nullptr, &prep, nullptr)))
            << preset << " " << sim;
        // A ranking's query is mostly the second argument: SIM is symmetric to the bit.
        EXPECT_TRUE(same_bits(sim, arg_similarity(b, q, w, nullptr, nullptr, &prep))) << preset;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 100);
}

TEST(PackedGraph, WhatNeedsNodeRecordsIsLeftToTheDecodedPath) {
  PackedGraph row;
  const Weights w = weights_preset("arg");
  // Colour, and formats 1 and 2: read whole.
  EXPECT_FALSE(read_packed_graph(serialize_arg(test::stored_graphs()[0]), w, row));
  ArgGraph old = deserialize_arg(plain_values()[4]);
  old.format = 2;
  EXPECT_FALSE(read_packed_graph(serialize_arg(old), w, row));
  EXPECT_FALSE(prep_fits(&row.prep, row.head, w));
  // Node groups read node records; so does a query without sim keys.
  ASSERT_TRUE(read_packed_graph(plain_values()[4], weights_preset("mrg"), row));
  const ArgGraph q = deserialize_arg(plain_values()[5]);
  MatchPrep prep;
  prepare_match(q, weights_preset("mrg"), prep);
  double sim = -1;
  EXPECT_FALSE(packed_similarity(q, &prep, row, weights_preset("mrg"), sim));
  ASSERT_TRUE(read_packed_graph(plain_values()[4], w, row));
  prepare_match(q, w, prep);
  EXPECT_TRUE(packed_similarity(q, &prep, row, w, sim));
  prep.sim_keys.clear();
  EXPECT_FALSE(packed_similarity(q, &prep, row, w, sim));
  EXPECT_FALSE(packed_similarity(q, nullptr, row, w, sim));
  // A head without its prep never reaches node records: matching refuses it.
  EXPECT_THROW(match_graphs(q, nullptr, row.head, nullptr, w), std::logic_error);
  EXPECT_THROW(arg_similarity(q, row.head, w, nullptr, &prep, &row.prep), std::logic_error);
}

TEST(PackedGraph, RefusesWhatTheFullReaderRefuses) {
  // Each byte of the nodes and sections changed in turn (every seventh, three ways): the two
  // readers accept the same values and name the same fault.
  const std::string& good = plain_values()[2];
  PackedGraph row;
  const Weights w = weights_preset("arg");
  int refused = 0;
  for (std::size_t at = 100; at < good.size(); at += 7)
    for (unsigned delta : {1u, 128u, 255u}) {
      std::string bad = good;
      bad[at] = char(std::uint8_t(bad[at]) + delta);
      std::string full_error, packed_error;
      try {
        (void)deserialize_arg(bad, false);
      } catch (const InputError& e) {
        full_error = e.what();
      }
      try {
        (void)read_packed_graph(bad, w, row);
      } catch (const InputError& e) {
        packed_error = e.what();
      }
      EXPECT_EQ(packed_error, full_error) << "byte " << at;
      refused += !full_error.empty();
    }
  EXPECT_GT(refused, 200);
}
