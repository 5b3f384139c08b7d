// Searching an arg_ivf index: the query's nearest cells, their lists ranked by
// arg_sketch_distance, rows returned nearest first.
#include <algorithm>
#include <cmath>

#include "search/sketch_cells.hpp"

#include "arg_ivf.hpp"

extern "C" {
#include "access/relscan.h"
#include "pgstat.h"
#include "utils/memutils.h"
#include "utils/snapmgr.h"
}

namespace {

using namespace argpg::ivf;

struct Hit {
  double distance;
  ItemPointerData tid;
};

// A scan's state: its hits once the lists are read, and where it stands in them.
struct ScanState {
  bool ranked;     // the lists have been read for the current keys
  bool unordered;  // the query is NULL: every row, no distance
  Hit* hits;
  Size count, capacity, next;
  arg::ShapeSketch* query;  // reused across rescans
  arg::ShapeSketch* row;    // one entry's sketch, reused
  MemoryContext memory;     // the hits and a ranking's working memory, reset on each ranking
};

void grow(ScanState& s, Size more) {
  if (s.count + more <= s.capacity) return;
  const Size capacity = std::max<Size>(s.capacity * 2, s.count + more);
  s.hits = static_cast<Hit*>(
      s.hits ? repalloc_huge(s.hits, capacity * sizeof(Hit))
             : MemoryContextAllocHuge(CurrentMemoryContext, capacity * sizeof(Hit)));
  s.capacity = capacity;
}

void check_interrupts() {
  CHECK_FOR_INTERRUPTS();
}

// Reads one cell's list into the hits: every entry's distance to the query (none when
// unordered). Pages are read one at a time under a share lock.
void read_list(IndexScanDesc scan, ScanState& s, const CellRef& cell, BlockNumber* blocks) {
  Relation index = scan->indexRelation;
  walk_list(index, cell, BUFFER_LOCK_SHARE, nullptr, blocks, check_interrupts,
            [&](Buffer, Page page, BlockNumber block) {
              const OffsetNumber items = PageGetMaxOffsetNumber(page);
              grow(s, items);
              // Entries are checked outside the guarded loop (ereport may not run inside it).
              const char* sketch[MaxOffsetNumber];
              Size size[MaxOffsetNumber];
              for (OffsetNumber item = FirstOffsetNumber; item <= items; ++item) {
                Hit& hit = s.hits[s.count + item - 1];
                read_entry(index, page, block, item, &hit.tid, &sketch[item - 1], &size[item - 1]);
                hit.distance = 0;
              }
              if (!s.unordered) {
                argpg::Outcome out = argpg::guarded([&] {
                  for (OffsetNumber item = 0; item < items; ++item) {
                    arg::read_shape_sketch(std::string_view(sketch[item], size[item]), *s.row);
                    const double d = arg::sketch_distance(*s.query, *s.row);
                    // Checked sketches give finite distances; a NaN would break the sort.
                    if (std::isnan(d)) throw arg::InputError("its distance is not a number");
                    s.hits[s.count + item].distance = d;
                  }
                });
                if (out.failure != argpg::Failure::None)
                  corrupted(index, block, psprintf("entry's sketch unreadable (%s)", out.message));
              }
              s.count += items;
            });
}

void rank(IndexScanDesc scan, ScanState& s) {
  Relation index = scan->indexRelation;
  if (!IsMVCCSnapshot(scan->xs_snapshot))
    ereport(ERROR, (errcode(ERRCODE_FEATURE_NOT_SUPPORTED),
                    errmsg("arg_ivf index \"%s\" needs an MVCC snapshot",
                           RelationGetRelationName(index))));
  if (scan->numberOfOrderBys != 1)
    ereport(ERROR,
            (errcode(ERRCODE_FEATURE_NOT_SUPPORTED),
             errmsg("arg_ivf index \"%s\" only orders by <~>", RelationGetRelationName(index))));
  const ScanKey key = &scan->orderByData[0];
  MemoryContextReset(s.memory);
  s.hits = nullptr;
  s.capacity = 0;
  MemoryContext caller = MemoryContextSwitchTo(s.memory);
  s.unordered = (key->sk_flags & SK_ISNULL) != 0;
  s.count = s.next = 0;
  if (!s.unordered) read_value(key->sk_argument, *s.query);
  // cells.centres lives in the relcache entry: nothing that may accept invalidation messages
  // (a lock, a detoast) may run before its last use below.
  const Cells cells = read_cells(index, !s.unordered);
  // A NULL query has no nearest: every row, in no order (all its distances are NULL).
  uint32 probes = s.unordered ? cells.count : uint32(argpg::ivf_probes());
  uint32* probed = static_cast<uint32*>(palloc(sizeof(uint32) * cells.count));
  uint32 n_probed = 0;
  if (s.unordered || !cells.refs[0].has_centre) {
    for (uint32 c = 0; c < cells.count; ++c) probed[n_probed++] = c;
  } else {
    argpg::Outcome out = argpg::guarded([&] {
      for (std::size_t c : arg::cells_to_probe(*s.query, cells.centres, cells.count, probes))
        probed[n_probed++] = uint32(c);
    });
    argpg::raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot compare arg_sketch values");
  }
  // No ring buffer: a catalogue's lists are read again by the next search, so they should stay
  // in shared buffers.
  BlockNumber blocks = RelationGetNumberOfBlocks(index);
  for (uint32 p = 0; p < n_probed; ++p) read_list(scan, s, cells.refs[probed[p]], &blocks);
  if (!s.unordered)
    std::sort(s.hits, s.hits + s.count, [](const Hit& a, const Hit& b) {
      if (a.distance != b.distance) return a.distance < b.distance;
      return ItemPointerCompare(const_cast<ItemPointer>(&a.tid), const_cast<ItemPointer>(&b.tid)) <
             0;
    });
  pfree(probed);
  pfree(cells.refs);
  MemoryContextSwitchTo(caller);
  s.ranked = true;
}

}  // namespace

