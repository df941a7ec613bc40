#!/usr/bin/env python3
"""`rs4sim run --device gridscan --link pty` against raw bytes, checked byte for byte.

No code of the simulator on this side: the script opens the pty with os/termios only, reads the
power-up messages, plays the communication-test exchange of [GridScan manual §10.3],
sends a request with a bad CRC (no reply) and asks for the full state of the scene given
on the command line (--door 10 --blocked 3). Then --mains off: silent until SIGUSR1.
Usage: gridscan_pty.py <path to rs4sim>
"""
import os
import signal
import select
import subprocess
import sys
import time

# The pty opened raw: shared with the Python tests of tests/rpc.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "rpc"))
from script_support import open_raw  # noqa: E402

SYNC = [0x43, 0x45, 0x44, 0x45]
# The power-up version message: SeqCnt 0, ID 0xA0, "01.02" (SW) "03.04" (HW), CRC32.
POWER_UP_VERSION = SYNC + [0x00, 0xA0, 0x30, 0x31, 0x2E, 0x30, 0x32, 0x30, 0x33, 0x2E, 0x30,
                           0x34, 0x33, 0x7F, 0x67, 0x4B]


def exited_ok(proc, what):
    rc = proc.wait(timeout=15)
    if rc != 0:
        print(f"FAIL {what} exited {rc}")
        sys.exit(1)


def read_exactly(fd, n, timeout):
    out = b""
    end = time.monotonic() + timeout
    while len(out) < n:
        left = end - time.monotonic()
        if left <= 0:
            break
        ready, _, _ = select.select([fd], [], [], left)
        if ready:
            out += os.read(fd, n - len(out))
    return list(out)


def expect(fd, what, frame, timeout=1.0):
    got = read_exactly(fd, len(frame), timeout)
    if got != frame:
        print(f"FAIL {what}:\n  expected {bytes(frame).hex(' ')}\n  got      {bytes(got).hex(' ')}")
        sys.exit(1)
    print(f"ok   {what}: {bytes(got).hex(' ')}")


def main():
    proc = subprocess.Popen(
        [sys.argv[1], "run", "--device", "gridscan", "--link", "pty", "--door", "10",
         "--blocked", "3", "--duration", "6"],
        stdout=subprocess.PIPE, text=True)
    fd = open_raw(proc.stdout.readline().strip(), vtime=0)
    try:
        expect(fd, "power-up version (SeqCnt 0, SW 01.02, HW 03.04)",
               POWER_UP_VERSION)
        expect(fd, "power-up reduced state (SeqCnt 1, door 10, interrupted)",
               SYNC + [0x01, 0xB0, 0x0A, 0x01, 0x36, 0x9C, 0xDB, 0xFF], timeout=3.0)
        exchange = [  # [GridScan manual §10.3]
            ([0, 0, 0, 0, 0x00, 0x23, 0, 0, 0, 0], SYNC + [0x01, 0xA3, 0x07, 0xEF, 0x30, 0x3F, 0x78]),
            ([0, 0, 0, 0, 0x02, 0x23, 0, 0, 0, 0], SYNC + [0x03, 0xA3, 0x05, 0x8F, 0x52, 0x0C, 0x72]),
            (SYNC + [0x04, 0x23, 0, 0, 0, 0], SYNC + [0x05, 0xA3, 0x01, 0x41, 0xCF, 0xDB, 0x65]),
            (SYNC + [0x06, 0x23, 0xE2, 0x4B, 0x01, 0x70],
             SYNC + [0x07, 0xA3, 0x00, 0xF8, 0x8B, 0xAB, 0x62]),
        ]
        for i, (request, answer) in enumerate(exchange):
            os.write(fd, bytes(request))
            expect(fd, f"communication test {i + 1}", answer)
            time.sleep(0.05)  # one request per t_CYCLE
        os.write(fd, bytes(SYNC + [0x08, 0x31, 0x08, 0x57, 0x0C, 0x5B]))  # CRC off by one bit
        silence = read_exactly(fd, 1, 0.2)
        if silence:
            print(f"FAIL bad CRC answered: {bytes(silence).hex(' ')}")
            sys.exit(1)
        print("ok   bad CRC: no reply")
        os.write(fd, bytes(SYNC + [0x08, 0x31, 0x08, 0x57, 0x0C, 0x5A]))  # Full state
        expect(fd, "full state (door 10, element 3 and the door's 11..22 interrupted)",
               SYNC + [0x09, 0xB1,
                       0x0A,              # door position 10
                       0x01,              # bit 8: an element below the edge interrupted
                       0x04, 0xFC, 0x3F,  # elements 3, 11..22
                       0x74, 0xE5, 0x5F, 0x05])
        # SIGUSR1: a power cycle once the line is open: the power-up messages again, SeqCnt 0.
        proc.send_signal(signal.SIGUSR1)
        expect(fd, "power-up version after SIGUSR1",
               POWER_UP_VERSION)
        expect(fd, "power-up reduced state after SIGUSR1",
               SYNC + [0x01, 0xB0, 0x0A, 0x01, 0x36, 0x9C, 0xDB, 0xFF], timeout=3.0)
    finally:
        os.close(fd)
    exited_ok(proc, "rs4sim")
    mains_off(sys.argv[1])
    print("all answers as expected")


def mains_off(rs4sim):
    """--mains off: the line stays silent after the client has opened it, until SIGUSR1
    switches the mains on; then the power-up messages, SeqCnt from 0."""
    proc = subprocess.Popen(
        [rs4sim, "run", "--device", "gridscan", "--link", "pty", "--mains", "off",
         "--duration", "3"], stdout=subprocess.PIPE, text=True)
    fd = open_raw(proc.stdout.readline().strip(), vtime=0)
    try:
        early = read_exactly(fd, 1, 0.5)
        if early:
            print(f"FAIL --mains off sent {bytes(early).hex(' ')} before SIGUSR1")
            sys.exit(1)
        print("ok   --mains off: silent until switched on")
        proc.send_signal(signal.SIGUSR1)
        expect(fd, "power-up version after --mains off and SIGUSR1",
               POWER_UP_VERSION)
    finally:
        os.close(fd)
    exited_ok(proc, "rs4sim --mains off")


if __name__ == "__main__":
    main()
