// arg_index_trigger(): keeps an arg column built from a bytea mesh column on INSERT and UPDATE.
//
//   CREATE TRIGGER objects_descr BEFORE INSERT OR UPDATE ON objects FOR EACH ROW
//     EXECUTE FUNCTION arg_index_trigger('mesh', 'descr' [, 'texture' [, 'levels=5 ...']]);
//
// A NULL mesh gives a NULL ARG. An UPDATE rebuilds only when the mesh or texture changed or the
// ARG was set to NULL, so editing a title does not rebuild (and SET descr = NULL forces a build).
#include "pipeline/build_arg.hpp"

#include "arg_bridge.hpp"
#include "arg_build.hpp"
#include "arg_guc.hpp"

// commands/trigger.h reaches PostgreSQL's spinlock headers, which use `register` (not C++17).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wregister"
extern "C" {
#include "access/htup_details.h"
#include "catalog/pg_type.h"
#include "commands/trigger.h"
#include "executor/spi.h"
#include "utils/builtins.h"
#include "utils/datum.h"
#include "utils/lsyscache.h"
#include "utils/rel.h"
#include "utils/syscache.h"
}
#pragma GCC diagnostic pop

namespace {

const char* const kUsage =
    "arg_index_trigger(mesh_column, arg_column [, texture_column [, build_options]])";

// The number of column `name` of the trigger's table, checked to have type `type` (or a domain
// over it) and not to be a generated column when it is the one written.
int column_of(Relation rel, const char* name, Oid type, const char* type_name, bool written) {
  TupleDesc desc = RelationGetDescr(rel);
  const int attnum = SPI_fnumber(desc, name);
  if (attnum <= 0)
    ereport(ERROR, (errcode(ERRCODE_UNDEFINED_COLUMN),
                    errmsg("arg_index_trigger: column \"%s\" of relation \"%s\" does not exist",
                           name, RelationGetRelationName(rel)),
                    errhint("Usage: %s.", kUsage)));
  Form_pg_attribute att = TupleDescAttr(desc, attnum - 1);
  if (getBaseType(att->atttypid) != type)
    ereport(ERROR, (errcode(ERRCODE_DATATYPE_MISMATCH),
                    errmsg("arg_index_trigger: column \"%s\" has type %s, not %s", name,
                           format_type_be(att->atttypid), type_name)));
  if (written && att->attgenerated)
    ereport(ERROR, (errcode(ERRCODE_INVALID_COLUMN_DEFINITION),
                    errmsg("arg_index_trigger: column \"%s\" is a generated column", name)));
  return attnum;
}

// The OID of type arg, found in the schema of this function (so search_path does not matter).
Oid arg_type_oid(FunctionCallInfo fcinfo) {
  const Oid schema = get_func_namespace(fcinfo->flinfo->fn_oid);
  const Oid type = GetSysCacheOid2(TYPENAMENSP, Anum_pg_type_oid, CStringGetDatum("arg"),
                                   ObjectIdGetDatum(schema));
  if (!OidIsValid(type))
    ereport(ERROR, (errcode(ERRCODE_UNDEFINED_OBJECT),
                    errmsg("arg_index_trigger: type arg not found in the extension's schema")));
  return type;
}

// True when column `attnum` holds the same raw datum in both tuples (an unchanged toasted value
// keeps its toast pointer; a value set again to equal bytes counts as changed).
bool unchanged(HeapTuple old_tuple, HeapTuple new_tuple, TupleDesc desc, int attnum) {
  bool old_null, new_null;
  const Datum old_value = heap_getattr(old_tuple, attnum, desc, &old_null);
  const Datum new_value = heap_getattr(new_tuple, attnum, desc, &new_null);
  if (old_null || new_null) return old_null == new_null;
  return datumIsEqual(old_value, new_value, false, -1);
}

}  // namespace

extern "C" {

PG_FUNCTION_INFO_V1(arg_index_trigger);

Datum arg_index_trigger(PG_FUNCTION_ARGS) {
  if (!CALLED_AS_TRIGGER(fcinfo))
    ereport(ERROR, (errcode(ERRCODE_E_R_I_E_TRIGGER_PROTOCOL_VIOLATED),
                    errmsg("arg_index_trigger: not called by the trigger manager")));
  TriggerData* data = reinterpret_cast<TriggerData*>(fcinfo->context);
  if (!TRIGGER_FIRED_FOR_ROW(data->tg_event) || !TRIGGER_FIRED_BEFORE(data->tg_event))
    ereport(ERROR,
            (errcode(ERRCODE_E_R_I_E_TRIGGER_PROTOCOL_VIOLATED),
             errmsg("arg_index_trigger: must be fired BEFORE INSERT OR UPDATE FOR EACH ROW")));
  HeapTuple tuple, old_tuple = nullptr;
  if (TRIGGER_FIRED_BY_INSERT(data->tg_event)) {
    tuple = data->tg_trigtuple;
  } else if (TRIGGER_FIRED_BY_UPDATE(data->tg_event)) {
    tuple = data->tg_newtuple;
    old_tuple = data->tg_trigtuple;
  } else {
    ereport(ERROR,
            (errcode(ERRCODE_E_R_I_E_TRIGGER_PROTOCOL_VIOLATED),
             errmsg("arg_index_trigger: must be fired BEFORE INSERT OR UPDATE FOR EACH ROW")));
  }

  const Trigger* trigger = data->tg_trigger;
  if (trigger->tgnargs < 2 || trigger->tgnargs > 4)
    ereport(ERROR,
            (errcode(ERRCODE_INVALID_PARAMETER_VALUE),
             errmsg("arg_index_trigger: expected 2 to 4 arguments, got %d", trigger->tgnargs),
             errhint("Usage: %s.", kUsage)));
  Relation rel = data->tg_relation;
  TupleDesc desc = RelationGetDescr(rel);
  const int mesh_col = column_of(rel, trigger->tgargs[0], BYTEAOID, "bytea", false);
  int arg_col = column_of(rel, trigger->tgargs[1], arg_type_oid(fcinfo), "arg", true);
  const bool textured = trigger->tgnargs >= 3 && trigger->tgargs[2][0] != '\0';
  const int texture_col =
      textured ? column_of(rel, trigger->tgargs[2], BYTEAOID, "bytea", false) : 0;
  const char* options = trigger->tgnargs == 4 ? trigger->tgargs[3] : "";

  bool arg_null = false;
  (void)heap_getattr(tuple, arg_col, desc, &arg_null);
  if (old_tuple && !arg_null && unchanged(old_tuple, tuple, desc, mesh_col) &&
      (!textured || unchanged(old_tuple, tuple, desc, texture_col)))
    return PointerGetDatum(tuple);

  bool mesh_null = false, texture_null = true;
  const Datum mesh_datum = heap_getattr(tuple, mesh_col, desc, &mesh_null);
  Datum texture_datum = 0;
  if (textured) texture_datum = heap_getattr(tuple, texture_col, desc, &texture_null);
  Datum value = 0;
  if (!mesh_null) {
    const varlena* mesh = PG_DETOAST_DATUM_PACKED(mesh_datum);
    const varlena* texture = texture_null ? nullptr : PG_DETOAST_DATUM_PACKED(texture_datum);
    varlena* result = argpg::build_arg_datum(
        argpg::view(mesh), texture ? argpg::view(texture) : std::string_view(), options);
    value = PointerGetDatum(result);
  }
  bool null = mesh_null;
  HeapTuple modified = heap_modify_tuple_by_cols(tuple, desc, 1, &arg_col, &value, &null);
  return PointerGetDatum(modified);
}

}  // extern "C"