extern "C" {

IndexScanDesc arg_ivf_beginscan(Relation index, int nkeys, int norderbys) {
  IndexScanDesc scan = RelationGetIndexScan(index, nkeys, norderbys);
  // The distances go back with the rows (the executor does not recompute them).
  scan->xs_orderbyvals = static_cast<Datum*>(palloc0(sizeof(Datum) * size_t(Max(norderbys, 1))));
  scan->xs_orderbynulls = static_cast<bool*>(palloc(sizeof(bool) * size_t(Max(norderbys, 1))));
  scan->xs_orderbynulls[0] = true;
  auto* s = static_cast<ScanState*>(palloc0(sizeof(ScanState)));
  s->query = static_cast<arg::ShapeSketch*>(palloc(sizeof(arg::ShapeSketch)));
  s->row = static_cast<arg::ShapeSketch*>(palloc(sizeof(arg::ShapeSketch)));
  s->memory = AllocSetContextCreate(CurrentMemoryContext, "arg_ivf scan", ALLOCSET_DEFAULT_SIZES);
  scan->opaque = s;
  return scan;
}

void arg_ivf_rescan(IndexScanDesc scan, ScanKey keys, int nkeys, ScanKey orderbys, int norderbys) {
  auto* s = static_cast<ScanState*>(scan->opaque);
  s->ranked = false;
  s->count = s->next = 0;
  if (keys && scan->numberOfKeys > 0)
    std::memmove(scan->keyData, keys, sizeof(ScanKeyData) * size_t(scan->numberOfKeys));
  if (orderbys && scan->numberOfOrderBys > 0)
    std::memmove(scan->orderByData, orderbys, sizeof(ScanKeyData) * size_t(scan->numberOfOrderBys));
}

bool arg_ivf_gettuple(IndexScanDesc scan, ScanDirection) {
  auto* s = static_cast<ScanState*>(scan->opaque);
  if (!s->ranked) {
    pgstat_count_index_scan(scan->indexRelation);
    rank(scan, *s);
  }
  if (s->next >= s->count) return false;
  const Hit& hit = s->hits[s->next++];
  scan->xs_heaptid = hit.tid;
  scan->xs_recheck = false;
  scan->xs_recheckorderby = false;
  if (scan->numberOfOrderBys > 0) {
    scan->xs_orderbyvals[0] = Float8GetDatum(hit.distance);
    scan->xs_orderbynulls[0] = s->unordered;
  }
  return true;
}

void arg_ivf_endscan(IndexScanDesc scan) {
  auto* s = static_cast<ScanState*>(scan->opaque);
  MemoryContextDelete(s->memory);
  pfree(s->query);
  pfree(s->row);
  pfree(s);
  scan->opaque = nullptr;
}

}  // extern "C"
