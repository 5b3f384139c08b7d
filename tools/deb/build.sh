#!/usr/bin/env bash
# Binary Debian packages of arg for the PostgreSQL here (make deb): postgresql-<major>-arg (the
# extension and its plug-ins) and argtool, built with debhelper and pg_buildext in a copy of the
# working tree under $BUILD_DIR/deb (debian/ comes from tools/deb/debian). The CMake build of
# $BUILD_DIR is reused, so after `make` only the extension's glue is compiled again. Prints the
# packages' paths.
set -euo pipefail

cd "$(dirname "$0")/../.."
build=$(mkdir -p "${BUILD_DIR:-build}" && cd "${BUILD_DIR:-build}" && pwd -P)
version=$(sed -n "s/^default_version *= *'\(.*\)'/\1/p" extension/arg.control)
out=$build/deb
src=$out/arg-$version
rm -rf "$out"
mkdir -p "$src"
tar -C . --exclude=./build --exclude='./build-*' --exclude=./.git --exclude='*.o' \
  --exclude='*.so' --exclude=.deps --exclude=__pycache__ -cf - . | tar -C "$src" -xf -
cp -r tools/deb/debian "$src/debian"
cat >"$src/debian/changelog" <<CHANGES
arg ($version) unstable; urgency=medium

  * Built from the arg source tree (make deb).

 -- arg developers <arg@localhost>  $(date -R)
CHANGES
# A make that called this passes its command-line variables down in MAKEFLAGS, which would
# override BUILD_DIR in the package build's own makes.
unset MAKEFLAGS MFLAGS MAKEOVERRIDES MAKELEVEL
# A tree not configured yet is configured without tests and benchmarks (packages need neither).
[[ -f "$build/CMakeCache.txt" ]] ||
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DARG_BUILD_TESTS=OFF -DARG_BUILD_BENCH=OFF >/dev/null
(cd "$src" && pg_buildext updatecontrol && BUILD_DIR="$build" dpkg-buildpackage -b -us -uc) \
  >"$out/build.log" 2>&1 || {
  tail -n 40 "$out/build.log"
  echo "deb: the package build failed ($out/build.log)" >&2
  exit 1
}
ls "$out"/*.deb
