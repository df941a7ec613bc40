"""Two RS4s in one `rs4sim run` (`--address 4 --address 5 --link pty --grpc`), driven by our
master (`rs4sim master --slave 4 --slave 5 --link serial --port <pty>`) on the wall clock and
through the Python harness (python3-grpcio, a third-party client): one API lists both
stations; each gets its own telegrams in the event stream; an obstacle in station 5's
protective field switches station 5's OSSD off and leaves station 4's on; an unknown
station is NOT_FOUND naming the run's stations.
Usage: python_run_two_rs4s_test.py RS4SIM REPO   (exit 77 = skipped: no python3-grpcio)"""
import os
import signal
import subprocess
import sys
import tempfile
import time

from script_support import (first_lines, pty_path, require_grpc, spawn, state_changes, stop_ok,
                            wait_for)

grpc = require_grpc()

rs4sim, repo = sys.argv[1], sys.argv[2]
from rs4sim import Rs4, error_details, pb  # noqa: E402


def stations_of(frame):
    """DA and SA of an SD1/SD2/SD3 frame (none for the short acknowledgement)."""
    if frame[0] in (0x10, 0xA2):
        return {frame[1] & 0x7F, frame[2] & 0x7F}
    if frame[0] == 0x68:
        return {frame[4] & 0x7F, frame[5] & 0x7F}
    return set()


work = tempfile.mkdtemp(prefix="rs4sim_two_rs4s_")
device = spawn(rs4sim, "run", "--address", "4", "--address", "5", "--link", "pty",
               "--boot-time", "1000", "--duration", "60", "--grpc", "127.0.0.1:0")
master = None
try:
    path = pty_path(device)
    (api,) = first_lines(device, "grpc: listening on ")
    master = subprocess.Popen([rs4sim, "master", "--slave", "4", "--slave", "5", "--link",
                               "serial", "--port", path, "--f-wd-time", "500", "--dp-watchdog",
                               "1000", "--archive", os.path.join(work, "archive.sqlite3"),
                               "--duration", "60"],
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    rs4, rs5 = Rs4(api, station=4), Rs4(api, station=5)
    listed = rs4.device.ListDevices(pb.ListDevicesRequest()).devices
    assert [(d.address, d.kind) for d in listed] == [(4, "rs4"), (5, "rs4")], listed

    # Both in data exchange with the master, the RS4s measuring, then OSSD on (restart pulse
    # through the start interlock when it holds them off).
    for r in (rs4, rs5):
        wait_for(f"station {r.station} in data exchange",
                 lambda r=r: r.state().connected, 20)
    for r in (rs4, rs5):
        if not r.state().ossd:
            time.sleep(1.5)  # boot 1 s
        if not r.state().ossd:
            r.press_restart(0.3)
        # The OSSD bit of the input byte too: PROFIsafe in run, the PLC reads it.
        wait_for(f"station {r.station} OSSD on",
                 lambda r=r: r.state().ossd and r.state().input.ossd, 10)
    assert rs5.state().f_dest_add == rs4.state().f_dest_add + 1  # the GSD rule: base + address

    # Each station's reply turnaround on the line (docs/serial.md): every reply timed, none
    # held back (no --tsl), the histogram holding them all, the percentiles in order.
    for r in (rs4, rs5):
        t = r.link_timing()
        assert t is not None and t.present and t.replies > 0 and t.late == 0, t
        assert sum(b.count for b in t.histogram) == t.replies, t  # one snapshot of the loop
        assert 0 < t.p50_ns <= t.p99_ns <= t.max_ns and t.mean_ns <= t.max_ns, t

    # Each station's telegrams through its own tap: a stream of station 5 sees 5's only.
    telegrams = rs5.events(telegrams=True)
    seen = set()
    for event in telegrams:
        if event.HasField("telegram"):
            assert event.address == 5, event
            seen |= stations_of(event.telegram.frame)
            if len(seen) >= 2:
                break
    telegrams.cancel()
    assert 5 in seen and 4 not in seen, seen

    events4, events5 = rs4.events(), rs5.events()
    rs5.violate_field("protective")
    wait_for("station 5 OSSD off", lambda: not rs5.state().input.ossd, 5)
    assert rs5.state().input.protective_field_violated
    time.sleep(0.3)  # station 4 stays on (a wrong target would have switched it by now)
    four = rs4.state()
    assert four.ossd and four.input.ossd and not four.input.protective_field_violated, four

    assert state_changes(events5, "ossd", 2, address=True) == [(5, "", "on"), (5, "on", "off")]
    events4.cancel()

    try:
        Rs4(api, station=6).state()
        raise AssertionError("station 6 answered")
    except grpc.RpcError as e:
        name, _, _ = error_details(e)
        assert name == "NOT_FOUND" and "stations: 4, 5" in e.details(), (name, e.details())
    print("ok: two RS4s on one pty, one API; station 5's obstacle trips station 5 only")
finally:
    if master is not None:
        master.send_signal(signal.SIGINT)
        master.communicate(timeout=20)
    out = stop_ok(device)
    assert "rs4 4: " in out and "rs4 5: " in out, out
    assert "turnaround 4: " in out and "turnaround 5: " in out, out
