#!/bin/sh
# The real-line CLI (docs/serial.md): `rs4sim serial-check` against a running `rs4sim run` on a
# pty pair (every FDL_Status request answered, the table printed, the run's turnaround counts
# them; a station that is not there exits 1), in loopback mode against `rs4sim run --device
# echo`; --tsl/--rt-priority refusals (exit 2) and
# --rt-priority without the right to it (exit 1 naming EPERM and the remedy).
set -eu
EXE="$1"
TMP=$(mktemp -d)
ECHO=
trap 'kill "$RUN" $ECHO 2>/dev/null || true; rm -rf "$TMP"' EXIT
# The first line of a run's stdout (its pty's path), once written (5 s at the most).
first_line() {
  i=0
  while [ ! -s "$1" ] && [ $i -lt 100 ]; do sleep 0.05; i=$((i + 1)); done
  head -n 1 "$1"
}
"$EXE" run --address 4 --boot-time 100 --link pty --baud 187.5k --duration 20 --json \
  >"$TMP/run.out" 2>"$TMP/run.err" &
RUN=$!
PTY=$(first_line "$TMP/run.out")
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

# Loopback mode: `rs4sim run --device echo` on a pty stands in for a loopback plug (TX wired
# to RX): every request comes back as it was sent (whole, after the echo device's 3.5
# characters of silence, where a plug returns each character at once), so serial-check counts
# loopback echoes, no replies, and measures the adapter's round trip.
"$EXE" run --device echo --link pty --baud 187500 --format 8E1 --duration 20 \
  >"$TMP/echo.out" 2>"$TMP/echo.err" &
ECHO=$!
EPTY=$(first_line "$TMP/echo.out")
"$EXE" serial-check --port "$EPTY" --baud 187.5k --address 4 --count 50 >"$TMP/loop.out"
cat "$TMP/loop.out"
grep -q "50 FDL_Status requests to station 4: 0 replies, 50 loopback echoes, 0 unanswered" \
  "$TMP/loop.out"
grep -q "(the adapter, there and back)" "$TMP/loop.out"
grep -q "^  187.5k " "$TMP/loop.out"
kill -INT "$ECHO"
wait "$ECHO" || true
# The echo device echoed each request once (6 bytes each: SD1 DA SA FC FCS ED).
grep -q "frames echoed 50," "$TMP/echo.err" "$TMP/echo.out"

# Usage errors: exit 2 with the reason.
set +e
"$EXE" run --link memory --rt-priority 10 >/dev/null 2>"$TMP/e1"; rc1=$?
"$EXE" run --link pty --baud 1.5M --tsl 20000 >/dev/null 2>"$TMP/e2"; rc2=$?
"$EXE" run --link pty --rt-priority 100 >/dev/null 2>"$TMP/e3"; rc3=$?
set -e
[ "$rc1" = 2 ] && grep -q "is for a real-time link" "$TMP/e1"
[ "$rc2" = 2 ] && grep -q "1..10922 µs at 1.5M" "$TMP/e2"
[ "$rc3" = 2 ] && grep -q "priorities are 1..99" "$TMP/e3"
# Without CAP_SYS_NICE and with a real-time limit of 0, SCHED_FIFO is refused: exit 1.
if command -v prlimit >/dev/null && command -v setpriv >/dev/null; then
  set +e
  prlimit --rtprio=0:0 setpriv --bounding-set -sys_nice --inh-caps -sys_nice \
    "$EXE" run --link pty --duration 5 --rt-priority 10 >/dev/null 2>"$TMP/e4"; rc4=$?
  set -e
  cat "$TMP/e4"
  [ "$rc4" = 1 ] && grep -q "(EPERM); a real-time priority needs CAP_SYS_NICE" "$TMP/e4" &&
    grep -q "ulimit -r 10" "$TMP/e4"
fi
echo OK
