#!/usr/bin/env bash
# A project-owned throwaway PostgreSQL cluster: data under the build tree, localhost only.
#
#   tools/pg/cluster.sh start DIR [--fresh]   init (once, or anew with --fresh) and start on a free port
#   tools/pg/cluster.sh stop DIR [--remove]   stop it (and delete its data); safe to call twice
#   tools/pg/cluster.sh status DIR            exit 0 when it is running
#   tools/pg/cluster.sh log-path DIR          print where its server log is (fails when none is)
#   tools/pg/cluster.sh set DIR NAME=VALUE...  start it if needed, ALTER SYSTEM each setting it
#                                             does not have yet and restart it when one changed
#                                             (a benchmark's shared_buffers, say)
#
# DIR/env holds PGHOST, PGPORT, PGUSER for clients (source it). The server listens on localhost
# only, has no Unix socket, and trusts local TCP connections: it is for tests and the demo, never
# for data anyone keeps. initdb and postgres refuse to run as root, so as root the cluster runs as
# the `postgres` system user (created by the postgresql-15 package); when that user cannot reach
# DIR (say the checkout is under /root), the data directory lives in /tmp and DIR/data links to it.
# The server log (postgres.log) is beside the data directory, so in /tmp too while the cluster
# exists: read it through `log-path`. A fresh cluster starts a fresh log; `stop --remove` keeps a
# copy of the last one in DIR.
set -euo pipefail

