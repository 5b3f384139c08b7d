// The arg_ivf access method: its handler, reloption, cost estimate and opclass check.
#include <algorithm>

#include "search/sketch_cells.hpp"

#include "arg_ivf.hpp"

extern "C" {
#include "access/amapi.h"
#include "access/htup_details.h"
#include "access/reloptions.h"
#include "catalog/pg_amop.h"
#include "catalog/pg_opclass.h"
#include "catalog/pg_type.h"
#include "commands/vacuum.h"
#include "optimizer/cost.h"
#include "optimizer/optimizer.h"
#include "utils/catcache.h"
#include "utils/lsyscache.h"
#include "utils/selfuncs.h"
#include "utils/spccache.h"
#include "utils/syscache.h"
}

namespace argpg::ivf {

namespace {

relopt_kind lists_kind;

struct Options {
  int32 vl_len_;
  int lists;
};

bytea* options(Datum reloptions, bool validate) {
  static const relopt_parse_elt table[] = {{"lists", RELOPT_TYPE_INT, offsetof(Options, lists)}};
  return static_cast<bytea*>(
      build_reloptions(reloptions, validate, lists_kind, sizeof(Options), table, 1));
}

uint32 cells_of(Oid index_oid) {
  Relation index = index_open(index_oid, AccessShareLock);
  const Meta meta = read_meta(index);
  index_close(index, AccessShareLock);
  return meta.cells;
}

// Far above any real plan (a disabled one costs 1e10 more than it would) yet finite.
constexpr Cost kNeverCost = 1.0e15;

// Whether this query level's result is cut by a LIMIT: a constant one the planner took as a
// hard limit (not LIMIT ALL or NULL; none under grouping, aggregates, window functions,
// DISTINCT or set-returning functions, which read every row first), or one computed at run
// time (a generic plan of LIMIT $1, often cast to bigint) under the same conditions.
bool row_limited(PlannerInfo* root) {
  const Query* q = root->parse;
  // These read every row before the limit applies (PostgreSQL 17 passes a window's query level
  // a row limit too).
  if (q->groupClause != NIL || q->groupingSets != NIL || q->distinctClause != NIL || q->hasAggs ||
      q->hasWindowFuncs || q->hasTargetSRFs || root->hasHavingQual)
    return false;
  if (root->limit_tuples > 0) return true;
  return q->limitCount != nullptr && !IsA(q->limitCount, Const);
}

// All of a search's work comes before its first row: the centres, then the probed share of
// the lists' pages and entries, one sketch distance each (arg_sketch_distance's COST 20).
void cost_estimate(PlannerInfo* root, IndexPath* path, double loop_count, Cost* startup,
                   Cost* total, Selectivity* selectivity, double* correlation, double* pages) {
  // Only ORDER BY <~> (one key) under a LIMIT that bounds the rows this level returns uses
  // it: without one a query asks for every row in order, which an index that reads some cells
  // cannot give.
  if (list_length(path->indexorderbys) != 1 || !row_limited(root)) {
    // A cost no plan reaches, but finite: PostgreSQL 17 subtracts a window's input costs from
    // each other, and infinity less infinity is NaN, which wins every comparison.
    *startup = *total = kNeverCost;
    *selectivity = 0;
    *correlation = 0;
    *pages = 0;
    return;
  }
  GenericCosts costs{};
  genericcostestimate(root, path, loop_count, &costs);
  const uint32 cells = cells_of(path->indexinfo->indexoid);
  const double share = std::min(1.0, double(argpg::ivf_probes()) / double(cells));
  double seq_page_cost;
  get_tablespace_page_costs(path->indexinfo->reltablespace, nullptr, &seq_page_cost);
  const double distance = 20 * cpu_operator_cost;
  const double entries = share * path->indexinfo->tuples;
  *startup = share * double(path->indexinfo->pages) * seq_page_cost +
             entries * (cpu_index_tuple_cost + distance) + double(cells) * distance;
  // An index of arg values ranks its first candidates by SIM (<~>'s COST 2000) before its first
  // row, each read from the table.
  const bool ranks =
      path->indexinfo->opcintype[0] != InvalidOid && is_arg_type(path->indexinfo->opcintype[0]);
  const double rank = 2000 * cpu_operator_cost + random_page_cost;
  if (ranks)
    *startup += std::min(double(argpg::ivf_candidates(path->indexinfo->tuples)), entries) * rank;
  // Past its first candidates an iterative search ranks one more candidate for each further row
  // it returns, so its whole run costs a SIM a table row: under LIMIT k and a filter that keeps
  // a share s of the rows the planner charges k/s SIMs, which is what the scan does, and a
  // selective filter goes to brute force over the rows that pass it.
  if (ranks && argpg::iterative_scan() != argpg::IterativeScan::Off)
    *total = *startup + path->indexinfo->tuples * rank;
  else
    *total = *startup + entries * cpu_tuple_cost;
  *selectivity = costs.indexSelectivity;
  *correlation = 0;
  *pages = share * double(path->indexinfo->pages);
}

// An opclass orders arg_sketch (arg_sketch_ops) or arg (arg_ops) by one operator and needs no
// support function.
bool validate(Oid opclass) {
  HeapTuple tuple = SearchSysCache1(CLAOID, ObjectIdGetDatum(opclass));
  if (!HeapTupleIsValid(tuple)) return false;
  const auto* form = reinterpret_cast<Form_pg_opclass>(GETSTRUCT(tuple));
  const Oid family = form->opcfamily, type = form->opcintype;
  ReleaseSysCache(tuple);
  HeapTuple type_tuple = SearchSysCache1(TYPEOID, ObjectIdGetDatum(type));
  if (!HeapTupleIsValid(type_tuple)) return false;
  const char* type_name = NameStr(reinterpret_cast<Form_pg_type>(GETSTRUCT(type_tuple))->typname);
  const bool sketch =
      std::strcmp(type_name, "arg_sketch") == 0 || std::strcmp(type_name, "arg") == 0;
  ReleaseSysCache(type_tuple);
  CatCList* ops = SearchSysCacheList1(AMOPSTRATEGY, ObjectIdGetDatum(family));
  bool ok = sketch && ops->n_members == 1;
  for (int i = 0; i < ops->n_members; ++i) {
    const auto* op = reinterpret_cast<Form_pg_amop>(GETSTRUCT(&ops->members[i]->tuple));
    ok = ok && op->amoppurpose == AMOP_ORDER && op->amopstrategy == 1;
  }
  ReleaseSysCacheList(ops);
  return ok;
}

}  // namespace

int lists_option(Relation index) {
  const auto* o = reinterpret_cast<const Options*>(index->rd_options);
  return o ? o->lists : 0;
}

void define_reloptions() {
  lists_kind = add_reloption_kind();
  add_int_reloption(lists_kind, "lists",
                    "Cells of an arg_ivf index (0: the square root of the rows at build)", 0, 0,
                    int(arg::kMaxSketchCells), AccessExclusiveLock);
}

}  // namespace argpg::ivf

