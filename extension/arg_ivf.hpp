// The arg_ivf index over arg_sketch: its pages, their checks, and the pieces its build, insert,
// scan and vacuum share.
//
// An inverted file: block 0 is the metapage; blocks 1 .. cell_pages hold the cells, one item
// each (its list's first and last page, then its centre's sketch bytes); every other page
// belongs to one cell's list, a chain of pages of entries (a heap row's address, then its
// sketch's bytes, as the table stores them). A search reads every centre, then the lists of the
// `arg.ivf_probes` nearest, and returns their rows by arg_sketch_distance. Every page and item
// is checked when read (kind, sizes, links, the sketch by its strict reader), and every change
// is WAL-logged with generic WAL records.
#pragma once

#include "search/coarse_sketch.hpp"
#include "search/ivf_page.hpp"
#include "search/shape_sketch.hpp"

#include "arg_bridge.hpp"
#include "arg_guc.hpp"

// The buffer manager's headers bring in the spinlock code, whose `register` C++17 refuses; for
// the rest of each file, whose later PostgreSQL headers bring it in too.
#pragma GCC diagnostic ignored "-Wregister"
extern "C" {
#include "access/genam.h"
#include "access/generic_xlog.h"
#include "storage/bufmgr.h"
#include "storage/bufpage.h"
#include "utils/rel.h"
}

namespace argpg::ivf {

// The page format and its byte-level checks are the core's (search/ivf_page.hpp, fuzzed).
using arg::ivf::kMagic;
using arg::ivf::kMaxSketchBytes;
using arg::ivf::kPageId;
using arg::ivf::kVersion;
enum PageKind : uint16 {
  kMetaPage = uint16(arg::ivf::PageKind::kMeta),
  kCellPage = uint16(arg::ivf::PageKind::kCell),
  kListPage = uint16(arg::ivf::PageKind::kList)
};

// A page's special space.
struct PageOpaque {
  BlockNumber next;  // a list page's next page, InvalidBlockNumber at the end; unused otherwise
  uint16 kind;
  uint16 page_id;
};

// The core reads these structures from raw bytes at its own offsets: they must agree.
static_assert(SizeOfPageHeaderData == arg::ivf::kPageHeaderSize &&
                  sizeof(ItemIdData) == arg::ivf::kItemIdSize &&
                  offsetof(PageHeaderData, pd_lower) == arg::ivf::kLowerAt &&
                  offsetof(PageHeaderData, pd_upper) == arg::ivf::kUpperAt &&
                  offsetof(PageHeaderData, pd_special) == arg::ivf::kSpecialAt &&
                  offsetof(PageHeaderData, pd_pagesize_version) == arg::ivf::kSizeVersionAt,
              "PostgreSQL's page layout is not the one search/ivf_page.hpp reads");
static_assert(MAXALIGN(sizeof(PageOpaque)) == arg::ivf::kSpecialSize &&
                  offsetof(PageOpaque, kind) == 4 && offsetof(PageOpaque, page_id) == 6 &&
                  InvalidBlockNumber == arg::ivf::kNoBlock,
              "the special space is not the one search/ivf_page.hpp reads");

// The metapage's contents.
struct Meta {
  uint32 magic;
  uint32 version;
  uint32 cells;       // >= 1
  uint32 cell_pages;  // blocks 1 .. cell_pages
};

// A cell item's head; the centre's sketch bytes follow (none for the one cell of an index
// built on an empty table, which every row joins).
struct CellHead {
  BlockNumber first, last;  // both InvalidBlockNumber while the list is empty
};

// An entry's head; the sketch bytes follow.
struct EntryHead {
  ItemPointerData tid;
};
static_assert(sizeof(Meta) == arg::ivf::kMetaSize && sizeof(CellHead) == arg::ivf::kCellHeadSize &&
                  sizeof(EntryHead) == arg::ivf::kEntryHeadSize,
              "items are not the size search/ivf_page.hpp reads");

// Where a cell is, its list, and its centre (when `has_centre`). List pages come after the
// cell pages: a link below `first_list_page` is corrupt.
struct CellRef {
  BlockNumber page;
  OffsetNumber item;
  bool has_centre;
  BlockNumber first, last;
  BlockNumber first_list_page;
};

// An index's cells, read from its pages: refs[i] and, when read with centres, centres[i] and
// their coarse sides coarse[i] (unset without a centre). The centres are kept decoded in the
// index's relcache entry (rd_amcache) until the relation is rebuilt: never freed by the caller.
struct Cells {
  uint32 count;
  CellRef* refs;
  const arg::ShapeSketch* centres;  // nullptr when read without centres
  const arg::CoarseQuery* coarse;   // likewise
};

// Reads and checks the metapage; raises XX002 (index corrupted) or, for another page version,
// 0A000 with a hint to REINDEX.
Meta read_meta(Relation index);

// Reads the metapage and every cell (their centres too when `with_centres`), checking every
// byte; raises XX002 (index corrupted) naming what is wrong.
Cells read_cells(Relation index, bool with_centres);

// A new page of `kind` at the end of the index's `fork`, exclusively locked, registered in
// `state` as a full image and initialised.
Buffer new_page(Relation index, ForkNumber fork, GenericXLogState* state, PageKind kind,
                Page* page);

// Raises XX002 "index "name" is corrupted: <what> at block B".
[[noreturn]] void corrupted(Relation index, BlockNumber block, const char* what);

// Checks that `page` (block `block`) is a page of `kind` of an arg_ivf index, its header sane
// (sizes, lower <= upper <= special); raises XX002.
void check_page(Relation index, Page page, BlockNumber block, PageKind kind);

// Checks a list link read on block `at`: a list page (at or after `first_list_page`) within
// the relation. `blocks` is the caller's count of blocks, read again when the link is beyond
// it (another backend may have added the page since); raises XX002.
void check_link(Relation index, BlockNumber* blocks, BlockNumber first_list_page, BlockNumber link,
                BlockNumber at);

// Reads a cell item (its head and centre bytes) at `item` of a checked cell page; its links
// are checked as check_link does. Raises XX002.
CellHead read_cell_item(Relation index, BlockNumber* blocks, BlockNumber first_list_page, Page page,
                        BlockNumber block, OffsetNumber item, const char** centre,
                        Size* centre_size);

// An entry of a checked list page: its row and sketch bytes; raises XX002 when malformed.
void read_entry(Relation index, Page page, BlockNumber block, OffsetNumber item,
                ItemPointerData* tid, const char** sketch, Size* sketch_size);

// Walks the pages of `cell`'s list in order, each locked in `lock_mode` and checked as a list
// page, calling `pace()` before each (interrupts, vacuum delay) and `visit(buffer, page,
// block)` on it. `blocks` is the caller's block count (check_link). Raises XX002 on a bad link
// or a loop.
template <class Visit>
void walk_list(Relation index, const CellRef& cell, int lock_mode, BufferAccessStrategy strategy,
               BlockNumber* blocks, void (*pace)(), Visit&& visit) {
  BlockNumber block = cell.first, at = cell.page, pages = 0;
  while (block != InvalidBlockNumber) {
    pace();
    check_link(index, blocks, cell.first_list_page, block, at);
    if (++pages > *blocks) corrupted(index, block, "list links in a loop");
    Buffer buf = ReadBufferExtended(index, MAIN_FORKNUM, block, RBM_NORMAL, strategy);
    LockBuffer(buf, lock_mode);
    Page page = BufferGetPage(buf);
    check_page(index, page, block, kListPage);
    visit(buf, page, block);
    at = block;
    block = reinterpret_cast<PageOpaque*>(PageGetSpecialPointer(page))->next;
    UnlockReleaseBuffer(buf);
  }
}

// Appends an entry for (`tid`, `sketch`) to the list of `cell`, extending it by a page when
// its last page is full, unless `fill_holes` and an earlier page of the list has room (space
// VACUUM freed: an insert's way; a build only appends); WAL-logged.
void append_entry(Relation index, const CellRef& cell, ItemPointer tid, const char* sketch,
                  Size sketch_size, bool fill_holes);

// Reads the sketch bytes of an indexed value into `out`; raises XX001 when it is not one.
void read_value(Datum value, arg::ShapeSketch& out);

// Whether `type` is the extension's type `arg` (by name: the extension's types have no fixed
// OIDs).
bool is_arg_type(Oid type);

// Whether `index` holds `arg` values (operator class arg_ops): its entries are the values'
// sketches, and a search re-ranks its nearest candidates by SIM, read from the table.
bool indexes_arg(Relation index);

// The table column an index of `arg` values is on; raises 0A000 for an expression, whose value
// a search could not read back from the table.
AttrNumber indexed_column(Relation index);

// An indexed value's sketch, read into `out`, and the bytes its entry stores (an arg_sketch's
// own, or the sketch made from an arg's graph), in CurrentMemoryContext. Raises XX001 when the
// value does not read.
varlena* entry_sketch(Relation index, Datum value, arg::ShapeSketch& out);

}  // namespace argpg::ivf

