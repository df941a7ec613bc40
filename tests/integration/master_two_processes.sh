#!/bin/sh
# `rs4sim run --device rs4 --link pty` and `rs4sim master --link serial --port <its pty>` as
# two processes on the wall clock: the master reaches data exchange, PROFIsafe RUN and sees
# Proxy-Request after the RS4's (shortened) boot; checked on its --json lines (docs/master.md).
# Usage: master_two_processes.sh RS4SIM
set -u
rs4sim=$1
dir=$(mktemp -d)
run_pid=
cleanup() {
  [ -n "$run_pid" ] && kill "$run_pid" 2>/dev/null && wait "$run_pid" 2>/dev/null
  rm -rf "$dir"
}
trap cleanup EXIT

"$rs4sim" run --device rs4 --address 4 --link pty --boot-time 1000 --duration 60 \
  >"$dir/run.out" 2>"$dir/run.err" &
run_pid=$!
i=0
while [ ! -s "$dir/run.out" ] && [ $i -lt 100 ]; do
  sleep 0.1
  i=$((i + 1))
done
path=$(head -n 1 "$dir/run.out")
case "$path" in
  /dev/*) ;;
  *) echo "rs4sim run printed no pty path"; cat "$dir/run.err"; exit 1 ;;
esac

# Generous watchdogs: the machine running the tests may be loaded.
"$rs4sim" master --slave 4 --link serial --port "$path" --json --duration 8 \
  --f-wd-time 500 --dp-watchdog 1000 >"$dir/master.out" 2>"$dir/master.err"
rc=$?
cat "$dir/master.out"
if [ $rc -ne 0 ]; then
  echo "rs4sim master exited with $rc"
  cat "$dir/master.err"
  exit 1
fi
fail=0
expect() {
  if ! grep -q -- "$1" "$dir/master.out"; then
    echo "missing: $1"
    fail=1
  fi
}
expect '"event":"start","link":"serial","rs4":\[4\]'
expect '"station":4,"event":"dp","state":"DataExchange","data_exchange":true'
expect '"station":4,"event":"profisafe","state":"run"'
expect '"station":4,"event":"input",.*"proxy_request":true'
expect '"station":4,"event":"stop","dp":"DataExchange","data_exchange":true,"profisafe":"run"'
exit $fail
