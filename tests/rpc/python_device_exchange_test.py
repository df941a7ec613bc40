"""The device exchange across processes ([RS4 manual §7.1, §7.2] scenarios 1, 2 and 4), driven
through python3-grpcio: an RS4 (`rs4sim run --serial-number`, shortened boot) and `rs4sim
master` with a real SQLite archive as two processes over UDP on loopback.
1. First commissioning: factory set, empty archive → CONFIG_SET_TO_DEFAULT.
2. The set changed with the parametrisation tool (Device.SetParameterSet: through the PC
   adapter) → the proxy uploads it; the archive's version has the unit's serial number and
   the CRC the RS4 reports.
3. Device.ExchangeScanner: a factory unit with another serial number → the proxy downloads
   the archived set; the RS4 then runs it (GetParameterSet) and the archive names the new
   serial number.
4. The RS4 process restarted with a third --serial-number (another unit, factory settings)
   and a --state file: the running master downloads the set again.
5. The RS4 process restarted with that --state file (the same unit, its set kept): a normal
   start, the proxy's check finds the set it archived and stores no new version.
Every version carries today's UTC date (`archive history`), not the time since boot.
Usage: python_device_exchange_test.py RS4SIM REPO   (exit 77 = skipped: no python3-grpcio)"""
import datetime
import signal
import subprocess
import sys
import tempfile
import time
import os

from script_support import first_line, free_udp_port, require_grpc, spawn, stop

require_grpc()

rs4sim, repo = sys.argv[1], sys.argv[2]
from rs4sim import Master, Rs4  # noqa: E402


def start_rs4(*unit):
    return spawn(rs4sim, "run", "--device", "rs4", "--address", "4", *unit,
                 "--link", "udp",
                 "--listen", f"127.0.0.1:{a}", "--peer", f"127.0.0.1:{b}",
                 "--boot-time", "3000", "--duration", "120",
                 "--grpc", "127.0.0.1:0")


def sync(m, action):
    """Runs action() with the progress stream subscribed; the statuses of the sync it causes."""
    watch = m.watch_sync([4], until_done=True, timeout=60)
    action()
    statuses = list(watch)
    last = statuses[-1]
    assert not last.running and last.outputs.error_number_fb == 0, last
    return statuses


def directions(statuses):
    return {s.direction for s in statuses if s.bytes_total > 0}


work = tempfile.mkdtemp(prefix="rs4sim_exchange_")
archive = os.path.join(work, "archive.sqlite3")
a, b = free_udp_port(), free_udp_port()
device = start_rs4("--serial-number", "1001")
master = spawn(rs4sim, "master", "--slave", "4", "--link", "udp",
               "--listen", f"127.0.0.1:{b}", "--peer", f"127.0.0.1:{a}",
               "--f-wd-time", "500", "--dp-watchdog", "1000", "--archive", archive,
               "--grpc", "127.0.0.1:0")
try:
    rs4 = Rs4(first_line(device, "grpc: listening on "), station=4)
    m = Master(first_line(master, "grpc: listening on "))

    # 1. Scenario 1: the factory unit 1001 and an empty archive.
    first = sync(m, lambda: None)
    assert first[-1].outputs.config_set_to_default, first[-1]
    assert rs4.parameter_set()["device"]["serial_number"] == 1001

    # 2. Scenario 2: the response time 80 + 2·40 = 160 ms [RS4 manual §6.6] set on site.
    upload = sync(m, lambda: rs4.set_parameter_set({"format": 1, "response_time_ms": 160}))
    assert directions(upload) == {"upload"}, upload
    site_crc = rs4.parameter_set_crc()
    v = m.history(4)[-1]
    assert v.source == "upload" and v.crc32 == site_crc and v.serial_number == "1001", v

    # 3. Scenario 4 on the running bus: a factory unit 2002 takes 1001's place.
    download = sync(m, lambda: rs4.exchange_scanner(2002))
    assert directions(download) == {"download"}, download
    doc = rs4.parameter_set()
    assert doc["device"]["serial_number"] == 2002 and doc["response_time_ms"] == 160, doc
    assert rs4.parameter_set_crc() == site_crc
    v = m.history(4)[-1]
    assert v.source == "download" and v.serial_number == "2002" and v.crc32 == site_crc, v

    # 4. The RS4 process replaced by another unit, 3003, with factory settings.
    code, _, err = stop(device)
    assert code == 0, (code, err)
    watch = m.watch_sync([4], until_done=True, timeout=60)
    state = os.path.join(work, "rs4.state")
    device = start_rs4("--serial-number", "3003", "--state", state)
    rs4 = Rs4(first_line(device, "grpc: listening on "), station=4)
    again = list(watch)
    assert directions(again) == {"download"} and again[-1].outputs.error_number_fb == 0, again
    doc = rs4.parameter_set()
    assert doc["device"]["serial_number"] == 3003 and doc["response_time_ms"] == 160, doc
    assert rs4.parameter_set_crc() == site_crc
    v = m.history(4)[-1]
    assert v.source == "download" and v.serial_number == "3003" and v.crc32 == site_crc, v

    # 5. The same unit again, from its state file.
    versions = len(m.history(4))
    code, _, err = stop(device)
    assert code == 0, (code, err)
    with open(state, "rb") as f:
        assert f.read(8) == b"RS4SIMNV", "the state file was written"
    watch = m.watch_sync([4], until_done=True, timeout=60)
    device = start_rs4("--state", state)
    rs4 = Rs4(first_line(device, "grpc: listening on "), station=4)
    check = list(watch)
    # The set is the archived one: nothing goes either way, only the background verify
    # reads it back ([RS4 manual §7.2]); the first status is the last sync's, kept.
    assert directions(check[1:]) <= {"verify"}, directions(check[1:])
    assert check[-1].outputs.error_number_fb == 0, check[-1]
    assert not check[-1].outputs.config_set_to_default, check[-1]
    doc = rs4.parameter_set()
    assert doc["device"]["serial_number"] == 3003 and doc["response_time_ms"] == 160, doc
    assert len(m.history(4)) == versions, m.history(4)

    # Dates that are dates: every version stored at the wall clock's UTC time, although the
    # master's loop runs on the steady clock (time since boot); `archive history` shows today.
    now_ms = time.time() * 1000
    for v in m.history(4):
        assert abs(v.stored_at_ms - now_ms) < 10 * 60 * 1000, (v.stored_at_ms, now_ms)
    shown = subprocess.run([rs4sim, "archive", "history", "--address", "4", "--archive", archive],
                           check=True, capture_output=True, text=True).stdout
    today = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d")
    assert today in shown and "1970-01-01" not in shown, shown
    print(f"ok: commissioning, upload (CRC-32 {site_crc:08X}), exchange 1001 → 2002 on the "
          f"bus and 2002 → 3003 by process, each downloaded; the restart from --state stored nothing; "
          f"{len(m.history(4))} versions")
finally:
    code, _, err = stop(master, signal.SIGINT)
    if device.poll() is None:
        stop(device)
    assert code == 0, (code, err)
