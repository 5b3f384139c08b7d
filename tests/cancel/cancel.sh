#!/usr/bin/env bash
# Cancellation: statement_timeout = '1s' and pg_cancel_backend stop a long arg_build (a mesh of a
# million triangles), a long ranking (every pair of a 1,000-row table) and a long part matching
# with SQLSTATE 57014 within 2 s of the start (or within 1 s of pg_cancel_backend, also for a
# build on two threads in a backend that loaded the image decoder, whose other threads must all
# block signals), the session answers afterwards, a cancelled INSERT through a generated column leaves no row, and a
# transaction goes on after ROLLBACK TO SAVEPOINT.
#
#   tests/cancel/cancel.sh      against the server in PGHOST/PGPORT/PGUSER (a superuser)
#
# Prints TAP lines ("ok N - ...", "not ok N - ...") with the measured times, and exits non-zero
# when one fails. tests/run_all.sh runs it on its throwaway cluster (about 40 s).
set -uo pipefail

db=arg_cancel
limit_ms=2000        # statement_timeout is 1 s: the error must arrive within 2 s of the start
cancel_limit_ms=1000 # and within 1 s of pg_cancel_backend
# shellcheck source=../tap_scratch_db.sh
. "$(dirname "${BASH_SOURCE[0]}")/../tap_scratch_db.sh"
q() { psql -X -q -v ON_ERROR_STOP=1 -tA "$@"; }
now_ms() { date +%s%3N; }

echo "1..11"
PGOPTIONS='-c client_min_messages=warning' psql -X -q -d postgres -c "DROP DATABASE IF EXISTS $db WITH (FORCE)" >/dev/null
q -d postgres -c "CREATE DATABASE $db" >/dev/null || exit 1

# Fixtures: a torus of 1000 x 500 vertices (500,000 vertices, 1,000,000 triangles, 38 MB of OFF,
# stored uncompressed so that reading it costs little), and a catalogue of 1,000 ARGs (40 models
# at resolution 8, each 25 times).
setup_started=$(now_ms)
PGOPTIONS="-c client_min_messages=warning" q -d "$db" >/dev/null <<'SQL' || exit 1
CREATE EXTENSION arg CASCADE;
CREATE TABLE big_mesh (mesh bytea);
ALTER TABLE big_mesh ALTER mesh SET STORAGE EXTERNAL;
INSERT INTO big_mesh
WITH g AS (SELECT 1000 AS nu, 500 AS nv)
SELECT convert_to(format(E'OFF\n%s %s 0\n', nu * nv, 2 * nu * nv), 'UTF8')
  || (SELECT convert_to(string_agg(format('%s %s %s', ((2 + cos(v)) * cos(u))::real,
                                          ((2 + cos(v)) * sin(u))::real, sin(v)::real),
                                   E'\n' ORDER BY i, j) || E'\n', 'UTF8')
      FROM g, generate_series(0, nu - 1) i, generate_series(0, nv - 1) j,
           LATERAL (SELECT 2 * pi() * i / nu AS u, 2 * pi() * j / nv AS v) a)
  || (SELECT convert_to(string_agg(format(E'3 %s %s %s\n3 %s %s %s',
                                          i * nv + j, ((i + 1) % nu) * nv + j, ((i + 1) % nu) * nv + (j + 1) % nv,
                                          i * nv + j, ((i + 1) % nu) * nv + (j + 1) % nv, i * nv + (j + 1) % nv),
                                   E'\n' ORDER BY i, j) || E'\n', 'UTF8')
      FROM g, generate_series(0, nu - 1) i, generate_series(0, nv - 1) j)
FROM g;
CREATE TABLE catalogue (id serial PRIMARY KEY, descr arg);
INSERT INTO catalogue (descr)
SELECT d FROM (SELECT arg_build(arg_generate_model(c, v, 8)) AS d
               FROM unnest(ARRAY['vase', 'cup', 'amphora', 'torus', 'fourleg', 'human', 'table', 'chair']) c,
                    generate_series(0, 4) v) m, generate_series(1, 25);
