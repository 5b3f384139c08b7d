// The arg_ivf index's page checks over bytes.
#include "search/ivf_page.hpp"

#include <cstring>

namespace arg::ivf {

namespace {

template <class T>
T native_at(const unsigned char* p) {
  T x;
  std::memcpy(&x, p, sizeof x);
  return x;
}

// A line pointer: PostgreSQL's ItemIdData, bit fields lp_off:15, lp_flags:2, lp_len:15 of one
// 32-bit word, allocated from the low bits on a little-endian machine and from the high bits
// on a big-endian one (as GCC and Clang lay out bit fields).
struct LinePointer {
  std::uint32_t offset, flags, length;
};
LinePointer line_pointer(const unsigned char* p) {
  const std::uint32_t w = native_at<std::uint32_t>(p);
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
  return {w >> 17, (w >> 15) & 3u, w & 0x7FFFu};
#else
  return {w & 0x7FFFu, (w >> 15) & 3u, w >> 17};
#endif
}
constexpr std::uint32_t kLpNormal = 1;

}  // namespace

const char* check_page(const unsigned char* page, std::size_t page_size, PageKind kind,
                       PageFacts* facts) {
  if (page_size < kPageHeaderSize + kSpecialSize || page_size > 0x8000)
    return "page of a size no index has";
  const auto upper = native_at<std::uint16_t>(page + kUpperAt);
  if (upper == 0) return "page never initialised";
  const auto lower = native_at<std::uint16_t>(page + kLowerAt);
  const auto special = native_at<std::uint16_t>(page + kSpecialAt);
  const auto size_version = native_at<std::uint16_t>(page + kSizeVersionAt);
  if ((size_version & 0xFF00u) != page_size || lower < kPageHeaderSize || lower > upper ||
      upper > special || special > page_size)
    return "page header out of range";
  if (page_size - special != kSpecialSize) return "page of another index type";
  const unsigned char* opaque = page + special;
  if (native_at<std::uint16_t>(opaque + 6) != kPageId) return "page of another index type";
  if (native_at<std::uint16_t>(opaque + 4) != std::uint16_t(kind)) return "page of the wrong kind";
  facts->lower = lower;
  facts->upper = upper;
  facts->special = special;
  facts->items = std::uint32_t(lower - kPageHeaderSize) / kItemIdSize;
  facts->next = native_at<std::uint32_t>(opaque);
  return nullptr;
}

const char* page_item(const unsigned char* page, const PageFacts& facts, std::uint32_t item,
                      std::size_t min_size, std::size_t max_size, std::string_view* bytes) {
  if (item < 1 || item > facts.items) return "out of range";
  const LinePointer lp = line_pointer(page + kPageHeaderSize + kItemIdSize * (item - 1));
  if (lp.flags != kLpNormal || lp.length < min_size || lp.length > max_size ||
      lp.offset < facts.upper || std::size_t(lp.offset) + lp.length > facts.special)
    return "of a wrong size or place";
  *bytes = std::string_view(reinterpret_cast<const char*>(page) + lp.offset, lp.length);
  return nullptr;
}

const char* read_meta(const unsigned char* page, const PageFacts& facts, MetaFields* meta) {
  if (facts.lower < kPageHeaderSize + kMetaSize) return "metapage too short";
  const unsigned char* p = page + kPageHeaderSize;
  meta->magic = native_at<std::uint32_t>(p);
  meta->version = native_at<std::uint32_t>(p + 4);
  meta->cells = native_at<std::uint32_t>(p + 8);
  meta->cell_pages = native_at<std::uint32_t>(p + 12);
  if (meta->magic != kMagic) return "not an arg_ivf metapage";
  return nullptr;
}

const char* check_meta_counts(const MetaFields& meta, std::uint32_t blocks,
                              std::uint32_t max_cells) {
  if (meta.cells < 1 || meta.cells > max_cells || meta.cell_pages < 1 ||
      meta.cell_pages > meta.cells || meta.cell_pages >= blocks)
    return "cell counts out of range";
  return nullptr;
}

const char* read_cell_item(std::string_view item, CellItem* cell) {
  if (item.size() < kCellHeadSize || item.size() > kCellHeadSize + kMaxSketchBytes)
    return "cell item of a wrong size";
  const auto* p = reinterpret_cast<const unsigned char*>(item.data());
  cell->first = native_at<std::uint32_t>(p);
  cell->last = native_at<std::uint32_t>(p + 4);
  cell->centre = item.substr(kCellHeadSize);
  if ((cell->first == kNoBlock) != (cell->last == kNoBlock)) return "cell's list half linked";
  return nullptr;
}

const char* check_link(std::uint32_t link, std::uint32_t first_list_page, std::uint32_t blocks) {
  if (link < first_list_page) return "list link to a page that is not a list's";
  if (link >= blocks) return "list link beyond the end of the index";
  return nullptr;
}

const char* read_entry(std::string_view item, Entry* entry) {
  if (item.size() <= kEntryHeadSize || item.size() > kEntryHeadSize + kMaxSketchBytes)
    return "entry of a wrong size";
  const auto* p = reinterpret_cast<const unsigned char*>(item.data());
  entry->block = std::uint32_t(native_at<std::uint16_t>(p)) << 16 | native_at<std::uint16_t>(p + 2);
  entry->offset = native_at<std::uint16_t>(p + 4);
  entry->sketch = item.substr(kEntryHeadSize);
  if (entry->offset == 0) return "entry's row address invalid";
  return nullptr;
}

}  // namespace arg::ivf
