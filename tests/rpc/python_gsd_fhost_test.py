"""Our master as F-host for GSD F-devices through the Python package (rs4sim.GsdMaster, docs/
profisafe.md "Our master as F-host for GSD F-devices"), two processes on the wall clock over a
pty pair: `rs4sim run --bus bus_rs4_f_devices.json --link pty --grpc` (an RS4, the V1 GSD
F-device 5 with F_Dest_Add 300, the V2 GSD F-device 6) and `rs4sim master --bus-file` of the same
file with --manual-ack and --f-wd-time 1000 (generous for a loaded machine). Both F-hosts reach
RUN with the F-parameters written (F_Dest_Add 300, F_WD_Time 1 s in seconds); the F-outputs set
go out in the PDU; station 5 off the bus (GsdStations.set_online) passivates its F-host by the
watchdog, back on the bus ACK_REQ stands until GsdMaster.acknowledge(); a needless
acknowledgement, another slot and a wrong length are refused with their details.
Usage: python_gsd_fhost_test.py RS4SIM REPO   (exit 77 = skipped: no python3-grpcio)"""
import os
import signal
import sys

from script_support import expect_error, first_lines, pty_path, require_grpc, spawn, stop_ok, \
    wait_for

grpc = require_grpc()

rs4sim, repo = sys.argv[1], sys.argv[2]
from rs4sim import GsdMaster, GsdStations  # noqa: E402

bus = os.path.join(repo, "tests/gsd/corpus/bus_rs4_f_devices.json")
device = spawn(rs4sim, "run", "--bus", bus, "--link", "pty", "--grpc", "127.0.0.1:0",
               "--duration", "60")
master = None
try:
    path = pty_path(device)
    (station_api,) = first_lines(device, "grpc: listening on ")
    master = spawn(rs4sim, "master", "--bus-file", bus, "--link", "serial", "--port", path,
                   "--manual-ack", "--f-wd-time", "1000", "--dp-watchdog", "2000", "--no-proxy",
                   "--grpc", "127.0.0.1:0", "--duration", "60")
    (master_api,) = first_lines(master, "grpc: listening on ")
    stations, gm = GsdStations(station_api), GsdMaster(master_api)

    def state(address):
        return gm.f_module(address).f_state

    # A loaded machine may lose a slave in the first seconds (a DP restart passivates its
    # F-host): such an ACK_REQ is acknowledged before the test starts.
    for address in (5, 6):
        wait_for(f"F-host {address} started",
                 lambda a=address: state(a) in ("run", "ack-required"), 20)
        if state(address) == "ack-required":
            gm.acknowledge(address)
        wait_for(f"F-host {address} in RUN", lambda a=address: state(a) == "run", 5)
    v1, v2 = gm.f_module(5), gm.f_module(6)
    assert (v1.mode, v2.mode) == ("V1", "V2"), (v1.mode, v2.mode)
    assert v1.parameters.f_dest_add == 300 and v2.parameters.f_dest_add == 1, (v1, v2)
    assert gm.f_wd_time(5) == 1.0 and gm.f_wd_time(6) == 1.0
    assert (v1.f_data_length, v2.f_data_length) == (4, 8)

    gm.set_f_outputs(5, 0, b"\x01\x02\x03\x04")
    wait_for("the F-outputs in the PDU", lambda: gm.f_module(5).f_outputs_sent == b"\x01\x02\x03\x04",
             5)
    details = expect_error(lambda: gm.acknowledge(5), "FAILED_PRECONDITION")
    assert "no ACK_REQ waits for an acknowledgement: the F-host is in state run" in details, details
    details = expect_error(lambda: gm.set_f_outputs(5, 0, b"\x01"), "INVALID_ARGUMENT", "data")
    assert "the F-module in slot 0 has 4 bytes" in details, details
    expect_error(lambda: gm.acknowledge(5, 1), "INVALID_ARGUMENT", "slot")
    expect_error(lambda: gm.acknowledge(4), "NOT_FOUND")  # the RS4 is no GSD slave

    # Off the bus for longer than F_WD_Time: passivated; back on: ACK_REQ until ACK_REI.
    stations.set_online(5, False)
    wait_for("F-host 5 passivated", lambda: gm.f_module(5).passivated, 10)
    assert gm.f_module(5).last_fault == "watchdog F_WD_Time expired", gm.f_module(5)
    stations.set_online(5, True)
    wait_for("ACK_REQ of F-host 5", lambda: gm.f_module(5).ack_req, 10)
    assert gm.f_module(5).f_outputs_sent == bytes(4)  # fail-safe values while passivated
    gm.acknowledge(5)
    wait_for("F-host 5 reintegrated", lambda: state(5) == "run", 5)
    assert gm.f_module(5).counters["reintegrations"] >= 1, gm.f_module(5).counters
    wait_for("the F-outputs again", lambda: gm.f_module(5).f_outputs_sent == b"\x01\x02\x03\x04", 5)
    print("GSD F-devices V1 and V2 with our F-host: RUN, passivation, ACK_REQ, ACK_REI: ok")
finally:
    ends = [stop_ok(p, sig) for p, sig in ((master, signal.SIGINT), (device, signal.SIGTERM))
            if p is not None]
# The master's console reported the F-host's state.
assert "GSD slave 5: PROFIsafe V1 slot 0: run" in ends[0], ends[0]
