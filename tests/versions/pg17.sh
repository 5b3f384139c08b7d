#!/usr/bin/env bash
# The SQL suites against PostgreSQL 17, in a Debian 13 (trixie) root made from Debian's archive
# (tools/pg/root.sh): the working tree copied into the root (/src: PGXS builds its objects beside
# the sources, so the two servers' builds must not share a tree), the extension built there
# against PostgreSQL 17's headers with Debian 13's libraries, then pg_regress, pgTAP, the reference examples, the round trips and the upgrade
# from 0.1.0 on a throwaway PostgreSQL 17 cluster inside the root (tests/run_all.sh with
# ARG_SUITES=sql). Ends with the inner run's "N passed, N failed".
#
#   tests/versions/pg17.sh root      make the root only (make test starts it before its build)
#   tests/versions/pg17.sh prepare   make the root and build there (no test); for a head start
#   tests/versions/pg17.sh           prepare if needed, then run the suites
#   tests/versions/pg17.sh deb       prepare if needed, then `make deb` in the root: the
#                                    packages for PostgreSQL 17 on Debian 13, in
#                                    ROOT/src/build-pg17/deb (their paths are printed)
#
# Environment: ARG_ROOTS (default build/roots), BUILD_DIR of the outer build (default build);
# the build inside the root goes to build-pg17/.
set -uo pipefail

cd "$(dirname "$0")/../.." || exit 1
src=/src  # the copy of the working tree inside the root
roots=${ARG_ROOTS:-build/roots}
root=$roots/trixie
inner_build=build-pg17
pg_config=/usr/lib/postgresql/17/bin/pg_config
packages=(
  # the server, its headers, pgTAP
  postgresql-17 postgresql-server-dev-17 postgresql-17-pgtap libtap-parser-sourcehandler-pgtap-perl
  # what the extension's libraries are built from, as in tools/pg/install_deps.sh
  libeigen3-dev libopenmesh-dev libtinygltf-dev nlohmann-json3-dev libstb-dev libopenimageio-dev
  libcli11-dev zlib1g-dev libopenvdb-dev libboost-dev libtbb-dev libspectra-dev
  cmake g++ make
  # make deb
  build-essential debhelper dpkg-dev postgresql-server-dev-all
)

# One maker of the root at a time (the head start and a later run may overlap): the second
# waits for the first, then finds the root made.
make_root() {
  flock "$root.lock" tools/pg/root.sh make "$root" trixie "${packages[@]}"
}

prepare() {
  make_root || return 1
  # The working tree, without this machine's builds; tar keeps the files' times, so an
  # unchanged source is not rebuilt.
  mkdir -p "$root$src"
  tar -C . --exclude=./build --exclude='./build-*' --exclude=./.git --exclude='*.o' \
    --exclude='*.so' --exclude=.deps --exclude=__pycache__ -cf - . | tar -C "$root$src" -xf - ||
    return 1
  # The core's libraries and the plug-ins (no tests, tools or benchmarks), then the extension.
  tools/pg/root.sh run "$root" -- sh -c "
    cd '$src' &&
    cmake -S . -B $inner_build -DCMAKE_BUILD_TYPE=Release -DARG_BUILD_TESTS=OFF \
      -DARG_BUILD_BENCH=OFF ${CI:+-DARG_WERROR=ON} >/dev/null &&
    make --no-print-directory -j\$(nproc) BUILD_DIR=$inner_build PG_CONFIG=$pg_config ${CI:+CI=true} all &&
    make --no-print-directory BUILD_DIR=$inner_build PG_CONFIG=$pg_config ARG_NO_CMAKE=1 install
  " >"$roots/pg17-build.log" 2>&1 || {
    tail -n 40 "$roots/pg17-build.log"
    echo "pg17: the build in the Debian 13 root failed ($roots/pg17-build.log)"
    return 1
  }
}

mkdir -p "$roots"
if [[ "${1:-}" == root ]]; then
  make_root
  exit
fi
if [[ "${1:-}" == prepare ]]; then
  prepare
  exit
fi
if [[ "${1:-}" == deb ]]; then
  prepare || exit 1
  tools/pg/root.sh run "$root" -- sh -c "
    cd '$src' && make --no-print-directory BUILD_DIR=$inner_build PG_CONFIG=$pg_config deb
  " | sed "s|^$src/|$root$src/|"
  exit "${PIPESTATUS[0]}"
fi
# Again after a head start: an up-to-date build costs seconds.
prepare || { echo "0 passed, 1 failed"; exit 1; }
tools/pg/root.sh run "$root" -- sh -c "
  cd '$src' && ARG_SUITES=sql BUILD_DIR=$inner_build PG_CONFIG=$pg_config tests/run_all.sh
"
