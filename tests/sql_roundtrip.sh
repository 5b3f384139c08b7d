#!/usr/bin/env bash
# Round trips of arg values out of the database and back: pg_dump -Fc / pg_restore into a new
# database, and COPY ... (FORMAT binary) out and in, must give byte-identical values (compared
# by md5 of arg_send over the whole table); a corrupted binary COPY must be refused with 22P03.
#
#   tests/sql_roundtrip.sh      against the server in PGHOST/PGPORT/PGUSER (superuser)
#
# Prints TAP lines ("ok N - ...", "not ok N - ...") and exits non-zero when one fails.
# tests/run_all.sh runs it on its throwaway cluster.
set -uo pipefail

pg_config=${PG_CONFIG:-/usr/lib/postgresql/15/bin/pg_config}
[[ -x "$pg_config" ]] || pg_config=$(command -v pg_config)
bindir=$("$pg_config" --bindir)
work=$(mktemp -d)
src=arg_roundtrip_src dst=arg_roundtrip_dst
drop_databases() {
  for db in $src $dst; do
    PGOPTIONS='-c client_min_messages=warning' psql -X -q -d postgres -c "DROP DATABASE IF EXISTS $db" \
      >/dev/null 2>&1
  done
}
trap 'drop_databases; rm -rf "$work"' EXIT

# shellcheck source=tap_checks.sh
. "$(dirname "${BASH_SOURCE[0]}")/tap_checks.sh"

# md5 over every row of a column's binary form, in id order (NULL rows count as 'null').
fingerprint() {  # DB TABLE COLUMN
  q -d "$1" -c "SELECT md5(string_agg(id || ':' || coalesce(encode(arg_send($3), 'hex'), 'null'), ',' ORDER BY id)) FROM $2"
}
weights_fingerprint() {  # DB TABLE
  q -d "$1" -c "SELECT md5(string_agg(id || ':' || coalesce(encode(arg_weights_send(w), 'hex'), 'null'), ',' ORDER BY id)) FROM $2"
}

echo "1..9"
drop_databases
q -d postgres -c "CREATE DATABASE $src" -c "CREATE DATABASE $dst" >/dev/null || exit 1

# The source: a museum table whose ARG is a generated column, a plain arg column holding the
# same values (dumped as text), weights, and a row without a mesh.
q -d "$src" >/dev/null <<'SQL' || exit 1
CREATE EXTENSION arg CASCADE;
CREATE TABLE objects (
  id     int PRIMARY KEY,
  title  text,
  mesh   bytea,
  descr  arg GENERATED ALWAYS AS (arg_build(mesh)) STORED,
  copied arg,
  w      arg_weights
);
INSERT INTO objects (id, title, mesh, w)
SELECT i, c, arg_generate_model(c, i::int, 16), (ARRAY['arg', 'mrg', 'shape lambda_2=0.5'])[i % 3 + 1]::arg_weights
FROM unnest(ARRAY['vase', 'cup', 'amphora', 'torus', 'fourleg', 'human', 'table', 'chair', 'octopus'])
       WITH ORDINALITY AS t(c, i);
INSERT INTO objects (id, title) VALUES (100, 'not scanned');
UPDATE objects SET copied = descr;
SQL
descr_src=$(fingerprint $src objects descr)
copied_src=$(fingerprint $src objects copied)
weights_src=$(weights_fingerprint $src objects)

# pg_dump -Fc, then pg_restore into another database.
check "pg_dump -Fc dumps the table" "$bindir/pg_dump" -Fc -d $src -f "$work/src.dump"
check "pg_restore restores it into a new database" \
  "$bindir/pg_restore" --exit-on-error -d $dst "$work/src.dump"
check "a stored arg column is byte-identical after dump and restore" \
  same "$copied_src" "$(fingerprint $dst objects copied)"
check "a generated arg column, rebuilt on restore, is byte-identical" \
  same "$descr_src" "$(fingerprint $dst objects descr)"
check "arg_weights are identical after dump and restore" \
  same "$weights_src" "$(weights_fingerprint $dst objects)"

# COPY (FORMAT binary) out of one database and into another: arg_send, then arg_recv.
q -d $src -c "\\copy (SELECT id, copied, w FROM objects) TO '$work/objects.bin' WITH (FORMAT binary)"
q -d $dst -c "CREATE TABLE copied_back (id int PRIMARY KEY, copied arg, w arg_weights)" >/dev/null
check "binary COPY out and in succeeds" \
  q -d $dst -c "\\copy copied_back FROM '$work/objects.bin' WITH (FORMAT binary)"
check "arg values are byte-identical after binary COPY" \
  same "$copied_src" "$(fingerprint $dst copied_back copied)"
check "arg_weights are identical after binary COPY" \
  same "$weights_src" "$(weights_fingerprint $dst copied_back)"

# One byte changed inside the first arg value of the binary COPY file (19-byte file header,
# 2-byte field count, the id's length and value, the arg's length, then 100 bytes into it):
# arg_recv validates like arg_in and refuses it with 22P03, and nothing is loaded.
cp "$work/objects.bin" "$work/corrupt.bin"
printf '\x5a' | dd of="$work/corrupt.bin" bs=1 seek=$((19 + 2 + 4 + 4 + 4 + 100)) conv=notrunc 2>/dev/null
q -d $dst -c "TRUNCATE copied_back"
refused() {
  local out
  out=$(psql -X -q -d $dst -v VERBOSITY=verbose \
    -c "\\copy copied_back FROM '$work/corrupt.bin' WITH (FORMAT binary)" 2>&1)
  if [[ $out == *"22P03"*"invalid binary input for type arg"* &&
        $(q -d $dst -c "SELECT count(*) FROM copied_back") == 0 ]]; then
    return 0
  fi
  echo "# $out" >&2
  return 1
}
check "a corrupted arg in a binary COPY is refused (22P03) and nothing is loaded" refused

echo "# $((n - failed)) passed, $failed failed"
[[ $failed -eq 0 ]]
