#!/bin/sh
# The byte-line half of tools/wireshark/rs4sim.lua in tshark against the manuals' printed
# frames: a LINKTYPE_USER1 capture (docs/capture.md#byte-lines) is written here from fixed
# bytes, independently of rs4sim, and every decoded field is compared with the value the
# manual gives. Then `rs4sim run --device gridscan --link memory --capture` end to end: the
# file's header and first record byte for byte. Exit 77 (skipped) without tshark.
# usage: line_dissector_test.sh RS4SIM DISSECTOR.lua
set -eu
rs4sim=$1
lua=$2
. "$(dirname "$0")/../integration/lib.sh"  # $dir: a temporary directory, removed at the end
fail() { echo "FAIL: $*"; exit 1; }

# rs4sim's own capture of the GridScan's power-up on the simulated line: pcap nanosecond
# header with LINKTYPE_USER1 (148), then the first record: direction 1 (device → master),
# protocol 1 (GridScan), the version message 0xA0 of the power-up [GridScan manual §9.2.3].
"$rs4sim" run --device gridscan --link memory --duration 1 --capture "$dir/gs.pcap" \
  > "$dir/run.txt" 2> "$dir/err.txt" || fail "run: $(cat "$dir/err.txt")"
grep -q "capture: [1-9][0-9]* frames in" "$dir/err.txt" || fail "no capture report: $(cat "$dir/err.txt")"
[ "$(od -A n -t x1 -N 24 "$dir/gs.pcap" | tr -d ' \n')" = \
  "4d3cb2a1020004000000000000000000ffff000094000000" ] || fail "header"
# record 1: 16-byte record header, then 01 01 and the CEDES frame: sync, SeqCnt, ID A0
[ "$(od -A n -t x1 -j 40 -N 6 "$dir/gs.pcap" | tr -d ' \n')" = "010143454445" ] ||
  fail "first record: $(od -A n -t x1 -j 40 -N 12 "$dir/gs.pcap")"
[ "$(od -A n -t x1 -j 47 -N 1 "$dir/gs.pcap" | tr -d ' \n')" = "a0" ] || fail "not the version message"

if ! command -v tshark > /dev/null 2>&1; then
  echo "tshark not installed: dissector check skipped"
  exit 77
fi
# direction protocol frame (hex), one record each
python3 - "$dir/manual.pcap" <<'PY'
import struct, sys
records = [
    # [GridScan manual §10.3] request 4 and answer 4
    "0001" "434544450623e24b0170",
    "0101" "434544450" "7a300f88bab62",
    # the same answer with one CRC byte changed
    "0101" "4345444507a300f88bab63",
    # METRON examples (docs/metron.md "Example bytes"): OSSD status, node 5; E1 answer
    "0002" "02050" "10cf3",
    "0102" "02050" "30c0101f1",
    "0102" "0201e11e",
    # [Polaris manual §8] P1 request and P2 answer (Modbus RTU FC 3)
    "0003" "0303200000084e2e",
    "0103" "030310ffffffffffffffff807ff03fffffffff1bd3",
    # P8: exception 07 to P1 with its CRC swapped
    "0103" "038307a132",
]
with open(sys.argv[1], "wb") as f:
    f.write(struct.pack("<IHHiIII", 0xA1B23C4D, 2, 4, 0, 0, 65535, 148))
    for i, r in enumerate(records):
        b = bytes.fromhex(r)
        f.write(struct.pack("<IIII", 1000 + i, 0, len(b), len(b)) + b)
PY
# booleans print as 1/0 with -T fields
fields() {
  tshark -X "lua_script:$lua" -r "$dir/manual.pcap" -T fields -E separator=, "$@" 2>&1 | grep -v "^Running as user"
}
got=$(fields -e rs4sim.line.direction -e rs4sim.line.protocol -e rs4sim.gridscan.seq \
  -e rs4sim.gridscan.command -e rs4sim.gridscan.response -e rs4sim.gridscan.payload \
  -e rs4sim.gridscan.crc -e rs4sim.gridscan.crc_ok -Y rs4sim.gridscan.seq)
want="0,1,6,0x23,0,,0x70014be2,1
1,1,7,0x23,1,00,0x62ab8bf8,1
1,1,7,0x23,1,00,0x63ab8bf8,0"
[ "$got" = "$want" ] || fail "GridScan: $got"
got=$(fields -e rs4sim.line.direction -e rs4sim.metron.node -e rs4sim.metron.length \
  -e rs4sim.metron.command -e rs4sim.metron.data -e rs4sim.metron.checksum \
  -e rs4sim.metron.checksum_ok -Y rs4sim.metron.length)
want="0,5,1,0x0c,,0xf3,1
1,5,3,0x0c,0101,0xf1,1
1,,1,0xe1,,0x1e,1"
[ "$got" = "$want" ] || fail "METRON: $got"
got=$(fields -e rs4sim.line.direction -e rs4sim.modbus.address -e rs4sim.modbus.function \
  -e rs4sim.modbus.start -e rs4sim.modbus.quantity -e rs4sim.modbus.byte_count \
  -e rs4sim.modbus.exception -e rs4sim.modbus.crc -e rs4sim.modbus.crc_ok -Y rs4sim.modbus.address)
want="0,3,3,0x2000,8,,,0x2e4e,1
1,3,3,,,16,,0xd31b,1
1,3,3,,,,0x07,0x32a1,1"
[ "$got" = "$want" ] || fail "Modbus: $got"
# rs4sim's own capture decodes without a CRC error
bad=$(tshark -X "lua_script:$lua" -r "$dir/gs.pcap" -Y 'rs4sim.gridscan.crc_ok == 0 || _ws.malformed' 2>/dev/null | wc -l)
good=$(tshark -X "lua_script:$lua" -r "$dir/gs.pcap" -Y 'rs4sim.gridscan.crc_ok == 1' 2>/dev/null | wc -l)
[ "$bad" -eq 0 ] && [ "$good" -gt 0 ] || fail "rs4sim's capture: $good good, $bad bad"
echo "ok: manual frames and rs4sim's capture dissected"
