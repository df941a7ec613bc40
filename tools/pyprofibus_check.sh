#!/usr/bin/env bash
# By-hand interoperability check: pyprofibus' DP master (a third-party master, GPL, never
# copied into this repository) against rs4sim's GSD-driven slaves on a pty.
# NOT run in CI: it needs a pyprofibus checkout and python3-serial, and it runs for ~30 s.
# Usage: tools/pyprofibus_check.sh PYPROFIBUS_CHECKOUT [RS4SIM_BINARY]
#   (default binary: build/app/rs4sim of this checkout). Checked with pyprofibus
#   e7c981589392b09720940538eca83a78e2cd68f8; results in docs/gsd.md "Checked with pyprofibus".
# What it does, in a fresh temporary folder:
#   1. copies pyprofibus' misc/dummy_modular.gsd as it is (rs4sim takes Max_Input_Len=249 as
#      244 with a warning: a DP data unit holds at most 244 bytes);
#   2. station 8 (`rs4sim run --gsd … --link pty --http`) with the modules pyprofibus sends
#      (rs4sim places the Preset "fixed module" first, as pyprofibus does), pyprofibus
#      configured like its example_dummy_oneslave
#      but sync_mode=0/freeze_mode=0 (the GSD declares no Sync/Freeze); outputs A5 3C written by
#      pyprofibus must show in GsdStations.GetStation, inputs 7E set through
#      GsdStations.SetInputs must reach pyprofibus;
#   3. a bus file with stations 8 and 42 on one pty, pyprofibus configured for both.
# Exit 0 when every station reached data exchange with the expected bytes both ways.
set -euo pipefail

pb="${1:?usage: $0 PYPROFIBUS_CHECKOUT [RS4SIM_BINARY]}"
pb="$(cd "$pb" && pwd)"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
rs4sim="${2:-$here/build/app/rs4sim}"
py=/usr/bin/python3
[[ -f "$pb/pyprofibus/dp_master.py" ]] || { echo "$pb: not a pyprofibus checkout" >&2; exit 2; }
[[ -x "$rs4sim" ]] || { echo "$rs4sim: no rs4sim binary" >&2; exit 2; }
"$py" -c 'import serial' || { echo "python3-serial is missing" >&2; exit 2; }
command -v curl >/dev/null || { echo "curl is missing" >&2; exit 2; }

work="$(mktemp -d)"
pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; rm -rf "$work"; }
trap cleanup EXIT
cd "$work"
echo "pyprofibus $(git -C "$pb" rev-parse HEAD 2>/dev/null || echo '(not a git checkout)')"
echo "rs4sim $(git -C "$here" rev-parse HEAD)"

cp "$pb/misc/dummy_modular.gsd" dummy_modular.gsd

# The master side: pyprofibus' own classes, driven for SECONDS; counts Data_Exchange
# responses per slave. Set_Prm's DPV1_Status bytes as pyprofibus' examples set them.
cat > driver.py <<'PY'
import sys, time
sys.path.insert(0, sys.argv[1])
import pyprofibus
from pyprofibus.dp import DpTelegram_SetPrm_Req as SetPrm
conf, seconds, outs = sys.argv[2], float(sys.argv[3]), sys.argv[4:]
config = pyprofibus.PbConf.fromFile(conf)
master = config.makeDPM()
out, count, connected, last = {}, {}, {}, {}
for i, sc in enumerate(config.slaveConfs):
    desc = sc.makeDpSlaveDesc()
    mask = bytearray((SetPrm.DPV1PRM0_FAILSAFE, SetPrm.DPV1PRM1_REDCFG, 0))
    desc.setUserPrmData(sc.gsd.getUserPrmData(dp1PrmMask=mask, dp1PrmSet=mask))
    print("slave %d: User_Prm_Data %s, Chk_Cfg %s" % (sc.addr,
          bytes(desc.setPrmTelegram.userPrmData).hex(" "),
          " ".join("%02x" % e.identifier for e in sc.gsd.getCfgDataElements())), flush=True)
    master.addSlave(desc)
    out[sc.addr], count[sc.addr] = bytes.fromhex(outs[i]), 0
master.initialize()
t0 = time.monotonic()
try:
    while time.monotonic() - t0 < seconds:
        for d in master.getSlaveList():
            d.setMasterOutData(bytearray(out[d.slaveAddr]))
        h = master.run()
        for d in master.getSlaveList():
            if d.isConnected():
                connected.setdefault(d.slaveAddr, time.monotonic() - t0)
        data = h.getMasterInData() if h is not None else None  # read once: it is consumed
        if data is not None:
            count[h.slaveAddr] += 1
            last[h.slaveAddr] = bytes(data)
finally:
    master.destroy()
for a in sorted(count):
    print("pyprofibus: slave %d: %d Data_Exchange responses, in data exchange after %s s, "
          "last inputs %s" % (a, count[a], "%.3f" % connected[a] if a in connected else "never",
                              last[a].hex(" ") if a in last else "none"), flush=True)
PY

