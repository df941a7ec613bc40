"""`rs4sim run --device polaris --link pty --grpc` driven by the Python harness
(the rs4sim package, python3-grpcio), checked over Modbus RTU with raw bytes on the
pty (os/termios only, no code of the project on that side): the beams blocked through the API
come back in the 485MB data block, the faults reach the wire, the event stream shows PN1, and
server reflection lists the Polaris service.

Known answers [Polaris manual §8.2]: a PL10 with 40 beams, slave 1, data block at 0x2000, one
bit per beam, 1 = free, beam 1 in bit 0; beams 9-13 and 25-34 interrupted give the words
0xE0FF (beams 1-16), 0x00FF (17-32), 0xFFFC (33-48, padded with 1s). The CRC is computed by the
tests' script_support.py, by the rule of [Modbus serial line V1.02 §6.2.2].
Usage: python_polaris_harness_test.py RS4SIM REPO   (exit 77 = skipped: no python3-grpcio)"""
import os
import signal
import sys

from script_support import (crc16, open_raw, pty_path, require_grpc, spawn, state_changes, transact,
                            with_crc)

grpc = require_grpc()

rs4sim, repo = sys.argv[1], sys.argv[2]
from rs4sim import Polaris, error_details  # noqa: E402


READ = with_crc([0x01, 0x03, 0x20, 0x00, 0x00, 0x03])  # FC 03, 0x2000, 3 words
ANSWER = with_crc([0x01, 0x03, 0x06, 0xE0, 0xFF, 0x00, 0xFF, 0xFF, 0xFC])
FREE = with_crc([0x01, 0x03, 0x06, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF])
BLOCKED = list(range(9, 14)) + list(range(25, 35))

proc = spawn(rs4sim, "run", "--device", "polaris", "--link", "pty", "--model", "PL10",
             "--beams", "40", "--address", "1", "--grpc", "127.0.0.1:0")
try:
    tty = pty_path(proc)  # byte devices: the pty path first ...
    line = proc.stdout.readline()         # ... then the API
    assert line.startswith("grpc: listening on 127.0.0.1:"), line
    polaris = Polaris(line.split()[-1], 1)
    fd = open_raw(tty)

    assert transact(fd, READ) == FREE, "all beams free at start"
    events = polaris.events()  # returns once subscribed (the snapshot arrived)
    polaris.set_blocked(BLOCKED)
    state = polaris.state()
    assert list(state.blocked) == BLOCKED and state.pn1 and state.pn2, state
    assert list(state.data_block) == [0xE0FF, 0x00FF, 0xFFFC], state.data_block

    got = transact(fd, READ)
    assert got == ANSWER, got.hex()
    state = polaris.state()
    assert state.last_frame.frame == ANSWER, state.last_frame.frame.hex()
    assert state.counters.requests == 2, state.counters

    pn1 = state_changes(events, "pn1", 2)
    assert pn1 == [("", "off"), ("off", "on")], pn1

    polaris.inject_fault("BAD_CRC")
    got = transact(fd, READ)
    assert got[:-2] == ANSWER[:-2] and crc16(got[:-2]) != got[-2:], got.hex()
    polaris.clear_fault("BAD_CRC")
    polaris.inject_fault("NO_ANSWER")
    assert transact(fd, READ) == b"", "no answer while NO_ANSWER is on"
    assert polaris.state().counters.suppressed == 1
    polaris.clear_fault("NO_ANSWER")
    assert transact(fd, READ) == ANSWER
    polaris.set_blocked([])
    assert transact(fd, READ) == FREE

    try:
        polaris.set_blocked([41])
        raise AssertionError("beam 41 of 40 accepted")
    except grpc.RpcError as e:
        code, violations, _ = error_details(e)
        assert code == "INVALID_ARGUMENT" and violations[0][0] == "blocked[0]", violations
    try:
        Polaris(line.split()[-1], 2).state()
        raise AssertionError("Modbus address 2 answered")
    except grpc.RpcError as e:
        assert e.code() == grpc.StatusCode.NOT_FOUND, e.code()

    call = polaris.channel.stream_stream(
        "/grpc.reflection.v1alpha.ServerReflection/ServerReflectionInfo")
    answer = b"".join(call(iter([b"\x3a\x00"])))  # list_services = ""
    for service in (b"rs4sim.v1.Polaris", b"rs4sim.v1.Observation"):
        assert service in answer, (service, answer)
    os.close(fd)
    print("ok: blocked beams, faults and events of the Polaris through the API and Modbus")
finally:
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=20)
    assert proc.returncode == 0, (proc.returncode, err)
    assert "polaris: requests" in out, out
