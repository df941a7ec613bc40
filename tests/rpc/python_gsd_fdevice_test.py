"""rs4sim.GsdStations' PROFIsafe F-module calls against `rs4sim run --device generic --gsd FILE
--link memory --grpc`: our master on the simulated bus runs an F-host for the station's
F-module. Two runs: the project's tests/gsd/corpus/f_module_v1.gsd (a drive's "PROFIsafe v1.x
Module" after a standard module: slot 1, 4 F-data bytes, V1, F_WD_Time 100 ms, F_Par_CRC 0x783E
as its maker wrote it) and f_module_v2.gsd (an F-Link's preset F-module: slot 0, 8 F-data bytes,
V2 with a 3-byte CRC2, F_WD_Time 150 ms, F_Par_CRC 0xBB95). In each the F-inputs set reach the
host, the F-outputs the host sends reach the device, and every fault injected into the device's
safety PDUs shows at the host as [IEC 61784-3-3 F-Host behaviour] says (CRC2 or consecutive
number: passivated at once; stale or late answers: a timeout after F_WD_Time; a wrong
F_Dest_Add at start-up: diagnosis 64, the standard's number, with the GSD's text where it has
one), then ACK_REQ and the operator's acknowledgement; the event stream carries it all.
Usage: python_gsd_fdevice_test.py RS4SIM REPO   (exit 77 = skipped: no python3-grpcio)"""
import os
import sys

from script_support import require_grpc

grpc = require_grpc()

rs4sim, repo = sys.argv[1], sys.argv[2]
from rs4sim import GsdStations, error_details  # noqa: E402
from rs4sim.process import Rs4simProcess  # noqa: E402

CORPUS = os.path.join(repo, "tests/gsd/corpus")
# (file, modules, F-module slot, mode, F-data, F_WD_Time s, diagnosis 64's text)
RUNS = [
    ("f_module_v1.gsd", ["Standard telegram 1, PZD-2/2", "PROFIsafe v1.x Module"], 1, "V1", 4,
     0.1, "F add. does not match F_Dest_Add"),  # the GSD's X_Value(64)
    ("f_module_v2.gsd", [], 0, "V2", 8, 0.15,
     "Mismatch of safety destination address (F_Dest_Add)"),  # none in the GSD: the standard's
]


def reintegrate(gsd, slot):
    """Healthy again: ACK_REQ; the operator's acknowledgement brings the host back to run."""
    gsd.advance(0.5)
    assert gsd.f_module(5, slot).host.state == "ack-required", gsd.f_module(5, slot)
    gsd.ack_f_host(5, slot)
    gsd.advance(0.05)
    assert gsd.f_module(5, slot).host.state == "run", gsd.f_module(5, slot)


