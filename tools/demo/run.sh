#!/usr/bin/env bash
# The demo: a throwaway cluster, a catalogue of models loaded into a table, one ranking query,
# and a web browser of the catalogue.
#
#   tools/demo/run.sh          the sample catalogue made by `argtool gen` (about 40 models)
#   tools/demo/run.sh DIR      every .off .obj .ply .stl .glb file under DIR instead, with the
#                              metadata of DIR/catalogue.csv when there is one
#                              (tools/demo/catalogue.py)
#
# Environment: BUILD_DIR (default build), QUERY (model_id to rank against, default the first one),
# DEMO_ROWS (rows to print, default 15), DEMO_PER_CLASS (sample models per class, default 5),
# DEMO_PROGRESS_EVERY (a progress line per this many models, default 10).
# The cluster stays up, with the catalogue browser (tools/browser) beside it on 127.0.0.1; `make
# demo-stop` stops both.
set -euo pipefail

cd "$(dirname "$0")/../.."
build=${BUILD_DIR:-build}
pgdir=$build/pg-demo
work=$build/demo
models_dir=${1:-}
# Debian's interpreter, which sees the python3-* packages (another python3 may come first on PATH).
python=${ARG_PYTHON:-/usr/bin/python3}
mkdir -p "$work"
work=$(cd "$work" && pwd -P)

# The catalogue: CSV with header model_id,path,class,inventory_no,title,artist,period,material,
# licence.
textures=()  # the OBJ files' texture images (tools/demo/catalogue.py --textures), for a folder
if [[ -z "$models_dir" ]]; then
  mode=sample
  rm -rf "$work/models"
  echo "demo: generating the sample catalogue"
  "$build/argtool" gen --out "$work/models" --per-class "${DEMO_PER_CLASS:-5}"
  catalogue=$work/models/catalogue.csv
  base=$work/models
else
  mode=user
  [[ -d "$models_dir" ]] || { echo "demo: MODELS=$models_dir is not a directory" >&2; exit 1; }
  base=$(cd "$models_dir" && pwd -P)
  catalogue=$work/user_catalogue.csv
  textures=(-v textures="$work/user_textures.csv")
  "$python" tools/demo/catalogue.py "$base" --textures "$work/user_textures.csv" >"$catalogue" ||
    { echo "demo: no .off .obj .ply .stl or .glb files under $base" >&2; exit 1; }
  echo "demo: $(($(wc -l <"$catalogue") - 1)) mesh files under $base"
fi

tools/pg/cluster.sh start "$pgdir"
# shellcheck disable=SC1091
source "$pgdir/env"
psql -X -q -d postgres -tAc "SELECT 1 FROM pg_database WHERE datname = 'museum'" | grep -q 1 ||
  psql -X -q -d postgres -c 'CREATE DATABASE museum'

echo "demo: loading the catalogue into table objects (database museum)"
# For a user's folder, each file that fails is reported on one line by load.sql; psql's own copy
# of the error goes to a log.
if [[ $mode == user ]]; then exec 3>"$work/load-errors.log"; else exec 3>&2; fi
psql -X -q -d museum -v ON_ERROR_STOP=1 -v mode="$mode" -v dir="$base" \
  -v script="$work/import.sql" -v every="${DEMO_PROGRESS_EVERY:-10}" "${textures[@]}" \
  -f tools/demo/load.sql <"$catalogue" 2>&3 || {
  [[ $mode == user ]] && tail -n 5 "$work/load-errors.log" >&2
  exit 1
}
exec 3>&-
if [[ $(psql -X -q -d museum -tAc 'SELECT count(*) FROM objects') -eq 0 ]]; then
  echo "demo: no model could be loaded" >&2
  exit 1
fi

echo "demo: rendering a thumbnail of each model for the browser (argtool render)"
# A user's model that does not render keeps no picture; the sample must render whole.
keep_going=()
[[ $mode == user ]] && keep_going=(--keep-going)
PGDATABASE=museum "$python" tools/browser/thumbnails.py --argtool "$build/argtool" "${keep_going[@]}"

if [[ -n "${QUERY:-}" ]] && [[ -z $(psql -X -q -d museum -v q="$QUERY" -tA \
  <<<"SELECT 1 FROM objects WHERE model_id = :'q'") ]]; then
  echo "demo: QUERY=$QUERY is not a model_id of the catalogue" >&2
  exit 1
fi
psql -X -q -d museum -v ON_ERROR_STOP=1 -v mode="$mode" -v query="${QUERY:-}" \
  -v rows="${DEMO_ROWS:-15}" -f tools/demo/rank.sql

# The catalogue browser beside the cluster; restarted, so that it reads the cluster just started.
tools/browser/server.sh stop "$pgdir" >/dev/null
tools/browser/server.sh start "$pgdir"

cat <<EOF

The demo cluster is still running (data in $pgdir): database museum, table objects, on
localhost port $PGPORT (no Unix socket). Set the connection in your shell first (PGHOST, PGPORT,
PGUSER, which psql and every libpq client read), then use it:
  source $(cd "$pgdir" && pwd -P)/env
  psql museum -c 'SELECT title, period FROM objects LIMIT 5'
  python3 -c 'import psycopg; print(psycopg.connect(dbname="museum").execute("SELECT count(*) FROM objects").fetchone())'
Browse the catalogue (this machine only): $(tools/browser/server.sh url "$pgdir")
Stop both with: make demo-stop
EOF