namespace argpg::ivf {
// Registers the reloption `lists`; called once from _PG_init.
void define_reloptions();
}  // namespace argpg::ivf

// The access method's entry points (arg_ivf_*.cpp).
extern "C" {
IndexBuildResult* arg_ivf_build(Relation heap, Relation index, IndexInfo* info);
void arg_ivf_buildempty(Relation index);
char* arg_ivf_buildphasename(int64 phase);
bool arg_ivf_insert(Relation index, Datum* values, bool* isnull, ItemPointer heap_tid,
                    Relation heap, IndexUniqueCheck check_unique, bool index_unchanged,
                    IndexInfo* info);
IndexScanDesc arg_ivf_beginscan(Relation index, int nkeys, int norderbys);
void arg_ivf_rescan(IndexScanDesc scan, ScanKey keys, int nkeys, ScanKey orderbys, int norderbys);
bool arg_ivf_gettuple(IndexScanDesc scan, ScanDirection dir);
void arg_ivf_endscan(IndexScanDesc scan);
IndexBulkDeleteResult* arg_ivf_bulkdelete(IndexVacuumInfo* info, IndexBulkDeleteResult* stats,
                                          IndexBulkDeleteCallback callback, void* state);
IndexBulkDeleteResult* arg_ivf_vacuumcleanup(IndexVacuumInfo* info, IndexBulkDeleteResult* stats);
}
