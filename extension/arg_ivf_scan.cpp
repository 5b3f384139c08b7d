// Searching an arg_ivf index: the query's nearest cells, their entries ranked by sketch
// distance; on an index of `arg` values, entries first ranked by the coarse distance (a few
// bytes of each), the nearest of them by sketch distance, the nearest of those by exact SIM,
// read from the table, batch after batch while the executor asks for more rows.
#include <algorithm>
#include <cmath>
#include <new>

#include "search/coarse_sketch.hpp"
#include "search/query_ranker.hpp"
#include "search/sketch_cells.hpp"

#include "arg_ivf.hpp"

extern "C" {
#include "access/relscan.h"
#include "access/tableam.h"
#include "executor/tuptable.h"
#include "pgstat.h"
#include "utils/memutils.h"
#include "utils/snapmgr.h"
}

namespace {

using namespace argpg::ivf;

struct Hit {
  double distance;  // coarse or sketch distance, then SIM once re-ranked
  ItemPointerData tid;
  BlockNumber block;  // where the entry was read (the coarse pass reads it again there)
  OffsetNumber item;
};

// How many entries, for each candidate ranked by SIM, the coarse pass hands to the sketch
// distance: a pool ranked by coarse distance keeps SIM's ten nearest among the sketch's
// nearest fifty, less .003, when four times as many as wanted are read whole (965 labelled
// models; core/search/coarse_sketch.hpp).
constexpr Size kRefineFactor = 4;

bool nearer(const Hit& a, const Hit& b) {
  if (a.distance != b.distance) return a.distance < b.distance;
  return ItemPointerCompare(const_cast<ItemPointer>(&a.tid), const_cast<ItemPointer>(&b.tid)) < 0;
}

// Min-heap order of the pool: the root is the nearest.
bool farther(const Hit& a, const Hit& b) {
  return nearer(b, a);
}

// A scan's state. Candidates are every entry of the probed cells by sketch distance; `taken` of
// them have gone to a batch. An index of sketches returns candidates as they are; an index of
// `arg` values re-ranks each batch of arg.ivf_candidates by SIM and returns it in that order.
struct ScanState {
  bool started;    // the query has been read for the current keys
  bool unordered;  // the query is NULL: every row, no distance
  bool exact;      // an index of arg values: batches re-ranked by SIM
  Hit* hits;       // the probed cells' entries; for an index of arg values by coarse distance
  Size count, capacity, taken;
  Hit* refined;  // entries read whole, not yet ranked by SIM: a min-heap by sketch distance
  Size refined_count, refined_capacity;
  arg::CoarseQuery* coarse;
  uint32* cell_order;  // every cell, nearest to the query first
  uint32 cells, probed;
  // Candidates ranked by SIM and not yet returned: a min-heap by SIM.
  Hit* pool;
  Size pool_count, pool_capacity;
  // SIM less sketch distance of every ranked row: how far SIM lies above the sketch's estimate,
  // which tells how near an unranked candidate's SIM could be (margin()).
  double* excess;
  Size excess_capacity;
  // Low quantiles of `excess`, refreshed after each batch: the tenth percentile while fewer rows
  // than a batch have been returned (a LIMIT k query), the least once more are wanted (a filter
  // rejects most rows, so each row found out of turn is one the query may miss).
  double margin, margin_late;
  Size returned;  // rows returned by this search
  int batches;
  Size reranked;    // rows ranked by SIM in this scan (arg.max_scan_tuples bounds it)
  Size candidates;  // arg.ivf_candidates for this index's size
  double last;      // the SIM of the last row returned (strict order drops rows below it)
  arg::ShapeSketch* query;
  arg::ShapeSketch* row;
  arg::QueryRanker* ranker;  // C++ state, deleted by `on_reset` with `memory`
  MemoryContextCallback on_reset;
  IndexFetchTableData* fetch;
  TupleTableSlot* slot;
  AttrNumber column;
  MemoryContext memory;       // hits, batch and the ranker, reset at each rescan
  MemoryContext row_memory;   // one row's detoasted value
  MemoryContext scan_memory;  // the scan's own (the table fetch and slot live there)
};

void delete_ranker(void* arg) {
  auto* s = static_cast<ScanState*>(arg);
  delete s->ranker;
  s->ranker = nullptr;
}

void grow(ScanState& s, Size more) {
  if (s.count + more <= s.capacity) return;
  const Size capacity = std::max<Size>(s.capacity * 2, s.count + more);
  s.hits = static_cast<Hit*>(s.hits ? repalloc_huge(s.hits, capacity * sizeof(Hit))
                                    : MemoryContextAllocHuge(s.memory, capacity * sizeof(Hit)));
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
                hit.block = block;
                hit.item = item;
              }
              if (s.unordered) {
              } else if (s.exact) {
                // A few bytes of each entry: its whole sketch is read (strictly) only if it
                // comes near; bytes that are no sketch at all are refused here.
                for (OffsetNumber k = 0; k < items; ++k) {
                  const double d =
                      arg::coarse_sketch_distance(*s.coarse, std::string_view(sketch[k], size[k]));
                  if (!std::isfinite(d))
                    corrupted(index, block, psprintf("entry %u is not a sketch", k + 1));
                  s.hits[s.count + k].distance = d;
                }
              } else {
                argpg::Outcome out = argpg::guarded([&] {
                  for (OffsetNumber k = 0; k < items; ++k) {
                    arg::read_shape_sketch(std::string_view(sketch[k], size[k]), *s.row);
                    const double d = arg::sketch_distance(*s.query, *s.row);
                    // Checked sketches give finite distances; a NaN would break the sort.
                    if (std::isnan(d)) throw arg::InputError("its distance is not a number");
                    s.hits[s.count + k].distance = d;
                  }
                });
                if (out.failure != argpg::Failure::None)
                  corrupted(index, block, psprintf("entry's sketch unreadable (%s)", out.message));
              }
              s.count += items;
            });
}

