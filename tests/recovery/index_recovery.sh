#!/usr/bin/env bash
# The arg_ivf index on an arg column through crashes and on a streaming standby. A throwaway
# primary (fsync and full_page_writes on, wal_consistency_checking for generic WAL, which is
# what the index writes) and a standby made from it by pg_basebackup; two sessions insert rows and a third deletes and
# vacuums while the primary crashes: twice a backend is killed with SIGKILL (the postmaster
# restarts every process and replays the WAL), once the server stops in immediate mode. After
# each crash arg_index_check passes (every live row indexed exactly once) and the index, with
# every cell and every row read, answers as brute force does; the standby, which replays every
# page image it is sent against its own pages, then holds an index that passes the same check
# and answers as the primary does.
#
#   tests/recovery/index_recovery.sh     (as root or as a user who may run postgres; after
#                                         make install)
#
# Prints TAP lines and exits non-zero when one fails; tests/run_all.sh runs it as a suite.
set -uo pipefail

cd "$(dirname "$0")/../.." || exit 1
build=${BUILD_DIR:-build}
base=$build/pg-recovery
primary=$base/primary
pg_config=${PG_CONFIG:-/usr/lib/postgresql/15/bin/pg_config}
[[ -x "$pg_config" ]] || pg_config=$(command -v pg_config)
bindir=$("$pg_config" --bindir)
if [[ $(id -u) -eq 0 ]]; then
  as_owner() { (cd / && runuser -u postgres -- "$@"); }
else
  as_owner() { (cd / && "$@"); }
fi
standby=$(mktemp -d /tmp/arg-standby.XXXXXX)
[[ $(id -u) -eq 0 ]] && chown postgres: "$standby"
chmod 700 "$standby"
workers=()

stop_all() {
  for pid in "${workers[@]}"; do kill "$pid" 2>/dev/null; done
  [[ -f "$standby/data/postmaster.pid" ]] &&
    as_owner "$bindir/pg_ctl" -D "$standby/data" -m immediate -w stop >/dev/null 2>&1
  rm -rf "$standby"
  tools/pg/cluster.sh stop "$primary" --remove >/dev/null 2>&1
}
trap stop_all EXIT
trap 'exit 130' INT TERM HUP

# shellcheck source=../tap_checks.sh
. tests/tap_checks.sh
bail() { echo "Bail out! $*"; exit 1; }
on_primary() { psql -X -q -tA -v ON_ERROR_STOP=1 -h localhost -p "$primary_port" -U postgres -d postgres "$@"; }
on_standby() { psql -X -q -tA -v ON_ERROR_STOP=1 -h localhost -p "$standby_port" -U postgres -d postgres "$@"; }

echo "1..11"
tools/pg/cluster.sh start "$primary" --fresh >/dev/null || bail "the primary did not start"
primary_port=$(cat "$primary/port")
on_primary -c "ALTER SYSTEM SET fsync = on" -c "ALTER SYSTEM SET full_page_writes = on" \
  -c "ALTER SYSTEM SET wal_consistency_checking = 'generic'" \
  -c "ALTER SYSTEM SET restart_after_crash = on" -c "SELECT pg_reload_conf()" >/dev/null ||
  bail "cannot configure the primary"
on_primary >/dev/null <<'SQL' || bail "cannot make the table"
CREATE EXTENSION arg CASCADE;
CREATE TABLE sources AS
SELECT row_number() OVER () AS n, arg_build(arg_generate_model(c, v, 12)) AS descr
FROM unnest(ARRAY['vase', 'cup', 'torus', 'chair', 'human', 'fourleg']) c, generate_series(0, 3) v;
CREATE TABLE objects (id bigserial PRIMARY KEY, source int, descr arg);
INSERT INTO objects (source, descr) SELECT n, descr FROM sources, generate_series(1, 5);
CREATE INDEX objects_descr ON objects USING arg_ivf (descr) WITH (lists = 4);
SQL

# The standby, streaming from the primary from here on.
as_owner "$bindir/pg_basebackup" -h localhost -p "$primary_port" -U postgres -D "$standby/data" \
  -R -X stream >"$standby/basebackup.log" 2>&1 || bail "pg_basebackup failed: $(tail -n 3 "$standby/basebackup.log")"
standby_port=$((primary_port + 1))
while (echo >"/dev/tcp/127.0.0.1/$standby_port") 2>/dev/null; do standby_port=$((standby_port + 1)); done
as_owner "$bindir/pg_ctl" -D "$standby/data" -l "$standby/postgres.log" -w -t 60 \
  -o "-p $standby_port" start >/dev/null || bail "the standby did not start: $(tail -n 5 "$standby/postgres.log")"
check "a standby streams from the primary" \
  same "streaming" "$(on_primary -c "SELECT state FROM pg_stat_replication LIMIT 1")"

