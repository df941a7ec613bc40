#!/bin/sh
# `rs4sim demo --capture` end to end: the pcap header byte for byte (libpcap nanosecond
# format, tcpdump.org "pcap-savefile" and "linktypes"), then the project's Lua dissector in
# tshark (when installed; exit 77 = skipped otherwise) on the RS4 demo's capture.
# usage: capture_dissector_test.sh RS4SIM DISSECTOR.lua
set -eu
rs4sim=$1
lua=$2
. "$(dirname "$0")/../integration/lib.sh"  # $dir: a temporary directory, removed at the end
fail() { echo "FAIL: $*"; exit 1; }

header() { od -A n -t x1 -N 24 "$1" | tr -d ' \n'; }
"$rs4sim" demo --capture "$dir/rs4.pcap" > "$dir/demo.txt" || fail "demo failed"
grep -q "capture: [0-9]* telegrams" "$dir/demo.txt" || fail "demo does not report the capture"
# magic A1B23C4D (ns), 2.4, zone 0, sigfigs 0, snaplen 65535, LINKTYPE_USER0 = 147
[ "$(header "$dir/rs4.pcap")" = "4d3cb2a1020004000000000000000000ffff000093000000" ] ||
  fail "user0 header: $(header "$dir/rs4.pcap")"
"$rs4sim" demo --device generic --capture "$dir/g.pcap" --capture-linktype 257 > /dev/null
[ "$(header "$dir/g.pcap")" = "4d3cb2a1020004000000000000000000ffff000001010000" ] ||
  fail "257 header: $(header "$dir/g.pcap")"
if "$rs4sim" demo --capture /nonexistent-dir/x.pcap > "$dir/err.txt" 2>&1; then
  fail "an unwritable capture file must fail"
fi
grep -q "cannot write '/nonexistent-dir/x.pcap'" "$dir/err.txt" || fail "$(cat "$dir/err.txt")"

if ! command -v tshark > /dev/null 2>&1; then
  echo "tshark not installed: dissector check skipped"
  exit 77
fi
count() { tshark -X "lua_script:$lua" -r "$dir/rs4.pcap" -Y "$1" 2>/dev/null | wc -l; }
total=$(count "rs4sim")
records=$(sed -n 's/.*capture: \([0-9]*\) telegrams.*/\1/p' "$dir/demo.txt")
[ "$total" -eq "$records" ] || fail "dissector saw $total of $records telegrams"
[ "$(count 'rs4sim.fdl.fcs_ok == 0 || _ws.malformed || _ws.expert')" -eq 0 ] ||
  fail "malformed or FCS errors in the dissection"
[ "$(count 'rs4sim.fdl.sd == 0xdc')" -gt 0 ] || fail "no token frames"
[ "$(count 'rs4sim.dp.service == "Set_Prm"')" -gt 0 ] || fail "no Set_Prm"
[ "$(count 'rs4sim.ps.control && rs4sim.fdl.request == 1')" -gt 1000 ] || fail "few PROFIsafe requests"
[ "$(count 'rs4sim.ps.status && rs4sim.fdl.request == 0')" -gt 1000 ] || fail "few PROFIsafe replies"
[ "$(count 'rs4sim.dpv1.function == 0x5f && rs4sim.rs4.command == 0x92')" -ge 1 ] ||
  fail "no PROFI_CMD_GET_RS4_DATA write"
[ "$(count 'rs4sim.dpv1.function == 0x5e && rs4sim.rs4.command == 0x23')" -ge 1 ] ||
  fail "no measurement telegram read"
[ "$(count 'rs4sim.rs4.block_number == 0xffff && !rs4sim.rs4.command')" -ge 1 ] ||
  fail "the last block of a multi-block answer is taken for a new command"
echo "ok: $total telegrams dissected"
