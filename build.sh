#!/usr/bin/env bash
# rs4sim: set up a Debian 12 machine, build, and run.
#
#   ./build.sh demo    install what is missing, build, run `rs4sim demo`
#   ./build.sh test    install what is missing, build and run every test:
#                        1. ctest (RelWithDebInfo), fastest tier first: unit (one library,
#                           manual clock), integration (master + slaves, CLI), realtime
#                           (wall clock: pty, UDP, benchmark smoke runs)
#                        2. clang, AddressSanitizer + UndefinedBehaviorSanitizer: every tier
#                           again (one build, the fuzz targets in it too)
#                        3. every libFuzzer target, briefly, from its seed corpus
#   ./build.sh build   install + build only
#   ./build.sh deps    install what `test` needs, run the preflight; no build (a fresh
#                      machine's check: tools/fresh_machine_check.sh)
#   ./build.sh configure MODE DIR
#                      configure DIR as MODE (demo, test, build) would, nothing else (the
#                      check of the modes: tests/tools/build_modes_test.sh)
#
# Every mode configures the tree it builds with everything that mode needs, whatever an
# earlier mode left in the tree's cache: `demo` then `test` builds and runs every tier.
# All modes compile the same way (-O2, line tables), so `test` after `demo` only adds the
# tests and benchmarks. Every build goes through ccache, set up so that another clone of
# the same commit hits the objects of this one (docs/ci.md).
#
# `test` and `deps` install the packages of tools/preflight.sh's table (what the tests import
# or call, each beside the test that needs it, what a dependency only recommends included)
# and run that preflight before anything is built: it names what is missing and its package.
#
# Environment: JOBS (parallel build jobs, default: nproc), FUZZ_SECONDS (per fuzz target
# in `test`, default 3), RS4SIM_WERROR (warnings are errors, default ON here; a plain
# `cmake` configure leaves them warnings).
set -euo pipefail
cd "$(dirname "$0")"

usage() { echo "usage: $0 demo|test|build|deps  (or: $0 configure demo|test|build DIR)" >&2; exit 2; }
mode=${1:-}
case "$mode" in demo|test|build|deps|configure) ;; *) usage ;; esac

JOBS=${JOBS:-$(nproc)}
FUZZ_SECONDS=${FUZZ_SECONDS:-3}
RS4SIM_WERROR=${RS4SIM_WERROR:-ON}

packages=(build-essential cmake ninja-build ccache pkg-config libboost-dev libsqlite3-dev
          libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev)
packages+=(libprotobuf-dev protobuf-compiler zlib1g-dev)   # storage/: archive export format, CRC-32
packages+=(libgrpc++-dev protobuf-compiler-grpc)           # rpc/: the control API
packages+=(libpq-dev)                                      # storage/: the PostgreSQL archive (libpq)
packages+=(libssl-dev)                                     # http/: HTTPS (Boost.Asio SSL on OpenSSL)
case "$mode" in test|deps) testing=true ;; *) testing=false ;; esac
if $testing; then
  # the tests' packages (fuzzing, dissector, gRPC and Modbus clients, ...): the preflight's table
  test_packages=$(tools/preflight.sh --packages)
  # shellcheck disable=SC2206  # one package name a line
  packages+=($test_packages)
fi

missing=()
[ "$mode" = configure ] && packages=()   # configure only: nothing is installed
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "==> installing: ${missing[*]}"
  sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

if $testing; then
  tools/preflight.sh
fi

# The compiler cache: paths under the source folder are hashed relative to it and the
# working folder is left out, so a fresh clone elsewhere hits this one's objects (test data
# paths reach the tests relative to their executable, and the unity batches include their
# files by relative path: tests/CMakeLists.txt). CCACHE_DIR keeps ccache's own default.
export CCACHE_BASEDIR=$PWD CCACHE_NOHASHDIR=1 CCACHE_MAXSIZE=${CCACHE_MAXSIZE:-20G}