ANALYZE catalogue;
CREATE TABLE objects (id int, mesh bytea, descr arg GENERATED ALWAYS AS (arg_build(mesh)) STORED);
-- An octahedron with texture coordinates and a 2 x 2 BMP: building it loads the image decoder.
CREATE TABLE textured AS SELECT convert_to(
  E'v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n'
  || E'vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\nvt 0.5 0.5\nvt 0.2 0.8\n'
  || E'f 1/1 3/3 5/5\nf 3/3 2/2 5/5\nf 2/2 4/4 5/5\nf 4/4 1/1 5/5\n'
  || E'f 3/3 1/1 6/6\nf 2/2 3/3 6/6\nf 4/4 2/2 6/6\nf 1/1 4/4 6/6\n', 'UTF8') AS mesh,
  '\x424d460000000000000036000000280000000200000002000000010018000000000010000000130b0000130b00000000000000000000ff000000ff00000000ff00ffffff0000'::bytea AS texture;
CREATE TABLE journal (step int);
SQL
triangles=$(q -d "$db" -c "SELECT split_part(split_part(convert_from(substr(mesh, 1, 40), 'UTF8'), E'\n', 2), ' ', 2) FROM big_mesh")
echo "# fixtures in $(( $(now_ms) - setup_started )) ms: a mesh of $triangles triangles, 1,000 catalogue rows"

build_sql="SELECT arg_build(mesh) IS NOT NULL FROM big_mesh"
rank_sql="SELECT a.id, b.id, a.descr <~> b.descr AS sim FROM catalogue a, catalogue b ORDER BY sim LIMIT 10"
part_sql="SELECT count(*) FROM catalogue a, catalogue b, LATERAL arg_part_match(a.descr, 2, 0, b.descr) p"

# Runs STATEMENT under statement_timeout = '1s' in one session, then asks that session for its
# backend pid. Sets: state (SQLSTATE of the statement), ms (its time as psql measured it) and
# alive (1 when the same session answered afterwards).
timed() {
  local out
  out=$(psql -X -d "$db" 2>&1 <<SQL
\set VERBOSITY sqlstate
SELECT 'pid:' || pg_backend_pid();
SET statement_timeout = '1s';
\timing on
$1;
\timing off
RESET statement_timeout;
SELECT 'pid:' || pg_backend_pid();
SQL
)
  state=$(sed -nE 's/^ERROR: +([0-9A-Z]{5}).*/\1/p' <<<"$out" | head -n 1)
  [[ -n "$state" ]] || state=00000
  ms=$(sed -nE 's/^Time: ([0-9.]+) ms.*/\1/p' <<<"$out" | head -n 1)
  ms=${ms%.*}
  local pids
  pids=$(grep -c '^ *pid:' <<<"$out")
  alive=0
  [[ $pids -eq 2 && $(grep '^ *pid:' <<<"$out" | sort -u | wc -l) -eq 1 ]] && alive=1
  [[ -n "$ms" ]] || ms=999999
}

for case in "build:arg_build of a mesh of $triangles triangles:$build_sql" \
            "rank:ranking every pair of 1,000 ARGs (ORDER BY <~> LIMIT 10):$rank_sql" \
            "part:part matching every pair of 1,000 ARGs:$part_sql"; do
  IFS=: read -r _ what sql <<<"$case"
  timed "$sql"
  result "$([[ $state == 57014 && $ms -le $limit_ms && $alive == 1 ]] && echo 1)" \
    "statement_timeout = '1s' stops $what: SQLSTATE $state after $ms ms, the session answers after"
done

