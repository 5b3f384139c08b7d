#!/usr/bin/env bash
# Out of memory: with its address space capped (prlimit on one backend), arg_build of a 70,000
# triangle mesh, the same with two threads, and a textured build whose 6000 x 6000 texture cannot
# be decoded each fail with SQLSTATE 53200, and the session goes on working afterwards; the
# server never restarts.
#
#   tests/oom/out_of_memory.sh      against the server in PGHOST/PGPORT/PGUSER (a superuser),
#                                   on the same machine (it needs /proc and prlimit)
#
# Prints TAP lines and exits non-zero when one fails. tests/run_all.sh runs it on its throwaway
# cluster (about 10 s).
set -uo pipefail

db=arg_oom
# shellcheck source=../tap_scratch_db.sh
. "$(dirname "${BASH_SOURCE[0]}")/../tap_scratch_db.sh"

if ! command -v prlimit > /dev/null; then
  echo "1..0 # SKIP prlimit not found (util-linux)"
  exit 0
fi

# Caps the address space of the backend in BACKEND_PID at its current size plus HEADROOM_MB.
# Only the backend's owner (or a process with CAP_SYS_RESOURCE) may do so: as root, run prlimit
# as the server's user.
cat > "$work/cap_backend.sh" << EOF
#!/usr/bin/env bash
set -eu
size_kb=\$(awk '/^VmSize/ {print \$2}' /proc/\$BACKEND_PID/status)
owner=\$(stat -c %U /proc/\$BACKEND_PID)
as=\$(( (size_kb + HEADROOM_MB * 1024) * 1024 ))
if [[ \$(id -un) == "\$owner" ]]; then prlimit --pid \$BACKEND_PID --as=\$as
else runuser -u "\$owner" -- prlimit --pid \$BACKEND_PID --as=\$as; fi
EOF
chmod +x "$work/cap_backend.sh"
export CAP_BACKEND="$work/cap_backend.sh"

echo "1..7"
PGOPTIONS='-c client_min_messages=warning' psql -X -q -d postgres \
  -c "DROP DATABASE IF EXISTS $db WITH (FORCE)" -c "CREATE DATABASE $db" > /dev/null || exit 1
started=$(psql -X -tA -d postgres -c "SELECT pg_postmaster_start_time()")

PGOPTIONS='-c client_min_messages=warning' psql -X -q -d "$db" -v ON_ERROR_STOP=1 << 'SQL' || exit 1
CREATE EXTENSION arg CASCADE;
CREATE TABLE big AS SELECT arg_generate_model('octopus', 1, 128) AS mesh;
-- An octahedron with texture coordinates, and BMP textures (24 bits, one grey).
CREATE TABLE textured AS SELECT convert_to(
  E'v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n'
  || E'vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\nvt 0.5 0.5\nvt 0.2 0.8\n'
  || E'f 1/1 3/3 5/5\nf 3/3 2/2 5/5\nf 2/2 4/4 5/5\nf 4/4 1/1 5/5\n'
  || E'f 3/3 1/1 6/6\nf 2/2 3/3 6/6\nf 4/4 2/2 6/6\nf 1/1 4/4 6/6\n', 'UTF8') AS mesh;
CREATE FUNCTION le32(v bigint) RETURNS bytea LANGUAGE sql IMMUTABLE
  AS $$ SELECT substr(int4send(v::int), 4, 1) || substr(int4send(v::int), 3, 1)
               || substr(int4send(v::int), 2, 1) || substr(int4send(v::int), 1, 1) $$;
CREATE FUNCTION bmp(side int) RETURNS bytea LANGUAGE sql IMMUTABLE
  AS $$ SELECT 'BM'::bytea || le32(54 + 3 * side * side) || le32(0) || le32(54) || le32(40)
               || le32(side) || le32(side) || '\x01001800'::bytea || le32(0)
               || le32(3 * side * side) || le32(2835) || le32(2835) || le32(0) || le32(0)
               || decode(repeat('5a', 3 * side * side), 'hex') $$;
CREATE TABLE texture AS SELECT bmp(6000) AS image;  -- 108 MB, twice that once decoded
SQL

# capped NAME HEADROOM_MB PREPARE STATEMENT AFTER: in a new session, runs PREPARE, caps the
# backend at its size plus HEADROOM_MB, runs STATEMENT and then AFTER; writes what each printed
# to $work/NAME.{statement,after} (VERBOSITY sqlstate prints an error as its SQLSTATE alone).
# The session loads the extension before the cap and runs without JIT: loading a library under
# the cap fails on its own (58P01), which is the server's business, not the extension's.
capped() {
  local name=$1 headroom=$2
  shift 2
  PGOPTIONS='-c client_min_messages=warning -c jit=off' HEADROOM_MB=$headroom \
    psql -X -tA -d "$db" > "$work/$name.out" 2>&1 << SQL
SELECT arg_version() IS NOT NULL;
$1
\set VERBOSITY sqlstate
SELECT pg_backend_pid() AS pid \gset
\setenv BACKEND_PID :pid
\! "\$CAP_BACKEND"
\echo ==statement
$2
\echo ==after
$3
SQL
  sed -n '/^==statement$/,/^==after$/p' "$work/$name.out" | sed '1d;$d' > "$work/$name.statement"
  sed -n '/^==after$/,$p' "$work/$name.out" | sed '1d' > "$work/$name.after"
  sed "s/^/# $name: /" "$work/$name.out"
}
# is_line FILE TEXT: 1 when FILE holds exactly the one line TEXT, else 0.
is_line() { [[ $(cat "$1") == "$2" ]] && echo 1 || echo 0; }

small="SELECT arg_build(arg_generate_model('vase', 0, 8)) IS NOT NULL;"
capped build 16 "" "SELECT arg_build(mesh) IS NOT NULL FROM big;" "$small"
result "$(is_line "$work/build.statement" "ERROR:  53200")" \
  "arg_build of 70,000 triangles with 16 MB of headroom fails with 53200"
result "$(is_line "$work/build.after" t)" "the session then builds a small model"

capped threads 16 "SET arg.max_build_threads = 2;" \
  "SELECT arg_build(mesh, 'threads=2') IS NOT NULL FROM big;" "$small"
result "$(is_line "$work/threads.statement" "ERROR:  53200")" \
  "the same build with two threads fails with 53200"
result "$(is_line "$work/threads.after" t)" "the session then builds a small model"

# The small textured build first loads the image decoder (OpenImageIO) while memory is plentiful;
# a textured build needs about 70 MB of address space more than idle, whatever the texture; this
# one needs its 108 MB of bytes and as much again for the pixels.
capped texture 150 "SELECT arg_build(mesh, bmp(4)) IS NOT NULL FROM textured;" \
  "SELECT arg_build(mesh, image) IS NOT NULL FROM textured, texture;" \
  "SELECT arg_build(mesh, bmp(4)) IS NOT NULL FROM textured;"
result "$(is_line "$work/texture.statement" "ERROR:  53200")" \
  "a textured build with a 6000 x 6000 texture and 150 MB of headroom fails with 53200"
result "$(is_line "$work/texture.after" t)" "the session then builds a small textured model"

now=$(psql -X -tA -d postgres -c "SELECT pg_postmaster_start_time()")
result $([[ -n $started && $now == "$started" ]] && echo 1 || echo 0) \
  "the server did not restart (started $started)"
exit $((failed > 0))
