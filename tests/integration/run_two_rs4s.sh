#!/bin/sh
# Two RS4s in one process: `rs4sim run --address 4 --address 5 --link pty` (two PROFIBUS
# stations on one pty) and `rs4sim master --slave 4 --slave 5 --link serial --port <path>` on
# the wall clock: on the master's --json lines (docs/master.md) both stations reach data
# exchange and PROFIsafe RUN and end in it; the run's banner and end status name both.
# Usage: run_two_rs4s.sh RS4SIM
set -u
rs4sim=$1
. "$(dirname "$0")/lib.sh"

bg_start run "$rs4sim" run --address 4 --address 5 --link pty --boot-time 1000 --duration 60
bg_await run.out '.'
path=$(head -n 1 "$dir/run.out")
case "$path" in
  /dev/*) ;;
  *) bg_fail "rs4sim run printed no pty path" ;;
esac
# The banner: the run serves its link, its SIGTERM handler is installed.
bg_await run.err 'Ctrl-C to stop'

# Generous watchdogs: the machine running the tests may be loaded.
"$rs4sim" master --slave 4 --slave 5 --link serial --port "$path" --json --duration 8 \
  --f-wd-time 500 --dp-watchdog 1000 --archive "$dir/archive.sqlite3" \
  >"$dir/master.out" 2>"$dir/master.err"
rc=$?
# The run ends at once: its RS4s still hold PROFIsafe run only until their F watchdog
# (--f-wd-time 500) sees the master gone; the checks below come after.
bg_stop run TERM
run_rc=$bg_rc
cat "$dir/master.out"
ended_ok "rs4sim master" $rc "$dir/master.err"
fail=0
expect() {
  if ! grep -q -- "$1" "$2"; then
    echo "missing in $(basename "$2"): $1"
    fail=1
  fi
}
m=$dir/master.out
expect '"event":"start","link":"[a-z]*","rs4":\[4,5\]' "$m"
for s in 4 5; do
  expect "\"station\":$s,\"event\":\"dp\",\"state\":\"DataExchange\",\"data_exchange\":true" "$m"
  expect "\"station\":$s,\"event\":\"profisafe\",\"state\":\"run\"" "$m"
  expect "\"station\":$s,\"event\":\"stop\",\"dp\":\"DataExchange\",\"data_exchange\":true,\"profisafe\":\"run\"" "$m"
done

[ $run_rc -eq 0 ] || { echo "rs4sim run exited with $run_rc"; cat "$dir/run.err"; fail=1; }
cat "$dir/run.err" "$dir/run.out"
expect 'rs4sim: 2 RS4/PROFIsafe at addresses 4, 5 (ident 0x[0-9a-f]*, F_Dest_Add [0-9]*, [0-9]*, boot 1000 ms) on pty' "$dir/run.err"
expect '^rs4 4: LED .*PROFIsafe run' "$dir/run.out"
expect '^rs4 5: LED .*PROFIsafe run' "$dir/run.out"
exit $fail