// The sketch distance of a probed entry, read whole again where it was (strictly); false when
// the entry is no longer there (VACUUM removed it since: its row is gone).
bool refine(IndexScanDesc scan, ScanState& s, const Hit& hit, double& distance) {
  Relation index = scan->indexRelation;
  Buffer buf = ReadBuffer(index, hit.block);
  LockBuffer(buf, BUFFER_LOCK_SHARE);
  Page page = BufferGetPage(buf);
  check_page(index, page, hit.block, kListPage);
  // VACUUM compacts a page's items: look at the entry's place first, then over the page.
  const OffsetNumber items = PageGetMaxOffsetNumber(page);
  ItemPointerData tid;
  const char* sketch = nullptr;
  Size size = 0;
  bool found = false;
  if (hit.item <= items) {
    read_entry(index, page, hit.block, hit.item, &tid, &sketch, &size);
    found = ItemPointerEquals(&tid, const_cast<ItemPointer>(&hit.tid));
  }
  for (OffsetNumber item = FirstOffsetNumber; item <= items && !found; ++item) {
    read_entry(index, page, hit.block, item, &tid, &sketch, &size);
    found = ItemPointerEquals(&tid, const_cast<ItemPointer>(&hit.tid));
  }
  if (found) {
    argpg::Outcome out = argpg::guarded([&] {
      arg::read_shape_sketch(std::string_view(sketch, size), *s.row);
      distance = arg::sketch_distance(*s.query, *s.row);
      if (std::isnan(distance)) throw arg::InputError("its distance is not a number");
    });
    if (out.failure != argpg::Failure::None)
      corrupted(index, hit.block, psprintf("entry's sketch unreadable (%s)", out.message));
  }
  UnlockReleaseBuffer(buf);
  return found;
}

// Reads whole the next kRefineFactor x `want` entries by coarse distance into the refined
// heap. Returns false when no entry of the probed cells is left to read.
bool refine_more(IndexScanDesc scan, ScanState& s, Size want) {
  if (s.taken >= s.count) return false;
  const Size n = std::min(kRefineFactor * want, s.count - s.taken);
  if (s.refined_count + n > s.refined_capacity) {
    const Size capacity = std::max(2 * s.refined_capacity, s.refined_count + n);
    s.refined =
        static_cast<Hit*>(s.refined ? repalloc_huge(s.refined, capacity * sizeof(Hit))
                                    : MemoryContextAllocHuge(s.memory, capacity * sizeof(Hit)));
    s.refined_capacity = capacity;
  }
  for (Size i = 0; i < n; ++i) {
    CHECK_FOR_INTERRUPTS();
    Hit hit = s.hits[s.taken + i];
    if (!refine(scan, s, hit, hit.distance)) continue;
    s.refined[s.refined_count++] = hit;
    std::push_heap(s.refined, s.refined + s.refined_count, farther);
  }
  s.taken += n;
  return true;
}

