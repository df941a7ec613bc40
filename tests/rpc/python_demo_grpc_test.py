"""`rs4sim demo --grpc` watched through python3-grpcio, a third-party gRPC client: the demo
runs in real time and serves the read-only Observation API; the event stream's snapshot is
the RS4 at power-on (DP Wait_Prm, OSSD off, the RS4 initialising [RS4 manual §4.3]), then the
DP start-up reaches data exchange; Device calls are not served (UNIMPLEMENTED: the story is
not to be disturbed); SIGTERM ends the demo between two steps with exit 130.
Usage: python_demo_grpc_test.py RS4SIM REPO   (exit 77 = skipped: no python3-grpcio)"""
import signal
import subprocess
import sys

from script_support import require_grpc

grpc = require_grpc()

rs4sim, repo = sys.argv[1], sys.argv[2]
from rs4sim import Rs4  # noqa: E402

demo = subprocess.Popen([rs4sim, "demo", "--grpc", "127.0.0.1:0"], stdout=subprocess.PIPE,
                        stderr=subprocess.PIPE, text=True)
try:
    line = demo.stdout.readline()
    assert line.startswith("grpc: listening on 127.0.0.1:"), line
    rs4 = Rs4(line.split()[-1], station=4)
    events = rs4.events()
    snapshot, changes = {}, []
    for e in events:
        if not e.HasField("state"):
            continue
        if e.state.previous == "" and not changes:
            snapshot[e.state.what] = e.state.to
            continue
        changes.append((e.state.what, e.state.previous, e.state.to))
        if changes[-1] == ("dp-state", "Wait_Cfg", "Data_Exch"):
            break
    events.cancel()
    assert snapshot["powered"] == "on" and snapshot["ossd"] == "off", snapshot
    assert snapshot["rs4-state"] == "initialisation", snapshot
    assert ("dp-state", "Wait_Prm", "Wait_Cfg") in changes, changes
    state = rs4.state()
    assert not state.ossd, "the RS4 is still booting (≈30 s)"
    try:
        rs4.press_restart(0.2)
        raise AssertionError("demo --grpc served a Device call")
    except grpc.RpcError as e:
        assert e.code() == grpc.StatusCode.UNIMPLEMENTED, e.code()
finally:
    demo.send_signal(signal.SIGTERM)
    out, err = demo.communicate(timeout=20)
assert demo.returncode == 130, (demo.returncode, err)
# "demo interrupted", then the line that says where the demo's archive went
tail = out.rstrip().splitlines()[-3:]
assert "demo interrupted" in tail, out[-200:]
assert tail[-1].startswith("archive: in memory only"), out[-200:]
print("ok: watched the demo's start-up through the API; SIGTERM ended it cleanly")
