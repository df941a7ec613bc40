"""Several masters at once on one PostgreSQL archive (docs/storage.md "Several masters"): a
plant's three PROFIBUS lines, each an RS4 (`rs4sim run --serial-number`, UDP on loopback) with
its own `rs4sim master` (bus line1/line2/line3, --site/--line/--user), all three writing one
database of the fixture's server at the same time; a second workstation's `rs4sim archive
watch` sees every version as it is stored.
1. All three masters commission their RS4 (scenario 1 of [RS4 manual §7.1, §7.2]).
2. The three sets are changed on site at once (Device.SetParameterSet): three uploads store
   concurrently.
3. The three units are exchanged at once (Device.ExchangeScanner): three downloads store a
   version with the new serial number each.
4. Failover: line1's master ends, a standby master takes line1 over against the same RS4
   (which keeps running); the next change on site is its version 3, after the first
   master's two.
psql then checks that nothing was lost or numbered twice, and what each version records.
Usage: python_masters_postgres_test.py RS4SIM REPO
(exit 77 = skipped: no python3-grpcio, or no PostgreSQL server unless RS4SIM_REQUIRE_POSTGRES=1)"""
import json
import os
import signal
import subprocess
import sys
import threading

from script_support import first_line, free_udp_port, require_grpc, spawn, stop

require_grpc()

rs4sim, repo = sys.argv[1], sys.argv[2]
from rs4sim import Master, Rs4  # noqa: E402

uri_file = os.environ.get("RS4SIM_TEST_POSTGRES_URI_FILE", "")
if not uri_file or not os.path.exists(uri_file) or os.path.getsize(uri_file) == 0:
    print("no PostgreSQL server (tests/storage/postgres_server.sh)")
    sys.exit(1 if os.environ.get("RS4SIM_REQUIRE_POSTGRES") == "1" else 77)
server = open(uri_file).read().strip()  # postgresql://rs4sim:PASSWORD@127.0.0.1:PORT/postgres
db = f"rs4sim_masters_{os.getpid()}"
archive = server.rsplit("/", 1)[0] + "/" + db
password = server.split("://rs4sim:", 1)[1].split("@", 1)[0]


def psql(uri, sql):
    return subprocess.run(["psql", uri, "-tAc", sql], check=True, capture_output=True,
                          text=True).stdout.strip()


LINES = ["line1", "line2", "line3"]
ports = {bus: (free_udp_port(), free_udp_port()) for bus in LINES}
serials = {"line1": 1001, "line2": 2002, "line3": 3003}
new_serials = {"line1": 1101, "line2": 2102, "line3": 3103}


def start_rs4(bus):
    a, b = ports[bus]
    return spawn(rs4sim, "run", "--device", "rs4", "--address", "4",
                 "--serial-number", str(serials[bus]), "--link", "udp",
                 "--listen", f"127.0.0.1:{a}", "--peer", f"127.0.0.1:{b}",
                 "--boot-time", "2000", "--duration", "150", "--grpc", "127.0.0.1:0")


def start_master(bus, user):
    a, b = ports[bus]
    return spawn(rs4sim, "master", "--slave", "4", "--link", "udp",
                 "--listen", f"127.0.0.1:{b}", "--peer", f"127.0.0.1:{a}",
                 "--f-wd-time", "500", "--dp-watchdog", "1000", "--archive", archive,
                 "--bus", bus, "--site", "Hamburg", "--line", "L" + bus[-1],
                 "--user", user, "--grpc", "127.0.0.1:0")


def sync(m, action):
    """Runs action() with the progress stream subscribed; the statuses of the sync it causes."""
    watch = m.watch_sync([4], until_done=True, timeout=90)
    action()
    statuses = list(watch)
    assert not statuses[-1].running and statuses[-1].outputs.error_number_fb == 0, statuses[-1]
    return statuses


def at_once(work):
    """work(bus) for the three lines in three threads at the same time; re-raises a failure."""
    errors = []

    def run(bus):
        try:
            work(bus)
        except Exception as e:  # noqa: BLE001  (reported below, with the bus)
            errors.append(f"{bus}: {e!r}")

    threads = [threading.Thread(target=run, args=(bus,)) for bus in LINES]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors, errors


