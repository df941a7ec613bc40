#!/usr/bin/python3
"""`rs4sim demo --http 127.0.0.1:0` (docs/http.md): the narrated RS4 demo serves the live view
and its read-only Observation service as JSON over HTTP while it runs (paced by the wall clock).

Checks the `http: listening on http://127.0.0.1:PORT/` line, one JSON call (GetState of the
demo's RS4 at address 4), its NOT_FOUND for an address the demo has not (404 with the
google.rpc.Status as JSON), a service the demo does not serve (501), the page, and the first
Server-Sent Event of /api/events (the snapshot: a state change from ""). Then SIGTERM: the demo
says it was interrupted and exits 130.
Usage: demo_http.py <path to rs4sim>. Standard library only.
"""
import json
import re
import signal
import subprocess
import sys
import tempfile
import threading
import urllib.error
import urllib.request

LINE = re.compile(r"^http: listening on (http://127\.0\.0\.1:[0-9]+/)$")


def post(base, method, request):
    req = urllib.request.Request(base + "api/" + method, data=json.dumps(request).encode(),
                                 headers={"Content-Type": "application/json"}, method="POST")
    try:
        with urllib.request.urlopen(req, timeout=30) as r:
            return r.status, r.headers.get("Content-Type"), json.load(r)
    except urllib.error.HTTPError as e:
        return e.code, e.headers.get("Content-Type"), json.load(e)


def main():
    rs4sim = sys.argv[1]
    err_file = tempfile.TemporaryFile(mode="w+")  # read at the end: a pipe could fill up
    proc = subprocess.Popen([rs4sim, "demo", "--http", "127.0.0.1:0"], stdout=subprocess.PIPE,
                            stderr=err_file, text=True)
    rest = []  # the narration after the listening line, drained so the demo never blocks
    try:
        base = None
        for _ in range(40):
            line = proc.stdout.readline()
            assert line, "the demo printed no 'http: listening on' line"
            m = LINE.match(line.rstrip("\n"))
            if m:
                base = m.group(1)
                break
        assert base, "no 'http: listening on http://127.0.0.1:PORT/' line in the first 40"
        drain = threading.Thread(target=lambda: rest.extend(proc.stdout), daemon=True)
        drain.start()

        status, ctype, state = post(base, "rs4sim.v1.Observation/GetState", {"address": 4})
        assert status == 200 and ctype == "application/json", (status, ctype, state)
        for key in ("rs4State", "ossd", "fdeviceState", "inputByte"):  # defaults printed too
            assert key in state, (key, state)

        status, ctype, error = post(base, "rs4sim.v1.Observation/GetState", {"address": 9})
        assert status == 404 and ctype == "application/json", (status, ctype, error)
        assert error["code"] == 5 and "9" in error["message"], error

        status, _, error = post(base, "rs4sim.v1.Device/ViolateField",
                                {"address": 4, "field": "FIELD_KIND_PROTECTIVE"})
        assert status == 501 and error["code"] == 12, (status, error)  # Observation only

        with urllib.request.urlopen(base, timeout=30) as r:
            page = r.read().decode()
        assert r.status == 200 and "rs4sim live view" in page, page[:200]

        with urllib.request.urlopen(base + "api/events?addresses=4", timeout=30) as r:
            assert r.headers.get("Content-Type", "").startswith("text/event-stream"), r.headers
            first = None
            for raw in r:
                text = raw.decode().rstrip("\n")
                if text.startswith("data: "):
                    first = json.loads(text[len("data: "):])
                    break
        assert first is not None, "no event"
        assert first.get("address") == 4 and first["state"]["from"] == "", first

        proc.send_signal(signal.SIGTERM)
        proc.wait(timeout=30)
        drain.join(timeout=30)
        out = "".join(rest)
        err_file.seek(0)
        err = err_file.read()
        assert "demo interrupted" in out, out[-2000:]
        assert proc.returncode == 130, (proc.returncode, err)
        print(f"ok: {base} answered GetState (rs4State {state['rs4State']}), 404 for address 9, "
              f"501 for Device, the page, the event stream's snapshot ({first['state']['what']} = "
              f"{first['state']['to']}); SIGTERM: exit 130")
        return 0
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()


if __name__ == "__main__":
    sys.exit(main())
