#!/usr/bin/python3
"""Figures of the HTTP server (docs/http.md), measured, not asserted:

  1. event -> SSE client latency: `rs4sim run --link pty --http` (the RS4 in real time)
     with `rs4sim master` on the pty; an SSE client on /api/events; 100 rounds of
     ViolateField (the OSSD goes off) and ClearScene + PressRestart (it comes on). The
     latency is from the event's own time (nowNs, the run's steady clock, CLOCK_MONOTONIC)
     to the moment the client has read it.
  2. server CPU of that run over 10 s of bus traffic, with no client and with one SSE client
     reading every telegram and state change (telegrams=true: the heaviest page).
  3. memory per open page: the run's RSS with 0 and with 50 idle SSE clients.

Usage: sse_figures.py build/app/rs4sim
"""
import json
import os
import socket
import statistics
import subprocess
import sys
import threading
import time
import urllib.request


def call(base, method, request=None):
    req = urllib.request.Request(base + "api/" + method, data=json.dumps(request or {}).encode(),
                                 headers={"Content-Type": "application/json"}, method="POST")
    with urllib.request.urlopen(req, timeout=60) as r:
        return json.load(r)


def sse(port, query="addresses=4"):
    s = socket.create_connection(("127.0.0.1", port))
    s.sendall(f"GET /api/events?{query} HTTP/1.1\r\nHost: x\r\n\r\n".encode())
    return s


def cpu_seconds(pid):
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def rss_kib(pid):
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return 0


def main():
    rs4sim = sys.argv[1]
    # The RS4 in real time on a pty, our master on the other side (the PLC's traffic).
    proc = subprocess.Popen([rs4sim, "run", "--address", "4", "--link", "pty", "--boot-time", "1000",
                             "--http", "127.0.0.1:0"],
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    master = None
    try:
        pts = proc.stdout.readline().strip()
        base = proc.stdout.readline().split()[-1]
        port = int(base.rstrip("/").rsplit(":", 1)[1])
        master = subprocess.Popen([rs4sim, "master", "--slave", "4", "--link", "serial", "--port", pts],
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        deadline = time.time() + 30
        while call(base, "rs4sim.v1.Observation/GetState", {"address": 4})["rs4State"] != "measuring":
            assert time.time() < deadline, "the RS4 does not measure"
            time.sleep(0.2)
        call(base, "rs4sim.v1.Device/PressRestart", {"address": 4, "durationMs": 200})
        time.sleep(1)

        # 1. latency: the event's own time (the run's steady clock = CLOCK_MONOTONIC) to the
        # moment this client has read it
        s = sse(port)
        buf = b""
        latencies = []

        def reader():
            nonlocal buf
            while True:
                try:
                    chunk = s.recv(65536)
                except OSError:
                    return
                if not chunk:
                    return
                now = time.monotonic_ns()
                buf += chunk
                while b"\n\n" in buf:
                    msg, buf = buf.split(b"\n\n", 1)
                    if b'"what":"ossd"' in msg and b'"from":""' not in msg:
                        data = json.loads(msg.split(b"data: ", 1)[1])
                        latencies.append((now - int(data["nowNs"])) / 1e6)
        threading.Thread(target=reader, daemon=True).start()
        for _ in range(100):
            call(base, "rs4sim.v1.Device/ViolateField", {"address": 4, "field": "FIELD_KIND_PROTECTIVE"})
            time.sleep(0.15)
            call(base, "rs4sim.v1.Device/ClearScene", {"address": 4})
            time.sleep(0.1)
            call(base, "rs4sim.v1.Device/PressRestart", {"address": 4, "durationMs": 200})
            time.sleep(0.4)
        s.close()
        latencies.sort()
        p = lambda q: latencies[min(len(latencies) - 1, int(q * len(latencies)))]
        print(f"event -> SSE client (real-time RS4 on a pty, our master): n={len(latencies)} "
              f"p50 {p(0.5):.2f} ms, p99 {p(0.99):.2f} ms, max {latencies[-1]:.2f} ms")

        # 2. CPU: 10 s of the running bus with no client and with one reading every telegram
        def measured(seconds, clients):
            socks = [sse(port, "telegrams=true") for _ in range(clients)]
            stop = threading.Event()
            counts = [0] * clients

            def drain(i, c):
                c.settimeout(0.5)
                while not stop.is_set():
                    try:
                        d = c.recv(65536)
                    except socket.timeout:
                        continue
                    except OSError:
                        return
                    if not d:
                        return
                    counts[i] += len(d)
            threads = [threading.Thread(target=drain, args=(i, c), daemon=True) for i, c in enumerate(socks)]
            for t in threads:
                t.start()
            c0, t0 = cpu_seconds(proc.pid), time.perf_counter()
            time.sleep(seconds)
            cpu = (cpu_seconds(proc.pid) - c0) / (time.perf_counter() - t0)
            stop.set()
            for t in threads:
                t.join()
            for c in socks:
                c.close()
            return cpu, sum(counts)
        idle_cpu, _ = measured(10, 0)
        page_cpu, sent = measured(10, 1)
        print(f"server CPU (the RS4's run): {idle_cpu * 100:.1f} % of a core without a client, "
              f"{page_cpu * 100:.1f} % with one SSE client of every telegram ({sent / 10 / 1024:.0f} KiB/s)")

        # 3. memory per open page
        time.sleep(0.5)
        r0 = rss_kib(proc.pid)
        pages = [sse(port) for _ in range(50)]
        time.sleep(2)
        r1 = rss_kib(proc.pid)
        print(f"memory: RSS {r0} KiB, with 50 open event streams {r1} KiB: "
              f"{(r1 - r0) / 50:.0f} KiB per open page")
        for c in pages:
            c.close()
    finally:
        for p_ in (master, proc):
            if p_ is not None:
                p_.terminate()
                p_.wait(timeout=10)


if __name__ == "__main__":
    main()
