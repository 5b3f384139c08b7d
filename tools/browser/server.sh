#!/usr/bin/env bash
# Starts and stops the catalogue browser beside a throwaway cluster (tools/pg/cluster.sh).
#
#   tools/browser/server.sh start DIR    serve DIR's cluster's database (PGDATABASE, default museum)
#                                         on 127.0.0.1 and print the URL; waits until it answers
#   tools/browser/server.sh stop DIR     stop it; safe to call twice, or when it never started
#   tools/browser/server.sh url DIR      print the URL of the running browser
#
# DIR is the cluster's folder (say build/pg-demo): the browser reads DIR/env to reach the server,
# and keeps DIR/browser.pid, DIR/browser.port and its log DIR/browser.log there. It binds
# 127.0.0.1 only; the port of the last run when it is free, else one the kernel picks.
# BROWSER_START_TIMEOUT (seconds, default 60) bounds the wait for the first answer. The 3D view
# runs argtool: ARG_ARGTOOL, else BUILD_DIR/argtool (default build/argtool) of this repository.
set -euo pipefail

usage() { echo "usage: $0 start DIR | stop DIR | url DIR" >&2; exit 2; }
[[ $# -eq 2 ]] || usage
action=$1
here=$(cd "$(dirname "$0")" && pwd -P)
python=${ARG_PYTHON:-/usr/bin/python3}
# The 3D view and the pair pictures run argtool (view-data, render-match) on the stored meshes.
argtool=${ARG_ARGTOOL:-$(cd "$here/../.." && pwd -P)/${BUILD_DIR:-build}/argtool}
if [[ ! -d "$2" ]]; then
  [[ $action == stop ]] && exit 0
  echo "browser: no cluster folder $2 (start the cluster first)" >&2
  exit 1
fi
dir=$(cd "$2" && pwd -P)
pid_file=$dir/browser.pid port_file=$dir/browser.port log=$dir/browser.log

# The browser's process id when it is running: the pid file names a live serve.py (not a
# process that reused the number).
running_pid() {
  local pid
  [[ -f "$pid_file" ]] || return 1
  pid=$(cat "$pid_file")
  [[ "$pid" =~ ^[0-9]+$ ]] && tr '\0' ' ' <"/proc/$pid/cmdline" 2>/dev/null | grep -q 'browser/serve.py' &&
    echo "$pid"
}

# Exit 0 while process $1 exists and has not exited (a zombie not yet reaped counts as exited).
alive() {
  local stat
  stat=$(cat "/proc/$1/stat" 2>/dev/null) || return 1
  stat=${stat##*) }
  [[ ${stat%% *} != Z ]]
}

url() { echo "http://127.0.0.1:$(cat "$port_file")/"; }

# Exit 0 once GET /healthz answers 200 (the pages load and the database answers).
answers() {
  "$python" - "$(url)healthz" <<'PY'
import sys, urllib.request
try:
    with urllib.request.urlopen(sys.argv[1], timeout=5) as response:
        sys.exit(0 if response.status == 200 else 1)
except Exception:
    sys.exit(1)
PY
}

start() {
  if pid=$(running_pid); then
    echo "browser: already running (pid $pid) at $(url)"
    return
  fi
  [[ -f "$dir/env" ]] || { echo "browser: no $dir/env: the cluster in $dir is not running" >&2; exit 1; }
  "$python" -c 'import fastapi, uvicorn, multipart, jinja2, psycopg, numpy' 2>/dev/null || {
    echo "browser: $python lacks FastAPI, uvicorn, python-multipart, Jinja2, psycopg or NumPy (run tools/pg/install_deps.sh)" >&2
    exit 1
  }
  local last=0
  [[ -f "$port_file" ]] && last=$(cat "$port_file")
  rm -f "$port_file"
  # serve.py leaves the caller's session, so that a closing terminal or Ctrl-C does not stop
  # it (make demo-stop does), and keeps this process id.
  (
    # shellcheck disable=SC1091
    source "$dir/env"
    export PGDATABASE=${PGDATABASE:-museum} PYTHONDONTWRITEBYTECODE=1 ARG_ARGTOOL=$argtool
    exec "$python" "$here/serve.py" --port "$last" --port-file "$port_file" </dev/null >"$log" 2>&1
  ) &
  local pid=$! deadline=$((SECONDS + ${BROWSER_START_TIMEOUT:-60}))
  echo "$pid" >"$pid_file"
  until [[ -f "$port_file" ]] && answers; do
    # By its id, not running_pid: until the subshell has exec'd, its command line is this script's.
    if ! alive "$pid"; then
      echo "browser: it stopped while starting; last lines of $log:" >&2
      tail -n 20 "$log" >&2
      rm -f "$pid_file"
      exit 1
    fi
    if ((SECONDS >= deadline)); then
      echo "browser: no answer within ${BROWSER_START_TIMEOUT:-60} s; last lines of $log:" >&2
      tail -n 20 "$log" >&2
      stop
      exit 1
    fi
    sleep 0.2
  done
  echo "browser: running at $(url) (pid $pid, log $log)"
}

stop() {
  local pid
  if pid=$(running_pid); then
    kill -TERM "$pid"
    # uvicorn finishes the requests under way, then exits; a browser that hangs is killed.
    for _ in $(seq 100); do running_pid >/dev/null || break; sleep 0.1; done
    if running_pid >/dev/null; then kill -KILL "$pid"; fi
    echo "browser: stopped ($dir)"
  fi
  rm -f "$pid_file"
}

case "$action" in
  start) start ;;
  stop) stop ;;
  url) running_pid >/dev/null || { echo "browser: not running ($dir)" >&2; exit 1; }; url ;;
  *) usage ;;
esac
