"""`rs4sim run --device gridscan|metron|polaris --link memory --grpc` driven by the Python
harness: the devices on the simulated clock, no pty. The known answers are the manuals' frames
as fixed bytes: the GridScan's power-up messages and the last step of the communication test
of [GridScan manual §10.3]; the Polaris's P7 [Polaris manual §8.2.3] with the beams of its
example (9-13, 25-34 of 40); the METRON's "status of all the beams" in node mode, laid out as
[METRON manual "With node"] gives it. Wire time at 115200 8N1: 10 bits a character. The LATE
fault through inject_fault(late=seconds) and its deprecated spellings late_ms=/delay_ms=
(a DeprecationWarning): the Polaris's reply leaves exactly that much later on the simulated clock.
Usage: python_line_memory_test.py RS4SIM REPO   (exit 77 = skipped: no python3-grpcio)"""
import sys
import warnings

from script_support import require_grpc, with_crc

grpc = require_grpc()

rs4sim, repo = sys.argv[1], sys.argv[2]
from rs4sim import GridScan, Metron, Polaris, error_details  # noqa: E402
from rs4sim.process import Rs4simProcess  # noqa: E402

VERSION = bytes([0x43, 0x45, 0x44, 0x45, 0x00, 0xA0, 0x30, 0x31, 0x2E, 0x30, 0x32,
                 0x30, 0x33, 0x2E, 0x30, 0x34, 0x33, 0x7F, 0x67, 0x4B])
REDUCED = bytes([0x43, 0x45, 0x44, 0x45, 0x01, 0xB0, 0x16, 0x00, 0x69, 0x78, 0x27, 0x24])
# The manual's first step: sync, SeqCnt and CRC all wrong -> error bits 0x07.
TEST_REQUEST = bytes([0x00, 0x00, 0x00, 0x00, 0x00, 0x23, 0x00, 0x00, 0x00, 0x00])
TEST_ANSWER = bytes([0x43, 0x45, 0x44, 0x45, 0x01, 0xA3, 0x07, 0xEF, 0x30, 0x3F, 0x78])


