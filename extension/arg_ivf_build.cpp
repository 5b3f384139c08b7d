// Building an arg_ivf index: a sample's centres, then every row filed under its nearest one.
#include <algorithm>
#include <cmath>

#include "common/parallel_for.hpp"
#include "search/sketch_cells.hpp"

#include "arg_guc.hpp"
#include "arg_ivf.hpp"

extern "C" {
#include "access/tableam.h"
#include "access/xloginsert.h"
#include "commands/progress.h"
#include "common/pg_prng.h"
#include "pgstat.h"
#include "utils/memutils.h"
}

namespace argpg::ivf {

// The reloption `lists` (0: the square root of the rows at build); arg_ivf_handler.cpp.
int lists_option(Relation index);

namespace {

// Sample rows a cell: enough for seeding to find the dense regions, few enough that choosing
// the centres (cells x sample distances) stays well under filing the rows (cells x rows).
constexpr double kSamplePerCell = 20;
// Rows filed at once, on arg.max_build_threads threads.
constexpr int kBatch = 256;

// The build's phases in pg_stat_progress_create_index (PostgreSQL numbers an access method's
// own phases from 2; arg_ivf_buildphasename names them).
enum BuildPhase : int64 { kPhaseSampling = 2, kPhaseCentres, kPhaseFiling };

struct Sampling {
  Relation index;
  MemoryContext row_memory;  // one row's value and entry bytes
  arg::ShapeSketch* sample;  // a reservoir of `capacity`
  Size capacity, filled;
  double rows;
  pg_prng_state random;
};

void sample_row(Relation, ItemPointer, Datum* values, bool* isnull, bool, void* state) {
  auto* s = static_cast<Sampling*>(state);
  if (isnull[0]) return;
  s->rows += 1;
  Size slot = s->filled;
  if (s->filled == s->capacity) {
    const uint64 k = pg_prng_uint64_range(&s->random, 0, uint64(s->rows) - 1);
    if (k >= s->capacity) return;
    slot = Size(k);
  } else {
    ++s->filled;
  }
  MemoryContext caller = MemoryContextSwitchTo(s->row_memory);
  entry_sketch(s->index, values[0], s->sample[slot]);
  MemoryContextSwitchTo(caller);
  MemoryContextReset(s->row_memory);
}

struct Filing {
  Relation index;
  bool of_arg;  // an index of arg values: entries are sketches made from them
  const Cells* cells;
  int threads;
  double rows;
  Size filed;  // rows written to their lists
  int count;
  ItemPointerData tids[kBatch];
  varlena* values[kBatch];
  arg::ShapeSketch* sketches;  // kBatch of them
  uint32 cell_of[kBatch];
  MemoryContext batch_memory;
};

void file_batch(Filing& f) {
  if (f.count == 0) return;
  const Cells& cells = *f.cells;
  if (cells.centres && cells.refs[0].has_centre) {
    Outcome out = guarded([&] {
      arg::parallel_for(std::size_t(f.count), f.threads, [&](std::size_t i) {
        f.cell_of[i] =
            uint32(arg::nearest_cell(f.sketches[i], cells.centres, cells.count, cells.coarse));
      });
    });
    raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot file arg_sketch");
  } else {
    for (int i = 0; i < f.count; ++i) f.cell_of[i] = 0;
  }
  for (int i = 0; i < f.count; ++i) {
    CHECK_FOR_INTERRUPTS();
    append_entry(f.index, cells.refs[f.cell_of[i]], &f.tids[i], VARDATA_ANY(f.values[i]),
                 VARSIZE_ANY_EXHDR(f.values[i]), /*fill_holes=*/false);
  }
  f.filed += f.count;
  pgstat_progress_update_param(PROGRESS_CREATEIDX_TUPLES_DONE, int64(f.filed));
  f.count = 0;
  MemoryContextReset(f.batch_memory);
}

void file_row(Relation, ItemPointer tid, Datum* values, bool* isnull, bool, void* state) {
  auto* f = static_cast<Filing*>(state);
  if (isnull[0]) return;
  // A copy in the batch's memory: the build scan's datum lives only for this call.
  MemoryContext old = MemoryContextSwitchTo(f->batch_memory);
  varlena* v = f->of_arg ? entry_sketch(f->index, values[0], f->sketches[f->count])
                         : PG_DETOAST_DATUM_COPY(values[0]);
  MemoryContextSwitchTo(old);
  if (!f->of_arg) {
    Outcome out = guarded([&] { arg::read_shape_sketch(view(v), f->sketches[f->count]); });
    raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot read arg_sketch");
  }
  f->tids[f->count] = *tid;
  f->values[f->count] = v;
  ++f->count;
  f->rows += 1;
  if (f->count == kBatch) file_batch(*f);
}

// Writes the metapage and the cell pages: `count` cells with the given centres (none: one
// cell without a centre).
void write_cells(Relation index, ForkNumber fork, const arg::ShapeSketch* centres, uint32 count) {
  const uint32 cells = std::max<uint32>(count, 1);
  GenericXLogState* state = GenericXLogStart(index);
  Page meta_page;
  Buffer meta_buf = new_page(index, fork, state, kMetaPage, &meta_page);
  if (BufferGetBlockNumber(meta_buf) != 0) elog(ERROR, "arg_ivf: metapage is not block 0");
  GenericXLogFinish(state);  // cell_pages is written once the cells are laid out
  uint32 cell_pages = 0, written = 0;
  Buffer buf = InvalidBuffer;
  Page page = nullptr;
  char* item = static_cast<char*>(palloc(sizeof(CellHead) + kMaxSketchBytes));
  const CellHead head = {InvalidBlockNumber, InvalidBlockNumber};
  std::memcpy(item, &head, sizeof head);
  while (written < cells) {
    Size centre_size = 0;
    if (count > 0) {
      Outcome out = guarded([&] {
        const std::string bytes = arg::write_shape_sketch(centres[written]);
        if (bytes.size() > kMaxSketchBytes) throw arg::InputError("centre's sketch too large");
        std::memcpy(item + sizeof head, bytes.data(), bytes.size());
        centre_size = bytes.size();
      });
      raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot write an arg_ivf centre");
    }
    const Size item_size = sizeof(CellHead) + centre_size;
    if (!BufferIsValid(buf) || PageGetFreeSpace(page) < MAXALIGN(item_size)) {
      if (BufferIsValid(buf)) {
        GenericXLogFinish(state);
        UnlockReleaseBuffer(buf);
      }
      state = GenericXLogStart(index);
      buf = new_page(index, fork, state, kCellPage, &page);
      ++cell_pages;
      if (BufferGetBlockNumber(buf) != cell_pages)
        elog(ERROR, "arg_ivf: cell pages are not contiguous");
    }
    if (PageAddItem(page, item, item_size, InvalidOffsetNumber, false, false) ==
        InvalidOffsetNumber)
      elog(ERROR, "arg_ivf: could not add a cell");
    ++written;
  }
  pfree(item);
  GenericXLogFinish(state);
  UnlockReleaseBuffer(buf);

  state = GenericXLogStart(index);
  Page m = GenericXLogRegisterBuffer(state, meta_buf, 0);
  const Meta meta = {kMagic, kVersion, cells, cell_pages};
  std::memcpy(PageGetContents(m), &meta, sizeof meta);
  ((PageHeader)m)->pd_lower = uint16((PageGetContents(m) - m) + sizeof meta);
  GenericXLogFinish(state);
  UnlockReleaseBuffer(meta_buf);
}

}  // namespace

}  // namespace argpg::ivf

