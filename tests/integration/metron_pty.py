#!/usr/bin/python3
"""`rs4sim run --device metron --link pty` end to end: raw bytes in, answers checked byte for
byte (docs/metron.md "Example bytes"). Standard library only (os, termios, through
tests/rpc/script_support.py); no code of the simulator on this side.
Usage: metron_pty.py <path of rs4sim>"""
import os
import subprocess
import sys
import time

# The pty opened raw, read until quiet: shared with the Python tests of tests/rpc.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "rpc"))
from script_support import open_raw, read_quiet  # noqa: E402

RS4SIM = sys.argv[1]
failures = []


def start(*flags):
    proc = subprocess.Popen([RS4SIM, "run", "--device", "metron", "--link", "pty",
                             "--duration", "20", *flags],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    path = ""
    for _ in range(10):  # notes on stderr may come first
        path = proc.stdout.readline().decode().strip()
        if path.startswith("/dev/") or not path:
            break
    if not path.startswith("/dev/"):
        rest = proc.stdout.read().decode() if proc.poll() is not None else ""
        sys.exit(f"no pty path from rs4sim run {' '.join(flags)}: {path!r} {rest}")
    # The banner ("...; Ctrl-C to stop") once the device serves the pty: a request sent from
    # then on is read.
    seen = []
    while not seen or "Ctrl-C to stop" not in seen[-1]:
        line = proc.stdout.readline().decode()
        if not line:
            sys.exit(f"rs4sim run {' '.join(flags)} ended before its banner: {''.join(seen)!r}")
        seen.append(line)
    return proc, open_raw(path, vtime=2)  # read() gives up after 0.2 s of silence


def check(name, fd, request, expected):
    os.write(fd, bytes(request))
    got = read_quiet(fd)
    if got != bytes(expected):
        failures.append(f"{name}: sent {bytes(request).hex(' ')}, expected "
                        f"{bytes(expected).hex(' ') or '(nothing)'}, got {got.hex(' ') or '(nothing)'}")
    else:
        print(f"ok  {name}: {bytes(request).hex(' ')} -> {got.hex(' ') or '(no reply)'}")


def stop(proc, fd):
    os.close(fd)
    proc.terminate()
    proc.wait(timeout=10)


# Slave line mode, no node, beams 9-13 of 24 interrupted.
proc, fd = start("--beams", "24", "--blocked", "9-13")
check("OSSD status (beams interrupted: both OFF)", fd,
      [0x02, 0x01, 0x0C, 0xF3], [0x02, 0x03, 0x0C, 0x00, 0x00, 0xF3])
check("all beams", fd, [0x02, 0x02, 0x09, 0x00, 0xF6], [0x02, 0x04, 0x09, 0x00, 0x1F, 0x00, 0xD7])
check("beam 10", fd, [0x02, 0x02, 0x09, 0x0A, 0xEC], [0x02, 0x02, 0x09, 0x01, 0xF5])
check("measurements first, last, count", fd, [0x02, 0x04, 0x0A, 0x01, 0x02, 0x03, 0xEF],
      [0x02, 0x04, 0x0A, 0x09, 0x0D, 0x05, 0xDA])
check("configuration", fd, [0x02, 0x01, 0x0B, 0xF4],
      [0x02, 0x06, 0x0B, 0x18, 0x00, 0x00, 0x0A, 0x14, 0xBE])
check("E1 bad checksum", fd, [0x02, 0x01, 0x0C, 0xF4], [0x02, 0x01, 0xE1, 0x1E])
check("E1 length 7", fd, [0x02, 0x07, 1, 2, 3, 4, 5, 6, 7, 0], [0x02, 0x01, 0xE1, 0x1E])
check("E2 wrong length", fd, [0x02, 0x02, 0x0C, 0x00, 0xF3], [0x02, 0x01, 0xE2, 0x1D])
check("E5 stop without start", fd, [0x02, 0x01, 0x08, 0xF7], [0x02, 0x01, 0xE5, 0x1A])
check("noise, then a good frame", fd, [0x55, 0xAA, 0x02, 0x01, 0x0D, 0xF2],
      [0x02, 0x02, 0x0D, 0x23, 0xCF])
check("truncated frame: no reply", fd, [0x02, 0x02, 0x09], [])
check("next good frame after it", fd, [0x02, 0x01, 0x0C, 0xF3], [0x02, 0x03, 0x0C, 0x00, 0x00, 0xF3])
check("reset software: no reply", fd, [0x02, 0x01, 0x01, 0xFE], [])
# The Receiver is deaf for 500 ms after Reset software (metron/options.h reset_time); the
# check above already waited its 0.2 s of silence: this is the device's timing, not a wait for
# the process.
time.sleep(0.5)
check("after the reset", fd, [0x02, 0x01, 0x0D, 0xF2], [0x02, 0x02, 0x0D, 0x23, 0xCF])
stop(proc, fd)

# Node 5: own address, another address, broadcast.
proc, fd = start("--node", "5")
check("node 5 OSSD status", fd, [0x02, 0x05, 0x01, 0x0C, 0xF3],
      [0x02, 0x05, 0x03, 0x0C, 0x01, 0x01, 0xF1])
check("node 6: ignored", fd, [0x02, 0x06, 0x01, 0x0C, 0xF3], [])
check("broadcast disable OSSD: executed, no reply", fd, [0x02, 0xFF, 0x01, 0x03, 0xFC], [])
check("node 5 sees OSSDs OFF", fd, [0x02, 0x05, 0x01, 0x0C, 0xF3],
      [0x02, 0x05, 0x03, 0x0C, 0x00, 0x00, 0xF3])
check("broadcast request: no reply", fd, [0x02, 0xFF, 0x01, 0x0D, 0xF2], [])
stop(proc, fd)

# Standard line mode, on request, hex with separator and checksum.
proc, fd = start("--mode", "on-request,hex,separator,checksum", "--blocked", "9-13")
check("report on request", fd, [0x3F],
      [0x02, 0x30, 0x39, 0x2C, 0x30, 0x44, 0x2C, 0x30, 0x35, 0xE4, 0x03])
stop(proc, fd)

if failures:
    print("\n".join(failures), file=sys.stderr)
    sys.exit(1)
print("all METRON pty exchanges match")
