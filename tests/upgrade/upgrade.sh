#!/usr/bin/env bash
# The upgrade path from arg 0.1.0: a database created at 0.1.0, holding values 0.1.0 wrote
# (binary format 1, builder 1.0: tests/unit/fixtures/format1), a generated arg column, a column a
# trigger keeps and GiST indexes, reaches with ALTER EXTENSION arg UPDATE exactly the catalogue
# of a fresh install; its values still read, compare with their own kind and are refused against
# newer builds (22023, naming both builders); arg_rebuild_needed finds them and the documented
# statements rebuild them; the indexes still answer; and a pg_dump of the 0.1.0 database restores
# into a database where arg is the current version.
#
#   tests/upgrade/upgrade.sh      against the server in PGHOST/PGPORT/PGUSER (superuser), with
#                                 the current extension installed (make install)
#
# Prints TAP lines ("ok N - ...", "not ok N - ...") and exits non-zero when one fails.
# tests/run_all.sh runs it on its throwaway cluster.
set -uo pipefail

cd "$(dirname "$0")/../.." || exit 1
pg_config=${PG_CONFIG:-/usr/lib/postgresql/15/bin/pg_config}
[[ -x "$pg_config" ]] || pg_config=$(command -v pg_config)
bindir=$("$pg_config" --bindir)
current=$(sed -n "s/^default_version *= *'\(.*\)'/\1/p" extension/arg.control)
old=arg_upgrade_old fresh=arg_upgrade_fresh restored=arg_upgrade_restored mid=arg_upgrade_mid
work=$(mktemp -d)
drop_databases() {
  for db in $old $fresh $restored $mid; do
    PGOPTIONS='-c client_min_messages=warning' psql -X -q -d postgres \
      -c "DROP DATABASE IF EXISTS $db WITH (FORCE)" >/dev/null 2>&1
  done
}
trap 'drop_databases; rm -rf "$work"' EXIT

# shellcheck source=../tap_checks.sh
. tests/tap_checks.sh
# fails_with DB SQLSTATE TEXT... SQL: the statement fails with that SQLSTATE and a message that
# holds every TEXT.
fails_with() {
  local db=$1 code=$2 out
  shift 2
  local sql=${*: -1}
  out=$(psql -X -q -d "$db" -v ON_ERROR_STOP=1 -v VERBOSITY=verbose -c "$sql" 2>&1) && {
    echo "#   succeeded: $sql" >&2
    return 1
  }
  for text in "$code" "${@:1:$#-1}"; do
    [[ $out == *"$text"* ]] || { echo "#   no '$text' in: $out" >&2; return 1; }
  done
}
fingerprint() { # DB TABLE COLUMN: md5 of every row's binary form, in id order
  q -d "$1" -c "SELECT md5(string_agg(id || ':' || coalesce(encode(arg_send($3), 'hex'), 'null'), ',' ORDER BY id)) FROM $2"
}
catalogue() { q -d "$1" -f tests/upgrade/catalogue.sql; }
# The ids an index scan gives for the nearest of TABLE to the value of row 1, and proof that an
# index answered: nearest DB TABLE.
nearest() {
  q -d "$1" -c "SET enable_seqscan = off" -c "SET enable_bitmapscan = off" \
    -c "EXPLAIN (COSTS OFF) SELECT id FROM $2 ORDER BY arg_global(descr) <#> arg_global((SELECT descr FROM $2 WHERE id = 1)) LIMIT 3" \
    -c "SELECT string_agg(id::text, ',') FROM (SELECT id FROM $2 ORDER BY arg_global(descr) <#> arg_global((SELECT descr FROM $2 WHERE id = 1)) LIMIT 3) s" |
    grep -E 'Index Scan|^[0-9,]+$' | sed -E 's/ using .*//; s/^ *-> *//' | tr '\n' ' '
}
value_of() { printf 'arg1:%s' "$(base64 -w0 "tests/unit/fixtures/format1/$1.arg")"; }

echo "1..33"
drop_databases
q -d postgres -c "CREATE DATABASE $old" -c "CREATE DATABASE $fresh" -c "CREATE DATABASE $restored" \
  >/dev/null || exit 1

# The database at 0.1.0: values 0.1.0 wrote in a plain column (legacy) and in a column its
# trigger kept (scans: the trigger is off while they are written, as if an 0.1.0 library had
# built them); a generated column (museum); GiST indexes on both kinds.
q -d $old -v human="$(value_of human_l2)" -v fourleg="$(value_of fourleg_l4_height)" \
  -v torus="$(value_of torus_l3_centroid)" >/dev/null <<'SQL' || exit 1
