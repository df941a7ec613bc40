#!/bin/sh
# What a newcomer reads on the console (README "Using it", docs/http.md):
# - each command's --help shows only its own options: `master` drives no byte device and has
#   no RS232 port (no --capture-rs232, no byte-device --baud), `run` has both;
# - `http: listening on …` is the first stdout line of `run --http` and of `master --http`
#   (docs/http.md), before the master's own start lines.
set -eu
EXE="$1"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$EXE" master --help >"$TMP/master.help"
"$EXE" run --help >"$TMP/run.help"
grep -q -- "--capture-rs232" "$TMP/master.help" && fail "master --help lists --capture-rs232"
grep -q "byte device" "$TMP/master.help" && fail "master --help mentions byte devices"
grep -q -- "--capture-rs232" "$TMP/run.help" || fail "run --help lacks --capture-rs232"
grep -q "a byte device: its bit rate" "$TMP/run.help" || fail "run --help lacks the byte devices' --baud"
grep -q -- "--address.*0\.\.125" "$TMP/run.help" || fail "run --help does not give 0..125"
grep -q "0\.\.126" "$TMP/run.help" && fail "run --help still offers 0..126"

# run: the memory bus under the API, 1 s of wall time.
"$EXE" run --link memory --http 127.0.0.1:0 --duration 1 >"$TMP/run.out" 2>"$TMP/run.err"
head -n 1 "$TMP/run.out" | grep -q "^http: listening on http://127\.0\.0\.1:[0-9]*/$" ||
  fail "run: first line: $(head -n 1 "$TMP/run.out")"
# master: on UDP with nobody at the peer (a real-time link; the page serves its archive).
"$EXE" master --slave 4 --link udp --listen 127.0.0.1:0 --peer 127.0.0.1:9 \
  --archive "$TMP/a.sqlite3" --http 127.0.0.1:0 --duration 1 >"$TMP/master.out" 2>"$TMP/master.err"
cat "$TMP/master.out"
head -n 1 "$TMP/master.out" | grep -q "^http: listening on http://127\.0\.0\.1:[0-9]*/$" ||
  fail "master: first line: $(head -n 1 "$TMP/master.out")"
grep -q "^master 1 on udp, RS4 at 4$" "$TMP/master.out" || fail "master: no start line"
echo OK
