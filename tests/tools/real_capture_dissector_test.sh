#!/bin/sh
# Bytes read off a real PROFIBUS line in Wireshark (docs/capture.md "Real bus traffic"): the
# NIKI 4.0 capture (a master at address 4 polling about 18 slaves, with line noise), read from
# the real material beside the repository (shared/real, or $RS4SIM_REAL_DIR), framed by the
# project's stream decoder into a pcap file (real_capture_pcap), then dissected by the project's
# Lua dissector in tshark: every record dissected, nothing malformed, no dissector error, every
# FCS right, and as many SD1 and SD2 frames as an independent count that checks each frame's
# FCS and end delimiter finds (15,727 and 34,833). Exit 77 (skipped) when the capture or
# tshark is absent.
# usage: real_capture_dissector_test.sh REAL_CAPTURE_PCAP DISSECTOR.lua SOURCE_DIR
set -eu
convert=$1
lua=$2
real=${RS4SIM_REAL_DIR:-$(dirname "$3")/shared/real}
capture=$real/captures/niki40-bus.txt
fail() { echo "FAIL: $*"; exit 1; }

if [ ! -f "$capture" ]; then
  echo "the real capture $capture is absent (RS4SIM_REAL_DIR names another place): skipped"
  exit 77
fi
if ! command -v tshark > /dev/null 2>&1; then
  echo "tshark not installed: skipped"
  exit 77
fi
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$convert" "$capture" "$dir/niki40.pcap" > "$dir/counts.txt" || fail "$(cat "$dir/counts.txt")"
count() { sed -n "s/.* $1 \([0-9]*\).*/\1/p" "$dir/counts.txt"; }
[ "$(count sd1)" -eq 15727 ] || fail "SD1 frames: $(cat "$dir/counts.txt")"
[ "$(count sd2)" -eq 34833 ] || fail "SD2 frames: $(cat "$dir/counts.txt")"

# One pass: frame number, start delimiter, FCS correct, malformed, expert info, DP service.
tshark -X "lua_script:$lua" -r "$dir/niki40.pcap" -T fields -E separator=/t -e frame.number \
  -e rs4sim.fdl.sd -e rs4sim.fdl.fcs_ok -e _ws.malformed -e _ws.expert -e rs4sim.dp.service \
  > "$dir/fields.txt" 2> "$dir/tshark.err" || fail "tshark: $(cat "$dir/tshark.err")"
records=$(sed -n 's/^records \([0-9]*\).*/\1/p' "$dir/counts.txt")
[ "$(wc -l < "$dir/fields.txt")" -eq "$records" ] ||
  fail "tshark read $(wc -l < "$dir/fields.txt") of $records records"
bad=$(awk -F'\t' '$4 != "" || $5 != ""' "$dir/fields.txt" | head -5)
[ -z "$bad" ] || fail "malformed or expert info: $bad"
sds() { awk -F'\t' -v sd="$1" '$2 == sd && $3 == "1"' "$dir/fields.txt" | wc -l; }
[ "$(sds 0x10)" -eq 15727 ] || fail "SD1 with a right FCS in the dissection: $(sds 0x10)"
[ "$(sds 0x68)" -eq 34833 ] || fail "SD2 with a right FCS in the dissection: $(sds 0x68)"
service() { awk -F'\t' -v s="$1" '$6 == s' "$dir/fields.txt" | wc -l; }
# The one frame with segment addresses, and the MSAC_C2 connection's Idle PDUs (station 0 to
# station 32, DSAP 40, SSAP 50, and back: counted by a separate script, 79 each way).
[ "$(service 'segment address (not DP)')" -eq 1 ] || fail "the segment-addressed frame"
[ "$(service 'Idle.req')" -eq 79 ] || fail "MSAC_C2 Idle requests: $(service 'Idle.req')"
[ "$(service 'Idle.res')" -eq 79 ] || fail "MSAC_C2 Idle responses: $(service 'Idle.res')"
echo "ok: $(cat "$dir/counts.txt")"