def wire_ns(chars, bits, baud):
    return -(-chars * bits * 10**9 // baud)  # rounded up


def check(cond, what):
    if not cond:
        print("FAILED:", what)
        sys.exit(1)


def gridscan():
    proc = Rs4simProcess(["run", "--device", "gridscan", "--link", "memory",
                          "--grpc", "127.0.0.1:0"], executable=rs4sim)
    try:
        with GridScan(proc.address) as g:
            t0 = g.now()
            frames = g.receive(1.702)
            check([f.frame for f in frames] == [VERSION, REDUCED], f"power-up messages {frames}")
            check(frames[1].start_ns - frames[0].start_ns == 1_700_000_000, "ready after 1700 ms")
            x = g.exchange(TEST_REQUEST)
            check(x.answered and x.reply == TEST_ANSWER, f"communication test answer {x}")
            check(x.reply_start_ns == frames[1].start_ns + 30_000_000, "answered at cycle end")
            check(x.reply_end_ns - x.reply_start_ns == wire_ns(11, 10, 115200), "wire time")
            check(x.reply_after_ns == x.reply_end_ns - x.sent_ns, "reply_after_ns")
            # The power cycle re-runs the power-up: SeqCnt from 0 again.
            g.power_cycle(0.1)
            frames = g.receive(1.702)
            check([f.frame for f in frames] == [VERSION, REDUCED], "power-up after the cycle")
            x = g.exchange(TEST_REQUEST)
            check(x.answered and x.reply == TEST_ANSWER, f"the same answer after the cycle {x}")
            check(g.now() > t0, "the clock moved")
            # Stuck elements fail the controller's check [GridScan manual §10.1.2]: element 3
            # blocked reads interrupted (state bit 8), stuck free it reads free, unstuck it
            # reads interrupted again. Reduced state: door 0x16 (22 elements, open), bits 8-15.
            check(crc32_mpeg2(REDUCED[4:-4]) == REDUCED[-4:], "CRC-32/MPEG-2 of the manual")
            g.set_blocked([3])
            seq = 2  # the device sent 0 (A0), 1 (B0) and the test answer 1: the next is 2
            for action, bit8 in ((None, 1), (lambda: g.stick_free([3]), 0), (g.unstick, 1)):
                if action:
                    action()
                x = g.exchange(seal(seq, 0x30, b""))
                check(x.answered and x.reply == seal(seq + 1, 0xB0, bytes([0x16, bit8])),
                      f"reduced state, bit 8 = {bit8}: {x.reply.hex()}")
                seq += 2
            try:
                g.exchange(b"")
                check(False, "an empty request is refused")
            except grpc.RpcError as e:
                check(e.code() == grpc.StatusCode.INVALID_ARGUMENT, f"code {e.code()}")
                check("request" in str(error_details(e)), f"the field: {error_details(e)}")
    finally:
        proc.stop()


def crc32_mpeg2(data):
    """CRC-32/MPEG-2 (poly 0x04C11DB7, init all ones, no reflection), least significant
    byte first on the wire [GridScan manual §9.2]."""
    crc = 0xFFFFFFFF
    for b in data:
        crc ^= b << 24
        for _ in range(8):
            crc = ((crc << 1) ^ 0x04C11DB7) & 0xFFFFFFFF if crc & 0x80000000 else (crc << 1) & 0xFFFFFFFF
    return crc.to_bytes(4, "little")


def seal(seq, ident, payload):
    body = bytes([seq, ident]) + payload
    return b"CEDE" + body + crc32_mpeg2(body)


def polaris():
    proc = Rs4simProcess(["run", "--device", "polaris", "--link", "memory", "--model", "PL10",
                          "--beams", "40", "--mode", "FL1", "--address", "1",
                          "--blocked", "9-13,25-34", "--grpc", "127.0.0.1:0"],
                         executable=rs4sim)
    try:
        with Polaris(proc.address, 1) as p:
            request = bytes([0x01, 0x03, 0x20, 0x00, 0x00, 0x02, 0xCF, 0xCB])
            check(with_crc(request[:-2]) == request, "the request's CRC")
            x = p.exchange(request)
            check(x.answered, "answered")
            check(x.reply == bytes([0x01, 0x03, 0x04, 0x00, 0x09, 0x00, 0x22, 0xAA, 0x28]),
                  f"P7 {x.reply.hex()}")
            check(x.arrived_ns - x.sent_ns == wire_ns(8, 10, 19200), "request wire time")
            # A broadcast is never answered: the clock runs the timeout.
            x = p.exchange(with_crc([0x00, 0x03, 0x20, 0x00, 0x00, 0x02]), timeout=0.05)
            check(not x.answered and x.now_ns - x.sent_ns == 50_000_000, f"broadcast {x}")
            before = p.now()
            check(abs(p.advance(0.25) - (before + 0.25)) < 1e-9, "SimTime.Advance in seconds")
            # LATE: the same P7 reply, late_ms later after the request's arrival. An answer
            # leaves at the end of the scan in progress (docs/polaris.md), so the wait depends
            # on where in its scan a request ends: each timed request is sent right after an
            # on-time reply (which began at a scan's end and is as long), in the same phase.
            p.exchange(request)
            x = p.exchange(request)
            on_time = x.reply_start_ns - x.arrived_ns
            y = p.exchange(request)
            check(y.sent_ns == x.reply_end_ns and y.reply_start_ns - y.arrived_ns == on_time,
                  f"the same phase gives the same wait: {y}")
            p.inject_fault("LATE", 0.04)
            check(p.state().late_ms == 40, f"late_ms {p.state().late_ms}")
            x = p.exchange(request)
            check(x.answered and x.reply_start_ns - x.arrived_ns == on_time + 40_000_000,
                  f"40 ms late: {x.reply_start_ns - x.arrived_ns} vs {on_time}")
            p.clear_fault("LATE")
            check(p.state().late_ms == 0, "LATE cleared")
            p.exchange(request)  # on time again: the next one starts in the same phase
            # delay_ms, late's oldest name (in ms): the same request, with a DeprecationWarning.
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                p.inject_fault("LATE", delay_ms=25)
            check([w.category for w in caught] == [DeprecationWarning], f"warnings {caught}")
            check("late=" in str(caught[0].message), str(caught[0].message))
            check(caught[0].filename == __file__, f"warned at {caught[0].filename}")
            check(p.state().late_ms == 25, f"delay_ms=25 gave late_ms {p.state().late_ms}")
            x = p.exchange(request)
            check(x.reply_start_ns - x.arrived_ns == on_time + 25_000_000, "25 ms late")
            # Both names at once must agree; nothing is sent when they do not.
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", DeprecationWarning)
                try:
                    p.inject_fault("LATE", late_ms=30, delay_ms=31)
                    check(False, "late_ms=30 with delay_ms=31 accepted")
                except TypeError as e:
                    check("give late (seconds) only" in str(e), str(e))
                p.inject_fault("LATE", late_ms=30, delay_ms=30)
            check(p.state().late_ms == 30, f"late_ms {p.state().late_ms}")
            # The service's own range check, the field named.
            try:
                p.inject_fault("LATE", 10.001)
                check(False, "late_ms 10001 accepted")
            except grpc.RpcError as e:
                check(e.code() == grpc.StatusCode.INVALID_ARGUMENT, f"code {e.code()}")
                check(error_details(e)[1] == [("late_ms", "10001 ms outside 1..10000")],
                      f"details {error_details(e)}")
    finally:
        proc.stop()


def metron():
    proc = Rs4simProcess(["run", "--device", "metron", "--link", "memory", "--node", "5",
                          "--blocked", "9-13", "--grpc", "127.0.0.1:0"], executable=rs4sim)
    try:
        with Metron(proc.address, 5) as m:
            # Status of all the beams (#9, data 00) to node 5: start 02, address 05, length 02,
            # command 09, data 00, checksum ~(09 + 00) = F6 (address and length not summed).
            request = bytes([0x02, 0x05, 0x02, 0x09, 0x00, 0xF6])
            # The reply: 02, node 05, length 04 (command + 3 data bytes), 09, the 24 beams a bit
            # each from beam 1 (beams 9-13 -> 00 1F 00), checksum ~(09 + 1F) = D7.
            x = m.exchange(request)
            all_beams = bytes([0x02, 0x05, 0x04, 0x09, 0x00, 0x1F, 0x00, 0xD7])
            check(x.answered and x.reply == all_beams, f"all beams {x.reply.hex()}")
            check(x.arrived_ns - x.sent_ns == wire_ns(6, 11, 19200), "request wire time (8E1)")
            # WRONG_NODE: the reply carries node 6 until cleared.
            m.inject_fault("WRONG_NODE")
            x = m.exchange(request)
            check(x.answered and x.reply[1] == 0x06, f"wrong node {x.reply.hex()}")
            m.clear_fault("WRONG_NODE")
            x = m.exchange(request)
            check(x.answered and x.reply[1] == 0x05, f"own node again {x.reply.hex()}")
            # 255 is the broadcast address, never the curtain's; another node is not this run.
            for address, code in ((255, grpc.StatusCode.INVALID_ARGUMENT),
                                  (4, grpc.StatusCode.NOT_FOUND)):
                m.address = address
                try:
                    m.exchange(request)
                    check(False, f"Exchange at {address} is refused")
                except grpc.RpcError as e:
                    check(e.code() == code, f"address {address}: code {e.code()}")
                    if address == 255:
                        check(e.details() == "address: 255 is the broadcast address "
                              "[METRON manual \"With node\"]; "
                              "the curtain's is its node (0..254), or 0 without node mode",
                              f"the message: {e.details()}")
    finally:
        proc.stop()


gridscan()
metron()
polaris()
print("ok")