def scenario(gsd, slot, mode, size, wd, text):
    events = gsd.events([5])
    gsd.advance(1.0)
    m = gsd.f_module(5, slot)
    assert (m.mode, m.state, m.host.state, m.f_data_length) == (mode, "run", "run", size), m
    assert m.f_wd_time_ms == round(wd * 1000), m

    f_in = bytes(range(0x11, 0x11 + size))
    gsd.set_f_inputs(5, slot, f_in)
    gsd.set_f_outputs(5, slot, bytes([0xA5] * size))
    gsd.advance(0.05)
    m = gsd.f_module(5, slot)
    assert m.host.f_inputs == f_in and m.f_outputs == bytes([0xA5] * size), m

    # Refused: the wrong F-input length, a slot without an F-module, no ACK_REQ to acknowledge.
    try:
        gsd.set_f_inputs(5, slot, b"\x01")
        raise AssertionError("1 F-input byte accepted")
    except grpc.RpcError as e:
        assert e.code() == grpc.StatusCode.INVALID_ARGUMENT, e
        assert error_details(e)[1][0][0] == "data", error_details(e)
    try:
        gsd.ack_f_host(5, slot)
        raise AssertionError("an acknowledgement without ACK_REQ accepted")
    except grpc.RpcError as e:
        assert e.code() == grpc.StatusCode.FAILED_PRECONDITION, e

    # CRC2 and consecutive number: the host passivates at once (V2 sends no number: a wrong
    # virtual number is a CRC2 fault at the host).
    gsd.inject_f_fault(5, slot, "CORRUPT_CRC2")
    gsd.advance(0.02)
    host = gsd.f_module(5, slot).host
    assert (host.crc_errors, host.passivations, host.last_fault) == (1, 1, "CRC2 error"), host
    assert host.f_inputs == bytes(size), host  # the substitute values
    reintegrate(gsd, slot)
    gsd.inject_f_fault(5, slot, "WRONG_NUMBER")
    gsd.advance(0.02)
    host = gsd.f_module(5, slot).host
    expected = (1, 1) if mode == "V1" else (0, 2)  # (number, CRC2) faults since the start
    assert (host.number_errors, host.crc_errors, host.passivations) == expected + (2,), host
    reintegrate(gsd, slot)
    # Stale answers (the previous PDU repeated) and answers held back: a timeout only past
    # F_WD_Time (one poll every 10 ms).
    gsd.inject_f_fault(5, slot, "REPEAT_NUMBER", count=round(wd * 1000 / 10) + 10)
    gsd.advance(wd + 0.2)
    host = gsd.f_module(5, slot).host
    assert (host.watchdog_timeouts, host.passivations) == (1, 3), host
    reintegrate(gsd, slot)
    gsd.inject_f_fault(5, slot, "DELAY", delay=wd / 2)
    gsd.advance(wd * 2)
    assert gsd.f_module(5, slot).host.passivations == 3  # within F_WD_Time: no fault
    gsd.inject_f_fault(5, slot, "DELAY", delay=wd * 2)
    gsd.advance(wd * 3)
    host = gsd.f_module(5, slot).host
    assert (host.watchdog_timeouts, host.passivations) == (2, 4), host
    reintegrate(gsd, slot)
    # The address switch at 2 and a power-up: our master's F_Dest_Add 1 is refused, 64.
    gsd.inject_f_fault(5, slot, "WRONG_F_DEST_ADD", f_dest_add=2)
    gsd.advance(0.5)
    m = gsd.f_module(5, slot)
    assert (m.state, m.diagnosis, m.diagnosis_text) == ("parameter-fault", 64, text), m
    assert m.host.state == "passivated" and gsd.station(5).dp_state != "Data_Exch", m
    assert list(gsd.station(5).diagnosis_texts) == [text], gsd.station(5)
    gsd.clear_f_faults(5, slot)
    reintegrate(gsd, slot)

    # The event stream: the host's five passivations each acknowledged, the device's states
    # and the diagnosis with its text, the F-inputs set.
    seen = {}
    for event in events:
        if event.HasField("state"):
            seen.setdefault(event.state.what, []).append(event.state.to)
            if seen.get("fhost-state", []).count("run") == 6:
                break
    events.cancel()
    assert seen["fhost-state"] == ["startup", "run"] + ["passivated", "ack-required", "run"] * 5, \
        seen["fhost-state"]
    for state in ("waiting-for-parameters", "run", "passivated", "parameter-fault"):
        assert state in seen["fdevice-state"], seen["fdevice-state"]
    assert "64: " + text in seen["fdevice-diagnosis"], seen["fdevice-diagnosis"]
    assert " ".join("%02x" % b for b in f_in) in seen["f-inputs"], seen["f-inputs"]


for file, modules, slot, mode, size, wd, text in RUNS:
    args = ["run", "--device", "generic", "--gsd", os.path.join(CORPUS, file)]
    for name in modules:
        args += ["--module", name]
    sim = Rs4simProcess(args + ["--address", "5", "--baud", "12M", "--link", "memory", "--grpc",
                                "127.0.0.1:0"], executable=rs4sim)
    try:
        with GsdStations(sim.address) as gsd:
            scenario(gsd, slot, mode, size, wd, text)
        print("GSD F-device %s (%s): ok" % (mode, file))
    finally:
        sim.stop()
