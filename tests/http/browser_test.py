#!/usr/bin/python3
"""The live view in a real browser (docs/http.md): Debian's chromium, headless, driven by
python3-selenium through chromium-driver.

Starts `rs4sim run --link memory --http 127.0.0.1:0` (the RS4 at address 4 on the manual
clock), brings the RS4 to measuring and loads the page: the station's row says OSSD on.
Then violates the protective field through the JSON API (POST
/api/rs4sim.v1.Device/ViolateField) and advances the clock: the row's data-ossd goes "off",
the SVG shows the object in the protective field, and the input byte's OSSD bit reads 0.
Then drops one reply on the bus: the row's data-repeats goes "1". Then the RS-485 devices,
each in its own `run --device X --link memory` (GridScan, METRON, Polaris): their elements or
beams drawn, some interrupted through the JSON API (X.SetBlocked), each cell's data-state, the
device's state in words and the page's clock after the time moved on.
Then `rs4sim master --archive --http` on UDP with an RS4 of `rs4sim run` beside it: the
master's page lists the station from the master's own view (BusMaster: data-state
DataExchange, data-syncs 1), the archive's station and its history (the first sync's upload);
two changes of the set through the run's JSON API (Device.SetParameterSet) are uploaded as
two versions and the page draws their diff (the picture of `rs4sim archive diff --svg`).
Before that, a bus file on the simulated bus (`run --bus bus_rs4_gsd.json --link memory`):
the GSD station's address, ident, modules, DP state and online, and the inputs set through
GsdStations.SetInputs bit by bit in the DOM; off the bus and back. Then a GSD F-device
(`run --gsd f_module_v1.gsd --link memory`): its PROFIsafe V1 F-module running with our
master's F-host, the F-inputs set, and diagnosis 64 with the GSD's own text after a wrong
F_Dest_Add.
At every stage the browser's console holds no 501 (the page asks Run.Describe what the run
serves and calls nothing else); the RS4's healthy start counts RS/RR but no Illegal; the
master's page names its archive file and shows the master's DataExchange as Data_Exch.
The screenshots are the test's artifacts: live_view.png, live_view_gridscan.png,
live_view_metron.png, live_view_polaris.png, live_view_gsd.png, live_view_gsd_fdevice.png and
live_view_master.png in
OUTDIR.

Usage: browser_test.py RS4SIM OUTDIR. Exit 77 (skipped) without selenium or chromium.
"""
import json
import os
import socket
import subprocess
import tempfile
import sys
import time
import urllib.error
import urllib.request

try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import WebDriverWait
except ImportError:
    print("skipped: python3-selenium is not installed (tools/preflight.sh lists it)")
    sys.exit(77)

CHROMIUM = "/usr/bin/chromium"
DRIVER = "/usr/bin/chromedriver"


def call(base, method, request):
    req = urllib.request.Request(base + "api/" + method, data=json.dumps(request).encode(),
                                 headers={"Content-Type": "application/json"}, method="POST")
    with urllib.request.urlopen(req, timeout=30) as r:
        return json.load(r)


def listening(proc):
    """The base URL from the run's first line."""
    line = proc.stdout.readline().strip()
    prefix = "http: listening on "
    assert line.startswith(prefix), f"first line: {line!r}"
    base = line[len(prefix):]
    assert base.startswith("http://127.0.0.1:") and base.endswith("/"), base
    return base


def listening_among(proc, prefix="http: listening on "):
    """The base URL from the first stdout line with `prefix` (other lines may come first)."""
    for _ in range(40):
        line = proc.stdout.readline()
        assert line, f"rs4sim printed no {prefix!r} line"
        if line.startswith(prefix):
            return line[len(prefix):].strip()
    raise AssertionError(f"no {prefix!r} line")


