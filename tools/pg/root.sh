#!/usr/bin/env bash
# A Debian root in a folder, made from Debian's archive, for what this machine's own Debian
# cannot test: PostgreSQL 17 on Debian 13, a package installed on a machine with nothing else.
#
#   tools/pg/root.sh make DIR SUITE [PACKAGE...]   debootstrap SUITE (minbase) into DIR once, then
#                                                  apt-get install the packages missing in it
#   tools/pg/root.sh run DIR [--bind PATH]... -- COMMAND...
#                                                  COMMAND inside DIR (as root, /proc /dev /sys
#                                                  mounted; each PATH of this machine at the same
#                                                  path inside), mounts undone afterwards
#   tools/pg/root.sh remove DIR                    undo any mount left and delete DIR
#
# Needs root (or sudo) and debootstrap; reaches only deb.debian.org (DEBIAN_MIRROR overrides).
set -euo pipefail

usage() {
  sed -n '4,10p' "$0" >&2
  exit 2
}
[[ $# -ge 2 ]] || usage
action=$1 dir=$2
shift 2
sudo=()
[[ $(id -u) -eq 0 ]] || sudo=(sudo)
mirror=${DEBIAN_MIRROR:-http://deb.debian.org/debian}

# Every mount under DIR, deepest first.
mounts_under() {
  local real
  real=$(readlink -f "$dir")
  awk -v d="$real" '$2 == d || index($2, d "/") == 1 { print $2 }' /proc/self/mounts | sort -r
}
unmount_all() {
  local m
  for m in $(mounts_under); do "${sudo[@]}" umount -l "$m" 2>/dev/null || true; done
}

# COMMAND inside DIR with the binds asked for.
in_root() {
  local binds=() path
  while [[ $# -gt 0 && "$1" != -- ]]; do
    [[ "$1" == --bind && $# -ge 2 ]] || usage
    binds+=("$(readlink -f "$2")")
    shift 2
  done
  [[ "${1:-}" == -- ]] && shift
  [[ $# -gt 0 ]] || usage
  trap unmount_all EXIT
  "${sudo[@]}" mount -t proc proc "$dir/proc"
  "${sudo[@]}" mount --rbind /dev "$dir/dev"
  "${sudo[@]}" mount --rbind /sys "$dir/sys"
  for path in "${binds[@]}"; do
    "${sudo[@]}" mkdir -p "$dir$path"
    "${sudo[@]}" mount --bind "$path" "$dir$path"
  done
  "${sudo[@]}" cp /etc/resolv.conf "$dir/etc/resolv.conf"
  local status=0
  "${sudo[@]}" chroot "$dir" /usr/bin/env -i HOME=/root TERM="${TERM:-dumb}" LANG=C.UTF-8 \
    PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin DEBIAN_FRONTEND=noninteractive \
    "$@" || status=$?
  unmount_all
  trap - EXIT
  return $status
}

case "$action" in
  make)
    [[ $# -ge 1 ]] || usage
    suite=$1
    shift
    if [[ ! -x "$dir/usr/bin/apt-get" ]]; then
      command -v debootstrap >/dev/null || { echo "root: debootstrap is not installed" >&2; exit 1; }
      unmount_all
      "${sudo[@]}" rm -rf "$dir"
      mkdir -p "$(dirname "$dir")"
      echo "root: debootstrap $suite into $dir"
      "${sudo[@]}" debootstrap --variant=minbase "$suite" "$dir" "$mirror" >"$dir.debootstrap.log" 2>&1 || {
        tail -n 20 "$dir.debootstrap.log" >&2
        exit 1
      }
      # As a Debian machine is set up: the release, its updates and its security fixes.
      printf 'deb %s %s main\ndeb %s %s-updates main\ndeb %s-security %s-security main\n' \
        "$mirror" "$suite" "$mirror" "$suite" "$mirror" "$suite" |
        "${sudo[@]}" tee "$dir/etc/apt/sources.list" >/dev/null
    fi
    [[ $# -gt 0 ]] || exit 0
    missing=()
    for p in "$@"; do
      "${sudo[@]}" chroot "$dir" dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null | grep -qx installed ||
        missing+=("$p")
    done
    [[ ${#missing[@]} -eq 0 ]] && exit 0
    echo "root: installing ${#missing[@]} packages into $dir"
    in_root -- sh -c "apt-get update -q >/dev/null && apt-get install -y -q --no-install-recommends $*" \
      >"$dir.apt.log" 2>&1 || {
      tail -n 20 "$dir.apt.log" >&2
      exit 1
    }
    ;;
  run) in_root "$@" ;;
  remove)
    unmount_all
    "${sudo[@]}" rm -rf "$dir" "$dir.debootstrap.log" "$dir.apt.log"
    ;;
  *) usage ;;
esac
