#!/usr/bin/python3
"""The live view's server under load (docs/http.md "Figures"), measured, not asserted: the CPU
of `rs4sim run --link udp --http` serving 125 RS4s (addresses 1..125, the most a DP segment
holds) polled by `rs4sim master --address 0 --no-proxy` on the other side (every station in
data exchange with its F-host running), with one page open in headless
chromium (python3-selenium + chromium-driver), in two phases of the same run:

  idle     nothing changes on the stations (the bus traffic and the page's own polling only)
  10 Hz    (then once more with the page closed) every station changes 10 times a second: its window contamination toggles between
           0 % and 50 % (LED5, input bit 6, the input byte: three event-stream items each
           time), driven through the JSON API (Device.SetContamination) over two keep-alive
           connections, 1250 calls a second

and reports the run's CPU (user + system, /proc/PID/stat) per wall second in each, the ratio
10 Hz / idle, the events the page received (counted in the page), and the calls achieved.

Usage: live_view_load.py build/app/rs4sim [seconds per phase, default 10]
"""
import http.client
import json
import os
import socket
import subprocess
import sys
import threading
import time

from selenium import webdriver
from selenium.webdriver.chrome.service import Service

STATIONS = list(range(1, 126))


def free_udp_port():
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def listening(proc, prefix="http: listening on "):
    for _ in range(400):
        line = proc.stdout.readline()
        if not line:
            break
        if line.startswith(prefix):
            return line[len(prefix):].strip()
    raise SystemExit(f"no {prefix!r} line")


def cpu_seconds(pid):
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


class Api:
    def __init__(self, base):
        host, port = base[len("http://"):].rstrip("/").split(":")
        self.c = http.client.HTTPConnection(host, int(port), timeout=30)

    def call(self, method, request):
        self.c.request("POST", "/api/" + method, body=json.dumps(request),
                       headers={"Content-Type": "application/json"})
        r = self.c.getresponse()
        body = r.read()
        if r.status != 200:
            raise RuntimeError(f"{method}: {r.status} {body[:200]!r}")
        return json.loads(body)


def drive(base, stations, stop, counter):
    """Toggles each station's contamination every 100 ms until `stop`."""
    api = Api(base)
    high = False
    tick = time.monotonic()
    while not stop.is_set():
        high = not high
        for a in stations:
            api.call("rs4sim.v1.Device/SetContamination", {"address": a, "percent": 50 if high else 0})
            counter[0] += 1
        tick += 0.1
        delay = tick - time.monotonic()
        if delay > 0:
            time.sleep(delay)


def phase(pid, seconds):
    c0, t0 = cpu_seconds(pid), time.monotonic()
    time.sleep(seconds)
    return (cpu_seconds(pid) - c0) / (time.monotonic() - t0)


def main():
    rs4sim = sys.argv[1]
    seconds = float(sys.argv[2]) if len(sys.argv) > 2 else 10.0
    a, b = free_udp_port(), free_udp_port()
    addresses = [x for s in STATIONS for x in ("--address", str(s))]
    slaves = [x for s in STATIONS for x in ("--slave", str(s))]
    run = subprocess.Popen([rs4sim, "run", "--device", "rs4", *addresses, "--link", "udp",
                            "--listen", f"127.0.0.1:{a}", "--peer", f"127.0.0.1:{b}",
                            "--boot-time", "1000", "--http", "127.0.0.1:0"],
                           stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    master = subprocess.Popen([rs4sim, "master", "--address", "0", *slaves, "--no-proxy",
                               "--link", "udp",
                               "--listen", f"127.0.0.1:{b}", "--peer", f"127.0.0.1:{a}"],
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    driver = None
    try:
        base = listening(run)
        threading.Thread(target=lambda: [None for _ in run.stdout], daemon=True).start()
        time.sleep(8)  # the DP start-up of 125 stations and the RS4s' boot
        options = webdriver.ChromeOptions()
        options.binary_location = "/usr/bin/chromium"
        for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage"):
            options.add_argument(arg)
        driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
        driver.get(base)
        # Count the events the page receives (a second listener on the page's own stream
        # would be a second client; wrap the page's handler instead).
        driver.execute_script("window.__events = 0; window.__dropped = 0; const f = window.onEvent;"
                              "window.onEvent = (e) => { window.__events++;"
                              " if (e.dropped) window.__dropped += Number(e.dropped.count); f(e); };")
        rows = exchanging = 0
        deadline = time.monotonic() + 60
        while exchanging < len(STATIONS) and time.monotonic() < deadline:
            time.sleep(1)
            rows = driver.execute_script(
                "return document.querySelectorAll('#stations tr.station').length")
            exchanging = driver.execute_script("return document.querySelectorAll("
                                               "'#stations tr.station[data-state=\"Data_Exch\"]').length")
        time.sleep(2)
        idle = phase(run.pid, seconds)
        e0 = driver.execute_script("return window.__events")
        stop, counters = threading.Event(), [[0], [0]]
        threads = [threading.Thread(target=drive, args=(base, STATIONS[i::2], stop, counters[i]))
                   for i in range(2)]
        for t in threads:
            t.start()
        time.sleep(1)
        n0 = sum(c[0] for c in counters)
        t0 = time.monotonic()
        busy = phase(run.pid, seconds)
        calls = (sum(c[0] for c in counters) - n0) / (time.monotonic() - t0)
        events = driver.execute_script("return window.__events") - e0
        dropped = driver.execute_script("return window.__dropped")
        driver.get("about:blank")  # the page closed, the changes go on
        time.sleep(1)
        no_page = phase(run.pid, seconds)
        stop.set()
        for t in threads:
            t.join()
        print(f"stations in the page's list: {rows}, in data exchange: {exchanging}")
        print(f"run CPU idle (125 RS4s polled, one page open): {idle * 100:.1f} % of a core")
        print(f"run CPU with every station changing at 10 Hz:  {busy * 100:.1f} % of a core "
              f"({calls:.0f} SetContamination calls/s achieved of 1250)")
        print(f"ratio 10 Hz / idle: {busy / idle:.2f}")
        print(f"  the same changes with no page open:       {no_page * 100:.1f} % of a core "
              f"(ratio {no_page / idle:.2f}; the open page's share {(busy - no_page) * 100:.1f} %)")
        print(f"events the page received in the 10 Hz phase: {events} "
              f"({events / seconds:.0f}/s; reported lost by the stream: {dropped})")
    finally:
        if driver is not None:
            driver.quit()
        for p in (master, run):
            p.terminate()
            try:
                p.wait(timeout=10)
            except subprocess.TimeoutExpired:
                p.kill()


if __name__ == "__main__":
    main()
