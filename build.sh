#!/usr/bin/env bash
# rs4sim: set up a Debian 12 machine, build, and run.
#
#   ./build.sh demo    install what is missing, build, run `rs4sim demo`
#   ./build.sh test    install what is missing, build and run every test:
#                        1. ctest (RelWithDebInfo), fastest tier first: unit (one library,
#                           manual clock), integration (master + slaves, CLI), realtime
#                           (wall clock: pty, UDP, benchmark smoke runs)
#                        2. the same under AddressSanitizer + UndefinedBehaviorSanitizer
#                        3. every libFuzzer target, briefly, from its seed corpus (clang)
#   ./build.sh build   install + build only
#
# Environment: JOBS (parallel build jobs, default: nproc), FUZZ_SECONDS (per fuzz target
# in `test`, default 10), RS4SIM_WERROR (warnings are errors, default ON here; a plain
# `cmake` configure leaves them warnings).
set -euo pipefail
cd "$(dirname "$0")"

mode=${1:-}
case "$mode" in demo|test|build) ;; *)
  echo "usage: $0 demo|test|build" >&2; exit 2;;
esac

JOBS=${JOBS:-$(nproc)}
FUZZ_SECONDS=${FUZZ_SECONDS:-10}
RS4SIM_WERROR=${RS4SIM_WERROR:-ON}

packages=(build-essential cmake ninja-build pkg-config libboost-dev libsqlite3-dev
          libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev)
packages+=(libprotobuf-dev protobuf-compiler zlib1g-dev)   # storage/: archive export format, CRC-32
packages+=(libgrpc++-dev protobuf-compiler-grpc)           # rpc/: the control API
[ "$mode" = test ] && packages+=(clang libclang-rt-14-dev tshark python3-grpcio python3-grpc-tools)  # fuzzing, dissector, RPC clients
[ "$mode" = test ] && packages+=(python3-pymodbus mbpoll)  # Polaris: real Modbus RTU clients
[ "$mode" = test ] && packages+=(python3-venv python3-pip python3-setuptools python3-wheel python3-pytest)  # the rs4sim Python package: venv, offline pip install, pytest plugin (docs/rpc.md)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "==> installing: ${missing[*]}"
  sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

configure_and_build() {  # dir, extra cmake args...
  local dir=$1; shift
  cmake -S . -B "$dir" -G Ninja -DRS4SIM_WERROR="$RS4SIM_WERROR" "$@" >/dev/null
  cmake --build "$dir" -j "$JOBS"
}

case "$mode" in
  build)
    configure_and_build build
    ;;
  demo)
    configure_and_build build -DRS4SIM_TESTS=OFF -DRS4SIM_BENCH=OFF
    exec build/app/rs4sim demo
    ;;
  test)
    echo "==> [1/3] build + ctest: unit, integration, realtime"
    configure_and_build build
    for tier in unit integration realtime; do
      echo "--- ctest -L $tier"
      (cd build && ctest -L "^$tier\$" --output-on-failure -j "$JOBS")
    done
    echo "==> [2/3] ASan + UBSan build + ctest"
    # -O1 -g1 (line tables only): the usual sanitizer setting; compiles about twice as fast as
    # -O2 -g and still gives file:line in every report.
    configure_and_build build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRS4SIM_SANITIZE=ON -DRS4SIM_BENCH=OFF \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG"
    (cd build-asan && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
       UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest --output-on-failure -j "$JOBS")
    echo "==> [3/3] libFuzzer targets, ${FUZZ_SECONDS}s each"
    configure_and_build build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRS4SIM_FUZZ=ON \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG"
    fuzz/run_all.sh build-fuzz/fuzz "$FUZZ_SECONDS"
    echo "==> all tests passed"
    ;;
esac