// Reads the next `n` cells of the query's order into the hits, and sorts the hits not yet
// taken.
void probe_cells(IndexScanDesc scan, ScanState& s, uint32 n) {
  const Cells cells = read_cells(scan->indexRelation, false);
  if (cells.count != s.cells) corrupted(scan->indexRelation, 0, "cell count changed");
  BlockNumber blocks = RelationGetNumberOfBlocks(scan->indexRelation);
  const uint32 end = std::min(s.cells, s.probed + n);
  for (; s.probed < end; ++s.probed)
    read_list(scan, s, cells.refs[s.cell_order[s.probed]], &blocks);
  pfree(cells.refs);
  if (!s.unordered) std::sort(s.hits + s.taken, s.hits + s.count, nearer);
}

// Reads the query, orders the cells by their centres' distance to it and reads the first
// arg.ivf_probes of them (every cell for a NULL query).
void start(IndexScanDesc scan, ScanState& s) {
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
  // The table is known once the scan has begun (index_beginscan sets it after ambeginscan).
  if (s.exact && !s.fetch) {
    if (!scan->heapRelation)
      ereport(ERROR, (errcode(ERRCODE_FEATURE_NOT_SUPPORTED),
                      errmsg("arg_ivf index \"%s\" is searched only by an index scan",
                             RelationGetRelationName(index))));
    MemoryContext caller = MemoryContextSwitchTo(s.scan_memory);
    s.fetch = table_index_fetch_begin(scan->heapRelation);
    s.slot = table_slot_create(scan->heapRelation, nullptr);
    MemoryContextSwitchTo(caller);
  }
  MemoryContextReset(s.memory);  // deletes the last query's ranker
  s.hits = s.pool = s.refined = nullptr;
  s.refined_count = s.refined_capacity = 0;
  s.excess = nullptr;
  s.capacity = s.count = s.taken = s.pool_count = s.pool_capacity = s.excess_capacity = 0;
  s.batches = 0;
  s.reranked = 0;
  s.margin = s.margin_late = 0;
  s.returned = 0;
  s.last = -1;
  s.on_reset = {delete_ranker, &s};
  MemoryContextRegisterResetCallback(s.memory, &s.on_reset);
  s.unordered = (key->sk_flags & SK_ISNULL) != 0;
  if (!s.unordered) {
    if (s.exact) {
      varlena* v = PG_DETOAST_DATUM_PACKED(key->sk_argument);
      argpg::Outcome out = argpg::guarded([&] {
        s.ranker = new arg::QueryRanker(argpg::view(v));
        *s.query = s.ranker->sketch();
        *s.coarse = arg::coarse_query(*s.query);
      });
      argpg::raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot read the query ARG");
    } else {
      read_value(key->sk_argument, *s.query);
    }
  }
  // cells.centres lives in the relcache entry: nothing that may accept invalidation messages
  // (a lock, a detoast) may run before its last use below.
  const Cells cells = read_cells(index, !s.unordered);
  s.cells = cells.count;
  s.candidates = Size(argpg::ivf_candidates(double(index->rd_rel->reltuples)));
  s.probed = 0;
  s.cell_order = static_cast<uint32*>(MemoryContextAlloc(s.memory, sizeof(uint32) * s.cells));
  if (s.unordered || !cells.refs[0].has_centre) {
    for (uint32 c = 0; c < cells.count; ++c) s.cell_order[c] = c;
  } else {
    argpg::Outcome out = argpg::guarded([&] {
      uint32 k = 0;
      for (std::size_t c :
           arg::cells_to_probe(*s.query, cells.centres, cells.count, cells.count, cells.coarse))
        s.cell_order[k++] = uint32(c);
    });
    argpg::raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot compare arg_sketch values");
  }
  pfree(cells.refs);
  // A NULL query has no nearest: every row, in no order (all its distances are NULL).
  probe_cells(scan, s, s.unordered ? s.cells : uint32(argpg::ivf_probes()));
  s.started = true;
}

