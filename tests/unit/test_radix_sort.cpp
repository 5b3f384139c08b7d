// The radix sort by a 64-bit key: std::stable_sort's order, every byte of the key counted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "common/radix_sort.hpp"

using namespace arg;

namespace {

struct Record {
  std::uint64_t key;
  int id;
};

void expect_stable_sorted(std::vector<Record> records) {
  std::vector<Record> expected = records, scratch;
  std::stable_sort(expected.begin(), expected.end(),
                   [](const Record& a, const Record& b) { return a.key < b.key; });
  radix_sort_by_key(records, [](const Record& r) { return r.key; }, scratch, {});
  ASSERT_EQ(records.size(), expected.size());
  for (std::size_t i = 0; i < records.size(); ++i) {
    EXPECT_EQ(records[i].key, expected[i].key) << i;
    EXPECT_EQ(records[i].id, expected[i].id) << i;
  }
}

}  // namespace

TEST(RadixSort, SortsKeysOverEveryByteAndKeepsTiesInOrder) {
  std::mt19937_64 random(7);
  std::vector<Record> records;
  for (int i = 0; i < 20000; ++i) records.push_back({random() >> (i % 64), i});
  for (int i = 0; i < 2000; ++i) records.push_back({records[std::size_t(i * 7)].key, 20000 + i});
  expect_stable_sorted(records);
}

TEST(RadixSort, SortsPositiveDoublesByTheirBits) {
  // Squared lengths in a narrow range: their sign and top exponent bits are one byte for all,
  // the pass on it skipped.
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> length(0.001, 0.1);
  std::vector<Record> records;
  for (int i = 0; i < 5000; ++i) {
    const double l = length(random), l2 = (i % 5 == 0) ? 0.0025 : l * l;
    std::uint64_t bits;
    std::memcpy(&bits, &l2, sizeof bits);
    records.push_back({bits, i});
  }
  expect_stable_sorted(records);
}

TEST(RadixSort, LeavesShortAndOneKeyInputsAlone) {
  expect_stable_sorted({});
  expect_stable_sorted({{5, 0}});
  expect_stable_sorted({{3, 0}, {3, 1}, {3, 2}});
}
