"""Names and bytes that match across the surfaces (issue: the harness as users meet it).
JSON over HTTP takes the Python harness's short enum names ("rs4_measuring", "protective",
"CORRUPT_CRC2") besides the long ones; a body with an unknown member ({"ms": 50}) is a 400
naming the message's fields; bytes written as bare hex digits ({"data": "1122334455667788"},
valid base64 of 12 bytes) are refused saying both readings, and "hex:..." or "11 22 ..." is
read as hex; GSD slots count from 0 (slot 1 is the second module, "AI 2", 4 input bytes).
Over gRPC: the state change's earlier value is `previous` (a Python name; `from` was a
keyword) and still "from" in JSON; a cancelled event stream ends quietly when iterated.
The GSD is the project's tests/gsd/corpus/modular_dpv1.gsd.
Usage: python_names_test.py RS4SIM REPO   (exit 77 = skipped: no python3-grpcio)"""
import json
import os
import subprocess
import sys
import urllib.error
import urllib.request

from script_support import check, require_grpc  # noqa: E402

require_grpc()

rs4sim, repo = sys.argv[1], sys.argv[2]
from rs4sim import Rs4  # noqa: E402


def start(*args):
    """rs4sim with --grpc and --http on loopback: (process, grpc address, http base URL)."""
    proc = subprocess.Popen([rs4sim, *args, "--grpc", "127.0.0.1:0", "--http", "127.0.0.1:0"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    found = {}
    while len(found) < 2:
        line = proc.stdout.readline()
        if not line:
            check(False, f"rs4sim printed no listening lines: {proc.stderr.read()}")
        for prefix in ("grpc: listening on ", "http: listening on "):
            if line.startswith(prefix):
                found[prefix] = line[len(prefix):].strip()
    return proc, found["grpc: listening on "], found["http: listening on "].rstrip("/")


def post(base, method, body):
    """(HTTP status, the answer as JSON)."""
    request = urllib.request.Request(f"{base}/api/rs4sim.v1.{method}",
                                     data=json.dumps(body).encode(), method="POST")
    try:
        with urllib.request.urlopen(request, timeout=60) as answer:
            return answer.status, json.loads(answer.read())
    except urllib.error.HTTPError as error:
        return error.code, json.loads(error.read())


def violations(answer):
    return [(v["field"], v["description"]) for d in answer.get("details", [])
            for v in d.get("fieldViolations", [])]


def rs4_names():
    proc, address, base = start("run", "--link", "memory")
    try:
        status, answer = post(base, "SimTime/Advance", {"ms": 50})
        check(status == 400, f"{{'ms': 50}}: {status} {answer}")
        check(violations(answer) == [("ms", "unknown field 'ms' in rs4sim.v1.AdvanceRequest; "
                                      "its fields: duration_ms (durationMs)")], answer)
        with Rs4(address) as rs4:
            events = rs4.events()
            status, answer = post(base, "SimTime/RunUntil", {"address": 4, "timeoutMs": 60000,
                                                             "condition": "rs4_measuring"})
            check(status == 200 and answer["reached"], f"short condition name: {status} {answer}")
            status, answer = post(base, "Device/ViolateField", {"address": 4, "field": "protective"})
            check(status == 200 and answer["obstacleId"] > 0, f"'protective': {status} {answer}")
            status, answer = post(base, "Faults/InjectSafetyFault",
                                  {"address": 4, "fault": "CORRUPT_CRC2", "count": 1})
            check(status == 200, f"'CORRUPT_CRC2': {status} {answer}")
            status, answer = post(base, "Device/ViolateField", {"address": 4, "field": "side"})
            check(status == 400 and "PROTECTIVE, WARNING" in str(violations(answer)), answer)
            first = next(events)
            check(first.state.previous == "", f"the snapshot's previous is '': {first}")
            check(next(events).HasField("state"), "a second event")
            events.cancel()
            rest = list(events)  # ends quietly, no grpc.RpcError CANCELLED
            check(len(rest) < 100, f"{len(rest)} events after cancel")
    finally:
        proc.terminate()
        proc.wait(10)


def gsd_bytes():
    gsd = os.path.join(repo, "tests/gsd/corpus/modular_dpv1.gsd")
    proc, _, base = start("run", "--device", "generic", "--gsd", gsd, "--module", "DI 8",
                          "--module", "AI 2", "--module", "DO 16 consistent", "--address", "5",
                          "--baud", "12M", "--link", "memory")
    try:
        status, answer = post(base, "GsdStations/SetInputs",
                              {"address": 5, "slot": 1, "data": "1122334455667788"})
        check(status == 400, f"bare hex accepted: {status} {answer}")
        check(violations(answer) == [("data", (
            "'1122334455667788' reads as hex (8 bytes) and as base64, protobuf's JSON for "
            "bytes (12 bytes d7 5d b6 df 7e 38 e7 9e …): write hex as 'hex:1122334455667788' "
            "or '11 22 33 44 55 66 77 88', base64 with its '=' padding where it has one"))],
            answer)
        for data in ("hex:11223344", "11 22 33 44", "ESIzRA=="):
            status, answer = post(base, "GsdStations/SetInputs",
                                  {"address": 5, "slot": 1, "data": data})
            check(status == 200, f"{data}: {status} {answer}")
            status, station = post(base, "GsdStations/GetStation", {"address": 5})
            modules = station["modules"]
            check(modules[1]["inputs"] == "ESIzRA==", f"{data}: slot 1 (AI 2) {modules[1]}")
            check(modules[0]["inputs"] in ("", "AA=="), f"slot 0 (DI 8) untouched {modules[0]}")
    finally:
        proc.terminate()
        proc.wait(10)


rs4_names()
gsd_bytes()
print("ok")
