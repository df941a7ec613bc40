#!/usr/bin/env bash
# The walk of docs/design.md "Adding a device", done: a scratch copy of the tree gets a dummy
# fifth line device `foo` (the Polaris's library renamed), then the six production files the
# walk names outside foo/ (CMakeLists.txt, stream/device_description.h, run.proto,
# devices.proto, rpc/foo_service.cpp, app/devices/device_foo.cpp). Fails when the walk needs
# another file: when the copy's configure does not wire foo into the generated lists
# (rpc::line_apis(), app::line_device_entries()) and its folders, or, with
# `compile` given, when what the walk wrote does not compile.
# Usage: line_device_walk_test.sh SOURCE_DIR [compile]
set -euo pipefail
src=$(cd "$1" && pwd)
if ! git -C "$src" rev-parse --git-dir > /dev/null 2>&1; then
  echo "SKIP: $src is no git checkout (the copy takes the files git tracks)"; exit 77
fi
top=$(mktemp -d)
trap 'rm -rf "$top"' EXIT
s=$top/src
mkdir -p "$s"
(cd "$src" && git ls-files -co --exclude-standard -z | xargs -0 cp --parents -t "$s")
cd "$s"
git init -q && git add -A && git -c user.email=walk@rs4sim -c user.name=walk commit -qm base
rename() { sed -i 's/polaris/foo/g; s/Polaris/Foo/g; s/POLARIS/FOO/g' "$@"; }
fail() { echo "FAIL: $*" >&2; exit 1; }

# The library, not counted (the device's own folder).
cp -r polaris foo && rename foo/*
# 1. CMakeLists.txt: foo in the one list.
sed -i 's/^\(set(RS4SIM_LINE_DEVICES .*\))$/\1 foo)/' CMakeLists.txt
# 2. stream/device_description.h: its DeviceKind and its word.
sed -i 's|^  kPolaris = 6, .*|&\n  kFoo = 7,|; s|^    case DeviceKind::kPolaris: return "polaris";|&\n    case DeviceKind::kFoo: return "foo";|' \
  stream/device_description.h
# 3. run.proto: its StationKind.
sed -i 's|^  STATION_KIND_POLARIS = 6;.*|&\n  STATION_KIND_FOO = 7;|' rpc/proto/rs4sim/v1/run.proto
# 4. devices.proto: service Foo and its messages (the Polaris's section, renamed).
proto=rpc/proto/rs4sim/v1/devices.proto
start=$(grep -n '^// ---- Optoscan Polaris' $proto | cut -d: -f1)
tail -n +"$start" $proto | sed 's/Polaris/Foo/g; s/POLARIS/FOO/g; s/polaris/foo/g' > "$top/foo.proto"
cat "$top/foo.proto" >> $proto
# 5. rpc/foo_service.cpp: the service class and its LineApi, no header.
{ grep -v '^#pragma once' rpc/polaris_service.h
  grep -v '#include "rpc/polaris_service.h"' rpc/polaris_service.cpp; } > rpc/foo_service.cpp
rename rpc/foo_service.cpp
# 6. app/devices/device_foo.cpp: the entry, without a demo.
cp app/devices/device_polaris.cpp app/devices/device_foo.cpp
rename app/devices/device_foo.cpp
sed -i 's/run_foo_demo/{}/' app/devices/device_foo.cpp

git add -A
git status --porcelain | grep -v ' foo/' > "$top/walk.txt" || true
cat "$top/walk.txt"
expected=$'M  CMakeLists.txt\nA  app/devices/device_foo.cpp\nA  rpc/foo_service.cpp\nM  rpc/proto/rs4sim/v1/devices.proto\nM  rpc/proto/rs4sim/v1/run.proto\nM  stream/device_description.h'
[ "$(cat "$top/walk.txt")" = "$expected" ] || fail "the walk touched other files than the six"
grep -q 'kFoo = 7' stream/device_description.h || fail "DeviceKind: the edit did not apply"
grep -q 'STATION_KIND_FOO = 7' rpc/proto/rs4sim/v1/run.proto || fail "run.proto: the edit did not apply"

b=$top/build
cmake -S "$s" -B "$b" -G Ninja -DRS4SIM_TESTS=OFF -DRS4SIM_BENCH=OFF -DRS4SIM_WERROR=ON \
  > "$top/configure.log" 2>&1 || { cat "$top/configure.log"; fail "configure"; }
grep -q 'LineApi foo_line_api();' "$b/rpc/line_apis.cpp" || fail "rpc::line_apis() lacks foo"
grep -q 'foo_line_api()}' "$b/rpc/line_apis.cpp" || fail "rpc::line_apis() does not list foo last"
grep -q 'DeviceEntry foo_device_entry();' "$b/app/line_device_entries.cpp" \
  || fail "app::line_device_entries() lacks foo"
grep -q 'foo/description.cpp' "$b/build.ninja" || fail "the library folder foo/ is not built"
grep -q 'rpc/foo_service.cpp' "$b/build.ninja" || fail "rpc/foo_service.cpp is not compiled"
grep -q 'devices/device_foo.cpp' "$b/build.ninja" || fail "device_foo.cpp is not compiled"
if [ "${2:-}" = compile ]; then
  # The generated API headers, then only the files the walk wrote and the generated lists,
  # with their compile commands (the rest of the tree is the one already built).
  ninja -C "$b" $(ninja -C "$b" -t targets all | grep -o '^rpc/proto/[^:]*\.pb\.h') > /dev/null
  for f in foo/description.cpp rpc/foo_service.cpp app/devices/device_foo.cpp \
           "$b/rpc/line_apis.cpp" "$b/app/line_device_entries.cpp"; do
    python3 - "$b/compile_commands.json" "$f" "$s" > "$top/cc.sh" <<'PY'
import json, os, sys
db, f, s = sys.argv[1], sys.argv[2], sys.argv[3]
path = f if os.path.isabs(f) else os.path.join(s, f)
e = next(e for e in json.load(open(db)) if e["file"] == path)
print("cd " + e["directory"] + " && " + e["command"])
PY
    echo "compiling $f"
    bash "$top/cc.sh" || fail "the walk does not compile: $f"
  done
fi
echo "the walk: 6 production files outside foo/"
