#!/usr/bin/env bash
# The README's two commands in the README's order: `./build.sh demo` leaves a tree without
# tests, and `./build.sh test` on that same tree must turn them on again (a cache that kept
# RS4SIM_TESTS=OFF once made `test` run no test at all and pass). Configures a scratch tree
# as each mode does (`build.sh configure MODE DIR`: no install, no build) and reads the cache;
# checks that every ctest call of build.sh fails on an empty selection.
#   build_modes_test.sh SOURCE_DIR
set -euo pipefail
src=$1
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
tree=$scratch/build

cache() {  # variable -> its value in the scratch tree's cache
  sed -n "s/^$1:[A-Z]*=//p" "$tree/CMakeCache.txt"
}
expect() {  # what, variable, value
  local got
  got=$(cache "$2")
  if [ "$got" != "$3" ]; then
    echo "FAIL: $1: $2 is '$got', expected '$3'"; exit 1
  fi
  echo "ok: $1: $2=$3"
}

"$src/build.sh" configure demo "$tree"
expect "demo" RS4SIM_TESTS OFF
expect "demo" RS4SIM_BENCH OFF
expect "demo" CMAKE_CXX_COMPILER_LAUNCHER ccache

"$src/build.sh" configure test "$tree"
expect "test after demo" RS4SIM_TESTS ON
expect "test after demo" RS4SIM_BENCH ON
# the tiers have tests in the tree (ctest lists them without building)
for tier in unit integration realtime; do
  (cd "$tree" && ctest -N -L "^$tier\$" --no-tests=error >/dev/null) \
    || { echo "FAIL: test after demo: no $tier test in the tree"; exit 1; }
  echo "ok: test after demo: the $tier tier has tests"
done

"$src/build.sh" configure demo "$tree"
expect "demo after test" RS4SIM_TESTS OFF

# Every ctest call of build.sh fails when its selection is empty.
calls=$(grep -nE '(^|&&|\() *ctest ' "$src/build.sh" | grep -v '^[0-9]*: *#')
[ -n "$calls" ] || { echo "FAIL: no ctest call found in build.sh"; exit 1; }
if grep -v -- '--no-tests=error' <<<"$calls"; then
  echo "FAIL: a ctest call above runs without --no-tests=error"; exit 1
fi
echo "ok: every ctest call of build.sh has --no-tests=error"