conf_head() {  # $1 = pty
  printf '[PROFIBUS]\ndebug=1\n[PHY]\ntype=serial\ndev=%s\nrtscts=False\ndsrdtr=False\n' "$1"
  printf 'baud=19200\n[FDL]\n[DP]\nmaster_class=1\nmaster_addr=2\n'
}
conf_slave() {  # $1 = index, $2 = address, $3 = output_size, $4 = input_size, $5... = modules
  local i=$1 a=$2 o=$3 n=$4 m k=0; shift 4
  printf '[SLAVE_%s]\nname=s%s\naddr=%s\ngsd=%s\nsync_mode=0\nfreeze_mode=0\n' "$i" "$a" "$a" \
    "$work/dummy_modular.gsd"
  printf 'group_mask=1\nwatchdog_ms=1000\n'  # the examples: 300; a loaded machine stalls the master longer
  for m in "$@"; do printf 'module_%d=%s\n' "$k" "$m"; k=$((k + 1)); done
  # pyprofibus: output_size = bytes the slave sends, input_size = bytes it receives
  printf 'output_size=%s\ninput_size=%s\ndiag_period=0\n' "$o" "$n"
}
start_rs4sim() {  # $1 = log name, rest = rs4sim run options; sets pty and url
  "$rs4sim" run "${@:2}" --link pty --baud 19.2k --duration 14 --http 127.0.0.1:0 \
    > "$1.out" 2> "$1.err" &
  pids+=($!)
  for _ in $(seq 50); do [[ $(wc -l < "$1.out") -ge 2 ]] && break; sleep 0.1; done
  pty="$(sed -n 1p "$1.out")"
  url="$(sed -n 2p "$1.out" | grep -o 'http://[0-9.:]*')"
}
api() { curl -sf -X POST "$url/api/rs4sim.v1.GsdStations/$1" -d "$2"; }
station() {  # $1 = address: "dpState inputs-hex outputs-hex" over the modules
  api GetStation "{\"address\": $1}" | "$py" -c '
import sys, json, base64
s = json.load(sys.stdin)
h = lambda k: "".join(base64.b64decode(m.get(k, "")).hex() for m in s["modules"])
print(s["dpState"], s.get("dataExchanges", "0"), "in=" + h("inputs"), "out=" + h("outputs"))'
}
status=0
expect_station() {  # $1 = address, $2 = wanted; up to 10 looks 0.3 s apart (the master may re-initialise)
  local got
  for _ in $(seq 10); do got="$(station "$1")"; grep -qE "$2" <<< "$got" && break; sleep 0.3; done
  expect "rs4sim station $1 during the run" "$got" "$2"
}
expect() {  # $1 = what, $2 = got, $3 = wanted (a grep -E pattern)
  if grep -qE "$3" <<< "$2"; then echo "ok: $1: $2"; else echo "FAILED: $1: $2 (wanted $3)"; status=1; fi
}

echo "== one GSD station (address 8)"
start_rs4sim one --gsd dummy_modular.gsd \
  --module "dummy output module" --module "dummy output module" --module "dummy input module" \
  --address 8
{ conf_head "$pty"; conf_slave 0 8 1 2 "dummy output module" "dummy output module" \
  "dummy input module"; } > one.conf
"$py" driver.py "$pb" one.conf 8 "a5 3c" > one.py.out 2>&1 &
master=$!
sleep 2
api SetInputs '{"address": 8, "slot": 3, "data": "fg=="}' > /dev/null   # 7E
sleep 3
expect_station 8 '^Data_Exch [0-9]+ in=7e out=a53c$'
wait "$master" || status=1
grep -v '^GSD parser\|^Bit(\|^ -->\|^DPM1' one.py.out
expect "pyprofibus slave 8" "$(grep '^pyprofibus: slave 8' one.py.out)" 'after [0-9.]+ s, last inputs 7e'

echo "== bus file: stations 8 and 42 on one pty"
cat > bus.json <<'JSON'
{"stations": [
  {"address": 8,  "gsd": "dummy_modular.gsd",
   "modules": ["dummy output module", "dummy output module", "dummy input module"]},
  {"address": 42, "gsd": "dummy_modular.gsd",
   "modules": ["dummy input module", "dummy output module"]}]}
JSON
start_rs4sim bus --bus bus.json
{ conf_head "$pty"
  conf_slave 0 8 1 2 "dummy output module" "dummy output module" "dummy input module"
  conf_slave 1 42 1 1 "dummy input module" "dummy output module"; } > bus.conf
"$py" driver.py "$pb" bus.conf 8 "a5 3c" "c3" > bus.py.out 2>&1 &
master=$!
sleep 2
api SetInputs '{"address": 8, "slot": 3, "data": "fg=="}' > /dev/null   # 7E
api SetInputs '{"address": 42, "slot": 1, "data": "gQ=="}' > /dev/null  # 81
sleep 3
expect_station 8 '^Data_Exch [0-9]+ in=7e out=a53c$'
expect_station 42 '^Data_Exch [0-9]+ in=81 out=c3$'
wait "$master" || status=1
grep -v '^GSD parser\|^Bit(\|^ -->\|^DPM1' bus.py.out
expect "pyprofibus slave 8" "$(grep '^pyprofibus: slave 8' bus.py.out)" 'after [0-9.]+ s, last inputs 7e'
expect "pyprofibus slave 42" "$(grep '^pyprofibus: slave 42' bus.py.out)" 'after [0-9.]+ s, last inputs 81'
echo "pyprofibus' re-initialisations: $(grep -c 'Trying to initialize' bus.py.out) (2 = none)"
exit "$status"
