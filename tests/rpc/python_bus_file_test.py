"""A whole bus from one file, driven through one API on the wall clock: `rs4sim run --bus
tests/gsd/corpus/bus_rs4_gsd.json --link pty --grpc` (an RS4 at 4, the modular GSD station at 5,
a generic slave at 7) and `rs4sim master --slave 4 --gsd-slave 5:FILE ... --link serial --port
<pty>` as a second process. The bus's one gRPC server serves the RS4's services and GsdStations
side by side; one event stream carries both stations; the RS4 calls name the other stations;
both stations reach data exchange with the master and the inputs set at GsdStations arrive at
its GsdMaster.
Usage: python_bus_file_test.py RS4SIM REPO   (exit 77 = skipped: no python3-grpcio)"""
import os
import signal
import sys

from script_support import first_line, pty_path, require_grpc, spawn, stop_ok, wait_for

grpc = require_grpc()

rs4sim, repo = sys.argv[1], sys.argv[2]
from rs4sim import GsdMaster, GsdStations, Rs4, pb  # noqa: E402

CORPUS = os.path.join(repo, "tests/gsd/corpus")
MODULES = ["DI 8", "AI 2", "DO 16 consistent"]
BAUD, SLOT_TIME = "9.6k", "1000"  # as python_gsd_master_test.py: room for a loaded machine


bus = spawn(rs4sim, "run", "--bus", os.path.join(CORPUS, "bus_rs4_gsd.json"),
            "--baud", BAUD, "--link", "pty", "--grpc", "127.0.0.1:0",
            "--duration", "60")
master = None
try:
    path = pty_path(bus)
    api = first_line(bus, "grpc: listening on ")
    stations, rs4 = GsdStations(api), Rs4(api, station=4)

    # One server, both kinds of station.
    assert [s.address for s in stations.stations()] == [5], stations.stations()
    assert [d.address for d in rs4.device.ListDevices(pb.ListDevicesRequest()).devices] == [4]
    for address, what in ((5, "a GSD station (rs4sim.v1.GsdStations)"),
                          (7, "a generic slave (--ident/--cfg: no API of its own)")):
        try:
            Rs4(api, station=address).state()
            raise AssertionError(f"station {address} answered as an RS4")
        except grpc.RpcError as e:
            assert e.code() == grpc.StatusCode.FAILED_PRECONDITION, e
            assert e.details() == f"address {address}: {what}, not an RS4 (RS4s: 4)", e.details()
    events = rs4.events(stations=[4, 5])
    snapshot = {}
    for _ in range(64):  # the snapshot of both stations comes first
        e = next(events)
        if e.HasField("state") and e.state.what == "dp-state":
            snapshot[e.address] = e.state.to
        if len(snapshot) == 2:
            break
    assert snapshot == {4: "Wait_Prm", 5: "Wait_Prm"}, snapshot

    gsd = os.path.join(CORPUS, "modular_dpv1.gsd")
    modules = [a for m in MODULES for a in ("--module", "5:" + m)]
    master = spawn(rs4sim, "master", "--slave", "4", "--gsd-slave", "5:" + gsd,
                   *modules, "--link", "serial", "--port", path, "--baud", BAUD,
                   "--slot-time", SLOT_TIME, "--dp-watchdog", "5000", "--no-proxy",
                   "--grpc", "127.0.0.1:0", "--duration", "60")
    gm = GsdMaster(first_line(master, "grpc: listening on "))

    # Both stations enter data exchange, seen in the one stream.
    entered = set()
    while entered != {4, 5}:
        e = next(events)
        if e.HasField("state") and e.state.what == "dp-state" and e.state.to == "Data_Exch":
            entered.add(e.address)
    events.cancel()
    assert rs4.state().connected
    wait_for("the master's GSD slave in data exchange", lambda: gm.slave(5).data_exchange, 20)
    stations.set_inputs(5, 1, b"\x11\x22\x33\x44")
    wait_for("the inputs at the master", lambda: gm.inputs(5, 1) == b"\x11\x22\x33\x44", 5)
    stations.close()
    rs4.close()
    gm.close()
    print("bus file: RS4 and GSD station through one API, data exchange with the master: ok")
finally:
    if master is not None:
        stop_ok(master, signal.SIGINT)
    stop_ok(bus)
