// arg_index_check(regclass): an arg_ivf index read whole and held to its table, as amcheck's
// heapallindexed does for B-trees. Raises XX002 (index corrupted) naming the first fault.
#include <algorithm>

#include "common/hash.hpp"
#include "search/sketch_cells.hpp"

#include "arg_ivf.hpp"

extern "C" {
#include "access/heapam.h"
#include "access/htup_details.h"
#include "access/table.h"
#include "access/tableam.h"
#include "catalog/index.h"
#include "catalog/pg_am.h"
#include "commands/defrem.h"
#include "funcapi.h"
#include "utils/acl.h"
#include "utils/lsyscache.h"
#include "utils/memutils.h"
#include "utils/snapmgr.h"
}

namespace {

using namespace argpg::ivf;

uint64 tid_key(const ItemPointerData& tid) {
  return (uint64(ItemPointerGetBlockNumberNoCheck(&tid)) << 16) |
         uint64(ItemPointerGetOffsetNumberNoCheck(&tid));
}

// One entry as the check keeps it: its row and a digest of its sketch's bytes (16 bytes an
// entry, where the sketches themselves would be 2.6 kB).
struct Held {
  uint64 key;
  uint64 digest;
};

uint64 digest_of(const char* bytes, Size size) {
  return arg::fnv1a_64(std::string_view(bytes, size));
}

// What the index holds, in palloc'd memory (an error leaves nothing to free by hand).
struct Holdings {
  Held* entries;
  Size count, capacity;
  int64 list_pages;
};

// Reads every page of the index: the metapage, the cells and their centres, every list page
// (each in one list only, no loop, ending where its cell says), every entry and its sketch,
// strictly.
void read_index(Relation index, Holdings& h) {
  const Cells cells = read_cells(index, true);
  BlockNumber blocks = RelationGetNumberOfBlocks(index);
  Size seen_size = blocks;
  bool* seen = static_cast<bool*>(palloc0(seen_size));
  auto* row = static_cast<arg::ShapeSketch*>(palloc(sizeof(arg::ShapeSketch)));
  for (uint32 c = 0; c < cells.count; ++c) {
    BlockNumber last_seen = InvalidBlockNumber;
    walk_list(
        index, cells.refs[c], BUFFER_LOCK_SHARE, nullptr, &blocks, [] { CHECK_FOR_INTERRUPTS(); },
        [&](Buffer, Page page, BlockNumber block) {
          if (block >= seen_size) {
            seen = static_cast<bool*>(repalloc(seen, block + 1));
            std::memset(seen + seen_size, 0, block + 1 - seen_size);
            seen_size = block + 1;
          }
          if (seen[block]) corrupted(index, block, "list page in two lists");
          seen[block] = true;
          ++h.list_pages;
          last_seen = block;
          const OffsetNumber items = PageGetMaxOffsetNumber(page);
          if (h.count + items > h.capacity) {
            h.capacity = std::max<Size>(2 * h.capacity, h.count + items);
            h.entries = static_cast<Held*>(repalloc_huge(h.entries, h.capacity * sizeof(Held)));
          }
          for (OffsetNumber item = FirstOffsetNumber; item <= items; ++item) {
            ItemPointerData tid;
            const char* sketch;
            Size size;
            read_entry(index, page, block, item, &tid, &sketch, &size);
            argpg::Outcome out = argpg::guarded(
                [&] { arg::read_shape_sketch(std::string_view(sketch, size), *row); });
            if (out.failure != argpg::Failure::None)
              corrupted(index, block, psprintf("entry %u unreadable (%s)", item, out.message));
            h.entries[h.count++] = {tid_key(tid), digest_of(sketch, size)};
          }
        });
    if (last_seen != cells.refs[c].last)
      corrupted(index, cells.refs[c].page, "a cell's last page is not the end of its list");
  }
  pfree(seen);
  pfree(row);
  pfree(cells.refs);
}

struct HeapCheck {
  Relation index;
  const Held* entries;  // sorted by key, no key twice
  Size count;
  int64 rows;
  MemoryContext row_memory;
};

// Each live row of the table with a value: in the index exactly once, under the sketch of the
// value it holds now.
void check_row(Relation, ItemPointer tid, Datum* values, bool* isnull, bool alive, void* state) {
  auto* c = static_cast<HeapCheck*>(state);
  if (!alive || isnull[0]) return;
  ++c->rows;
  const Held probe = {tid_key(*tid), 0};
  const Held* end = c->entries + c->count;
  const Held* found = std::lower_bound(c->entries, end, probe,
                                       [](const Held& a, const Held& b) { return a.key < b.key; });
  if (found == end || found->key != probe.key)
    corrupted(c->index, 0,
              psprintf("row (%u,%u) of the table is not indexed", ItemPointerGetBlockNumber(tid),
                       ItemPointerGetOffsetNumber(tid)));
  MemoryContext caller = MemoryContextSwitchTo(c->row_memory);
  auto* sketch = static_cast<arg::ShapeSketch*>(palloc(sizeof(arg::ShapeSketch)));
  varlena* bytes = entry_sketch(c->index, values[0], *sketch);
  const bool same = digest_of(VARDATA_ANY(bytes), VARSIZE_ANY_EXHDR(bytes)) == found->digest;
  MemoryContextSwitchTo(caller);
  MemoryContextReset(c->row_memory);
  if (!same)
    corrupted(c->index, 0,
              psprintf("row (%u,%u) of the table is indexed under another value's sketch",
                       ItemPointerGetBlockNumber(tid), ItemPointerGetOffsetNumber(tid)));
}

}  // namespace