CREATE EXTENSION cube;
CREATE EXTENSION arg VERSION '0.1.0';
CREATE TABLE legacy (id int PRIMARY KEY, name text, descr arg);
INSERT INTO legacy VALUES (1, 'human', :'human'), (2, 'fourleg', :'fourleg'), (3, 'torus', :'torus');
CREATE INDEX legacy_global ON legacy USING gist (arg_global(descr));
CREATE TABLE scans (id int PRIMARY KEY, mesh bytea, descr arg);
CREATE TRIGGER scans_descr BEFORE INSERT OR UPDATE ON scans FOR EACH ROW
  EXECUTE FUNCTION arg_index_trigger('mesh', 'descr');
ALTER TABLE scans DISABLE TRIGGER scans_descr;
INSERT INTO scans SELECT id, arg_generate_model(name, 0, 12), descr FROM legacy;
ALTER TABLE scans ENABLE TRIGGER scans_descr;
CREATE TABLE museum (
  id int PRIMARY KEY,
  mesh bytea,
  descr arg GENERATED ALWAYS AS (arg_build(mesh)) STORED);
INSERT INTO museum SELECT i, arg_generate_model(c, i::int, 12)
FROM unnest(ARRAY['vase', 'cup', 'torus', 'chair', 'human']) WITH ORDINALITY AS t(c, i);
CREATE INDEX museum_global ON museum USING gist (arg_global(descr));
SQL
PGOPTIONS='-c client_min_messages=warning' q -d $fresh -c "CREATE EXTENSION arg CASCADE" >/dev/null || exit 1

legacy_before=$(fingerprint $old legacy descr)
museum_before=$(fingerprint $old museum descr)
legacy_nearest=$(nearest $old legacy)
museum_nearest=$(nearest $old museum)
check "CREATE EXTENSION arg VERSION '0.1.0' installs 0.1.0" \
  same "0.1.0" "$(q -d $old -c "SELECT extversion FROM pg_extension WHERE extname = 'arg'")"
check "values 0.1.0 wrote read as format 1 of builder 1.0.0" \
  same "1 1.0.0|1 1.0.0|1 1.0.0" \
  "$(q -d $old -c "SELECT string_agg(format('%s %s', arg_info(descr)->'format_version', arg_info(descr)->>'builder_version'), '|' ORDER BY id) FROM legacy")"

# A dump of the 0.1.0 database, restored below into a database at the current version.
check "pg_dump -Fc dumps the 0.1.0 database" "$bindir/pg_dump" -Fc -d $old -f "$work/old.dump"

check "ALTER EXTENSION arg UPDATE succeeds" q -d $old -c "ALTER EXTENSION arg UPDATE"
check "the extension is now at $current" \
  same "$current" "$(q -d $old -c "SELECT extversion FROM pg_extension WHERE extname = 'arg'")"
catalogue $fresh > "$work/fresh.txt"
catalogue $old > "$work/updated.txt"
check "the updated catalogue equals a fresh $current install" \
  diff -u "$work/fresh.txt" "$work/updated.txt"
check "the stored 0.1.0 values are byte-identical after the update" \
  same "$legacy_before" "$(fingerprint $old legacy descr)"
check "the generated column is byte-identical after the update" \
  same "$museum_before" "$(fingerprint $old museum descr)"
check "the GiST index on the 0.1.0 values answers as before" \
  same "$legacy_nearest" "$(nearest $old legacy)"
check "the GiST index on the generated column answers as before" \
  same "$museum_nearest" "$(nearest $old museum)"
[[ $legacy_nearest == "Index Scan "* ]] || echo "#   no index scan: $legacy_nearest" >&2

check "a 0.1.0 value compares with itself (SIM 0)" \
  same "0" "$(q -d $old -c "SELECT arg_sim(descr, descr) FROM legacy WHERE id = 1")"
check "0.1.0 values of other build options are refused (22023, naming both options)" \
  fails_with $old 22023 "levels=2" "levels=3" "builder 1.0.0" \
  "SELECT arg_sim(a.descr, b.descr) FROM legacy a, legacy b WHERE a.id = 1 AND b.id = 3"
check "a 0.1.0 value against a build of today, same options: refused (22023, naming builders 1.0.0 and 1.8.0)" \
  fails_with $old 22023 "builder 1.0.0" "builder 1.8.0" "arg_rebuild_needed" \
  "SELECT descr <~> arg_build(arg_generate_model('human', 0, 12), 'levels=2 base_points=16 surface=mesh holes=keep') FROM legacy WHERE id = 1"
check "arg_matches and arg_part_match refuse them too" \
  fails_with $old 22023 "builder 1.0.0" \
  "SELECT (SELECT count(*) FROM arg_part_match(a.descr, 1, 0, b.descr)) + (SELECT count(*) FROM arg_matches(a.descr, b.descr)) FROM legacy a, museum b WHERE a.id = 1 AND b.id = 1"
