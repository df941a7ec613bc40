"""`rs4sim run --device generic --gsd FILE --link pty --grpc` driven by the Python harness
(rs4sim.GsdStations, python3-grpcio): the station as its GSD describes it, a module's inputs set
and read back, the refusals with their details, the event stream's "inputs" and "online"
changes, and off the bus: an FDL_Status request on the pty gets no answer until the station is
back [IEC 61158-4-3 FDL_Status]; the replies' turnaround (link_timing) counts the answered
requests; the bus faults refused on the pty (FAILED_PRECONDITION, docs/gsd.md). Then the same
station on the simulated bus (`--link memory`): the bus faults act on its clock (the master's
requests dropped, the station hears no Data_Exchange until ClearBusFaults). The GSD is the
project's tests/gsd/corpus/modular_dpv1.gsd ("DI 8": 1 input byte, "AI 2": 4, "DO 16
consistent": 2 output bytes; ident 0xB756).
Usage: python_gsd_harness_test.py RS4SIM REPO   (exit 77 = skipped: no python3-grpcio)"""
import os
import sys

from script_support import open_raw, pty_path, require_grpc, spawn, transact

grpc = require_grpc()

rs4sim, repo = sys.argv[1], sys.argv[2]
from rs4sim import GsdStations, error_details  # noqa: E402
from rs4sim.process import Rs4simProcess  # noqa: E402

# SD1 request, DA 5, SA 1, FC 0x49 (Request FDL Status), FCS = (5 + 1 + 0x49) mod 256, ED.
FDL_STATUS = bytes([0x10, 0x05, 0x01, 0x49, 0x4F, 0x16])


gsd = os.path.join(repo, "tests/gsd/corpus/modular_dpv1.gsd")
proc = spawn(rs4sim, "run", "--device", "generic", "--gsd", gsd, "--module", "DI 8",
             "--module", "AI 2", "--module", "DO 16 consistent", "--address", "5",
             "--baud", "12M", "--link", "pty", "--grpc", "127.0.0.1:0")
try:
    tty = pty_path(proc)
    line = proc.stdout.readline()
    assert line.startswith("grpc: listening on 127.0.0.1:"), line
    stations = GsdStations(line.split()[-1])
    fd = open_raw(tty)

    [station] = stations.stations()
    assert station.address == 5 and station.ident_number == 0xB756, station
    assert [(m.name, m.input_length, m.output_length) for m in station.modules] == [
        ("DI 8", 1, 0), ("AI 2", 4, 0), ("DO 16 consistent", 0, 2)], station.modules
    assert station.dp_state == "Wait_Prm" and station.online, station
    assert list(station.alarms) == ["diagnostic", "process"], station.alarms

    events = stations.events([5])
    stations.set_inputs(5, 1, b"\x11\x22\x33\x44")
    assert stations.inputs(5, 1) == b"\x11\x22\x33\x44"
    assert stations.outputs(5, 2) == b"\x00\x00"  # no master has written yet

    try:
        stations.set_inputs(5, 1, b"\x11")
        raise AssertionError("1 byte for a 4-byte module accepted")
    except grpc.RpcError as e:
        assert e.code() == grpc.StatusCode.INVALID_ARGUMENT, e
        _, [(field, description)], _ = error_details(e)
        assert field == "data", field
        assert description == '1 bytes; module "AI 2" (slot 1) has 4 input bytes', description
    try:
        stations.station(9)
        raise AssertionError("station 9 found")
    except grpc.RpcError as e:
        assert e.code() == grpc.StatusCode.NOT_FOUND, e
    try:
        stations.raise_alarm(5, "status")
        raise AssertionError("a status alarm the GSD does not declare accepted")
    except grpc.RpcError as e:
        assert e.code() == grpc.StatusCode.FAILED_PRECONDITION, e
        _, _, [(kind, subject, description)] = error_details(e)
        assert (kind, subject) == ("GSD", "station 5"), (kind, subject)
        assert "does not declare Status_Alarm_supp = 1" in description, description

    answer = transact(fd, FDL_STATUS)
    assert answer[:3] == bytes([0x10, 0x01, 0x05]), answer.hex()
    stations.set_online(5, False)
    assert not stations.station(5).online
    assert transact(fd, FDL_STATUS) == b"", "an answer off the bus"
    stations.set_online(5, True)
    assert transact(fd, FDL_STATUS)[:3] == bytes([0x10, 0x01, 0x05])
    # Two requests answered (the one off the bus was not): two replies timed, none late.
    timing = stations.link_timing(5)
    assert timing is not None and timing.replies == 2 and timing.late == 0, timing

    # Bus faults need the simulated bus: on the pty both calls are refused with the reason.
    link_refusal = [("LINK", "bus faults", "this run is on a real link; bus faults need the "
                     "simulated bus (--link memory)")]
    for call in (lambda: stations.inject_bus_fault(5, "DROP", "FROM_STATION"),
                 stations.clear_bus_faults):
        try:
            call()
            raise AssertionError("a bus fault accepted on the pty")
        except grpc.RpcError as e:
            assert e.code() == grpc.StatusCode.FAILED_PRECONDITION, e
            assert error_details(e)[2] == link_refusal, error_details(e)
    assert transact(fd, FDL_STATUS)[:3] == bytes([0x10, 0x01, 0x05])  # nothing dropped

    seen = {}
    for event in events:
        if event.HasField("state") and event.state.what in ("inputs", "online"):
            seen.setdefault(event.state.what, []).append(event.state.to)
            if len(seen.get("online", [])) == 3:
                break
    assert seen["inputs"][:2] == ["00 00 00 00 00", "00 11 22 33 44"], seen
    assert seen["online"] == ["yes", "no", "yes"], seen
    events.cancel()
    stations.close()
    os.close(fd)
    print("GSD station harness: ok")