# The cmake arguments of a mode, into the array `args`; every mode states every option it
# depends on, so what an earlier mode left in a tree's cache never decides.
mode_args() {  # mode
  args=(-G Ninja -DRS4SIM_WERROR="$RS4SIM_WERROR" -DCMAKE_BUILD_TYPE=RelWithDebInfo
        -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  # -g1 (line tables): every backtrace still has file:line; full -g costs a third of the
  # build time here for nothing a test run reads.
  local gcc=(-DCMAKE_CXX_COMPILER=g++ -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG"
             -DRS4SIM_FUZZ=OFF -DRS4SIM_SANITIZE=OFF)
  case "$1" in
    demo) args+=("${gcc[@]}" -DRS4SIM_TESTS=OFF -DRS4SIM_BENCH=OFF) ;;
    test|build) args+=("${gcc[@]}" -DRS4SIM_TESTS=ON -DRS4SIM_BENCH=ON) ;;
    # One clang build serves the sanitizers and the fuzzers (stage 2 of `test`).
    asan) args+=(-DCMAKE_CXX_COMPILER=clang++ -DRS4SIM_FUZZ=ON -DRS4SIM_TESTS=ON
                 -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG") ;;
    *) usage ;;
  esac
}

configure() {  # dir, mode
  local args
  mode_args "$2"
  cmake -S . -B "$1" "${args[@]}" >/dev/null
}

configure_and_build() {  # dir, mode
  configure "$1" "$2"
  cmake --build "$1" -j "$JOBS"
}

case "$mode" in
  configure)
    [ $# -eq 3 ] || usage
    configure "$3" "$2"
    ;;
  build)
    configure_and_build build build
    ;;
  deps)
    ;;
  demo)
    configure_and_build build demo
    exec build/app/rs4sim demo
    ;;
  test)
    # Where the time goes is printed per stage (CI's breakdown: docs/ci.md).
    stage_start=$SECONDS
    stage_done() { echo "==> $1: $((SECONDS - stage_start)) s"; stage_start=$SECONDS; }
    # ./build.sh test installed PostgreSQL's server programs: the PostgreSQL half of the
    # archive tests must run, a server that does not start is a failure (never a skip).
    export RS4SIM_REQUIRE_POSTGRES=1
    ccache --zero-stats >/dev/null
    echo "==> [1/3] build + ctest: unit, integration, realtime"
    configure_and_build build test
    stage_done "build"
    for tier in unit integration realtime; do
      echo "--- ctest -L $tier"
      # A selection that finds no test is a broken build, not a pass.
      (cd build && ctest -L "^$tier\$" --no-tests=error --output-on-failure -j "$JOBS")
      stage_done "ctest -L $tier"
    done
    echo "==> [2/3] clang: ASan + UBSan build (with the libFuzzer targets) + ctest, every tier"
    # One clang build serves the sanitizers and the fuzzers; every test runs again here, the
    # realtime tier too (pty, UDP, processes: the rs4sim they start is the instrumented one).
    configure_and_build build-asan asan
    stage_done "sanitizer build"
    (cd build-asan && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
       UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
       ctest -L '^(unit|integration|realtime)$' --no-tests=error --output-on-failure -j "$JOBS")
    stage_done "sanitizer ctest"
    echo "==> [3/3] libFuzzer targets, ${FUZZ_SECONDS}s each, $JOBS at a time"
    JOBS=$JOBS fuzz/run_all.sh build-asan/fuzz "$FUZZ_SECONDS"
    stage_done "fuzz"
    echo "==> compiler cache: $(ccache --print-stats | awk -F'\t' '$1=="direct_cache_hit"||$1=="preprocessed_cache_hit"{h+=$2} $1=="cache_miss"{m=$2} END{printf "%d hits, %d misses", h, m}')"
    echo "==> all tests passed"
    ;;
esac
