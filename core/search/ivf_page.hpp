// The arg_ivf index's pages as bytes: every check a read makes, without a server, so that a
// fuzzer reaches them.
//
// Pages have PostgreSQL's standard layout (bufpage.h: a 24-byte header, 4-byte line pointers,
// items at the end, a special space last), in the machine's byte order; the extension checks
// at compile time that its headers agree with the offsets here. Every function reads only
// within the `page_size` bytes it is given and returns nullptr when what it read is sane, or
// otherwise a fixed message saying what is wrong (the extension reports it as XX002 with the
// block).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace arg::ivf {

inline constexpr std::uint32_t kMagic = 0x41524749;  // "ARGI"
inline constexpr std::uint32_t kVersion = 1;
inline constexpr std::uint16_t kPageId = 0xA6F1;  // in every page's special space
enum class PageKind : std::uint16_t { kMeta = 1, kCell = 2, kList = 3 };

// PostgreSQL's page layout.
inline constexpr std::size_t kPageHeaderSize = 24, kItemIdSize = 4;
inline constexpr std::size_t kLowerAt = 12, kUpperAt = 14, kSpecialAt = 16, kSizeVersionAt = 18;
// The special space: the next page of a list (or 0xFFFFFFFF), the kind, kPageId.
inline constexpr std::size_t kSpecialSize = 8;
inline constexpr std::uint32_t kNoBlock = 0xFFFFFFFF;

// The largest sketch an entry or a centre may hold: three fit a page. A sketch with every part
// is 2,596 bytes (2,588 in version 1, without the digest).
inline constexpr std::size_t kMaxSketchBytes = 2600;
// An entry's head: the heap row's address (block as two 16-bit halves, then the offset).
inline constexpr std::size_t kEntryHeadSize = 6;
// A cell item's head: its list's first and last block.
inline constexpr std::size_t kCellHeadSize = 8;

// What check_page read of a sane page.
struct PageFacts {
  std::uint16_t lower = 0, upper = 0, special = 0;
  std::uint32_t items = 0;        // line pointers
  std::uint32_t next = kNoBlock;  // a list page's next page
};

// Whether `page` (`page_size` bytes, PostgreSQL's page size) is an initialised page of `kind`
// with a sane header: lower <= upper <= special <= page size, the special space exactly ours.
const char* check_page(const unsigned char* page, std::size_t page_size, PageKind kind,
                       PageFacts* facts);

// Item `item` (1-based) of a checked page: in range, in use, within upper .. special, of a
// length in [min_size, max_size]. The message ("out of range", "of a wrong size or place")
// follows the item's name.
const char* page_item(const unsigned char* page, const PageFacts& facts, std::uint32_t item,
                      std::size_t min_size, std::size_t max_size, std::string_view* bytes);

// The metapage's contents (after the header).
struct MetaFields {
  std::uint32_t magic = 0, version = 0, cells = 0, cell_pages = 0;
};
inline constexpr std::size_t kMetaSize = 16;
// Reads the fields of a checked metapage and checks its magic (the version is the caller's:
// another version is not corruption).
const char* read_meta(const unsigned char* page, const PageFacts& facts, MetaFields* meta);
// The counts of a metapage of this version, against the index's `blocks` and its largest
// number of cells.
const char* check_meta_counts(const MetaFields& meta, std::uint32_t blocks,
                              std::uint32_t max_cells);

// A cell item: its list's ends and its centre's sketch bytes (none for the one cell of an
// index built on an empty table).
struct CellItem {
  std::uint32_t first = kNoBlock, last = kNoBlock;
  std::string_view centre;
};
const char* read_cell_item(std::string_view item, CellItem* cell);

// A list link read on some page: a list page (at or after `first_list_page`), within the
// index's `blocks`.
const char* check_link(std::uint32_t link, std::uint32_t first_list_page, std::uint32_t blocks);

// An entry: its row's address (a valid one: offset >= 1) and its sketch's bytes (at least one).
struct Entry {
  std::uint32_t block = 0;
  std::uint16_t offset = 0;
  std::string_view sketch;
};
const char* read_entry(std::string_view item, Entry* entry);

}  // namespace arg::ivf
