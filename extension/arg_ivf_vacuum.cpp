// VACUUM of an arg_ivf index: entries of removed rows leave their list pages.
#include "search/sketch_cells.hpp"

#include "arg_ivf.hpp"

extern "C" {
#include "commands/vacuum.h"
}

using namespace argpg::ivf;

namespace {

// Walks every list; with a callback, removes the entries it names. Counts what stays.
void walk_lists(IndexVacuumInfo* info, IndexBulkDeleteResult* stats,
                IndexBulkDeleteCallback callback, void* callback_state) {
  Relation index = info->index;
  const Cells cells = read_cells(index, false);
  BlockNumber blocks = RelationGetNumberOfBlocks(index);
  stats->num_index_tuples = 0;
  for (uint32 c = 0; c < cells.count; ++c)
    walk_list(index, cells.refs[c], callback ? BUFFER_LOCK_EXCLUSIVE : BUFFER_LOCK_SHARE,
              info->strategy, &blocks, vacuum_delay_point,
              [&](Buffer buf, Page page, BlockNumber block) {
                const OffsetNumber items = PageGetMaxOffsetNumber(page);
                OffsetNumber dead[MaxOffsetNumber];
                int n_dead = 0;
                for (OffsetNumber item = FirstOffsetNumber; item <= items; ++item) {
                  ItemPointerData tid;
                  const char* sketch;
                  Size size;
                  read_entry(index, page, block, item, &tid, &sketch, &size);
                  if (callback && callback(&tid, callback_state))
                    dead[n_dead++] = item;
                  else
                    stats->num_index_tuples += 1;
                }
                if (n_dead > 0) {
                  GenericXLogState* state = GenericXLogStart(index);
                  Page changed = GenericXLogRegisterBuffer(state, buf, 0);
                  PageIndexMultiDelete(changed, dead, n_dead);
                  GenericXLogFinish(state);
                  stats->tuples_removed += n_dead;
                }
              });
  stats->num_pages = RelationGetNumberOfBlocks(index);
  pfree(cells.refs);
}

}  // namespace

extern "C" {

// Emptied pages stay in their lists, and a later insert into the cell fills them before it adds
// a page; REINDEX still packs an index tighter after large deletions.
IndexBulkDeleteResult* arg_ivf_bulkdelete(IndexVacuumInfo* info, IndexBulkDeleteResult* stats,
                                          IndexBulkDeleteCallback callback, void* state) {
  if (!stats) stats = static_cast<IndexBulkDeleteResult*>(palloc0(sizeof(IndexBulkDeleteResult)));
  walk_lists(info, stats, callback, state);
  return stats;
}

IndexBulkDeleteResult* arg_ivf_vacuumcleanup(IndexVacuumInfo* info, IndexBulkDeleteResult* stats) {
  if (info->analyze_only) return stats;
  if (!stats) {  // no bulk delete ran: count the entries
    stats = static_cast<IndexBulkDeleteResult*>(palloc0(sizeof(IndexBulkDeleteResult)));
    walk_lists(info, stats, nullptr, nullptr);
  }
  return stats;
}

}  // extern "C"
