#!/bin/sh
# `rs4sim run --device echo --link pty`: the byte-device path of the shell end to end. The
# first stdout line is the pty path; a raw client writes a frame and reads it back after the
# idle gap; SIGINT ends the run with exit 0 and the status line. Usage: echo_pty.sh RS4SIM
set -u
rs4sim=$1
. "$(dirname "$0")/lib.sh"
bg_start echo "$rs4sim" run --device echo --link pty --baud 115200 --format 8E1 --duration 20
bg_await echo.out '.'
path=$(head -n 1 "$dir/echo.out")
case "$path" in
  /dev/*) ;;
  *) bg_fail "no pty path first" ;;
esac
# the banner: the SIGINT handler is installed
bg_await echo.err 'Ctrl-C to stop'
python3 - "$path" <<'PY'
import os, select, sys, time, tty
fd = os.open(sys.argv[1], os.O_RDWR | os.O_NOCTTY)
tty.setraw(fd)
frame = bytes([0x02, 0x10, 0x20, 0x03])
os.write(fd, frame)
got, end = b"", time.time() + 10
while len(got) < len(frame) and time.time() < end:
    if select.select([fd], [], [], 0.1)[0]:
        got += os.read(fd, 64)
sys.exit(0 if got == frame else f"echo: got {got.hex()}, want {frame.hex()}")
PY
client=$?
bg_stop echo INT
rc=$bg_rc
cat "$dir/echo.out" "$dir/echo.err"
[ $client -eq 0 ] || exit 1
[ $rc -eq 0 ] || { echo "exit $rc"; exit 1; }
grep -q 'echo: frames echoed 1, oversized 0, bytes received 4, sent 4' "$dir/echo.out" || exit 1
grep -q '115200 8E1' "$dir/echo.err" || exit 1