extern "C" {

PG_FUNCTION_INFO_V1(arg_ivf_handler);

Datum arg_ivf_handler(PG_FUNCTION_ARGS) {
  IndexAmRoutine* am = makeNode(IndexAmRoutine);
  am->amstrategies = 0;
  am->amsupport = 0;
  am->amoptsprocnum = 0;
  am->amcanorder = false;
  am->amcanorderbyop = true;
  am->amcanbackward = false;
  am->amcanunique = false;
  am->amcanmulticol = false;
  am->amoptionalkey = true;
  am->amsearcharray = false;
  am->amsearchnulls = false;
  am->amstorage = false;
  am->amclusterable = false;
  am->ampredlocks = false;
  am->amcanparallel = false;
  am->amcaninclude = false;
  am->amusemaintenanceworkmem = false;
#if PG_VERSION_NUM >= 160000
  am->amsummarizing = false;
#endif
  am->amparallelvacuumoptions = VACUUM_OPTION_PARALLEL_BULKDEL;
  am->amkeytype = InvalidOid;
  am->ambuild = arg_ivf_build;
  am->ambuildempty = arg_ivf_buildempty;
  am->aminsert = arg_ivf_insert;
  am->ambulkdelete = arg_ivf_bulkdelete;
  am->amvacuumcleanup = arg_ivf_vacuumcleanup;
  am->amcanreturn = nullptr;
  am->amcostestimate = argpg::ivf::cost_estimate;
  am->amoptions = argpg::ivf::options;
  am->amproperty = nullptr;
  am->ambuildphasename = arg_ivf_buildphasename;
  am->amvalidate = argpg::ivf::validate;
  am->amadjustmembers = nullptr;
  am->ambeginscan = arg_ivf_beginscan;
  am->amrescan = arg_ivf_rescan;
  am->amgettuple = arg_ivf_gettuple;
  am->amgetbitmap = nullptr;
  am->amendscan = arg_ivf_endscan;
  am->ammarkpos = nullptr;
  am->amrestrpos = nullptr;
  am->amestimateparallelscan = nullptr;
  am->aminitparallelscan = nullptr;
  am->amparallelrescan = nullptr;
  PG_RETURN_POINTER(am);
}

}  // extern "C"
