#!/usr/bin/env bash
# The catalogue browser's suite: a small sample catalogue loaded as the demo loads it, thumbnails,
# the browser started beside the cluster, then tests/browser/browser_checks.py in headless
# Chromium. Prints TAP lines; run by tests/run_all.sh on its throwaway cluster, or alone:
#
#   tools/pg/cluster.sh start build/pg-test && source build/pg-test/env && tests/browser/run_browser_tests.sh
#
# Needs PGHOST/PGPORT/PGUSER of a running cluster with the extension installed, and the build
# (BUILD_DIR, default build: argtool). Uses the databases arg_browser and arg_browser_textured
# (made anew) and $BUILD_DIR/test-browser; stops the browser it started, whatever happens.
# shellcheck disable=SC2317  # the set-up functions below are called through step's "$@"
set -uo pipefail

cd "$(dirname "$0")/../.." || exit 1
build=${BUILD_DIR:-build}
python=${ARG_PYTHON:-/usr/bin/python3}
work=$build/test-browser
mkdir -p "$work"
work=$(cd "$work" && pwd -P)
export PGDATABASE=arg_browser
# Two models per class keeps the load and the thumbnails short; the checks need two per class.
per_class=${BROWSER_TEST_PER_CLASS:-2}

number=0
# One TAP line for a set-up step: step NAME COMMAND... (output kept in the step's log).
step() {
  local name=$1 log
  shift
  number=$((number + 1))
  log=$work/step$number.log
  if "$@" >"$log" 2>&1; then
    echo "ok $number - $name"
  else
    echo "not ok $number - $name"
    sed 's/^/#   /' "$log" | tail -n 15
    echo "# the browser's checks did not run: set-up failed"
    exit 1
  fi
}

# The browser sits beside the cluster, as in the demo: server.sh reads the cluster's env from here.
printf 'PGHOST=%s\nPGPORT=%s\nPGUSER=%s\nexport PGHOST PGPORT PGUSER\n' \
  "${PGHOST:?run on a cluster: source its env}" "${PGPORT:?}" "${PGUSER:-postgres}" >"$work/env"
trap 'tools/browser/server.sh stop "$work" >/dev/null' EXIT

make_database() {
  PGOPTIONS='-c client_min_messages=warning' psql -X -q -d postgres -v ON_ERROR_STOP=1 \
    -c 'DROP DATABASE IF EXISTS arg_browser' -c 'CREATE DATABASE arg_browser'
}

load_catalogue() {
  rm -rf "$work/models"
  "$build/argtool" gen --out "$work/models" --per-class "$per_class" &&
    psql -X -q -v ON_ERROR_STOP=1 -v mode=sample -v dir="$work/models" -v script="$work/import.sql" \
      -v every=1000 -f tools/demo/load.sql <"$work/models/catalogue.csv" &&
    [[ $(psql -X -tAc 'SELECT count(*) FROM objects') -eq \
       $(($(wc -l <"$work/models/catalogue.csv") - 1)) ]]
}

every_thumbnail() {
  "$python" tools/browser/thumbnails.py --argtool "$build/argtool" &&
    [[ $(psql -X -tAc "SELECT count(*) FROM objects WHERE thumbnail IS NULL OR thumbnail_mu IS NULL
                        OR substr(thumbnail, 1, 8) <> '\\x89504e470d0a1a0a'::bytea
                        OR substr(thumbnail_mu, 1, 8) <> '\\x89504e470d0a1a0a'::bytea") -eq 0 ]]
}

start_browser() {
  # The largest sample model stands for one too large to display in 3D.
  ARG_VIEW_MAX_TRIANGLES=$(psql -X -tAc "SELECT max((arg_info(descr)->>'triangles')::int) - 1 FROM objects") &&
    export ARG_VIEW_MAX_TRIANGLES &&
    tools/browser/server.sh stop "$work" && tools/browser/server.sh start "$work"
}

upload_files_pytest() {
  (cd tests/browser && PYTHONDONTWRITEBYTECODE=1 "$python" -m pytest -q -p no:cacheprovider \
     test_upload_files.py test_demo_catalogue.py)
}

# A folder with an OBJ of two materials and a soup, as `make demo MODELS=DIR` loads it, in a database of its
# own: the texture colours the ARG and the thumbnail, each material's image reaches the 3D view,
# and the soup, built on its proxy, is viewed as its own triangles.
textured_folder() {
  local dir=$work/textured
  rm -rf "$dir" && mkdir -p "$dir/models" &&
    "$python" tests/browser/textured_folder.py write "$dir/models" &&
    "$python" tools/demo/catalogue.py "$dir/models" --textures "$dir/textures.csv" >"$dir/catalogue.csv" &&
    PGOPTIONS='-c client_min_messages=warning' psql -X -q -d postgres -v ON_ERROR_STOP=1 \
      -c 'DROP DATABASE IF EXISTS arg_browser_textured' -c 'CREATE DATABASE arg_browser_textured' &&
    PGDATABASE=arg_browser_textured psql -X -q -v ON_ERROR_STOP=1 -v mode=user -v dir="$dir/models" \
      -v script="$dir/import.sql" -v every=1000 -v textures="$dir/textures.csv" \
      -f tools/demo/load.sql <"$dir/catalogue.csv" &&
    PGDATABASE=arg_browser_textured "$python" tools/browser/thumbnails.py --argtool "$build/argtool" &&
    PGDATABASE=arg_browser_textured "$python" tests/browser/textured_folder.py check "$build/argtool"
}

step "what a search by upload accepts: one mesh, an OBJ with its MTL and images, a zip (pytest)" \
  upload_files_pytest
step "a folder loads as the demo loads it: an OBJ's textures, a soup shown as itself" \
  textured_folder
step "a database for the browser's catalogue" make_database
step "the sample catalogue loads as the demo loads it (tools/demo/load.sql)" load_catalogue
step "every model gets PNG thumbnails in the table, own colours and mu (argtool render)" every_thumbnail
step "the browser starts beside the cluster and answers" start_browser

url=$(tools/browser/server.sh url "$work")
echo "# browser at $url; its log: $work/browser.log"
(cd tests/browser && PYTHONDONTWRITEBYTECODE=1 timeout 900 "$python" browser_checks.py \
  --url "$url" --models "$work/models" --first $((number + 1)) --screenshot "$work/grid.png")
status=$?
[[ $status -eq 124 ]] && echo "not ok $((number + 1)) - the browser's checks finished within 900 s"
echo "# screenshot of the grid: $work/grid.png"
exit "$status"
