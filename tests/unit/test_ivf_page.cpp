// The arg_ivf index's page checks over bytes: real pages (the fuzzer's seeds, written by the
// server) read whole, and each kind of damage named.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "search/ivf_page.hpp"
#include "search/shape_sketch.hpp"

namespace arg::ivf {
namespace {

constexpr std::size_t kPage = 8192;

// A page the server wrote (tests/fuzz/corpus/fuzz_ivf_page/NAME.page: an index of 30
// generated models in 4 cells; its first byte, the LSN's, was overwritten for the fuzzer).
std::string server_page(const char* name) {
  const auto path = std::filesystem::path(__FILE__).parent_path().parent_path() / "fuzz" /
                    "corpus" / "fuzz_ivf_page" / (std::string(name) + ".page");
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

const unsigned char* bytes(const std::string& page) {
  return reinterpret_cast<const unsigned char*>(page.data());
}

void put16(std::string& page, std::size_t at, std::uint16_t v) {
  std::memcpy(&page[at], &v, 2);
}

TEST(IvfPage, ReadsTheMetapageTheServerWrote) {
  const std::string page = server_page("meta");
  ASSERT_EQ(page.size(), kPage);
  PageFacts facts;
  ASSERT_EQ(check_page(bytes(page), kPage, PageKind::kMeta, &facts), nullptr);
  MetaFields meta;
  ASSERT_EQ(read_meta(bytes(page), facts, &meta), nullptr);
  EXPECT_EQ(meta.version, kVersion);
  EXPECT_EQ(meta.cells, 4u);
  EXPECT_EQ(meta.cell_pages, 2u);  // three centres a page
  EXPECT_EQ(check_meta_counts(meta, 14, 4096), nullptr);
  EXPECT_STREQ(check_meta_counts(meta, 2, 4096), "cell counts out of range");
  EXPECT_STREQ(check_meta_counts(meta, 14, 3), "cell counts out of range");
  EXPECT_STREQ(check_page(bytes(page), kPage, PageKind::kList, &facts), "page of the wrong kind");
}

TEST(IvfPage, ReadsEveryCellAndEntryTheServerWrote) {
  for (const char* name : {"cells", "list"}) {
    const std::string page = server_page(name);
    const bool cell = std::string(name) == "cells";
    PageFacts facts;
    ASSERT_EQ(check_page(bytes(page), kPage, cell ? PageKind::kCell : PageKind::kList, &facts),
              nullptr);
    ASSERT_GE(facts.items, 1u) << name;
    for (std::uint32_t item = 1; item <= facts.items; ++item) {
      std::string_view b;
      ASSERT_EQ(page_item(bytes(page), facts, item, 1, 8 + kMaxSketchBytes, &b), nullptr);
      std::string_view sketch;
      if (cell) {
        CellItem c;
        ASSERT_EQ(read_cell_item(b, &c), nullptr);
        EXPECT_NE(c.first, kNoBlock);
        EXPECT_EQ(check_link(c.first, 3, 14), nullptr);
        sketch = c.centre;
      } else {
        Entry e;
        ASSERT_EQ(read_entry(b, &e), nullptr);
        EXPECT_GE(e.offset, 1);
        sketch = e.sketch;
      }
      ShapeSketch s;
      EXPECT_NO_THROW(read_shape_sketch(sketch, s)) << name << " item " << item;
    }
    std::string_view none;
    EXPECT_STREQ(page_item(bytes(page), facts, facts.items + 1, 1, kPage, &none), "out of range");
    EXPECT_STREQ(page_item(bytes(page), facts, 0, 1, kPage, &none), "out of range");
  }
}

TEST(IvfPage, NamesEachDamage) {
  const std::string good = server_page("list");
  PageFacts facts;
  std::string page = good;
  put16(page, kUpperAt, 0);
  EXPECT_STREQ(check_page(bytes(page), kPage, PageKind::kList, &facts), "page never initialised");
  page = good;
  put16(page, kLowerAt, 10);
  EXPECT_STREQ(check_page(bytes(page), kPage, PageKind::kList, &facts), "page header out of range");
  page = good;
  put16(page, kSpecialAt, kPage - 16);
  EXPECT_STREQ(check_page(bytes(page), kPage, PageKind::kList, &facts),
               "page of another index type");
  page = good;
  put16(page, kPage - 2, 0x1234);  // the page id
  EXPECT_STREQ(check_page(bytes(page), kPage, PageKind::kList, &facts),
               "page of another index type");
  EXPECT_STREQ(check_page(bytes(good), 4096, PageKind::kList, &facts), "page header out of range");
  // An item's length beyond the special space.
  ASSERT_EQ(check_page(bytes(good), kPage, PageKind::kList, &facts), nullptr);
  std::string_view b;
  EXPECT_STREQ(page_item(bytes(good), facts, 1, 1, 10, &b), "of a wrong size or place");
  // An entry with row offset 0, a cell linked at one end only, links out of range.
  std::string entry(kEntryHeadSize + 1, '\0');
  Entry e;
  EXPECT_STREQ(read_entry(entry, &e), "entry's row address invalid");
  EXPECT_STREQ(read_entry(entry.substr(0, kEntryHeadSize), &e), "entry of a wrong size");
  std::string item(kCellHeadSize, '\xFF');
  item[0] = 5;
  CellItem c;
  EXPECT_STREQ(read_cell_item(item, &c), "cell's list half linked");
  EXPECT_STREQ(check_link(2, 3, 14), "list link to a page that is not a list's");
  EXPECT_STREQ(check_link(14, 3, 14), "list link beyond the end of the index");
}

}  // namespace
}  // namespace arg::ivf
