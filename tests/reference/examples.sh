#!/usr/bin/env bash
# Runs every example of docs/REFERENCE.md, in the order of the page, in a scratch database: each
# ```sql block, and each statement in a table cell (a `code` span that starts with SELECT, SET,
# CREATE, COPY or RESET). Each runs through psql in a session of its own. A block whose first line
# is "-- fails with SQLSTATE XXXXX" must fail, with that SQLSTATE and no other; every other
# example must run without an error.
#
#   tests/reference/examples.sh      against the server in PGHOST/PGPORT/PGUSER (a superuser:
#                                    some examples write and read files on the server)
#
# Prints TAP lines ("ok N - ...", "not ok N - ...") and exits non-zero when one fails.
# tests/run_all.sh runs it on its throwaway cluster.
set -uo pipefail

cd "$(dirname "$0")/../.." || exit 1
reference=docs/REFERENCE.md
db=arg_reference
# shellcheck source=../tap_scratch_db.sh
. tests/tap_scratch_db.sh

# One file per example in $work (001.sql, ...), and a manifest: number, line, expected SQLSTATE.
awk -v dir="$work" '
  function example(line, expected) {
    n++
    file = sprintf("%s/%03d.sql", dir, n)
    printf "%03d\t%d\t%s\n", n, line, expected > (dir "/manifest")
  }
  /^```sql[[:space:]]*$/ && !block { block = 1; first = 1; start = NR; body = ""; next }
  block && /^```[[:space:]]*$/ {
    block = 0
    example(start, expected)
    printf "%s", body > file
    close(file)
    expected = ""
    next
  }
  block {
    if (first && index($0, "-- fails with SQLSTATE ") == 1) expected = substr($0, 24, 5)
    first = 0
    body = body $0 "\n"
    next
  }
  /^\|/ {
    rest = $0
    while (match(rest, /`[^`]*`/)) {
      span = substr(rest, RSTART + 1, RLENGTH - 2)
      rest = substr(rest, RSTART + RLENGTH)
      if (span ~ /^(SELECT|SET|CREATE|COPY|RESET) /) {
        example(NR, "")
        print span ";" > file
        close(file)
      }
    }
  }
' "$reference"

total=$(wc -l < "$work/manifest" 2>/dev/null || echo 0)
echo "1..$((total + 1))"
result "$([[ $total -ge 50 ]] && echo 1 || echo 0)" "$reference holds $total examples (at least 50)"

PGOPTIONS='-c client_min_messages=warning' psql -X -q -d postgres -c "DROP DATABASE IF EXISTS $db" \
  -c "CREATE DATABASE $db" > /dev/null || exit 1

while IFS=$'\t' read -r number line expected; do
  file=$work/$number.sql
  what=$(grep -v -m 1 -E '^(--|$)' "$file" | cut -c 1-70)
  # The module loaded from the start, so that SET checks arg.* settings as it would after any
  # call of an arg function (before one, a misspelt name would pass as a placeholder).
  PGOPTIONS='-c session_preload_libraries=arg' \
    psql -X -q -d "$db" -v VERBOSITY=sqlstate -f "$file" > /dev/null 2> "$work/err"
  status=$?
  states=$(grep -oE 'ERROR:  [0-9A-Z]{5}' "$work/err" | cut -c 9- | sort -u | tr '\n' ' ')
  if [[ -z "$expected" ]]; then
    ok=$([[ $status -eq 0 && -z "$states" ]] && echo 1 || echo 0)
    result "$ok" "$reference line $line runs: $what"
  else
    ok=$([[ $status -eq 0 && "$states" == "$expected " ]] && echo 1 || echo 0)
    result "$ok" "$reference line $line fails with $expected: $what"
  fi
  [[ $ok -eq 1 ]] || sed -n '1,8s/^/#   /p' "$work/err"
done < "$work/manifest"

[[ $failed -eq 0 ]]
