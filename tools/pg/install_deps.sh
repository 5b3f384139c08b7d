#!/usr/bin/env bash
# Installs the Debian packages the project needs, only when one of them is missing.
#
#   tools/pg/install_deps.sh          what every test needs (make test)
#   tools/pg/install_deps.sh --demo   only what the demo builds and runs (make demo): no test
#                                     tools, sanitizers, fuzzers or browser for tests
#
# Runs apt-get update first; uses sudo only when not root. ARG_SKIP_DEPS=1 skips the check.
# Then the browser's JavaScript from npm, pinned by tools/browser/package-lock.json.
set -euo pipefail

demo_packages=(
  # server, headers for PGXS, contrib (cube)
  postgresql-15 postgresql-server-dev-15 postgresql-contrib
  # core libraries (zlib checks PNG chunk checksums; tinygltf's header needs nlohmann-json and stb, which its package does not pull in)
  libeigen3-dev libopenmesh-dev libtinygltf-dev nlohmann-json3-dev libstb-dev libopenimageio-dev
  libcli11-dev zlib1g-dev
  # OpenVDB (distance fields of the watertight proxy); its headers also need Boost's and TBB's
  libopenvdb-dev libboost-dev libtbb-dev
  # Spectra (header-only eigen-solver of the Laplace-Beltrami spectrum)
  libspectra-dev
  # build tools
  cmake g++ make
  # the Python client (clients/python) and the catalogue browser (tools/browser): Debian's
  # packages, as PyPI is not used
  python3-psycopg python3-numpy python3-fastapi python3-uvicorn python3-multipart python3-jinja2
  # the browser's 3D view: three.js from the npm registry (tools/browser/install_js.sh)
  npm
)
test_packages=(
  # pgTAP and pg_prove
  postgresql-15-pgtap libtap-parser-sourcehandler-pgtap-perl
  # unit tests, benchmarks, formatting
  clang-format libgtest-dev libbenchmark-dev
  # the client's tests; the browser's test in headless Chromium (Pillow decodes its screenshot)
  python3-pytest python3-selenium chromium chromium-driver python3-pil
  # libFuzzer targets and the sanitizer runtimes (tests/fuzz)
  clang libclang-rt-14-dev
  # Debian roots for PostgreSQL 17 (Debian 13) and the packages' clean installs (tools/pg/root.sh)
  debootstrap
  # make deb: Debian's tools for packages of PostgreSQL extensions
  build-essential debhelper dpkg-dev postgresql-server-dev-all
)

if [[ "${ARG_SKIP_DEPS:-0}" == 1 ]]; then exit 0; fi
packages=("${demo_packages[@]}")
[[ "${1:-}" == --demo ]] || packages+=("${test_packages[@]}")

missing=()
for p in "${packages[@]}"; do
  # Any npm will do: a Node.js from elsewhere (NodeSource's conflicts with Debian's npm).
  [[ $p == npm ]] && command -v npm >/dev/null && continue
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  [[ "$status" == installed ]] || missing+=("$p")
done

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "deps: all ${#packages[@]} packages present"
  exec "$(dirname "$0")/../browser/install_js.sh"
fi

sudo=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "deps: missing ${missing[*]}; run as root or install sudo" >&2; exit 1; }
  sudo=(sudo)
fi

echo "deps: installing ${missing[*]}"
"${sudo[@]}" apt-get update -q
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y -q --no-install-recommends "${missing[@]}"
"$(dirname "$0")/../browser/install_js.sh"