usage() {
  echo "usage: $0 start DIR [--fresh] | stop DIR [--remove] | status DIR | log-path DIR |" \
    "set DIR NAME=VALUE..." >&2
  exit 2
}
[[ $# -ge 2 ]] || usage
action=$1
settings=()
if [[ "$action" == set ]]; then
  settings=("${@:3}")
  [[ ${#settings[@]} -gt 0 ]] || usage
  set -- "$1" "$2"
fi
if [[ "$action" == start || "$action" == set ]]; then mkdir -p "$2"; elif [[ ! -d "$2" ]]; then
  [[ "$action" == log-path ]] && echo "cluster: no cluster in $2 (no such folder), so no server log" >&2
  [[ "$action" == stop ]] && exit 0 || exit 1
fi
dir=$(cd "$2" && pwd -P)
fresh=0 remove=0
case "${3:-}" in --fresh) fresh=1 ;; --remove) remove=1 ;; "") ;; *) usage ;; esac

pg_config=${PG_CONFIG:-/usr/lib/postgresql/15/bin/pg_config}
[[ -x "$pg_config" ]] || pg_config=$(command -v pg_config) || { echo "cluster: pg_config not found" >&2; exit 1; }
bindir=$("$pg_config" --bindir)

# Runs a server program as the cluster's owner, from a directory that owner can read.
if [[ $(id -u) -eq 0 ]]; then
  id postgres >/dev/null 2>&1 || { echo "cluster: no 'postgres' user (install postgresql-15)" >&2; exit 1; }
  as_owner() { (cd / && runuser -u postgres -- "$@"); }
else
  as_owner() { (cd / && "$@"); }
fi

data_dir() { if [[ -e "$dir/data" ]]; then readlink -f "$dir/data"; else echo "$dir/data"; fi; }

is_running() {
  local data
  data=$(data_dir)
  [[ -f "$data/postmaster.pid" ]] && as_owner "$bindir/pg_ctl" -D "$data" status >/dev/null 2>&1
}

# True when something listens on TCP port $1 (any address), read from /proc: no extra tools.
port_in_use() {
  local hex
  hex=$(printf ':%04X' "$1")
  awk -v h="$hex" 'FNR > 1 && $4 == "0A" && substr($2, length($2) - 4) == h { found = 1 }
                   END { exit !found }' /proc/net/tcp /proc/net/tcp6 2>/dev/null
}

# A free port below the kernel's ephemeral range; prefers $1 (the port used last time).
free_port() {
  local port=${1:-}
  if [[ -n "$port" ]] && ! port_in_use "$port"; then echo "$port"; return; fi
  for _ in $(seq 200); do
    port=$((15000 + RANDOM % 17000))
    port_in_use "$port" || { echo "$port"; return; }
  done
  echo "cluster: no free port found" >&2
  return 1
}

init_cluster() {
  local root=$dir
  if [[ $(id -u) -eq 0 ]]; then
    chown postgres: "$dir"
    if ! runuser -u postgres -- test -w "$dir" 2>/dev/null; then
      # The postgres user cannot traverse to the build tree: keep the data in /tmp, keyed by DIR.
      root=/tmp/arg-pg-$(printf '%s' "$dir" | cksum | cut -d' ' -f1)
      rm -rf "$root"
      mkdir -p "$root"
      chown postgres: "$root"
      chmod 700 "$root"
    fi
  fi
  rm -rf "$dir/data"
  # pg_ctl appends to its log: without this, a crash of an earlier cluster would stay in it, and
  # a copy left in DIR by `stop --remove` would be taken for the new cluster's log.
  rm -f "$dir/postgres.log" "$root/postgres.log"
  [[ "$root" == "$dir" ]] || ln -s "$root/data" "$dir/data"
  as_owner "$bindir/initdb" -D "$root/data" -U postgres --auth=trust --no-locale --encoding=UTF8 \
    --no-sync >"$dir/initdb.log" 2>&1 || { cat "$dir/initdb.log" >&2; exit 1; }
  cat >>"$root/data/postgresql.conf" <<'CONF'

# Throwaway cluster of the arg project (tools/pg/cluster.sh): localhost only, no socket, no fsync.
listen_addresses = 'localhost'
unix_socket_directories = ''
fsync = off
synchronous_commit = off
full_page_writes = off
max_connections = 30
logging_collector = off
log_min_messages = warning
CONF
}

start() {
  if is_running; then
    echo "cluster: already running on port $(cat "$dir/port") ($dir)"
    return
  fi
  if [[ $fresh -eq 1 || ! -f "$(data_dir)/PG_VERSION" ]]; then init_cluster; fi
  local data log last="" port attempt
  data=$(data_dir)
  log=$(dirname "$data")/postgres.log
  [[ -f "$dir/port" ]] && last=$(cat "$dir/port")
  for attempt in 1 2 3 4 5; do
    port=$(free_port "$last")
    last=""
    # One malloc arena: glibc otherwise gives a build's worker thread a new arena whenever two
    # threads happen to contend, a step of 20-25 MB in a backend's private memory that the
    # leak check (tests/pgtap/03_memory.sql) saw on some runs and not others.
    if as_owner env MALLOC_ARENA_MAX=1 "$bindir/pg_ctl" -D "$data" -l "$log" -w -t 60 \
         -o "-p $port" start >/dev/null; then
      printf 'PGHOST=localhost\nPGPORT=%s\nPGUSER=postgres\nexport PGHOST PGPORT PGUSER\n' "$port" \
        >"$dir/env"
      echo "$port" >"$dir/port"
      echo "cluster: running on localhost:$port ($dir)"
      return
    fi
    # Another process may have taken the port between the check and the bind: try another one.
    grep -q 'could not bind\|could not create any TCP/IP sockets' "$log" 2>/dev/null || break
    echo "cluster: port $port was taken, retrying (attempt $attempt)" >&2
  done
  echo "cluster: could not start; last lines of $log:" >&2
  tail -n 20 "$log" >&2 || true
  exit 1
}

stop() {
  [[ -e "$dir/data" ]] || return 0
  local data
  data=$(data_dir)
  if [[ -f "$data/postmaster.pid" ]]; then
    as_owner "$bindir/pg_ctl" -D "$data" -m fast -w -t 60 stop >/dev/null 2>&1 ||
      as_owner "$bindir/pg_ctl" -D "$data" -m immediate -w -t 30 stop >/dev/null 2>&1 || true
  fi
  if is_running; then
    echo "cluster: could not stop the server in $data" >&2
    exit 1
  fi
  rm -f "$dir/env"
  if [[ $remove -eq 1 ]]; then
    # The data goes; the server log stays in DIR (copied there first when the data was in /tmp).
    if [[ -L "$dir/data" ]]; then
      cp "$(dirname "$data")/postgres.log" "$dir/postgres.log" 2>/dev/null || true
      rm -rf "$(dirname "$data")"
    fi
    rm -rf "$dir/data"
  fi
  echo "cluster: stopped ($dir)"
}

# The log the server of DIR writes (pg_ctl -l in start): beside the data directory, wherever
# that is. Fails, saying where it looked, when there is no such file.
log_path() {
  local data log
  data=$(data_dir) || data=""
  if [[ -z "$data" ]]; then
    echo "cluster: the data directory of $dir is gone ($dir/data links nowhere), so no server log" >&2
    exit 1
  fi
  log=$(dirname "$data")/postgres.log
  if [[ ! -f "$log" ]]; then
    echo "cluster: no server log at $log (the cluster in $dir was never started, or was removed)" >&2
    exit 1
  fi
  echo "$log"
}

# ALTER SYSTEM for each NAME=VALUE whose current value differs, then a restart (most such
# settings, shared_buffers among them, take effect only then).
set_settings() {
  start >/dev/null
  local setting name value changed=0
  local sql=(psql -X -q -tA -v ON_ERROR_STOP=1 -h localhost -p "$(cat "$dir/port")" -U postgres -d postgres)
  for setting in "${settings[@]}"; do
    name=${setting%%=*} value=${setting#*=}
    [[ "$name" =~ ^[a-z_.]+$ && "$setting" == *=* ]] || { echo "cluster: not NAME=VALUE: $setting" >&2; exit 2; }
    [[ $("${sql[@]}" -c "SELECT current_setting('$name')") == "$value" ]] && continue
    "${sql[@]}" -c "ALTER SYSTEM SET $name = '${value//\'/\'\'}'" || exit 1
    changed=1
  done
  if [[ $changed -eq 1 ]]; then
    stop >/dev/null
    start
  else
    echo "cluster: running on localhost:$(cat "$dir/port") ($dir), settings as asked"
  fi
}

case "$action" in
  start) start ;;
  set) set_settings ;;
  stop) stop ;;
  status) is_running ;;
  log-path) log_path ;;
  *) usage ;;
esac
