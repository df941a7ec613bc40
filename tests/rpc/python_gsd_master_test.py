"""A GSD station and our master configured from the same GSD, as two processes on the wall clock
over a pty pair, each driven through its API (python3-grpcio): `rs4sim run --device generic --gsd
FILE --module ... --link pty --grpc` and `rs4sim master --gsd-slave 5:FILE --module 5:... --link
serial --port <pty> --grpc --http`. The master parametrises the station from the GSD (Set_Prm with
the GSD's default User_Prm_Data, Chk_Cfg from the modules), both sides reach data exchange, the
inputs set at the station's GsdStations arrive at the master's GsdMaster and the outputs set there
arrive at the station; the refusals carry their details; JSON/HTTP serves the same call.
The GSD is the project's tests/gsd/corpus/modular_dpv1.gsd ("DI 8": 1 input byte, "AI 2": 4,
"DO 16 consistent": 2 output bytes; ident 0xB756).
Usage: python_gsd_master_test.py RS4SIM REPO   (exit 77 = skipped: no python3-grpcio)"""
import json
import os
import signal
import sys
import urllib.request

from script_support import first_lines, pty_path, require_grpc, spawn, stop_ok, wait_for

grpc = require_grpc()

rs4sim, repo = sys.argv[1], sys.argv[2]
from rs4sim import GsdMaster, GsdStations, error_details  # noqa: E402

MODULES = ["DI 8", "AI 2", "DO 16 consistent"]
# 9.6 kbit/s, one of the GSD's two rates, with a slot time of 1000 bit times = 104 ms: room for
# a loaded machine (12M's longest slot time, 16383 bit times, is 1.4 ms), and the master's token
# time-out before it claims the token (6 + 2 * address slot times) stays below a second.
BAUD = "9.6k"
SLOT_TIME = "1000"


gsd = os.path.join(repo, "tests/gsd/corpus/modular_dpv1.gsd")
station_args = [a for m in MODULES for a in ("--module", m)]
device = spawn(rs4sim, "run", "--device", "generic", "--gsd", gsd, *station_args,
               "--address", "5", "--baud", BAUD, "--link", "pty", "--grpc",
               "127.0.0.1:0", "--duration", "60")
master = None
try:
    path = pty_path(device)
    (station_api,) = first_lines(device, "grpc: listening on ")
    master_args = [a for m in MODULES for a in ("--module", "5:" + m)]
    master = spawn(rs4sim, "master", "--gsd-slave", "5:" + gsd, *master_args,
                   "--link", "serial", "--port", path, "--baud", BAUD, "--slot-time", SLOT_TIME,
                   "--dp-watchdog", "5000", "--no-proxy", "--grpc", "127.0.0.1:0",
                   "--http", "127.0.0.1:0", "--duration", "60")
    master_api, http = first_lines(master, "grpc: listening on ", "http: listening on ")
    stations, gm = GsdStations(station_api), GsdMaster(master_api)

    [slave] = gm.slaves()
    assert slave.address == 5 and slave.ident_number == 0xB756 and slave.file == gsd, slave
    assert [(m.name, m.input_length, m.output_length) for m in slave.modules] == [
        ("DI 8", 1, 0), ("AI 2", 4, 0), ("DO 16 consistent", 0, 2)], slave.modules
    # Worked out by hand from the file: Ext_User_Prm_Data_Const(0) 80 00 00 01, byte 3 with
    # "Diagnosis" Bit(2) = 1 and "Mode" BitArea(4-6) = 3 -> 35; module "AI 2": Const AA,
    # "Filter time" Unsigned16 300 = 01 2C, "Offset" Signed8 -5 = FB. Chk_Cfg: 10 51 A1.
    assert slave.user_prm_data == bytes.fromhex("80000035aa012cfb"), slave.user_prm_data.hex()
    assert slave.cfg == bytes.fromhex("1051a1"), slave.cfg.hex()

    wait_for("the master in data exchange", lambda: gm.slave(5).data_exchange, 20)
    wait_for("the station in Data_Exch", lambda: stations.station(5).dp_state == "Data_Exch", 5)
    station = stations.station(5)
    assert station.prm_fault == "", station.prm_fault  # the GSD's defaults are in range

    # Inputs: station -> master.
    stations.set_inputs(5, 0, b"\x5a")
    stations.set_inputs(5, 1, b"\x11\x22\x33\x44")
    wait_for("the inputs at the master",
             lambda: [m.inputs for m in gm.slave(5).modules[:2]] == [b"\x5a", b"\x11\x22\x33\x44"],
             5)
    # Outputs: master -> station.
    assert stations.outputs(5, 2) == b"\x00\x00"
    gm.set_outputs(5, 2, b"\xbe\xef")
    assert gm.outputs(5, 2) == b"\xbe\xef"
    wait_for("the outputs at the station", lambda: stations.outputs(5, 2) == b"\xbe\xef", 5)

    try:
        gm.set_outputs(5, 2, b"\x01")
        raise AssertionError("1 byte for a 2-byte module accepted")
    except grpc.RpcError as e:
        assert e.code() == grpc.StatusCode.INVALID_ARGUMENT, e
        _, [(field, description)], _ = error_details(e)
        assert (field, description) == (
            "data", '1 bytes; module "DO 16 consistent" (slot 2) has 2 output bytes'), description
    try:
        gm.slave(4)
        raise AssertionError("slave 4 found")
    except grpc.RpcError as e:
        assert e.code() == grpc.StatusCode.NOT_FOUND, e
        assert "this master's GSD slaves: 5" in e.details(), e.details()

    # The same service over JSON/HTTP (docs/http.md).
    request = urllib.request.Request(http.rstrip("/") + "/api/rs4sim.v1.GsdMaster/GetSlave",
                                     data=json.dumps({"address": 5}).encode(),
                                     headers={"Content-Type": "application/json"})
    with urllib.request.urlopen(request, timeout=10) as reply:
        got = json.loads(reply.read())
    assert got["address"] == 5 and got["dpState"] == "DataExchange", got
    assert got["modules"][2]["outputs"] == "vu8=", got  # base64 of be ef
    stations.close()
    gm.close()
    print("GSD station and master from one GSD: data exchange, I/O both ways: ok")
finally:
    if master is not None:
        out = stop_ok(master, signal.SIGINT)
        assert "GSD slave 5: end: DP DataExchange" in out, out
    stop_ok(device)