check "arg_rebuild_needed is true for every 0.1.0 value, false for today's builds" \
  same "3|3|0" \
  "$(q -d $old -c "SELECT (SELECT count(*) FILTER (WHERE arg_rebuild_needed(descr)) FROM legacy), (SELECT count(*) FILTER (WHERE arg_rebuild_needed(descr)) FROM scans), (SELECT count(*) FILTER (WHERE arg_rebuild_needed(descr)) FROM museum)")"

# The documented rebuild statements: SET descr = NULL where a trigger keeps the column, SET mesh
# = mesh for a generated column, arg_build again for a plain column.
check "UPDATE ... SET descr = NULL rebuilds the trigger's column: none left to rebuild" \
  same "3 0 t" \
  "$(q -d $old -c "WITH u AS (UPDATE scans SET descr = NULL WHERE arg_rebuild_needed(descr) RETURNING 1) SELECT count(*) FROM u" \
       -c "SELECT count(*) FILTER (WHERE arg_rebuild_needed(descr)), bool_and(descr = arg_build(mesh)) FROM scans" | tr '\n|' '  ' | sed 's/ $//')"
check "UPDATE ... SET mesh = mesh recomputes the generated column as arg_build(mesh)" \
  same "5 t" \
  "$(q -d $old -c "WITH u AS (UPDATE museum SET mesh = mesh RETURNING descr = arg_build(mesh) AS fresh) SELECT count(*), bool_and(fresh) FROM u" | tr '|' ' ')"
check "UPDATE ... SET descr = arg_build(...) rebuilds a plain column: none left to rebuild" \
  same "0" \
  "$(q -d $old -c "UPDATE legacy l SET descr = arg_build(s.mesh) FROM scans s WHERE s.id = l.id AND arg_rebuild_needed(l.descr)" \
       -c "SELECT count(*) FILTER (WHERE arg_rebuild_needed(descr)) FROM legacy")"
check "after the rebuild the values compare: the query's own row ranks first" \
  same "1" \
  "$(q -d $old -c "SET enable_seqscan = off" -c "SELECT id FROM legacy ORDER BY arg_global(descr) <#> arg_global((SELECT descr FROM legacy WHERE id = 1)), descr <~> (SELECT descr FROM legacy WHERE id = 1) LIMIT 1")"

# pg_dump of 0.1.0 restored where arg is the current version.
check "pg_restore of the 0.1.0 dump succeeds where arg is $current" \
  "$bindir/pg_restore" --exit-on-error -d $restored "$work/old.dump"
check "the restored database has arg $current and the catalogue of a fresh install" \
  diff -u "$work/fresh.txt" <(catalogue $restored)
check "the restored 0.1.0 values are byte-identical" \
  same "$legacy_before" "$(fingerprint $restored legacy descr)"
check "the restored generated column is rebuilt byte-identical" \
  same "$museum_before" "$(fingerprint $restored museum descr)"
check "the restored indexes answer as in 0.1.0" \
  same "$legacy_nearest $museum_nearest" "$(nearest $restored legacy) $(nearest $restored museum)"

# From 0.2.0: a stored sketch column with its arg_ivf index keeps working, and the arg column
# takes an index of its own, which the plain query then uses.
q -d postgres -c "CREATE DATABASE $mid" >/dev/null || exit 1
q -d $mid >/dev/null <<'SQL' || exit 1
CREATE EXTENSION cube;
CREATE EXTENSION arg VERSION '0.2.0';
-- A database a 0.2.0 library made holds 0.2.0's weights behind DEFAULT 'arg' (a default is
-- stored as the value it read as then): 'part' reads as they did.
CREATE OR REPLACE FUNCTION arg_sim(a arg, b arg, weights arg_weights DEFAULT 'part') RETURNS float8
  AS '$libdir/arg', 'arg_sim' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 2000;
CREATE OR REPLACE FUNCTION arg_matches(a arg, b arg, weights arg_weights DEFAULT 'part')
  RETURNS TABLE (level int, a_node int, b_node int, match_group int, loss float8, sim float8)
  AS '$libdir/arg', 'arg_matches' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 600 ROWS 40;
CREATE OR REPLACE FUNCTION arg_sketch_distance(a arg_sketch, b arg_sketch,
                                               weights arg_weights DEFAULT 'part')
  RETURNS float8
  AS '$libdir/arg', 'arg_sketch_distance' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 20;
CREATE OR REPLACE FUNCTION arg_part_match(query arg, level int, node int, candidate arg,
                                          weights arg_weights DEFAULT 'part')
  RETURNS TABLE (candidate_level int, candidate_node int, score float8)
  AS '$libdir/arg', 'arg_part_match' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 1500 ROWS 5;
