"""`rs4sim master --grpc` driven through python3-grpcio, a third-party gRPC client: an RS4
(`rs4sim run`, shortened boot) and the master as two processes over UDP on loopback, a real
SQLite archive. The Proxy service's progress stream shows the first-commissioning sync
([RS4 manual §7.1, §7.2] scenario 1: factory set, empty archive) from its first status to
its end with CONFIG_SET_TO_DEFAULT; GetStatus shows the FB outputs ([RS4 manual §6.4]).
Then scenario 2: the PC adapter attached (through the RS4's API), the set changed over the
RS232 port with `rs4sim param set` and the password, the adapter removed: the stream shows
the upload byte by byte, and the Archive service on the master's server holds the new set.
Bad requests get INVALID_ARGUMENT / NOT_FOUND with the field named.
Usage: python_master_proxy_test.py RS4SIM REPO   (exit 77 = skipped: no python3-grpcio)"""
import json
import os
import signal
import subprocess
import sys
import tempfile

from script_support import expect_error, first_lines, free_udp_port, require_grpc, spawn, stop

require_grpc()

rs4sim, repo = sys.argv[1], sys.argv[2]
# Imported before the processes start: loading grpc and the stubs takes a moment.
from rs4sim import Master, Rs4, archive_pb  # noqa: E402


work = tempfile.mkdtemp(prefix="rs4sim_master_grpc_")
archive = os.path.join(work, "archive.sqlite3")
a, b = free_udp_port(), free_udp_port()
# A boot of 3 s: the stream is subscribed before the RS4 asks for its sync.
device = spawn(rs4sim, "run", "--device", "rs4", "--address", "4", "--link", "udp",
               "--listen", f"127.0.0.1:{a}", "--peer", f"127.0.0.1:{b}",
               "--boot-time", "3000", "--duration", "60", "--rs232", "pty",
               "--pc-adapter", "detached", "--grpc", "127.0.0.1:0")
master = spawn(rs4sim, "master", "--slave", "4", "--link", "udp",
               "--listen", f"127.0.0.1:{b}", "--peer", f"127.0.0.1:{a}",
               "--f-wd-time", "500", "--dp-watchdog", "1000", "--archive", archive,
               "--grpc", "127.0.0.1:0")
try:
    rs232, device_api = first_lines(device, "rs232: ", "grpc: listening on ")
    (master_api,) = first_lines(master, "grpc: listening on ")
    m = Master(master_api)
    statuses = list(m.watch_sync([4], until_done=True, timeout=40))
    first, last = statuses[0], statuses[-1]
    assert first.address == 4 and first.bus == "default", first
    assert not first.running and first.queue_position == -1 and first.step == "idle", first
    steps = [s.step for s in statuses]
    for step in ("proxy begin", "identify", "identify (repeat)", "proxy end"):
        assert step in steps, (step, steps)
    assert any(s.running and s.outputs.fb_busy for s in statuses), statuses
    # The end: FB_BUSY off, no error, the factory set reported ([RS4 manual §6.4]).
    assert not last.running and last.step == "idle", last
    assert not last.outputs.fb_busy and last.outputs.config_set_to_default, last
    assert last.outputs.error_number_fb == 0 and last.outputs.error_code_sfc == 0, last
    assert all(x.now_ns <= y.now_ns for x, y in zip(statuses, statuses[1:])), "time order"

    status = m.proxy_status()
    assert status.bus == "default" and status.max_parallel == 1, status
    assert status.running == 0 and list(status.queue) == [], status
    assert [s.address for s in status.stations] == [4], status
    assert status.stations[0].outputs.config_set_to_default, status.stations[0]
    # The master's own view of the station (BusMaster): in data exchange, synchronised once.
    (seen,) = m.stations()
    assert seen.address == 4 and seen.dp_state == "DataExchange" and not seen.dp_error, seen
    assert seen.plc.fhost_state == "run" and seen.plc.dp.syncs == 1, seen.plc
    # The Archive service beside it reads the file the proxy wrote.
    listed = m.archive.ListStations(archive_pb.ListStationsRequest())
    assert any(s.key.address == 4 for s in listed.stations), listed

    # Scenario 2: a new set through the PC adapter, then the upload when it is removed.
    rs4 = Rs4(device_api, station=4)
    rs4.set_pc_adapter(True)
    doc = json.loads(subprocess.run([rs4sim, "param", "get", "--port", rs232], check=True,
                                    capture_output=True, text=True).stdout)
    doc["response_time_ms"] = 160
    site = os.path.join(work, "site.json")
    with open(site, "w") as f:
        json.dump(doc, f)
    subprocess.run([rs4sim, "param", "set", site, "--port", rs232, "--password", "ROD4LE"],
                   check=True, capture_output=True)
    watch = m.watch_sync([4], until_done=True, timeout=40)  # subscribed before the removal
    rs4.set_pc_adapter(False)
    upload = list(watch)
    moving = [s for s in upload if s.bytes_total > 0]
    assert moving and all(s.direction == "upload" for s in moving), upload
    total = moving[0].bytes_total
    done = [s.bytes_done for s in moving]
    assert all(s.bytes_total == total for s in moving) and done == sorted(done), done
    # Sampled each master cycle: the last chunk's answer and the archive's store happen in
    # one cycle, so the last sample is the start of the last chunk (1024-byte chunks).
    assert total - 1024 < done[-1] < total and len(set(done)) > 1, (done, total)
    assert not upload[-1].running and upload[-1].outputs.error_number_fb == 0, upload[-1]
    assert not upload[-1].outputs.config_set_to_default, upload[-1]
    versions = m.history(4)
    assert versions[0].source == "upload" and versions[0].size == total, versions[0]

    expect_error(lambda: m.proxy_status([200]), "INVALID_ARGUMENT", "addresses[0]")
    details = expect_error(lambda: m.proxy_status([4, 9]), "NOT_FOUND")
    assert "station 9" in details, details
    expect_error(lambda: m.watch_sync([4, 127]), "INVALID_ARGUMENT", "addresses[1]")
    expect_error(lambda: m.watch_sync([5]), "NOT_FOUND")
    print(f"ok: first sync {' → '.join(dict.fromkeys(steps))}; "
          f"upload of {total} bytes seen at {len(set(done))} points")
finally:
    code, out, err = stop(master, signal.SIGINT)
    stop(device)
    assert code == 0, (code, err)
