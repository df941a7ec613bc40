#!/bin/sh
# The manual's scenario 2 the way a user performs it, over two real pseudo-terminals
# ([RS4 manual §7.1, §7.2], docs/rs232.md, docs/param.md): `rs4sim run --device rs4` serves
# PROFIBUS on one pty and the RS4's RS232 interface on another (--rs232 pty); `rs4sim master`
# on the PROFIBUS side completes the first-commissioning sync; then the PC adapter is attached
# (through the gRPC API), the RS232 port streams 0x23 measurement frames whose contour values match a known
# scene (an obstacle placed through the gRPC API, the distances computed here from the
# geometry alone), `rs4sim param set` changes the
# response time with the password, the adapter is removed (SIGUSR2), Proxy-Request comes and
# the master's proxy uploads the new set into its archive.
# Usage: rs232_scenario2.sh RS4SIM PYTHON (a python with the rs4sim package installed: the
# tests' venv, tests/rpc/python_venv_setup.py)
set -u
rs4sim=$1
python=$2
. "$(dirname "$0")/lib.sh"
fail() { bg_fail "$1"; }

# 187.5 kbit/s: the master's real-line slot time (16383 bit times) is 87 ms there (33 ms at
# 500k, 11 ms at the default 1.5M), room for a loaded CI machine that is slow to schedule the
# RS4's process. A reply lost through every retry makes the master restart the slave; the RS4
# leaves data exchange, the upload fails, and the RS4 rolls back to factory settings as
# [RS4 manual §6.4] prescribes ("Schlägt entweder der Upload oder der Download fehl, so wird der
# RS4/PROFIsafe auf seine Werkeinstellung zurück gesetzt"), so the retry has nothing to upload
# (on the manual clock: DeviceSync.LinkLostDuringTheUploadAfterRemovalRollsBackAsTheManualSays).
bg_start run "$rs4sim" run --device rs4 --address 4 --link pty --baud 187.5k --boot-time 1000 --duration 60 \
  --rs232 pty --pc-adapter detached --grpc 127.0.0.1:0
