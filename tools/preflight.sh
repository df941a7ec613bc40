#!/bin/sh
# What the tests import or call, checked before they run: every Python module (with the
# interpreter ctest runs, /usr/bin/python3), external command and file of the table below,
# with the Debian package that provides it. `./build.sh test` and `./build.sh deps` install
# the table's packages (tools/preflight.sh --packages) and then run this check; it fails at
# once, naming what is missing and its package, instead of a test failing later with a
# traceback.
#
#   tools/preflight.sh              check; exit 0 when all is there, 1 listing what is missing
#   tools/preflight.sh --packages   the table's Debian packages, one a line
#   tools/preflight.sh --list       the table: kind, name, package
#
# Environment: RS4SIM_PYTHON, the interpreter whose modules are checked (default
# /usr/bin/python3). The check itself uses shell builtins only (it works with any PATH).
set -u
python=${RS4SIM_PYTHON:-/usr/bin/python3}

# One row per thing a test needs: kind (python: a module importable by $python; command: on
# PATH or an absolute path; file: a path pattern with at least one match), name, Debian
# package, who needs it. A package a dependency only recommends gets its own row (build.sh
# installs with --no-install-recommends).
table='
python  grpc               python3-grpcio          rpc_python_*, cli_rs232_scenario2: the gRPC client (the rs4sim package, python/)
python  google.protobuf    python3-protobuf        the rs4sim package: the message classes of its stubs
python  pymodbus.client    python3-pymodbus        cli_run_polaris_modbus_clients: a real Modbus RTU client
python  serial             python3-serial          pymodbus serial client (python3-pymodbus only recommends it)
python  serial_asyncio     python3-serial-asyncio  pymodbus serial client (python3-pymodbus only recommends it)
python  pytest             python3-pytest          rpc_python_pytest_*: the pytest plugin of the package
python  ensurepip          python3-venv            python3 -m venv for the Python package tests
python  setuptools         python3-setuptools      the Python package build backend
python  wheel              python3-wheel           the package build by pip (bdist_wheel)
python  pip                python3-pip             python_package_venv: the offline install into the venv (after setuptools: importing pip first breaks it)
python  selenium           python3-selenium        http_live_view_browser: drives the browser
command /usr/bin/chromium  chromium                http_live_view_browser: the page in a real browser, headless
command /usr/bin/chromedriver chromium-driver      http_live_view_browser: the WebDriver of chromium for selenium
command /usr/bin/python3   python3                 every Python test and script (ctest runs /usr/bin/python3)
command mbpoll             mbpoll                  cli_run_polaris_modbus_clients: libmodbus client
command tshark             tshark                  capture_dissector, cli_master_run_two_processes*: the Lua dissector
command clang++            clang                   ./build.sh test stage 2: the sanitizer build with the libFuzzer targets
command grpc_python_plugin protobuf-compiler-grpc  python/package.cmake: the gRPC stubs of the package
file    /usr/lib/llvm-14/lib/clang/*/lib/linux/libclang_rt.fuzzer-*.a  libclang-rt-14-dev  stage 2: the libFuzzer runtime
file    /usr/lib/postgresql/*/bin/initdb  postgresql   rs4sim_postgres fixture: the throw-away server of the PostgreSQL archive tests
command psql               postgresql-client       cli_archive_postgres: reads the rows the commands reported
'

rows() {  # the table without blank lines
  while read -r kind name package needed; do
    [ -n "$kind" ] && printf '%s %s %s %s\n' "$kind" "$name" "$package" "$needed"
  done <<EOF
$table
EOF
}

case "${1:-}" in
  --packages)
    seen=" "
    rows | while read -r kind name package needed; do
      case "$seen" in *" $package "*) continue ;; esac
      seen="$seen$package "
      echo "$package"
    done
    exit 0
    ;;
  --list)
    rows | while read -r kind name package needed; do printf '%-8s %-20s %s\n' "$kind" "$name" "$package"; done
    exit 0
    ;;
  "") ;;
  *) echo "usage: $0 [--packages|--list]" >&2; exit 2 ;;
esac

# The Python modules in one run of the interpreter: a line "module<TAB>why" for each that does
# not import. A module that fails only because another module of the table is missing is left
# out: that one is the cause and is named.
modules=
while read -r kind name package needed; do
  [ "$kind" = python ] && modules="$modules $name"
done <<EOF
$(rows)
EOF
tab=$(printf '\t')
if command -v "$python" >/dev/null 2>&1; then
  # shellcheck disable=SC2086  # the module names, one argument each
  broken=$("$python" - $modules <<'PY' 2>&1
import importlib
import sys

wanted = sys.argv[1:]
for name in wanted:
    try:
        importlib.import_module(name)
    except Exception as e:  # ImportError, or any error while the module imports
        cause = getattr(e, "name", None)
        if isinstance(e, ImportError) and cause and cause != name and cause in wanted:
            continue
        print(name, f"{type(e).__name__}: {e}".replace("\n", " "), sep="\t")
PY
)
else
  broken=
  for m in $modules; do broken="$broken$m${tab}no interpreter $python
"; done
fi

missing=0
checked=0
packages=
report=
while read -r kind name package needed; do
  checked=$((checked + 1))
  why=
  case "$kind" in
    python)
      while IFS="$tab" read -r m detail; do
        [ "$m" = "$name" ] && why="python module ($detail)"
      done <<EOF
$broken
EOF
      ;;
    command)
      command -v "$name" >/dev/null 2>&1 || why="command not found"
      ;;
    file)
      why="no file matches"
      for f in $name; do [ -e "$f" ] && why=; done
      ;;
    *) why="unknown kind '$kind' in the table" ;;
  esac
  if [ -n "$why" ]; then
    missing=$((missing + 1))
    report="$report  $kind $name: $why
      package $package, for $needed
"
    case " $packages " in *" $package "*) ;; *) packages="${packages:+$packages }$package" ;; esac
  fi
done <<EOF
$(rows)
EOF

if [ "$missing" -gt 0 ]; then
  {
    echo "preflight: $missing of the $checked modules, commands and files the tests need are missing:"
    printf '%s' "$report"
    echo "install: apt-get install --no-install-recommends $packages   (./build.sh deps does it)"
  } >&2
  exit 1
fi
echo "preflight: all $checked modules, commands and files the tests need are there"
