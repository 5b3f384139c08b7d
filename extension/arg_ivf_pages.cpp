// The arg_ivf index's pages: checked reads of the metapage, cells and entries, new pages, and
// appending an entry to a cell's list.
#include "graph/serialize.hpp"
#include "search/sketch_cells.hpp"

#include "arg_ivf.hpp"

extern "C" {
#include "access/htup_details.h"
#include "catalog/pg_type.h"
#include "storage/lmgr.h"
#include "utils/memutils.h"
#include "utils/syscache.h"
}

namespace argpg::ivf {

namespace {

const unsigned char* bytes_of(Page page) {
  return reinterpret_cast<const unsigned char*>(page);
}

// A checked page's facts; raises XX002.
arg::ivf::PageFacts page_facts(Relation index, Page page, BlockNumber block, PageKind kind) {
  arg::ivf::PageFacts facts;
  if (const char* wrong =
          arg::ivf::check_page(bytes_of(page), BLCKSZ, arg::ivf::PageKind(kind), &facts))
    corrupted(index, block, wrong);
  return facts;
}

// An item of a page of `kind`: in range, in use, its bytes between the header's upper and
// special offsets, of a length in [min_size, max_size].
std::string_view item_bytes(Relation index, Page page, PageKind kind, BlockNumber block,
                            OffsetNumber item, Size min_size, Size max_size, const char* what) {
  const arg::ivf::PageFacts facts = page_facts(index, page, block, kind);
  std::string_view bytes;
  if (const char* wrong =
          arg::ivf::page_item(bytes_of(page), facts, item, min_size, max_size, &bytes))
    corrupted(index, block, psprintf("%s %s", what, wrong));
  return bytes;
}

}  // namespace

Meta read_meta(Relation index) {
  Buffer buf = ReadBuffer(index, 0);
  LockBuffer(buf, BUFFER_LOCK_SHARE);
  Page page = BufferGetPage(buf);
  const arg::ivf::PageFacts facts = page_facts(index, page, 0, kMetaPage);
  arg::ivf::MetaFields fields;
  const char* wrong = arg::ivf::read_meta(bytes_of(page), facts, &fields);
  UnlockReleaseBuffer(buf);
  if (wrong) corrupted(index, 0, wrong);
  if (fields.version != kVersion)
    ereport(ERROR, (errcode(ERRCODE_FEATURE_NOT_SUPPORTED),
                    errmsg("index \"%s\" has arg_ivf page version %u, this build reads %u",
                           RelationGetRelationName(index), fields.version, kVersion),
                    errhint("REINDEX it.")));
  if (const char* bad = arg::ivf::check_meta_counts(fields, RelationGetNumberOfBlocks(index),
                                                    uint32(arg::kMaxSketchCells)))
    corrupted(index, 0, bad);
  return Meta{fields.magic, fields.version, fields.cells, fields.cell_pages};
}

void corrupted(Relation index, BlockNumber block, const char* what) {
  ereport(ERROR, (errcode(ERRCODE_INDEX_CORRUPTED),
                  errmsg("index \"%s\" is corrupted: %s at block %u",
                         RelationGetRelationName(index), what, block),
                  errhint("REINDEX it.")));
  pg_unreachable();
}

void check_page(Relation index, Page page, BlockNumber block, PageKind kind) {
  (void)page_facts(index, page, block, kind);
}

void check_link(Relation index, BlockNumber* blocks, BlockNumber first_list_page, BlockNumber link,
                BlockNumber at) {
  // Another backend may have added the page since the caller counted.
  if (link >= *blocks && link >= first_list_page) *blocks = RelationGetNumberOfBlocks(index);
  if (const char* wrong = arg::ivf::check_link(link, first_list_page, *blocks))
    corrupted(index, at, wrong);
}

Buffer new_page(Relation index, ForkNumber fork, GenericXLogState* state, PageKind kind,
                Page* page) {
#if PG_VERSION_NUM >= 160000
  Buffer buf = ExtendBufferedRel(BMR_REL(index), fork, nullptr, EB_LOCK_FIRST);
#else
  // The extension lock keeps two backends from adding the same block.
  LockRelationForExtension(index, ExclusiveLock);
  Buffer buf = ReadBufferExtended(index, fork, P_NEW, RBM_NORMAL, nullptr);
  LockBuffer(buf, BUFFER_LOCK_EXCLUSIVE);
  UnlockRelationForExtension(index, ExclusiveLock);
#endif
  *page = GenericXLogRegisterBuffer(state, buf, GENERIC_XLOG_FULL_IMAGE);
  PageInit(*page, BLCKSZ, sizeof(PageOpaque));
  auto* opaque = reinterpret_cast<PageOpaque*>(PageGetSpecialPointer(*page));
  opaque->next = InvalidBlockNumber;
  opaque->kind = kind;
  opaque->page_id = kPageId;
  return buf;
}

CellHead read_cell_item(Relation index, BlockNumber* blocks, BlockNumber first_list_page, Page page,
                        BlockNumber block, OffsetNumber item, const char** centre,
                        Size* centre_size) {
  const std::string_view bytes = item_bytes(index, page, kCellPage, block, item, sizeof(CellHead),
                                            sizeof(CellHead) + kMaxSketchBytes, "cell item");
  arg::ivf::CellItem cell;
  if (const char* wrong = arg::ivf::read_cell_item(bytes, &cell)) corrupted(index, block, wrong);
  *centre = cell.centre.data();
  *centre_size = cell.centre.size();
  if (cell.first != InvalidBlockNumber) {
    check_link(index, blocks, first_list_page, cell.first, block);
    check_link(index, blocks, first_list_page, cell.last, block);
  }
  return CellHead{cell.first, cell.last};
}

void read_entry(Relation index, Page page, BlockNumber block, OffsetNumber item,
                ItemPointerData* tid, const char** sketch, Size* sketch_size) {
  const std::string_view bytes =
      item_bytes(index, page, kListPage, block, item, sizeof(EntryHead) + 1,
                 sizeof(EntryHead) + kMaxSketchBytes, "entry");
  arg::ivf::Entry entry;
  if (const char* wrong = arg::ivf::read_entry(bytes, &entry)) corrupted(index, block, wrong);
  ItemPointerSet(tid, entry.block, entry.offset);
  *sketch = entry.sketch.data();
  *sketch_size = entry.sketch.size();
}

namespace {

// An index's decoded centres, kept in its relcache entry (rd_amcache, freed when the entry is
// rebuilt) for the relation file they were read from.
struct CentreCache {
  Oid file;
  uint32 cells, cell_pages;
  arg::CoarseQuery* coarse;  // `cells` of them, after the centres
  arg::ShapeSketch centres[FLEXIBLE_ARRAY_MEMBER];
};

Size centre_cache_size(uint32 cells) {
  return offsetof(CentreCache, centres) + sizeof(arg::ShapeSketch) * cells +
         sizeof(arg::CoarseQuery) * cells;
}

Oid file_of(Relation index) {
#if PG_VERSION_NUM >= 160000
  return index->rd_locator.relNumber;
#else
  return index->rd_node.relNode;
#endif
}

}  // namespace

namespace {

// Reads every cell page into `refs` and, when `centres` is given, decodes the centres into it.
void read_cell_pages(Relation index, const Meta& meta, CellRef* refs, arg::ShapeSketch* centres,
                     arg::CoarseQuery* coarse) {
  BlockNumber blocks = RelationGetNumberOfBlocks(index);
  const BlockNumber first_list_page = meta.cell_pages + 1;
  uint32 seen = 0;
  for (BlockNumber block = 1; block <= meta.cell_pages; ++block) {
    Buffer buf = ReadBuffer(index, block);
    LockBuffer(buf, BUFFER_LOCK_SHARE);
    Page page = BufferGetPage(buf);
    check_page(index, page, block, kCellPage);
    const OffsetNumber items = PageGetMaxOffsetNumber(page);
    if (items < 1 || items > meta.cells - seen) corrupted(index, block, "cell count wrong");
    for (OffsetNumber item = FirstOffsetNumber; item <= items; ++item) {
      const char* centre;
      Size size;
      const CellHead head =
          read_cell_item(index, &blocks, first_list_page, page, block, item, &centre, &size);
      refs[seen] = {block, item, size > 0, head.first, head.last, first_list_page};
      if (size == 0 && meta.cells != 1) corrupted(index, block, "cell without a centre");
      if (centres && size > 0) {
        Outcome out = guarded([&] {
          arg::read_shape_sketch(std::string_view(centre, size), centres[seen]);
          coarse[seen] = arg::coarse_query(centres[seen]);
        });
        if (out.failure != Failure::None)
          corrupted(index, block, psprintf("cell centre unreadable (%s)", out.message));
      }
      ++seen;
    }
    UnlockReleaseBuffer(buf);
  }
  if (seen != meta.cells) corrupted(index, meta.cell_pages, "fewer cells than the metapage says");
}

}  // namespace

Cells read_cells(Relation index, bool with_centres) {
  const Meta meta = read_meta(index);
  Cells cells;
  cells.count = meta.cells;
  cells.refs = static_cast<CellRef*>(palloc(sizeof(CellRef) * meta.cells));
  auto* const cache = static_cast<CentreCache*>(index->rd_amcache);
  const bool cached = cache && cache->file == file_of(index) && cache->cells == meta.cells &&
                      cache->cell_pages == meta.cell_pages;
  // Decoded straight into the relcache entry's memory, freed again should a page fail its
  // checks (a corrupt index read again and again would otherwise grow the entry each time).
  CentreCache* const fill = with_centres && !cached
                                ? static_cast<CentreCache*>(MemoryContextAllocHuge(
                                      index->rd_indexcxt, centre_cache_size(meta.cells)))
                                : nullptr;
  if (fill) fill->coarse = reinterpret_cast<arg::CoarseQuery*>(fill->centres + meta.cells);
  PG_TRY();
  {
    read_cell_pages(index, meta, cells.refs, fill ? fill->centres : nullptr,
                    fill ? fill->coarse : nullptr);
  }
  PG_CATCH();
  {
    if (fill) pfree(fill);
    PG_RE_THROW();
  }
  PG_END_TRY();
  cells.centres = nullptr;
  cells.coarse = nullptr;
  if (fill) {
    fill->file = file_of(index);
    fill->cells = meta.cells;
    fill->cell_pages = meta.cell_pages;
    if (index->rd_amcache) pfree(index->rd_amcache);
    index->rd_amcache = fill;
    cells.centres = fill->centres;
    cells.coarse = fill->coarse;
  } else if (with_centres) {
    cells.centres = cache->centres;
    cells.coarse = cache->coarse;
  }
  return cells;
}

namespace {

// The first page of the cell's list before its last with room for `size` more bytes, or
// InvalidBlockNumber: the holes VACUUM left. Pages read one at a time under a share lock, while
// the caller holds the cell page (no other insert into the cell can fill them meanwhile).
BlockNumber page_with_room(Relation index, const CellHead& head, BlockNumber first_list_page,
                           BlockNumber cell_page, Size size) {
  BlockNumber block = head.first, at = cell_page, found = InvalidBlockNumber, pages = 0;
  BlockNumber blocks = RelationGetNumberOfBlocks(index);
  while (block != InvalidBlockNumber && block != head.last && found == InvalidBlockNumber) {
    CHECK_FOR_INTERRUPTS();
    check_link(index, &blocks, first_list_page, block, at);
    if (++pages > blocks) corrupted(index, block, "list links in a loop");
    Buffer buf = ReadBuffer(index, block);
    LockBuffer(buf, BUFFER_LOCK_SHARE);
    Page page = BufferGetPage(buf);
    check_page(index, page, block, kListPage);
    if (PageGetFreeSpace(page) >= size) found = block;
    at = block;
    block = reinterpret_cast<PageOpaque*>(PageGetSpecialPointer(page))->next;
    UnlockReleaseBuffer(buf);
  }
  return found;
}

}  // namespace

void append_entry(Relation index, const CellRef& cell, ItemPointer tid, const char* sketch,
                  Size sketch_size, bool fill_holes) {
  if (sketch_size == 0 || sketch_size > kMaxSketchBytes)
    ereport(ERROR, (errcode(ERRCODE_PROGRAM_LIMIT_EXCEEDED),
                    errmsg("arg_sketch of %zu bytes does not fit an arg_ivf entry", sketch_size)));
  const Size entry_size = sizeof(EntryHead) + sketch_size;
  char* entry = static_cast<char*>(palloc(entry_size));
  std::memcpy(entry, tid, sizeof(EntryHead));
  std::memcpy(entry + sizeof(EntryHead), sketch, sketch_size);

  // The cell page stays locked while its list grows, so two appends to one cell take turns;
  // locks go cell page first, then list pages, as everywhere.
  Buffer cell_buf = ReadBuffer(index, cell.page);
  LockBuffer(cell_buf, BUFFER_LOCK_EXCLUSIVE);
  Page cell_page = BufferGetPage(cell_buf);
  check_page(index, cell_page, cell.page, kCellPage);
  const char* centre;
  Size centre_size;
  BlockNumber blocks = RelationGetNumberOfBlocks(index);
  CellHead head = read_cell_item(index, &blocks, cell.first_list_page, cell_page, cell.page,
                                 cell.item, &centre, &centre_size);

  Buffer last_buf = InvalidBuffer;
  // Where the last page is full, a page VACUUM left room in takes the entry (entries never
  // move and pages never leave their list, so a concurrent scan misses nothing).
  if (fill_holes && head.last != InvalidBlockNumber) {
    Buffer probe = ReadBuffer(index, head.last);
    LockBuffer(probe, BUFFER_LOCK_SHARE);
    const bool last_full = PageGetFreeSpace(BufferGetPage(probe)) < MAXALIGN(entry_size);
    UnlockReleaseBuffer(probe);
    const BlockNumber hole = last_full ? page_with_room(index, head, cell.first_list_page,
                                                        cell.page, MAXALIGN(entry_size))
                                       : InvalidBlockNumber;
    if (hole != InvalidBlockNumber) {
      Buffer buf = ReadBuffer(index, hole);
      LockBuffer(buf, BUFFER_LOCK_EXCLUSIVE);
      check_page(index, BufferGetPage(buf), hole, kListPage);
      GenericXLogState* state = GenericXLogStart(index);
      Page target = GenericXLogRegisterBuffer(state, buf, 0);
      if (PageAddItem(target, entry, entry_size, InvalidOffsetNumber, false, false) ==
          InvalidOffsetNumber) {
        GenericXLogAbort(state);
        elog(ERROR, "arg_ivf: could not add an entry to index \"%s\"",
             RelationGetRelationName(index));
      }
      GenericXLogFinish(state);
      UnlockReleaseBuffer(buf);
      UnlockReleaseBuffer(cell_buf);
      pfree(entry);
      return;
    }
  }
  if (head.last != InvalidBlockNumber) {
    last_buf = ReadBuffer(index, head.last);
    LockBuffer(last_buf, BUFFER_LOCK_EXCLUSIVE);
    Page last = BufferGetPage(last_buf);
    check_page(index, last, head.last, kListPage);
    if (reinterpret_cast<PageOpaque*>(PageGetSpecialPointer(last))->next != InvalidBlockNumber)
      corrupted(index, head.last, "a list's last page links on");
  }
  GenericXLogState* state = GenericXLogStart(index);
  Buffer new_buf = InvalidBuffer;
  Page target;
  if (BufferIsValid(last_buf) &&
      PageGetFreeSpace(BufferGetPage(last_buf)) >= MAXALIGN(entry_size)) {
    target = GenericXLogRegisterBuffer(state, last_buf, 0);
  } else {
    new_buf = new_page(index, MAIN_FORKNUM, state, kListPage, &target);
    const BlockNumber added = BufferGetBlockNumber(new_buf);
    if (BufferIsValid(last_buf)) {
      Page last = GenericXLogRegisterBuffer(state, last_buf, 0);
      reinterpret_cast<PageOpaque*>(PageGetSpecialPointer(last))->next = added;
    }
    Page cp = GenericXLogRegisterBuffer(state, cell_buf, 0);
    if (head.first == InvalidBlockNumber) head.first = added;
    head.last = added;
    std::memcpy(PageGetItem(cp, PageGetItemId(cp, cell.item)), &head, sizeof head);
  }
  if (PageAddItem(target, entry, entry_size, InvalidOffsetNumber, false, false) ==
      InvalidOffsetNumber) {
    GenericXLogAbort(state);
    elog(ERROR, "arg_ivf: could not add an entry to index \"%s\"", RelationGetRelationName(index));
  }
  GenericXLogFinish(state);
  if (BufferIsValid(new_buf)) UnlockReleaseBuffer(new_buf);
  if (BufferIsValid(last_buf)) UnlockReleaseBuffer(last_buf);
  UnlockReleaseBuffer(cell_buf);
  pfree(entry);
}

void read_value(Datum value, arg::ShapeSketch& out) {
  varlena* v = PG_DETOAST_DATUM_PACKED(value);
  Outcome result = guarded([&] { arg::read_shape_sketch(view(v), out); });
  if (v != reinterpret_cast<varlena*>(DatumGetPointer(value))) pfree(v);
  raise_if_failed(result, ERRCODE_DATA_CORRUPTED, "cannot read arg_sketch");
}

bool is_arg_type(Oid type) {
  HeapTuple tuple = SearchSysCache1(TYPEOID, ObjectIdGetDatum(type));
  if (!HeapTupleIsValid(tuple)) return false;
  const bool is_arg =
      std::strcmp(NameStr(reinterpret_cast<Form_pg_type>(GETSTRUCT(tuple))->typname), "arg") == 0;
  ReleaseSysCache(tuple);
  return is_arg;
}

bool indexes_arg(Relation index) {
  return is_arg_type(index->rd_opcintype[0]);
}

AttrNumber indexed_column(Relation index) {
  const AttrNumber column = index->rd_index->indkey.values[0];
  if (column <= 0)
    ereport(ERROR,
            (errcode(ERRCODE_FEATURE_NOT_SUPPORTED),
             errmsg("arg_ivf index \"%s\" is on an expression", RelationGetRelationName(index)),
             errdetail("An index of arg values re-ranks its candidates by SIM, reading the "
                       "values from the table: it must be on a column."),
             errhint("Store the expression in a generated column and index that column.")));
  return column;
}

varlena* entry_sketch(Relation index, Datum value, arg::ShapeSketch& out) {
  varlena* v = PG_DETOAST_DATUM_PACKED(value);
  if (!indexes_arg(index)) {
    Outcome result = guarded([&] { arg::read_shape_sketch(view(v), out); });
    raise_if_failed(result, ERRCODE_DATA_CORRUPTED, "cannot read arg_sketch");
    return v;
  }
  varlena* bytes = nullptr;
  // Stored values were checked on input: read without the digest pass, as <~> reads them.
  Outcome result = guarded([&] {
    out = arg::shape_sketch(arg::deserialize_arg(view(v), /*check_digest=*/false));
    bytes = to_varlena(arg::write_shape_sketch(out));
  });
  if (v != reinterpret_cast<varlena*>(DatumGetPointer(value))) pfree(v);
  raise_if_failed(result, ERRCODE_DATA_CORRUPTED, "cannot read the indexed ARG");
  return bytes;
}

}  // namespace argpg::ivf