CREATE TABLE objects (id int PRIMARY KEY, descr arg,
                      sk arg_sketch GENERATED ALWAYS AS (arg_sketch(descr)) STORED);
INSERT INTO objects SELECT i, arg_build(arg_generate_model(c, i::int, 12))
FROM unnest(ARRAY['vase', 'cup', 'torus', 'chair', 'human', 'table']) WITH ORDINALITY AS t(c, i);
CREATE INDEX objects_sk ON objects USING arg_ivf (sk) WITH (lists = 2);
SQL
sketch_nearest() {
  q -d $mid -c "SET enable_seqscan = off" -c "SET arg.ivf_probes = 2" \
    -c "SELECT string_agg(id::text, ',') FROM (SELECT id FROM objects ORDER BY sk <~> (SELECT sk FROM objects WHERE id = 1) LIMIT 6) s"
}
mid_before=$(sketch_nearest)
check "ALTER EXTENSION arg UPDATE from 0.2.0 succeeds" q -d $mid -c "ALTER EXTENSION arg UPDATE"
check "the catalogue updated from 0.2.0 equals a fresh $current install" \
  diff -u "$work/fresh.txt" <(catalogue $mid)
check "the 0.2.0 arg_ivf index of sketches answers as before" same "$mid_before" "$(sketch_nearest)"
check "after it arg_sim's default weights are <~>'s, and arg_matches' are arg_sim's" \
  same "t|t" "$(q -d $mid -c "SELECT bool_and(arg_sim(a.descr, b.descr) = (a.descr <~> b.descr)),
                                     bool_and((SELECT array_agg(m ORDER BY m) FROM arg_matches(a.descr, b.descr) m) =
                                              (SELECT array_agg(m ORDER BY m) FROM arg_matches(a.descr, b.descr, 'arg') m))
                              FROM objects a, objects b WHERE a.id = 1")"
check "arg_index_check passes on the 0.2.0 index of sketches" \
  same "6|6" "$(q -d $mid -c "SELECT entries, table_rows FROM arg_index_check('objects_sk')")"
check "an arg_ivf index on the arg column is taken by the plain query" \
  same "Index Scan using objects_descr on objects" \
  "$(q -d $mid -c "CREATE INDEX objects_descr ON objects USING arg_ivf (descr) WITH (lists = 2)" \
       -c "SET enable_seqscan = off" \
       -c "EXPLAIN (COSTS OFF) SELECT id FROM objects ORDER BY descr <~> (SELECT descr FROM objects WHERE id = 1) LIMIT 3" |
     grep -o 'Index Scan using objects_descr on objects')"
check "it ranks as brute force does (every cell probed)" \
  same "$(q -d $mid -c "SELECT string_agg(id::text, ',' ORDER BY descr <~> (SELECT descr FROM objects WHERE id = 1), id) FROM objects")" \
  "$(q -d $mid -c "SET enable_seqscan = off" -c "SET arg.ivf_probes = 2" \
       -c "SELECT string_agg(id::text, ',') FROM (SELECT id FROM objects ORDER BY descr <~> (SELECT descr FROM objects WHERE id = 1) LIMIT 6) s")"

# A library older than the SQL script: the script's first statement refuses it by name. The
# check of the current script, made to claim a later version, stands in for a newer script.
sharedir=$("$pg_config" --sharedir)/extension
future=$sharedir/arg--$current--9.9.9.sql
sudo_if_needed=()
[[ -w $sharedir ]] || sudo_if_needed=(sudo -n)
{
  echo "-- arg 9.9.9 (a test of the library check only)"
  sed -n '/^DO \$check\$/,/^\$check\$;/p' "extension/$(ls extension | grep -E -- "--$current\.sql$")" |
    sed "s/'$current'/'9.9.9'/g; s/script is $current/script is 9.9.9/"
} >"$work/future.sql"
if "${sudo_if_needed[@]}" cp "$work/future.sql" "$future" 2>/dev/null; then
  check "a SQL script newer than the library fails: version mismatch (0A000, both versions)" \
    fails_with $mid 0A000 "arg version mismatch" "the library is $current" "script is 9.9.9" \
    "ALTER EXTENSION arg UPDATE TO '9.9.9'"
  check "the extension stays at $current and its index still checks" \
    same "$current|6" "$(q -d $mid -c "SELECT (SELECT extversion FROM pg_extension WHERE extname = 'arg'), (SELECT entries FROM arg_index_check('objects_descr'))")"
  "${sudo_if_needed[@]}" rm -f "$future"
else
  echo "ok $((++n)) # SKIP cannot write $sharedir"
  echo "ok $((++n)) # SKIP cannot write $sharedir"
fi

echo "# $((n - failed)) passed, $failed failed"
[[ $failed -eq 0 ]]
