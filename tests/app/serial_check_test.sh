#!/bin/sh
# `rs4sim serial-check` against a running `rs4sim run` on a pty pair (docs/serial.md): every
# FDL_Status request is answered, the table is printed; a port where nothing answers exits 1.
set -eu
EXE="$1"
TMP=$(mktemp -d)
trap 'kill "$RUN" 2>/dev/null || true; rm -rf "$TMP"' EXIT
"$EXE" run --address 4 --boot-time 100 --link pty --baud 187.5k --duration 20 --json \
  >"$TMP/run.out" 2>"$TMP/run.err" &
RUN=$!
i=0
while [ ! -s "$TMP/run.out" ] && [ $i -lt 100 ]; do sleep 0.05; i=$((i + 1)); done
PTY=$(head -n 1 "$TMP/run.out")
"$EXE" serial-check --port "$PTY" --baud 187.5k --address 4 --count 200 >"$TMP/check.out"
cat "$TMP/check.out"
grep -q "200 replies, 0 loopback echoes, 0 unanswered" "$TMP/check.out"
grep -q "^  187.5k " "$TMP/check.out"
grep -q "retry limit 2-3" "$TMP/check.out"
# Station 9 is not on the line: nothing answers, exit 1 with the reason.
if "$EXE" serial-check --port "$PTY" --address 9 --count 3 --timeout 20 >/dev/null 2>"$TMP/err"; then
  echo "serial-check answered for an absent station"; exit 1
fi
grep -q "nothing answered" "$TMP/err"
kill -INT "$RUN"
wait "$RUN" || true
# The run's summary has the 200 replies in its turnaround (FDL_Status of the check).
grep -q '"event":"turnaround","address":4,"replies":20[0-9]' "$TMP/run.out"
echo OK