# Signal masks of the backend PID's threads: sets threads (how many besides the backend's own),
# blocking (how many of those block SIGINT, the cancel signal) and main_blocks (1 when the
# backend's own thread blocks it). Bit 1 of SigBlk is signal 2, SIGINT.
# The backend's own thread blocks every signal for the few microseconds it takes to start a
# worker (so the worker is born blocking them; a cancel sent then waits and is taken when the
# mask is restored), and mu starts workers for every block of runs, so one read can land in
# such a window: the backend's thread counts as blocking only if ten reads, 20 ms apart, all
# find SIGINT blocked.
signal_masks() {
  local task mask
  threads=0 blocking=0 main_blocks=1
  local state
  for task in /proc/"$1"/task/*; do
    [[ ${task##*/} == "$1" ]] && continue
    mask=$(awk '/^SigBlk/ {print $2}' "$task/status" 2>/dev/null) || continue
    [[ -n "$mask" ]] || continue
    # As in watch_workers: a thread read as it exits may show its signal state released.
    if (( ((0x$mask >> 1) & 1) == 0 )); then
      state=$(awk '/^State/ {print $2}' "$task/status" 2>/dev/null) || continue
      [[ -n $state && $state != [XZ]* ]] || continue
    fi
    threads=$((threads + 1))
    blocking=$((blocking + ((0x$mask >> 1) & 1)))
  done
  for _ in 1 2 3 4 5 6 7 8 9 10; do
    mask=$(awk '/^SigBlk/ {print $2}' /proc/"$1"/status 2>/dev/null) || break
    [[ -n "$mask" ]] || break
    main_blocks=$(( (0x$mask >> 1) & 1 ))
    [[ $main_blocks == 0 ]] && break
    sleep 0.02
  done
}

# Worker threads of backend $1 that parallel_for started (it names them "arg worker"; Linux),
# each read once: sets workers (how many were seen) and workers_blocking (how many of them
# blocked SIGINT). mu's workers live for four Dijkstras each, a millisecond or so, so the loop
# reads /proc with the shell's own read and never forks; it polls until one is seen or the
# statement has run 20 s. A thread read as it exits shows an empty SigBlk (its signal state is
# gone by then), so a mask without SIGINT counts only if the thread is still there, not dead.
watch_workers() {
  local task name key value tid mask state
  declare -A seen=()
  workers=0 workers_blocking=0
  while [[ $workers -lt 1 && $(($(now_ms) - started)) -lt 20000 ]]; do
    for task in /proc/"$1"/task/*; do
      tid=${task##*/}
      [[ $tid == "$1" || -n ${seen[$tid]:-} ]] && continue
      name=""
      { read -r name < "$task/comm"; } 2>/dev/null
      [[ $name == "arg worker" ]] || continue
      mask=""
      while read -r key value; do
        [[ $key == SigBlk: ]] && { mask=$value; break; }
      done 2>/dev/null < "$task/status"
      [[ -n $mask ]] || continue
      if (( ((0x$mask >> 1) & 1) == 0 )); then  # only a thread still alive after it counts
        state=""
        while read -r key value; do
          [[ $key == State: ]] && { state=$value; break; }
        done 2>/dev/null < "$task/status"
        [[ -n $state && $state != [XZ]* ]] || continue
      fi
      seen[$tid]=1
      workers=$((workers + 1))
      workers_blocking=$((workers_blocking + ((0x$mask >> 1) & 1)))
    done
  done
}