// The table row's value of the indexed column, detoasted into row_memory, or nullptr when the
// row is not visible to the scan's snapshot (or its value is NULL).
varlena* table_value(IndexScanDesc scan, ScanState& s, ItemPointerData tid) {
  bool call_again = false, all_dead = false;
  if (!table_index_fetch_tuple(s.fetch, &tid, scan->xs_snapshot, s.slot, &call_again, &all_dead))
    return nullptr;
  bool isnull = false;
  const Datum value = slot_getattr(s.slot, s.column, &isnull);
  varlena* v = nullptr;
  if (!isnull) {
    MemoryContext caller = MemoryContextSwitchTo(s.row_memory);
    v = PG_DETOAST_DATUM_PACKED(value);
    MemoryContextSwitchTo(caller);
  }
  ExecClearTuple(s.slot);
  return v;
}

// Ranks the next arg.ivf_candidates candidates by SIM into the pool, reading further cells in
// an iterative scan once the probed ones are all ranked. Returns false when it may rank no
// more: nothing left, arg.iterative_scan off after the first batch, or arg.max_scan_tuples
// reached.
bool rank_batch(IndexScanDesc scan, ScanState& s, argpg::IterativeScan mode) {
  if (s.batches > 0 &&
      (mode == argpg::IterativeScan::Off || s.reranked >= Size(argpg::max_scan_tuples())))
    return false;
  const Size want = s.candidates;
  // Once a batch's worth of rows has been returned and more are wanted (a filter rejects most
  // of them), each batch reads further cells too: the nearest rows of cells farther out come
  // sooner than the far rows of the cells read first. A plain LIMIT k search never gets here.
  // Then enough entries read whole, more cells when the probed ones are used up.
  if (s.batches > 0 && s.returned >= want && s.probed < s.cells)
    probe_cells(scan, s, uint32(argpg::ivf_probes()));
  while (s.refined_count < want) {
    if (refine_more(scan, s, want)) continue;
    if (s.batches == 0 || s.probed >= s.cells) break;
    probe_cells(scan, s, uint32(argpg::ivf_probes()));
  }
  if (s.refined_count == 0) return false;
  const Size n = std::min(want, s.refined_count);
  if (s.pool_count + n > s.pool_capacity) {
    const Size capacity = std::max(2 * s.pool_capacity, s.pool_count + n);
    s.pool = static_cast<Hit*>(s.pool ? repalloc_huge(s.pool, capacity * sizeof(Hit))
                                      : MemoryContextAllocHuge(s.memory, capacity * sizeof(Hit)));
    s.pool_capacity = capacity;
  }
  if (s.reranked + n > s.excess_capacity) {
    const Size capacity = std::max(2 * s.excess_capacity, s.reranked + n);
    s.excess = static_cast<double*>(
        s.excess ? repalloc_huge(s.excess, capacity * sizeof(double))
                 : MemoryContextAllocHuge(s.memory, capacity * sizeof(double)));
    s.excess_capacity = capacity;
  }
  Size ranked = 0;
  for (Size i = 0; i < n; ++i) {
    CHECK_FOR_INTERRUPTS();
    std::pop_heap(s.refined, s.refined + s.refined_count, farther);
    const Hit candidate = s.refined[--s.refined_count];
    MemoryContextReset(s.row_memory);
    varlena* v = table_value(scan, s, candidate.tid);
    if (!v) continue;  // not visible to this scan, or NULL now
    double sim = 0;
    argpg::Outcome out = argpg::guarded([&] { sim = s.ranker->sim(argpg::view(v)); });
    argpg::raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot compare ARGs");
    s.pool[s.pool_count++] = {sim, candidate.tid, candidate.block, candidate.item};
    std::push_heap(s.pool, s.pool + s.pool_count, farther);
    s.excess[s.reranked + ranked++] = sim - candidate.distance;
  }
  s.reranked += ranked;
  ++s.batches;
  // How far SIM lay above the sketch's distance among ranked rows: a candidate not yet ranked
  // is taken to lie at least that far above its sketch distance (the tenth percentile, then the
  // least).
  if (s.reranked > 0) {
    const Size at = s.reranked / 10;
    std::nth_element(s.excess, s.excess + at, s.excess + s.reranked);
    s.margin = s.excess[at];
    s.margin_late = *std::min_element(s.excess, s.excess + at + 1);
  }
  return true;
}

