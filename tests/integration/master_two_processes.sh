#!/bin/sh
# `rs4sim run --device rs4` and `rs4sim master` as two processes on the wall clock, over a
# pty pair (`run --link pty` prints its path, `master --link serial --port <path>`) or UDP on
# localhost: the master reaches data exchange, PROFIsafe RUN and sees Proxy-Request after the
# RS4's (shortened) boot, and the parameter proxy completes the first-commissioning sync
# over the real link (the RS4 holds its factory set, the archive is empty:
# CONFIG_SET_TO_DEFAULT, scenario 1 of [RS4 manual §7.1, §7.2]); checked on its --json lines
# (docs/master.md).
# Usage: master_two_processes.sh RS4SIM [pty|udp]
set -u
rs4sim=$1
link=${2:-pty}
dir=$(mktemp -d)
run_pid=
cleanup() {
  [ -n "$run_pid" ] && kill "$run_pid" 2>/dev/null && wait "$run_pid" 2>/dev/null
  rm -rf "$dir"
}
trap cleanup EXIT

if [ "$link" = udp ]; then
  # ports from the process id, in the dynamic range
  a=$((49152 + ($$ * 2) % 16000))
  b=$((a + 1))
  "$rs4sim" run --device rs4 --address 4 --link udp --listen 127.0.0.1:$a --peer 127.0.0.1:$b \
    --boot-time 1000 --duration 60 >"$dir/run.out" 2>"$dir/run.err" &
  run_pid=$!
  set -- --link udp --listen 127.0.0.1:$b --peer 127.0.0.1:$a
else
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
  set -- --link serial --port "$path"
fi

# Generous watchdogs: the machine running the tests may be loaded.
"$rs4sim" master --slave 4 "$@" --json --duration 8 \
  --f-wd-time 500 --dp-watchdog 1000 --archive "$dir/archive.sqlite3" \
  >"$dir/master.out" 2>"$dir/master.err"
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
expect '"event":"start","link":"[a-z]*","rs4":\[4\]'
expect '"station":4,"event":"dp","state":"DataExchange","data_exchange":true'
expect '"station":4,"event":"profisafe","state":"run"'
expect '"station":4,"event":"input",.*"proxy_request":true'
expect '"station":4,"event":"stop","dp":"DataExchange","data_exchange":true,"profisafe":"run"'
expect '"station":4,"event":"proxy",.*"step":"identify"'
expect '"station":4,"event":"proxy",.*"step":"idle",.*"fb_busy":false,"config_set_to_default":true,"error_number_fb":0'
exit $fail