# pg_cancel_backend from a second session, once the statement has run for a second; with a
# third argument "masks", the backend's threads' signal masks are read just before the cancel.
# $prelude (if set) runs first in the same session as a statement of its own, so the second
# counts from the statement under test.
cancelled() {  # SQL WHAT [masks]
  local sql=$1 what=$2 pid="" started cancel_at end_at delay
  local first=(-c "${prelude:-SELECT 1}")
  (PGAPPNAME=arg_cancel_probe psql -X -d "$db" -v VERBOSITY=sqlstate "${first[@]}" -c "$sql" \
     >"$work/probe.out" 2>&1
   now_ms >"$work/probe.end") &
  local probe=$!
  started=$(now_ms)
  while [[ $(( $(now_ms) - started )) -lt 20000 ]]; do
    pid=$(q -d postgres -c "SELECT pid FROM pg_stat_activity WHERE application_name = 'arg_cancel_probe'
                            AND state = 'active' AND now() - query_start > interval '1 s'
                            AND query NOT LIKE '%FROM textured%'")
    [[ -n "$pid" ]] && break
    sleep 0.05
  done
  if [[ -z "$pid" ]]; then
    wait "$probe"
    result 0 "pg_cancel_backend stops $what: the statement never ran for a second"
    return
  fi
  if [[ ${3:-} == masks ]]; then  # the build's workers and, then, every thread's mask
    watch_workers "$pid"
    signal_masks "$pid"
  fi
  cancel_at=$(now_ms)
  q -d postgres -c "SELECT pg_cancel_backend($pid)" >/dev/null
  wait "$probe"
  end_at=$(cat "$work/probe.end")
  delay=$((end_at - cancel_at))
  state=$(sed -nE 's/^ERROR: +([0-9A-Z]{5}).*/\1/p' "$work/probe.out" | head -n 1)
  result "$([[ $state == 57014 && $delay -le $cancel_limit_ms ]] && echo 1)" \
    "pg_cancel_backend stops $what: SQLSTATE ${state:-none} $delay ms after the cancel"
}
cancelled "$build_sql" "arg_build of a mesh of $triangles triangles"
cancelled "$rank_sql" "ranking every pair of 1,000 ARGs"

# A build on two threads in a backend that has loaded the image decoder (whose libraries start
# threads of their own): the cancel still arrives, because only the backend's own thread takes
# signals; every other thread blocks them.
# The textured build is a statement of its own, so the second counts from the big build; its
# workers are found by name (worker_threads), whenever mu started them. The big mesh is built
# on a collapsed copy whose mu, with the default base points, runs for a few tens of
# milliseconds, after about two seconds of cleaning and collapse: 4,096 base points keep mu,
# and its workers, running for most of a second more.
prelude="SET arg.max_build_threads = 2; SELECT arg_build(mesh, texture) IS NOT NULL FROM textured"
threads_sql="SELECT arg_build(mesh, 'threads=2 base_points=4096') IS NOT NULL FROM big_mesh"
cancelled "$threads_sql" "a two-thread arg_build after a textured build" masks
prelude=""
result "$([[ $workers -ge 1 && $workers_blocking == "$workers" && $blocking == "$threads" && $main_blocks == 0 ]] && echo 1)" \
  "during it $workers_blocking of $workers worker threads seen and $blocking of the backend's $threads other threads block SIGINT, its own thread does not ($main_blocks)"

# A cancelled INSERT through the generated column leaves no row.
timed "INSERT INTO objects (id, mesh) SELECT 1, mesh FROM big_mesh"
rows=$(q -d "$db" -c "SELECT count(*) FROM objects")
result "$([[ $state == 57014 && $ms -le $limit_ms && $rows == 0 ]] && echo 1)" \
  "a cancelled INSERT whose generated column builds the ARG: SQLSTATE $state after $ms ms, $rows rows written"

# In a transaction: the cancelled statement rolls back to its savepoint and the transaction goes on.
out=$(psql -X -d "$db" -v VERBOSITY=sqlstate 2>&1 <<'SQL'
BEGIN;
INSERT INTO journal VALUES (1);
SAVEPOINT before_build;
SET LOCAL statement_timeout = '1s';
INSERT INTO objects (id, mesh) SELECT 2, mesh FROM big_mesh;
ROLLBACK TO SAVEPOINT before_build;
INSERT INTO journal VALUES (2);
INSERT INTO objects (id, mesh) SELECT 3, arg_generate_model('cup', 0, 8);
COMMIT;
SQL
)
state=$(sed -nE 's/^ERROR: +([0-9A-Z]{5}).*/\1/p' <<<"$out" | head -n 1)
journal=$(q -d "$db" -c "SELECT string_agg(step::text, ',' ORDER BY step) FROM journal")
objects=$(q -d "$db" -c "SELECT string_agg(id || ':' || (arg_info(descr) IS NOT NULL), ',' ORDER BY id) FROM objects")
result "$([[ $state == 57014 && $journal == "1,2" && $objects == "3:true" ]] && echo 1)" \
  "after ROLLBACK TO SAVEPOINT the transaction goes on: cancel $state, journal $journal, objects $objects (id:built)"
result "$(grep -q '^COMMIT' <<<"$out" && echo 1)" "that transaction commits"

# Nothing is left running: no backend of this database is still active.
active=$(q -d postgres -c "SELECT count(*) FROM pg_stat_activity WHERE datname = '$db' AND state = 'active'")
result "$([[ $active == 0 ]] && echo 1)" "no statement is left running after the cancels ($active active)"

[[ $failed -eq 0 ]]