# Two inserting sessions (a commit a row) and one that deletes a row in seven and vacuums, until
# the server goes away.
workload() {
  for s in 1 2; do
    on_primary -c "DO \$\$ BEGIN FOR i IN 1..1000000 LOOP
      INSERT INTO objects (source, descr) SELECT n, descr FROM sources WHERE n = 1 + (i * 7 + $s) % 24;
      COMMIT; END LOOP; END \$\$" >/dev/null 2>&1 &
    workers+=($!)
  done
  (for _ in $(seq 1000); do
     on_primary -c "DELETE FROM objects WHERE id % 7 = 0" -c "VACUUM objects" >/dev/null 2>&1 || break
   done) &
  workers+=($!)
}
wait_workers() {
  for pid in "${workers[@]}"; do wait "$pid" 2>/dev/null; done
  workers=()
}
wait_up() {
  for _ in $(seq 120); do on_primary -c "SELECT 1" >/dev/null 2>&1 && return 0; sleep 0.5; done
  return 1
}
# The check passes at once (entries of rows that died in the crash not yet vacuumed) and after
# VACUUM: "before|entries|table_rows|count", before true when the first check counted every
# live row, the rest from the check after VACUUM.
checked() {
  local before
  before=$(on_primary -c "SELECT c.table_rows = (SELECT count(*) FROM objects)
                          FROM arg_index_check('objects_descr') c") || return
  on_primary -c "VACUUM objects" || return
  echo "$before|$(on_primary -F '|' -c "SELECT c.entries, c.table_rows, (SELECT count(*) FROM objects)
                                        FROM arg_index_check('objects_descr') c")"
}
# For five queries, every row through the index (every cell, every row a candidate) against
# brute force: the SIMs in order and the ids as a set agree (equal values tie, in either order).
answers() { # psql-function
  "$1" -c "SET enable_seqscan = off" -c "SET arg.ivf_probes = 4" -c "SET arg.ivf_candidates = 100000" -c "
    SELECT string_agg(md5(sims::text) || ':' || md5(ids::text), ' ' ORDER BY n) FROM (
      SELECT s.n,
             (SELECT array_agg(d) FROM (SELECT descr <~> s.descr AS d FROM objects
                                        ORDER BY descr <~> s.descr LIMIT 1000000) i) AS sims,
             (SELECT array_agg(id ORDER BY id) FROM (SELECT id FROM objects ORDER BY descr <~> s.descr LIMIT 1000000) i) AS ids
      FROM sources s WHERE s.n IN (1, 6, 11, 16, 21)) q"
}
brute_force() {
  on_primary -c "SET enable_indexscan = off" -c "
    SELECT string_agg(md5(sims::text) || ':' || md5(ids::text), ' ' ORDER BY n) FROM (
      SELECT s.n,
             (SELECT array_agg(descr <~> s.descr ORDER BY descr <~> s.descr) FROM objects) AS sims,
             (SELECT array_agg(id ORDER BY id) FROM objects) AS ids
      FROM sources s WHERE s.n IN (1, 6, 11, 16, 21)) q"
}
index_rows_ok() { # "t|entries|table_rows|count": the last three equal, and rows left
  local b e t c
  IFS='|' read -r b e t c <<<"$1"
  [[ $b == t && -n "$c" && "$e" == "$t" && "$t" == "$c" && "$c" -gt 0 ]] ||
    { echo "#   have: $1" >&2; return 1; }
}

for round in 1 2 3; do
  workload
  sleep 2
  if [[ $round -lt 3 ]]; then
    how="a backend killed with SIGKILL"
    victim=$(on_primary -c "SELECT pid FROM pg_stat_activity WHERE query LIKE 'DO %INSERT INTO objects%' LIMIT 1")
    [[ -n "$victim" ]] && kill -9 "$victim"
  else
    how="an immediate stop"
    as_owner "$bindir/pg_ctl" -D "$(readlink -f "$primary/data")" -m immediate -w stop >/dev/null 2>&1
    wait_workers
    tools/pg/cluster.sh start "$primary" >/dev/null
    primary_port=$(cat "$primary/port")
  fi
  wait_workers
  wait_up || bail "the primary did not come back after $how"
  check "round $round, $how: arg_index_check passes, before and after VACUUM" \
    index_rows_ok "$(checked)"
  check "round $round: the index answers as brute force does" \
    same "$(brute_force)" "$(answers on_primary)"
done

# The standby replays up to the primary's last WAL position, then answers alike.
target=$(on_primary -c "SELECT pg_current_wal_lsn()")
caught_up() {
  for _ in $(seq 600); do  # a shared machine replays the checked page images slowly
    [[ $(on_standby -c "SELECT pg_last_wal_replay_lsn() >= '$target'::pg_lsn" 2>/dev/null) == t ]] && return 0
    sleep 0.5
  done
  echo "#   the standby replayed up to $(on_standby -c "SELECT pg_last_wal_replay_lsn()" 2>&1), not $target; its log ends:" >&2
  tail -n 5 "$standby/postgres.log" | sed 's/^/#   /' >&2
  return 1
}
check "the standby replays the primary's WAL through the crashes" caught_up
check "arg_index_check passes on the standby" \
  same "$(on_primary -F '|' -c "SELECT entries, table_rows FROM arg_index_check('objects_descr')")" \
  "$(on_standby -F '|' -c "SELECT entries, table_rows FROM arg_index_check('objects_descr')")"
check "the standby's index answers as the primary's" same "$(answers on_primary)" "$(answers on_standby)"
# A page that differs from the primary's image stops the standby (FATAL, "inconsistent page").
check "no page of the standby differed from the primary's page image (wal_consistency_checking)" \
  bash -c "! grep -E 'inconsistent page|PANIC' '$standby/postgres.log' >&2"

echo "# $((n - failed)) passed, $failed failed"
[[ $failed -eq 0 ]]
