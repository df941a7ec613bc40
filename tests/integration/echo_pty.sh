#!/bin/sh
# `rs4sim run --device echo --link pty`: the byte-device path of the shell end to end. The
# first stdout line is the pty path; a raw client writes a frame and reads it back after the
# idle gap; SIGINT ends the run with exit 0 and the status line. Usage: echo_pty.sh RS4SIM
set -u
rs4sim=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$rs4sim" run --device echo --link pty --baud 115200 --format 8E1 --duration 20 \
  >"$dir/out" 2>"$dir/err" &
pid=$!
i=0
while [ ! -s "$dir/out" ] && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
path=$(head -n 1 "$dir/out")
case "$path" in
  /dev/*) ;;
  *) echo "no pty path first"; cat "$dir/err"; kill "$pid"; exit 1 ;;
esac
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
kill -INT "$pid"
wait "$pid"
rc=$?
cat "$dir/out" "$dir/err"
[ $client -eq 0 ] || exit 1
[ $rc -eq 0 ] || { echo "exit $rc"; exit 1; }
grep -q 'echo: frames echoed 1, oversized 0, bytes received 4, sent 4' "$dir/out" || exit 1
grep -q '115200 8E1' "$dir/err" || exit 1
