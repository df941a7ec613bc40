#!/bin/sh
# `rs4sim run --device rs4` and `rs4sim master` as two processes on the wall clock, over a
# pty pair (`run --link pty` prints its path, `master --link serial --port <path>`) or UDP on
# localhost: the master reaches data exchange, PROFIsafe RUN and sees Proxy-Request after the
# RS4's (shortened) boot, and the parameter proxy completes the first-commissioning sync
# over the real link (the RS4 holds its factory set, the archive is empty:
# CONFIG_SET_TO_DEFAULT, scenario 1 of [RS4 manual §7.1, §7.2]); checked on its --json lines
# (docs/master.md). Both processes write --capture files of the real link: the pcap header
# byte for byte, telegrams in both, and (with tshark) the project's dissector finds no FCS
# error and PROFIsafe PDUs both ways.
# Usage: master_two_processes.sh RS4SIM [pty|udp]
set -u
rs4sim=$1
link=${2:-pty}
lua=$(cd "$(dirname "$0")/../.." && pwd)/tools/wireshark/rs4sim.lua
. "$(dirname "$0")/lib.sh"

if [ "$link" = udp ]; then
  # ports from the process id, in the dynamic range
  a=$((49152 + ($$ * 2) % 16000))
  b=$((a + 1))
  bg_start run "$rs4sim" run --device rs4 --address 4 --link udp --listen 127.0.0.1:$a \
    --peer 127.0.0.1:$b --boot-time 1000 --duration 60 --capture "$dir/run.pcap"
  set -- --link udp --listen 127.0.0.1:$b --peer 127.0.0.1:$a
else
  bg_start run "$rs4sim" run --device rs4 --address 4 --link pty --boot-time 1000 --duration 60 \
    --capture "$dir/run.pcap"
  bg_await run.out '.'
  path=$(head -n 1 "$dir/run.out")
  case "$path" in
    /dev/*) ;;
    *) bg_fail "rs4sim run printed no pty path" ;;
  esac
  set -- --link serial --port "$path"
fi
# The banner: the run serves its link, its SIGTERM handler is installed.
bg_await run.err 'Ctrl-C to stop'

# Generous watchdogs: the machine running the tests may be loaded.
"$rs4sim" master --slave 4 "$@" --json --duration 8 \
  --f-wd-time 500 --dp-watchdog 1000 --archive "$dir/archive.sqlite3" \
  --capture "$dir/master.pcap" --capture-linktype 257 >"$dir/master.out" 2>"$dir/master.err"
rc=$?
cat "$dir/master.out"
ended_ok "rs4sim master" $rc "$dir/master.err"
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

# The captures: the run ends on SIGTERM and reports its file.
bg_stop run TERM
run_rc=$bg_rc
[ $run_rc -eq 0 ] || { echo "rs4sim run exited with $run_rc"; cat "$dir/run.err"; fail=1; }
telegrams() { sed -n 's/^rs4sim: capture: \([0-9]*\) telegrams in .*/\1/p' "$1"; }
n_run=$(telegrams "$dir/run.err")
n_master=$(telegrams "$dir/master.err")
echo "captured: run $n_run, master $n_master telegrams"
[ "${n_run:-0}" -gt 100 ] || { echo "run capture: '${n_run}'"; cat "$dir/run.err"; fail=1; }
[ "${n_master:-0}" -gt 100 ] || { echo "master capture: '${n_master}'"; cat "$dir/master.err"; fail=1; }
header() { od -A n -t x1 -N 24 "$1" | tr -d ' \n'; }
# libpcap nanosecond magic A1B23C4D, 2.4, snaplen 65535; LINKTYPE_USER0 147 / PROFIBUS_DL 257
[ "$(header "$dir/run.pcap")" = "4d3cb2a1020004000000000000000000ffff000093000000" ] ||
  { echo "run.pcap header $(header "$dir/run.pcap")"; fail=1; }
[ "$(header "$dir/master.pcap")" = "4d3cb2a1020004000000000000000000ffff000001010000" ] ||
  { echo "master.pcap header $(header "$dir/master.pcap")"; fail=1; }
if command -v tshark > /dev/null 2>&1; then
  count() { tshark -X "lua_script:$lua" -r "$dir/run.pcap" -Y "$1" 2>/dev/null | wc -l; }
  [ "$(count rs4sim)" -eq "$n_run" ] || { echo "dissected $(count rs4sim) of $n_run"; fail=1; }
  [ "$(count 'rs4sim.fdl.fcs_ok == 0 || _ws.malformed || _ws.expert')" -eq 0 ] ||
    { echo "FCS errors or malformed telegrams in run.pcap"; fail=1; }
  [ "$(count 'rs4sim.ps.control && rs4sim.fdl.request == 1')" -gt 10 ] ||
    { echo "no PROFIsafe requests in run.pcap"; fail=1; }
  [ "$(count 'rs4sim.ps.status && rs4sim.fdl.request == 0')" -gt 10 ] ||
    { echo "no PROFIsafe replies in run.pcap"; fail=1; }
fi
exit $fail