extern "C" {

PG_FUNCTION_INFO_V1(arg_index_check);

// arg_index_check(index regclass) RETURNS TABLE (list_pages bigint, entries bigint, rows bigint)
Datum arg_index_check(PG_FUNCTION_ARGS) {
  const Oid index_oid = PG_GETARG_OID(0);
  const Oid table_oid = IndexGetRelation(index_oid, true);
  if (!OidIsValid(table_oid))
    ereport(ERROR, (errcode(ERRCODE_WRONG_OBJECT_TYPE),
                    errmsg("\"%s\" is not an index",
                           get_rel_name(index_oid) ? get_rel_name(index_oid) : "?")));
  // Reading every row: the right to read the table.
  if (pg_class_aclcheck(table_oid, GetUserId(), ACL_SELECT) != ACLCHECK_OK)
    ereport(ERROR, (errcode(ERRCODE_INSUFFICIENT_PRIVILEGE),
                    errmsg("permission denied for table %s", get_rel_name(table_oid))));
  Relation heap = table_open(table_oid, AccessShareLock);
  Relation index = index_open(index_oid, AccessShareLock);
  if (index->rd_rel->relam != get_index_am_oid("arg_ivf", false))
    ereport(ERROR,
            (errcode(ERRCODE_WRONG_OBJECT_TYPE),
             errmsg("index \"%s\" is not an arg_ivf index", RelationGetRelationName(index))));

  // The snapshot before the index is read: a row it sees committed before, so its entry was
  // written before the read.
  Snapshot snapshot = RegisterSnapshot(GetTransactionSnapshot());
  Holdings h{};
  h.capacity = 1024;
  h.entries = static_cast<Held*>(palloc(h.capacity * sizeof(Held)));
  read_index(index, h);
  std::sort(h.entries, h.entries + h.count,
            [](const Held& a, const Held& b) { return a.key < b.key; });
  for (Size i = 1; i < h.count; ++i)
    if (h.entries[i].key == h.entries[i - 1].key)
      corrupted(index, 0,
                psprintf("row (%u,%u) of the table has two entries", uint32(h.entries[i].key >> 16),
                         uint32(h.entries[i].key & 0xffff)));

  // Every live row: table_index_build_scan gives each HOT chain's root, as the index holds it.
  HeapCheck c{};
  c.index = index;
  c.entries = h.entries;
  c.count = h.count;
  c.row_memory =
      AllocSetContextCreate(CurrentMemoryContext, "arg_index_check row", ALLOCSET_DEFAULT_SIZES);
  IndexInfo* info = BuildIndexInfo(index);
  info->ii_Concurrent = true;  // an MVCC snapshot's scan, as amcheck's heapallindexed does
  TableScanDesc scan = table_beginscan_strat(heap, snapshot, 0, nullptr, true, false);
  table_index_build_scan(heap, index, info, false, false, check_row, &c, scan);
  UnregisterSnapshot(snapshot);
  MemoryContextDelete(c.row_memory);

  TupleDesc desc;
  if (get_call_result_type(fcinfo, nullptr, &desc) != TYPEFUNC_COMPOSITE)
    elog(ERROR, "arg_index_check must return a row");
  Datum values[3] = {Int64GetDatum(h.list_pages), Int64GetDatum(int64(h.count)),
                     Int64GetDatum(c.rows)};
  bool nulls[3] = {false, false, false};
  pfree(h.entries);
  index_close(index, AccessShareLock);
  table_close(heap, AccessShareLock);
  PG_RETURN_DATUM(HeapTupleGetDatum(heap_form_tuple(BlessTupleDesc(desc), values, nulls)));
}

}  // extern "C"