using namespace argpg::ivf;

extern "C" {

IndexBuildResult* arg_ivf_build(Relation heap, Relation index, IndexInfo* info) {
  if (RelationGetNumberOfBlocks(index) != 0)
    elog(ERROR, "index \"%s\" already contains data", RelationGetRelationName(index));
  const int lists = lists_option(index);
  const bool of_arg = indexes_arg(index);
  if (of_arg) (void)indexed_column(index);  // refuses an expression before any work

  // First pass: a uniform sample (a reservoir) within maintenance_work_mem.
  Sampling s{};
  s.index = index;
  s.row_memory =
      AllocSetContextCreate(CurrentMemoryContext, "arg_ivf build row", ALLOCSET_DEFAULT_SIZES);
  const Size by_memory = Size(maintenance_work_mem) * 1024 / sizeof(arg::ShapeSketch);
  const Size wanted = Size(kSamplePerCell * (lists > 0 ? lists : int(arg::kMaxSketchCells)));
  s.capacity = std::max<Size>(1, std::min(by_memory, wanted));
  s.sample = static_cast<arg::ShapeSketch*>(
      MemoryContextAllocHuge(CurrentMemoryContext, sizeof(arg::ShapeSketch) * s.capacity));
  // The same table gives the same index: a fixed seed, and scans that start at block 0 (no
  // synchronised scans).
  pg_prng_seed(&s.random, 0x41524749);
  pgstat_progress_update_param(PROGRESS_CREATEIDX_SUBPHASE, kPhaseSampling);
  table_index_build_scan(heap, index, info, false, true, sample_row, &s, nullptr);
  pgstat_progress_update_param(PROGRESS_CREATEIDX_SUBPHASE, kPhaseCentres);

  // Centres: `lists`, or the square root of the rows, at most one a sampled row.
  Size cells = lists > 0 ? Size(lists) : Size(std::ceil(std::sqrt(s.rows)));
  cells = std::min<Size>({std::max<Size>(cells, 1), arg::kMaxSketchCells, s.filled});
  // The sample in random order, so that its first 20 a cell are a uniform sample too.
  for (Size i = s.filled; i > 1; --i)
    std::swap(s.sample[i - 1], s.sample[pg_prng_uint64_range(&s.random, 0, i - 1)]);
  const Size used = std::min<Size>(s.filled, Size(kSamplePerCell * double(cells)));
  arg::ShapeSketch* centres = nullptr;
  uint32 count = 0;
  if (cells > 0) {
    centres = static_cast<arg::ShapeSketch*>(
        MemoryContextAllocHuge(CurrentMemoryContext, sizeof(arg::ShapeSketch) * cells));
    argpg::Outcome out = argpg::guarded([&] {
      const std::vector<std::size_t> picked =
          arg::choose_cell_centres(s.sample, used, cells, 0x41524749, argpg::stop_requested);
      for (std::size_t c = 0; c < picked.size(); ++c) centres[c] = s.sample[picked[c]];
      count = uint32(picked.size());
    });
    argpg::raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot choose arg_ivf centres");
  }
  pfree(s.sample);
  MemoryContextDelete(s.row_memory);
  write_cells(index, MAIN_FORKNUM, centres, count);

  // Second pass: every row to its nearest centre's list.
  Cells cell_set = read_cells(index, false);
  cell_set.centres = centres;
  // palloc'd, as everything that an error (a cancel while filing) may leave behind.
  auto* coarse = static_cast<arg::CoarseQuery*>(
      MemoryContextAllocHuge(CurrentMemoryContext, sizeof(arg::CoarseQuery) * (count + 1)));
  for (uint32 c = 0; c < count; ++c) coarse[c] = arg::coarse_query(centres[c]);
  cell_set.coarse = coarse;
  Filing* f = static_cast<Filing*>(palloc0(sizeof(Filing)));
  f->index = index;
  f->of_arg = of_arg;
  f->cells = &cell_set;
  f->threads = argpg::max_build_threads();
  f->sketches = static_cast<arg::ShapeSketch*>(
      MemoryContextAllocHuge(CurrentMemoryContext, sizeof(arg::ShapeSketch) * kBatch));
  f->batch_memory =
      AllocSetContextCreate(CurrentMemoryContext, "arg_ivf build batch", ALLOCSET_DEFAULT_SIZES);
  {
    const int params[] = {PROGRESS_CREATEIDX_SUBPHASE, PROGRESS_CREATEIDX_TUPLES_TOTAL,
                          PROGRESS_CREATEIDX_TUPLES_DONE};
    const int64 values[] = {kPhaseFiling, int64(s.rows), 0};
    pgstat_progress_update_multi_param(3, params, values);
  }
  const double heap_rows =
      table_index_build_scan(heap, index, info, false, true, file_row, f, nullptr);
  file_batch(*f);

  IndexBuildResult* result = static_cast<IndexBuildResult*>(palloc(sizeof(IndexBuildResult)));
  result->heap_tuples = heap_rows;
  result->index_tuples = f->rows;
  MemoryContextDelete(f->batch_memory);
  return result;
}

// The name of a build phase for pg_stat_progress_create_index ("building index: " + it).
char* arg_ivf_buildphasename(int64 phase) {
  switch (phase) {
    case PROGRESS_CREATEIDX_SUBPHASE_INITIALIZE:
      return const_cast<char*>("initializing");
    case kPhaseSampling:
      return const_cast<char*>("sampling rows");
    case kPhaseCentres:
      return const_cast<char*>("choosing centres");
    case kPhaseFiling:
      return const_cast<char*>("filing rows");
    default:
      return nullptr;
  }
}

// An unlogged table's index after a crash: one cell without a centre, which every row joins
// until the index is rebuilt. The init fork is WAL-logged whole (generic records skip an
// unlogged relation), so that it survives the crash it is for.
void arg_ivf_buildempty(Relation index) {
  write_cells(index, INIT_FORKNUM, nullptr, 0);
  log_newpage_range(index, INIT_FORKNUM, 0, RelationGetNumberOfBlocksInFork(index, INIT_FORKNUM),
                    true);
}

}  // extern "C"