psql(server, f"CREATE DATABASE {db}")
devices, masters, rs4, m = {}, {}, {}, {}
watcher = None
try:
    for bus in LINES:
        devices[bus] = start_rs4(bus)
    for bus in LINES:
        masters[bus] = start_master(bus, f"master-{bus}")
    for bus in LINES:
        rs4[bus] = Rs4(first_line(devices[bus], "grpc: listening on "), station=4)
        m[bus] = Master(first_line(masters[bus], "grpc: listening on "))
    # The masters have opened (and one of them created) the archive: a second workstation
    # watches it from the beginning.
    watcher = spawn(rs4sim, "archive", "watch", "--archive", archive, "--after", "0",
                    "--count", "6", "--timeout", "120", "--json")

    # 1. Commissioning on the three lines (the first sync each master sees end).
    at_once(lambda bus: sync(m[bus], lambda: None))
    # The same feed over gRPC: line2's master streams what all three store.
    api_watch = m["line2"].watch_versions(timeout=120)
    # 2. Three parameter changes on site at once: three uploads, each a version 1.
    at_once(lambda bus: sync(m[bus], lambda: rs4[bus].set_parameter_set(
        {"format": 1, "response_time_ms": 160 if bus == "line1" else 200})))
    # 3. Three device exchanges at once: each archived set downloaded to the new unit.
    at_once(lambda bus: sync(m[bus], lambda: rs4[bus].exchange_scanner(new_serials[bus])))
    for bus in LINES:
        h = m[bus].history(4, bus=bus)
        assert [v.number for v in h] == [1, 2], (bus, h)
        assert [v.source for v in h] == ["upload", "download"], (bus, h)
        assert h[1].serial_number == str(new_serials[bus]), (bus, h)

    # The second workstation saw the six versions as they were stored.
    out, err = watcher.communicate(timeout=60)
    assert watcher.returncode == 0, (watcher.returncode, err)
    seen = [json.loads(line) for line in out.splitlines()]
    assert len(seen) == 6, seen
    ids = [v["id"] for v in seen]
    # Delivered in commit order, each once. Three masters commit at once, and an id is drawn
    # before its commit, so across stations the ids can come out of order (docs/storage.md
    # "Change feed"); one station's versions queue on its row lock: ascending per bus.
    assert len(set(ids)) == 6, ids
    for bus in LINES:
        mine = [v["id"] for v in seen if v["bus"] == bus]
        assert mine == sorted(mine), (bus, seen)
    assert {(v["bus"], v["number"]) for v in seen} == {(b, n) for b in LINES for n in (1, 2)}, seen
    assert all(v["user"] == "master-" + v["bus"] for v in seen), seen
    assert password not in out + err
    streamed = [next(api_watch) for _ in range(6)]
    api_watch.cancel()
    assert sorted(v.id for v in streamed) == sorted(ids), (streamed, ids)
    for bus in LINES:
        assert ([v.id for v in streamed if v.station.bus == bus]
                == [v["id"] for v in seen if v["bus"] == bus]), (bus, streamed, seen)
    assert {v.user for v in streamed} == {"master-" + bus for bus in LINES}, streamed

    # 4. Failover on line1: its master ends, a second one takes over the same bus.
    code, _, err = stop(masters["line1"], signal.SIGINT, timeout=30)
    assert code == 0, (code, err)
    logs_before = int(psql(archive, "SELECT count(*) FROM sync_log l JOIN stations s ON "
                                    "s.id = l.station_id WHERE s.bus = 'line1'"))
    masters["line1"] = start_master("line1", "standby-master")
    m["line1"] = Master(first_line(masters["line1"], "grpc: listening on "))
    # The RS4 kept running (no new power-up, no Proxy-Request): the standby master's first
    # sync is the next change on site, numbered after the first master's versions.
    upload = sync(m["line1"], lambda: rs4["line1"].set_parameter_set(
        {"format": 1, "response_time_ms": 240}))
    assert {st.direction for st in upload if st.bytes_total > 0} == {"upload"}, upload
    h = m["line1"].history(4, bus="line1")
    assert [v.number for v in h] == [1, 2, 3], h
    logs_after = int(psql(archive, "SELECT count(*) FROM sync_log l JOIN stations s ON "
                                   "s.id = l.station_id WHERE s.bus = 'line1'"))
    assert logs_after == logs_before + 1, (logs_before, logs_after)

    # psql: nothing lost, nothing numbered twice, what each version records.
    rows = psql(archive, "SELECT s.bus, v.number, v.source, v.serial_number, v.user_name, "
                         "v.host_name <> '', s.site, s.line FROM versions v JOIN stations s ON "
                         "s.id = v.station_id ORDER BY s.bus, v.number").splitlines()
    expected = []
    for bus in LINES:
        expected.append(f"{bus}|1|1|{serials[bus]}|master-{bus}|t|Hamburg|L{bus[-1]}")
        expected.append(f"{bus}|2|2|{new_serials[bus]}|master-{bus}|t|Hamburg|L{bus[-1]}")
        if bus == "line1":
            expected.append(f"{bus}|3|1|{new_serials[bus]}|standby-master|t|Hamburg|L1")
    assert rows == expected, rows
    twice = psql(archive, "SELECT count(*) FROM (SELECT station_id, number FROM versions "
                          "GROUP BY 1, 2 HAVING count(*) > 1) d")
    assert twice == "0", twice
    current = psql(archive, "SELECT string_agg(v.number::text, ',' ORDER BY s.bus) FROM "
                            "current_versions c JOIN versions v ON v.id = c.version_id "
                            "JOIN stations s ON s.id = c.station_id")
    assert current == "3,2,2", current
    listed = subprocess.run([rs4sim, "archive", "list", "--archive", archive, "--site", "Hamburg",
                             "--line", "L2"], check=True, capture_output=True, text=True).stdout
    assert "line2" in listed and "line1" not in listed and "line3" not in listed, listed
    print("ok: 3 masters at once into one PostgreSQL archive, 6 versions numbered once each, "
          "seen by a second workstation's watch; the standby master on line1 numbered on from 2")
finally:
    for proc in list(masters.values()) + list(devices.values()) + ([watcher] if watcher else []):
        if proc.poll() is None:
            proc.kill()
            proc.communicate(timeout=30)
    subprocess.run(["psql", server, "-qc", f"DROP DATABASE IF EXISTS {db} WITH (FORCE)"],
                   capture_output=True)