# stdout: the PROFIBUS pty, then the RS232 pty, then the API; stderr: the banner once the
# links are served and the signal handlers (SIGUSR2 below) are installed
bg_await run.out '^rs232: '
bg_await run.out '^grpc: listening on '
bg_await run.err 'Ctrl-C to stop'
bus=$(sed -n 1p "$dir/run.out")
rs232=$(sed -n 2p "$dir/run.out" | sed 's/^rs232: //')
case "$bus" in /dev/*) ;; *) fail "no PROFIBUS pty path" ;; esac
case "$rs232" in /dev/*) ;; *) fail "no 'rs232: <path>' line" ;; esac
api=$(sed -n 's/^grpc: listening on //p' "$dir/run.out")
[ -n "$api" ] || fail "no 'grpc: listening on' line"

# The known scene: a round post of radius 300 mm, 4 m straight ahead (segment 264 at 90°).
"$python" - "$api" <<'PY' || fail "AddObstacle"
import sys
from rs4sim import Rs4
Rs4(sys.argv[1], station=4).add_circle(0, 4000, 300)
PY

bg_start master "$rs4sim" master --slave 4 --link serial --port "$bus" --baud 187.5k --json --duration 20 \
  --f-wd-time 500 --dp-watchdog 1000 --archive "$dir/archive.sqlite3"

# First commissioning: factory set, empty archive (scenario 1).
bg_await master.out '"event":"proxy",.*"step":"idle",.*"config_set_to_default":true,"error_number_fb":0'

# The PC adapter attached through the API (Device.SetPcAdapter goes through the RS232 port,
# which opens with it); removed below with SIGUSR2, the command-line way.
"$python" - "$api" <<'PY' || fail "SetPcAdapter"
import sys
from rs4sim import Rs4
Rs4(sys.argv[1], station=4).set_pc_adapter(True)
PY
/usr/bin/python3 - "$rs232" <<'PY' || fail "no 0x23 measurement frames on the RS232 port"
import os, select, sys, termios, time
fd = os.open(sys.argv[1], os.O_RDWR | os.O_NOCTTY)
attrs = termios.tcgetattr(fd)
attrs[0] = attrs[1] = attrs[3] = 0          # raw
attrs[2] = termios.CS8 | termios.CREAD | termios.CLOCAL
termios.tcsetattr(fd, termios.TCSANOW, attrs)


# Frames: 00 00 | body (zero-stuffed: FF after two 00) | CHK | 00 00 00; CHK = XOR of the sent
# body bytes, 0x00 sent as 0xFF ([roboticslibrary/rl LeuzeRs4.cpp], docs/rs232.md).
def good_frames(data):
    good = 0
    for raw in data.split(b"\x00\x00\x00"):
        raw = raw.lstrip(b"\x00")
        if len(raw) < 3 or raw[0] != 0x23:
            continue
        body, chk = raw[:-1], raw[-1]
        x = 0
        for b in body:
            x ^= b
        if (x or 0xFF) == chk:
            good += 1
    return good


# The stream runs from the moment the adapter is attached: read until three whole frames are
# in (the deadline is for a loaded machine), then drop what follows the last frame's end.
data = b""
end = time.time() + 20
while good_frames(data) < 3 and time.time() < end:
    if select.select([fd], [], [], 0.1)[0]:
        data += os.read(fd, 65536)
os.close(fd)
data = data[:data.rfind(b"\x00\x00\x00") + 3]
good = good_frames(data)
print(f"0x23 frames with a good check byte: {good}")
if good < 2:
    sys.exit(1)

# The contour of the last whole frame ([RS4 manual §5.2.3.4], docs/rs232.md): 0x23 | OPT1
# (bits 1..0: the number of option bytes, OPT1 included) | scan number (8) | step | start u16 |
# stop u16 |
# one big-endian u16 in mm per segment start, start+step, ..., stop. On the line a 0x00 that
# follows a 0x00 is followed by a stuffed 0xFF, which the receiver drops.
import math
def unstuff(raw):
    out, zeros = bytearray(), 0
    for b in raw:
        if zeros >= 2 and b == 0xFF:
            zeros = 0
            continue
        out.append(b)
        zeros = zeros + 1 if b == 0 else 0
    return bytes(out)
frames = [f for f in (unstuff(r.lstrip(b"\x00")) for r in data.split(b"\x00\x00\x00"))
          if len(f) > 20 and f[0] == 0x23]
body = frames[-1][:-1]
i = 1 + (body[1] & 0x03) + 8
step = body[i]; start = body[i + 1] << 8 | body[i + 2]; stop = body[i + 3] << 8 | body[i + 4]
values = body[i + 5:]
contour = {start + k * step: values[2 * k] << 8 | values[2 * k + 1]
           for k in range(len(values) // 2)}
# Segment n looks along -5.04° + n·0.36°, counter-clockwise from +x; the post's edge along
# that beam is the nearer root of |t·(cos, sin) - (0, 4000)| = 300.
def expected(n):
    a = math.radians(-5.04 + 0.36 * n)
    b = 4000 * math.sin(a)
    disc = b * b - (4000 * 4000 - 300 * 300)
    return None if disc < 0 else round(b - math.sqrt(disc))
checked = 0
for n in range(240, 290):
    if n not in contour:
        continue
    want = expected(n)
    got = contour[n]
    if want is None:
        ok = got == 0xFFFE  # no echo within range (docs/rs4-scanner.md)
    else:
        ok = abs(got - want) <= 1
    if not ok:
        print(f"segment {n}: {got} mm, expected {want}")
        sys.exit(1)
    checked += 1
print(f"contour: {checked} segments around the post as the geometry says "
      f"(segment 264: {contour.get(264)} mm)")
sys.exit(0 if checked >= 10 and contour.get(264) == 3700 else 1)
PY

"$rs4sim" param get --port "$rs232" >"$dir/site.json" 2>"$dir/param.err" || fail "param get: $(cat "$dir/param.err")"
/usr/bin/python3 - "$dir/site.json" <<'PY' || fail "the document has no response_time_ms"
import json, sys
doc = json.load(open(sys.argv[1]))
assert doc["response_time_ms"] == 80, doc["response_time_ms"]
doc["response_time_ms"] = 160
json.dump(doc, open(sys.argv[1], "w"))
PY
"$rs4sim" param set "$dir/site.json" --port "$rs232" >"$dir/param.out" 2>"$dir/param.err" &&
  fail "param set without the password was accepted"
"$rs4sim" param set "$dir/site.json" --port "$rs232" --password ROD4LE \
  >"$dir/param.out" 2>"$dir/param.err" || fail "param set: $(cat "$dir/param.err")"

bg_signal run USR2  # the PC adapter removed: Proxy-Request, the proxy uploads the new set
bg_wait master
rc=$bg_rc
[ $rc -eq 0 ] || fail "rs4sim master exited with $rc"
grep -q '"event":"proxy",.*"step":"upload' "$dir/master.out" || fail "no upload step"
# The manual's rollback after a failed upload: say so rather than "not archived".
if sed -n '/"step":"upload/,$p' "$dir/master.out" | grep -q '"config_set_to_default":true'; then
  fail "the upload failed (the link was lost on a loaded machine) and the RS4 rolled back to its factory settings, as the manual prescribes after a failed upload"
fi
"$rs4sim" param get --archive "$dir/archive.sqlite3" --address 4 >"$dir/archived.json" \
  2>"$dir/param.err" || fail "param get --archive: $(cat "$dir/param.err")"
grep -q '"response_time_ms": *160' "$dir/archived.json" || fail "the archive does not hold the new set"
echo "scenario 2 over the RS232 port: set changed through the PC adapter, uploaded and archived"
