// Inserting into an arg_ivf index: a new row joins the list of its nearest centre.
#include "search/sketch_cells.hpp"

#include "arg_ivf.hpp"

extern "C" {
#include "utils/memutils.h"
}

using namespace argpg::ivf;

extern "C" {

bool arg_ivf_insert(Relation index, Datum* values, bool* isnull, ItemPointer heap_tid, Relation,
                    IndexUniqueCheck, bool, IndexInfo*) {
  if (isnull[0]) return false;  // NULL sketches are not indexed
  MemoryContext memory =
      AllocSetContextCreate(CurrentMemoryContext, "arg_ivf insert", ALLOCSET_DEFAULT_SIZES);
  MemoryContext caller = MemoryContextSwitchTo(memory);
  // Detoasted once: read here, stored below (an arg's sketch is made from it).
  auto* sketch = static_cast<arg::ShapeSketch*>(palloc(sizeof(arg::ShapeSketch)));
  varlena* v = entry_sketch(index, values[0], *sketch);
  // cells.centres lives in the relcache entry: nothing that may accept invalidation messages
  // (a lock, a detoast) may run before its last use, nearest_cell.
  const Cells cells = read_cells(index, true);
  std::size_t cell = 0;
  if (cells.refs[0].has_centre) {
    argpg::Outcome out = argpg::guarded(
        [&] { cell = arg::nearest_cell(*sketch, cells.centres, cells.count, cells.coarse); });
    argpg::raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot compare arg_sketch values");
  }
  append_entry(index, cells.refs[cell], heap_tid, VARDATA_ANY(v), VARSIZE_ANY_EXHDR(v),
               /*fill_holes=*/true);
  MemoryContextSwitchTo(caller);
  MemoryContextDelete(memory);
  return false;
}

}  // extern "C"