finally:
    proc.terminate()
    proc.wait(timeout=10)

# The simulated bus: our master configured from the same GSD, on the run's manual clock.
sim = Rs4simProcess(["run", "--device", "generic", "--gsd", gsd, "--module", "DI 8", "--module",
                     "AI 2", "--module", "DO 16 consistent", "--address", "5", "--baud", "12M",
                     "--link", "memory", "--grpc", "127.0.0.1:0"], executable=rs4sim)
try:
    with GsdStations(sim.address) as stations:
        t0 = stations.now()
        assert stations.station(5).dp_state == "Wait_Prm"  # nothing moves the clock but advance
        assert abs(stations.advance(0.5) - (t0 + 0.5)) < 1e-9
        station = stations.station(5)
        assert station.dp_state == "Data_Exch", station.dp_state
        assert stations.link_timing(5) is None  # nothing is timed on the simulated bus

        # DELAY without its delay: the Faults service's rule, the field named.
        try:
            stations.inject_bus_fault(5, "DELAY", "FROM_STATION")
            raise AssertionError("a DELAY of 0 ms accepted")
        except grpc.RpcError as e:
            assert e.code() == grpc.StatusCode.INVALID_ARGUMENT, e
            assert error_details(e)[1] == [("delay_ms", "0 outside 1..10000")], error_details(e)

        # The master's next 1000 requests to station 5 dropped: injected, nothing happens until
        # the clock moves; over 50 ms (5 poll cycles of 10 ms) the station hears no
        # Data_Exchange; cleared, our master brings it back to data exchange.
        heard = station.data_exchanges
        assert heard > 0, station
        assert stations.inject_bus_fault(5, "DROP", "TO_STATION", count=1000) > 0
        assert stations.station(5).data_exchanges == heard
        stations.advance(0.05)
        assert stations.station(5).data_exchanges == heard, "a request got through the DROP"
        stations.clear_bus_faults()
        stations.advance(1.0)
        station = stations.station(5)
        assert station.dp_state == "Data_Exch" and station.data_exchanges > heard, station
        # Without the fault the same 50 ms bring Data_Exchanges.
        heard = station.data_exchanges
        stations.advance(0.05)
        assert stations.station(5).data_exchanges > heard
finally:
    sim.stop()
print("GSD station on the simulated bus: ok")