// The next row in SIM order: the pool's nearest, once no candidate left to rank is likely to
// be nearer (its sketch distance plus the margin is not below it); otherwise the next batch is
// ranked first. In strict order a row nearer than one already returned is left out (a
// candidate the estimate missed); relaxed order returns it.
bool next_ranked(IndexScanDesc scan, ScanState& s, Hit& out) {
  const argpg::IterativeScan mode = argpg::iterative_scan();
  bool more = true;  // rank_batch may still add rows
  for (;;) {
    if (s.pool_count > 0) {
      const Hit& nearest = s.pool[0];
      // The nearest candidate not yet ranked is the refined heap's root (an entry not yet
      // read whole is taken to lie no nearer than those read).
      const double margin = s.returned < s.candidates ? s.margin : s.margin_late;
      const bool settled =
          !more || mode == argpg::IterativeScan::RelaxedOrder ||
          (s.refined_count > 0 && nearest.distance <= s.refined[0].distance + margin);
      if (settled) {
        out = nearest;
        std::pop_heap(s.pool, s.pool + s.pool_count, farther);
        --s.pool_count;
        if (mode == argpg::IterativeScan::StrictOrder && out.distance < s.last) continue;
        ++s.returned;
        return true;
      }
    }
    if (more) more = rank_batch(scan, s, mode);
    if (!more && s.pool_count == 0) return false;
  }
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
  s->coarse = static_cast<arg::CoarseQuery*>(palloc(sizeof(arg::CoarseQuery)));
  s->memory = AllocSetContextCreate(CurrentMemoryContext, "arg_ivf scan", ALLOCSET_DEFAULT_SIZES);
  s->row_memory =
      AllocSetContextCreate(CurrentMemoryContext, "arg_ivf scan row", ALLOCSET_DEFAULT_SIZES);
  s->exact = indexes_arg(index);
  if (s->exact) s->column = indexed_column(index);
  s->scan_memory = CurrentMemoryContext;
  scan->opaque = s;
  return scan;
}

void arg_ivf_rescan(IndexScanDesc scan, ScanKey keys, int nkeys, ScanKey orderbys, int norderbys) {
  auto* s = static_cast<ScanState*>(scan->opaque);
  s->started = false;
  if (keys && scan->numberOfKeys > 0)
    std::memmove(scan->keyData, keys, sizeof(ScanKeyData) * size_t(scan->numberOfKeys));
  if (orderbys && scan->numberOfOrderBys > 0)
    std::memmove(scan->orderByData, orderbys, sizeof(ScanKeyData) * size_t(scan->numberOfOrderBys));
}

bool arg_ivf_gettuple(IndexScanDesc scan, ScanDirection) {
  auto* s = static_cast<ScanState*>(scan->opaque);
  if (!s->started) {
    pgstat_count_index_scan(scan->indexRelation);
    start(scan, *s);
  }
  Hit hit;
  if (s->exact && !s->unordered) {
    if (!next_ranked(scan, *s, hit)) return false;
    s->last = std::max(s->last, hit.distance);
  } else {
    // An index of sketches returns the candidates of the probed cells themselves; a NULL
    // query, every row.
    if (s->taken >= s->count) return false;
    hit = s->hits[s->taken++];
  }
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
  if (s->fetch) table_index_fetch_end(s->fetch);
  if (s->slot) ExecDropSingleTupleTableSlot(s->slot);
  MemoryContextDelete(s->memory);  // deletes the ranker
  MemoryContextDelete(s->row_memory);
  pfree(s->query);
  pfree(s->row);
  pfree(s->coarse);
  pfree(s);
  scan->opaque = nullptr;
}

}  // extern "C"
