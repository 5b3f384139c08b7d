#!/usr/bin/env bash
# The Debian packages installed where nothing else is: a root made from Debian's archive with
# only PostgreSQL (no -dev package but Debian 13's postgresql-common-dev, which its server
# depends on; no compiler), the packages of `make deb` installed with
# apt-get (which brings their Depends from the archive, so missing ones fail here), then the
# extension created, meshes built and ranked in SQL (a proxy build loads arg_vdb.so), argtool
# run from the PATH (a picture loads its arg_image.so), and both removed again. TAP lines.
#
#   tests/packages/deb_install.sh prepare MAJOR   make the clean root only (in the background of
#                                                 make test)
#   tests/packages/deb_install.sh MAJOR DEBS_DIR  the test, with the packages of DEBS_DIR
#
# MAJOR 15 uses Debian 12 (bookworm), 17 Debian 13 (trixie). Roots under ARG_ROOTS (default
# build/roots).
set -uo pipefail

cd "$(dirname "$0")/../.." || exit 1
roots=${ARG_ROOTS:-build/roots}
mode=run
if [[ "${1:-}" == prepare ]]; then mode=prepare; shift; fi
major=${1:?usage: deb_install.sh [prepare] MAJOR [DEBS_DIR]}
case $major in
  15) suite=bookworm ;;
  17) suite=trixie ;;
  *) echo "deb_install: no Debian release with PostgreSQL $major here" >&2; exit 2 ;;
esac
root=$roots/clean-$suite

# A root holds only PostgreSQL: made once, then copied for each run, so that a run starts clean.
template=$roots/clean-$suite-template
mkdir -p "$roots"
# One maker at a time (make test's head start and run_all may overlap): the second waits.
exec 9>"$template.lock"
flock 9
if [[ ! -f "$template/.ready" ]]; then
  tools/pg/root.sh make "$template" "$suite" "postgresql-$major" >/dev/null || {
    echo "deb_install: cannot make the clean Debian $suite root" >&2
    exit 1
  }
  touch "$template/.ready"
fi
flock -u 9
[[ $mode == prepare ]] && exit 0

debs=${2:?usage: deb_install.sh MAJOR DEBS_DIR}
n=0 failed=0
check() {  # check DESCRIPTION COMMAND...
  local out
  n=$((n + 1))
  if out=$("${@:2}" 2>&1); then
    echo "ok $n - $1"
  else
    failed=$((failed + 1))
    echo "not ok $n - $1"
    printf '%s\n' "$out" | tail -n 15 | sed 's/^/#   /'
  fi
}
in_root() { tools/pg/root.sh run "$root" -- "$@"; }
sql() { in_root runuser -u postgres -- psql -X -q -v ON_ERROR_STOP=1 -tA -d arg_check "$@"; }
same() { [[ "$1" == "$2" ]] || { echo "expected: $1"; echo "got:      $2"; return 1; }; }

tools/pg/root.sh remove "$root"
cp -a "$template" "$root"
mkdir -p "$root/tmp/debs"
cp "$debs"/postgresql-"$major"-arg_*.deb "$debs"/argtool_*.deb "$root/tmp/debs/"

check "the clean root has PostgreSQL $major and no compiler or -dev package" in_root sh -c \
  "test -x /usr/lib/postgresql/$major/bin/postgres && ! command -v gcc && ! command -v g++ &&
   ! dpkg-query -W -f='\${Package} \${db:Status-Status}\n' | grep -E -- '-dev installed' | grep -v '^postgresql-common-dev '"
check "apt-get installs postgresql-$major-arg and argtool from their .deb files" in_root sh -c \
  "apt-get update -q >/dev/null && apt-get install -y -q --no-install-recommends /tmp/debs/*.deb"
check "still no compiler or -dev package: the Depends are runtime libraries" in_root sh -c \
  "! command -v gcc && ! command -v g++ &&
   ! dpkg-query -W -f='\${Package} \${db:Status-Status}\n' | grep -E -- '-dev installed' | grep -v '^postgresql-common-dev '"
check "argtool is on the PATH" in_root sh -c "command -v argtool && argtool --version"
check "argtool generates a model and renders it (its image plug-in)" in_root sh -c \
  "argtool gen --out /tmp/models --per-class 1 >/dev/null &&
   argtool render /tmp/models/cup_00.off -o /tmp/cup.png && test -s /tmp/cup.png"

# A cluster of the package's PostgreSQL, as an administrator would have it.
in_root sh -c "pg_lsclusters -h | grep -q '^$major main' || pg_createcluster $major main >/dev/null" &&
  in_root pg_ctlcluster "$major" main start
check "the cluster runs" in_root runuser -u postgres -- psql -X -q -tA -c "SELECT 1"
in_root runuser -u postgres -- psql -X -q -c "CREATE DATABASE arg_check" >/dev/null
check "CREATE EXTENSION arg CASCADE" sql -c "CREATE EXTENSION arg CASCADE"
check "the library and the SQL scripts agree" same "arg 0.3.0 (binary format 3)" "$(sql -c "SELECT arg_version()")"
check "meshes build, index and rank; a proxy build loads arg_vdb.so" same "6|1|true" "$(sql -c "
  CREATE TABLE objects (id int PRIMARY KEY, class text, mesh bytea,
                        descr arg GENERATED ALWAYS AS (arg_build(mesh)) STORED);
  INSERT INTO objects SELECT i, c, arg_generate_model(c, i::int, 12)
  FROM unnest(ARRAY['cup', 'vase', 'human', 'chair', 'torus', 'cup']) WITH ORDINALITY AS t(c, i);
  CREATE INDEX ON objects USING arg_ivf (descr);
  SET enable_seqscan = off;
  SELECT count(*),
         (SELECT id FROM objects ORDER BY descr <~> (SELECT descr FROM objects WHERE id = 1) LIMIT 1),
         (SELECT arg_info(arg_build(mesh, 'surface=proxy'))->>'proxy' FROM objects WHERE id = 1)
  FROM objects")"
check "DROP EXTENSION arg" sql -c "DROP TABLE objects; DROP EXTENSION arg; DROP EXTENSION cube"
in_root pg_ctlcluster "$major" main stop
check "apt-get removes both packages" in_root apt-get remove -y -q "postgresql-$major-arg" argtool
check "no file of theirs is left" in_root sh -c \
  "test ! -e /usr/lib/postgresql/$major/lib/arg.so && test ! -e /usr/lib/postgresql/$major/lib/arg_vdb.so &&
   test ! -e /usr/share/postgresql/$major/extension/arg.control && test ! -e /usr/bin/argtool &&
   test ! -e /usr/lib/argtool"
tools/pg/root.sh remove "$root"
echo "1..$n"
[[ $failed -eq 0 ]]