def simulated_page(driver, procs, rs4sim, args, advance_ms):
    """`rs4sim run ARGS --link memory --baud 12M --http` started, its clock moved by
    `advance_ms`, its page opened; returns the page's base URL."""
    proc = subprocess.Popen([rs4sim, "run"] + args + ["--link", "memory", "--baud", "12M",
                                                     "--http", "127.0.0.1:0"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    procs.append(proc)
    base = listening_among(proc)
    call(base, "rs4sim.v1.SimTime/Advance", {"durationMs": advance_ms})
    driver.get(base)
    return base


def free_udp_port():
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def no_unserved_calls(driver, stage):
    """The browser's console since the last look holds no request the run answered with 501
    (a service it does not serve)."""
    unserved = [e["message"] for e in driver.get_log("browser") if "status of 501" in e["message"]]
    assert not unserved, (stage, unserved)


def line_stage(driver, wait, rs4sim, procs, outdir, kind, address, blocked, pattern, words,
               screenshot):
    """`run --device KIND --link memory --http`: the device's cells (one per element or beam)
    all free, then `blocked` interrupted through the JSON API and the simulated clock moved on:
    each cell's data-state as `pattern` says ("I" interrupted, "." free, cell 1 first) and,
    when given, `words` in the device's heading; the page's clock at the time moved on to.
    Leaves `screenshot` in `outdir`."""
    proc = subprocess.Popen([rs4sim, "run", "--device", kind, "--link", "memory",
                             "--http", "127.0.0.1:0"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    procs.append(proc)
    base = listening(proc)
    driver.get(base)
    box = f'#lines .line-device[data-address="{address}"][data-kind="{kind}"]'
    wait.until(lambda d: d.find_elements(By.CSS_SELECTOR, box + '[data-state="free"] .beam'))
    cells = len(driver.find_elements(By.CSS_SELECTOR, box + " .beam"))
    assert cells == len(pattern), (kind, cells, len(pattern))
    service = {"gridscan": "GridScan", "metron": "Metron", "polaris": "Polaris"}[kind]
    call(base, f"rs4sim.v1.{service}/SetBlocked", {"address": address, "blocked": blocked})
    now = call(base, "rs4sim.v1.SimTime/Advance", {"durationMs": 500})
    wait.until(lambda d: d.find_elements(By.CSS_SELECTOR, box + '[data-state="interrupted"]'))
    # The page's clock follows time moved by another client (here: this script).
    # The clock shows the time since the run began: now_ns - start_ns (a simulated clock does
    # not start at 0).
    clock = f"{(int(now['nowNs']) - int(now['startNs'])) // 1_000_000 / 1000:.3f} s"
    wait.until(lambda d: d.find_element(By.ID, "clock-now").text == clock)
    # (the cells are redrawn four times a second: read them in one script)
    states = wait.until(lambda d: d.execute_script(
        "const c = document.querySelectorAll(arguments[0] + ' .beam');"
        "return c.length ? [...c].map((e) => e.dataset.state === 'interrupted' ? 'I' : "
        "e.dataset.state === 'free' ? '.' : '?').join('') : null;", box))
    assert states == pattern, (kind, states, pattern)
    no_unserved_calls(driver, kind)
    if words is not None:
        heading = wait.until(lambda d: d.execute_script(
            "const h = document.querySelector(arguments[0] + ' h3');"
            "return h && h.textContent.includes(arguments[1]) ? h.textContent : null;",
            box, words))
    else:
        heading = driver.execute_script(
            "return document.querySelector(arguments[0] + ' h3').textContent;", box)
    driver.execute_script("document.getElementById('lines-panel').scrollIntoView()")
    shot = os.path.join(outdir, screenshot)
    driver.save_screenshot(shot)
    print(f"ok: {kind} {len(pattern)} cells, {states}; {heading!r}; screenshot {shot}")
    proc.terminate()  # done with it (main's cleanup checks how it ended)
    proc.wait(timeout=10)


def main():
    rs4sim, outdir = sys.argv[1], sys.argv[2]
    for path in (CHROMIUM, DRIVER):
        if not os.path.exists(path):
            print(f"skipped: {path} is missing (chromium, chromium-driver)")
            return 77
    proc = subprocess.Popen([rs4sim, "run", "--link", "memory", "--http", "127.0.0.1:0"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    procs = [proc]
    driver = None
    try:
        base = listening(proc)
        # The boot: measuring, then the start interlock's restart pulse [RS4 manual §4.3].
        for condition, timeout in (("CONDITION_RS4_MEASURING", 60000), ("PRESS", 0),
                                   ("CONDITION_OSSD_ON", 2000)):
            if condition == "PRESS":
                call(base, "rs4sim.v1.Device/PressRestart", {"address": 4, "durationMs": 200})
                continue
            reached = call(base, "rs4sim.v1.SimTime/RunUntil",
                           {"address": 4, "condition": condition, "timeoutMs": timeout})
            assert reached["reached"], (condition, reached)

        options = webdriver.ChromeOptions()
        options.binary_location = CHROMIUM
        for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                    "--window-size=1400,1000"):
            options.add_argument(arg)
        # The browser's console: the page asks the run what it serves (Run.Describe) and calls
        # nothing else, so no load logs a 501 (no_unserved_calls below).
        options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
        driver = webdriver.Chrome(service=Service(DRIVER), options=options)
        driver.get(base)
        wait = WebDriverWait(driver, 10)
        row = '#stations tr[data-address="4"]'
        wait.until(lambda d: d.find_elements(By.CSS_SELECTOR, row + '[data-ossd="on"]'))
        state = driver.find_element(By.CSS_SELECTOR, row).get_attribute("data-state")
        assert state == "Data_Exch", state
        wait.until(lambda d: d.find_elements(By.CSS_SELECTOR, '#scan[data-ossd="on"]'))
        assert driver.find_element(By.ID, "protective-field").get_attribute("d"), "no field drawn"
        assert not driver.find_elements(By.CSS_SELECTOR, "#obstacles .obstacle"), "an obstacle before"

        call(base, "rs4sim.v1.Device/ViolateField", {"address": 4, "field": "FIELD_KIND_PROTECTIVE"})
        call(base, "rs4sim.v1.SimTime/Advance", {"durationMs": 500})
        wait.until(lambda d: d.find_elements(By.CSS_SELECTOR, row + '[data-ossd="off"]'))
        wait.until(lambda d: d.find_elements(By.CSS_SELECTOR, '#scan[data-ossd="off"]'))
        # (the panel is redrawn four times a second: read it in one script, not element by
        # element)
        hits = wait.until(lambda d: d.execute_script(
            'return document.querySelectorAll(\'#obstacles .obstacle[data-field="protective"]\').length'))
        assert hits > 0, "no obstacle in the protective field"
        wait.until(lambda d: d.execute_script(
            'return document.querySelector(\'#in-bits td[data-bit="7"]\').textContent') == "0")
        driver.find_element(By.CSS_SELECTOR, "#clock:not([hidden])")
        # The master's counters in ProfiTrace's names: one dropped reply is one repeat. The
        # RS4's boot answers the master's start-up with RS: RS/RR, not Illegal.
        wait.until(lambda d: d.find_elements(
            By.CSS_SELECTOR, row + '[data-repeats="0"][data-syncs="1"][data-illegal="0"]'))
        negative = int(driver.find_element(By.CSS_SELECTOR, row).get_attribute("data-negative"))
        assert negative > 0, negative
        no_unserved_calls(driver, "the RS4 run")
        call(base, "rs4sim.v1.Faults/InjectBusFault",
             {"address": 4, "kind": "BUS_FAULT_KIND_DROP", "direction": "DIRECTION_FROM_STATION",
              "count": 1})
        call(base, "rs4sim.v1.SimTime/Advance", {"durationMs": 200})
        wait.until(lambda d: d.find_elements(
            By.CSS_SELECTOR, row + '[data-repeats="1"][data-lost="0"][data-syncs="1"]'))
        shot = os.path.join(outdir, "live_view.png")
        driver.save_screenshot(shot)
        print(f"ok: OSSD off in the DOM, {hits} contour points in the protective field, "
              f"one repeat counted; screenshot {shot}")

        # The RS-485 devices on the simulated line, each from `run --device X --link memory`:
        # its cells drawn, some interrupted through the JSON API (X.SetBlocked), the others
        # free, the device's state in words. Each pattern is cell 1 first, "I" interrupted.
        # GridScan/Pro SI RC: 22 elements, 3..5 blocked.
        line_stage(driver, wait, rs4sim, procs, outdir, "gridscan", 0, [3, 4, 5],
                   "..III" + "." * 17, None, "live_view_gridscan.png")
        # METRON Receiver: 24 beams, 9..13 blocked: both OSSDs off, and the measurements
        # first 9, last 13, count 5 (#10) [METRON manual "Slave line mode"].
        line_stage(driver, wait, rs4sim, procs, outdir, "metron", 0, [9, 10, 11, 12, 13],
                   "." * 8 + "IIIII" + "." * 11, "OSSD off, synchronised, 5 interrupted (9–13)",
                   "live_view_metron.png")
        # Polaris PL10: 16 beams, 3..5 and 10..11 blocked: PN1 (an object) and PN2 (two
        # objects) on [Polaris manual §3].
        line_stage(driver, wait, rs4sim, procs, outdir, "polaris", 1, [3, 4, 5, 10, 11],
                   "..III....II.....", "PL10 485MB, PN1 on, PN2 on", "live_view_polaris.png")

        # A bus from one file on the simulated bus: the RS4 at 4, a GSD station at 5
        # (modular_dpv1.gsd: "DI 8" 1 input byte, "AI 2" 4 input bytes, "DO 16 consistent" 2
        # output bytes) and a generic slave at 7. Inputs set through the JSON API
        # (GsdStations.SetInputs, bytes in base64) appear bit by bit; off the bus and back.
        bus_file = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "gsd", "corpus",
                                "bus_rs4_gsd.json")
        # past the RS4's PROFIBUS adapter start (LED steady 2-3 s [RS4 manual §4.4], 2.5 s)
        base = simulated_page(driver, procs, rs4sim, ["--bus", bus_file], 3000)
        gsd = '#gsd .gsd-station[data-address="5"]'
        wait.until(lambda d: d.find_elements(
            By.CSS_SELECTOR,
            gsd + '[data-state="Data_Exch"][data-online="yes"][data-ident="0xB756"]'))
        modules = driver.execute_script(
            "return [...document.querySelectorAll(arguments[0] + ' .gsd-module .module')]"
            ".map((e) => e.textContent);", gsd)
        assert modules == ["DI 8", "AI 2", "DO 16 consistent"], modules
        wait.until(lambda d: d.find_elements(
            By.CSS_SELECTOR, '#stations tr[data-address="5"][data-state="Data_Exch"]'))
        call(base, "rs4sim.v1.GsdStations/SetInputs", {"address": 5, "slot": 0, "data": "pQ=="})  # A5
        call(base, "rs4sim.v1.GsdStations/SetInputs",
             {"address": 5, "slot": 1, "data": "ESIzRA=="})  # 11 22 33 44
        call(base, "rs4sim.v1.SimTime/Advance", {"durationMs": 100})
        wait.until(lambda d: d.find_elements(
            By.CSS_SELECTOR, gsd + ' .gsd-module[data-slot="1"][data-inputs="11 22 33 44"]'))
        bits = wait.until(lambda d: d.execute_script(
            "const c = document.querySelectorAll(arguments[0] + ' .gsd-module[data-slot=\"0\"]"
            " .bytes.in .byte[data-byte=\"0\"] .b');"
            "return c.length === 8 ? [...c].map((e) => e.dataset.bit + ':' + e.textContent) : null;",
            gsd))
        assert bits == ["7:1", "6:0", "5:1", "4:0", "3:0", "2:1", "1:0", "0:1"], bits  # 0xA5
        # (the station is redrawn after each of its events: read the attribute in one script,
        # not through an element that may be gone by the time it is asked)
        outputs = wait.until(lambda d: d.execute_script(
            "const m = document.querySelector(arguments[0] + ' .gsd-module[data-slot=\"2\"]');"
            "return m ? m.dataset.outputs : null;", gsd))
        assert outputs == "00 00", outputs  # our master writes zeros
        call(base, "rs4sim.v1.GsdStations/SetOnline", {"address": 5, "online": False})
        call(base, "rs4sim.v1.SimTime/Advance", {"durationMs": 300})
        wait.until(lambda d: d.find_elements(By.CSS_SELECTOR, gsd + '[data-online="no"]'))
        call(base, "rs4sim.v1.GsdStations/SetOnline", {"address": 5, "online": True})
        call(base, "rs4sim.v1.SimTime/Advance", {"durationMs": 1000})
        wait.until(lambda d: d.find_elements(
            By.CSS_SELECTOR, gsd + '[data-online="yes"][data-state="Data_Exch"]'))
        wait.until(lambda d: d.find_elements(
            By.CSS_SELECTOR, '#stations tr[data-address="4"][data-state="Data_Exch"]'))
        driver.execute_script("document.getElementById('gsd-panel').scrollIntoView()")
        shot = os.path.join(outdir, "live_view_gsd.png")
        driver.save_screenshot(shot)
        print(f"ok: GSD station 5 drawn (ident 0xB756, {len(modules)} modules), inputs A5 and "
              f"11 22 33 44 bit by bit, off the bus and back; screenshot {shot}")

        # A GSD F-device on the simulated bus with our master's F-host (`run --gsd
        # f_module_v1.gsd --link memory`): the drive's "PROFIsafe v1.x Module" in slot 1 (V1, 4
        # F-data bytes) runs; F-inputs set through the JSON API appear; the address switch at 2
        # and a power-up: diagnosis 64 with the GSD's own text (its X_Value(64)).
        corpus = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "gsd", "corpus")
        base = simulated_page(driver, procs, rs4sim,
                              ["--gsd", os.path.join(corpus, "f_module_v1.gsd"), "--module",
                               "Standard telegram 1, PZD-2/2", "--module", "PROFIsafe v1.x Module",
                               "--address", "5"], 1000)
        fmod = '#gsd .gsd-station[data-address="5"] .gsd-fmodule[data-slot="1"]'
        wait.until(lambda d: d.find_elements(
            By.CSS_SELECTOR, fmod + '[data-mode="V1"][data-state="run"][data-host="run"]'))
        call(base, "rs4sim.v1.GsdStations/SetFInputs",
             {"address": 5, "slot": 1, "data": "ESIzRA=="})  # 11 22 33 44
        call(base, "rs4sim.v1.SimTime/Advance", {"durationMs": 50})
        wait.until(lambda d: d.find_elements(By.CSS_SELECTOR, fmod + '[data-f-inputs="11 22 33 44"]'))
        call(base, "rs4sim.v1.GsdStations/InjectFFault",
             {"address": 5, "slot": 1, "fault": "GSD_F_FAULT_WRONG_F_DEST_ADD", "fDestAdd": 2})
        call(base, "rs4sim.v1.SimTime/Advance", {"durationMs": 500})
        wait.until(lambda d: d.find_elements(
            By.CSS_SELECTOR, fmod + '[data-state="parameter-fault"][data-diagnosis="64"]'))
        text = wait.until(lambda d: d.execute_script(
            "const p = document.querySelector(arguments[0] + ' .gsd-fdiag');"
            "return p ? p.textContent : null;", fmod))
        assert text.startswith("diagnosis 64: F add. does not match F_Dest_Add"), text
        driver.execute_script("document.getElementById('gsd-panel').scrollIntoView()")
        shot = os.path.join(outdir, "live_view_gsd_fdevice.png")
        driver.save_screenshot(shot)
        print(f"ok: GSD F-device V1 drawn, F-inputs 11 22 33 44, diagnosis 64 with the GSD's "
              f"text; screenshot {shot}")

        # `master` with an archive, its RS4 in `rs4sim run` on UDP (a 3 s boot).
        work = tempfile.mkdtemp(prefix="rs4sim_browser_master_")
        a, b = free_udp_port(), free_udp_port()
        device = subprocess.Popen(
            [rs4sim, "run", "--device", "rs4", "--address", "4", "--link", "udp", "--listen",
             f"127.0.0.1:{a}", "--peer", f"127.0.0.1:{b}", "--boot-time", "3000", "--duration",
             "60", "--pc-adapter", "detached", "--http", "127.0.0.1:0"],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        procs.append(device)
        master = subprocess.Popen(
            [rs4sim, "master", "--slave", "4", "--link", "udp", "--listen", f"127.0.0.1:{b}",
             "--peer", f"127.0.0.1:{a}", "--f-wd-time", "500", "--dp-watchdog", "1000",
             "--archive", os.path.join(work, "archive.sqlite3"), "--http", "127.0.0.1:0"],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        procs.append(master)
        device_base = listening_among(device)
        base = listening_among(master)
        driver.get(base)
        wait = WebDriverWait(driver, 30)
        row = '#stations tr[data-address="4"]'
        wait.until(lambda d: d.find_elements(
            By.CSS_SELECTOR, row + '[data-state="DataExchange"][data-syncs="1"][data-lost="0"]'))
        wait.until(lambda d: d.find_elements(
            By.CSS_SELECTOR, '#archive-stations tr.archive-station[data-address="4"]'))
        # The factory set is not archived (the first sync reports it); each change of the set on
        # site (the parametrisation tool through the PC adapter, [RS4 manual §7.2]) is uploaded.
        version = '#archive-history tr.version[data-address="4"][data-source="upload"]'
        for response_time_ms, versions in ((160, 1), (200, 2)):
            call(device_base, "rs4sim.v1.Device/SetParameterSet",
                 {"address": 4, "json": json.dumps({"format": 1,
                                                    "response_time_ms": response_time_ms})})
            wait.until(lambda d, n=versions: len(d.find_elements(By.CSS_SELECTOR, version)) == n)
        diff = '#archive-diff[data-address="4"][data-identical="false"] svg'
        wait.until(lambda d: d.find_elements(By.CSS_SELECTOR, diff))
        versions = len(driver.find_elements(By.CSS_SELECTOR, '#archive-history tr.version'))
        assert versions == 2, versions
        # Which archive the page shows, and the master's DP state in the slave's words.
        archive = driver.find_element(By.ID, "archive-name").text
        assert archive == os.path.join(work, "archive.sqlite3"), archive
        shown = driver.find_element(By.CSS_SELECTOR, row + " td:nth-child(3)").text
        assert shown == "Data_Exch", shown
        no_unserved_calls(driver, "the master")
        text = driver.find_element(By.ID, "archive-diff-text").text
        assert "response" in text, text
        shot = os.path.join(outdir, "live_view_master.png")
        driver.save_screenshot(shot)
        print(f"ok: master's station list from BusMaster, {versions} archived versions, their "
              f"diff drawn ({text.splitlines()[0] if text else ''}); screenshot {shot}")
        return 0
    finally:
        if driver is not None:
            driver.quit()
        for p in procs:
            p.terminate()
            try:
                p.wait(timeout=10)
            except subprocess.TimeoutExpired:
                p.kill()
            err = p.stderr.read()
            if p.returncode not in (0, -15):
                print(f"rs4sim exited {p.returncode}: {err}")


if __name__ == "__main__":
    sys.exit(main())
