#!/usr/bin/python3
"""The master page's F-hosts of GSD F-devices in a real browser (docs/profisafe.md "Our master as
F-host for GSD F-devices"): Debian's chromium, headless, driven by python3-selenium.

`rs4sim run --bus bus_rs4_f_devices.json --link pty --http` (an RS4, the V1 GSD F-device 5 with
F_Dest_Add 300, the V2 GSD F-device 6) and `rs4sim master --bus-file` of the same file on the
other end of the pty, with --manual-ack and generous watchdogs (--f-wd-time 1000) and --http.
The page lists one F-host row per F-module (V1, V2) in RUN with its ACK_REI button disabled.
Station 5 taken off the bus through the run's JSON API (GsdStations.SetOnline) for longer than
F_WD_Time: its row goes passivated and, back on the bus, ack-required with the button enabled
; a click on ACK_REI reintegrates it (data-state "run"). The
browser's console holds no 501. The screenshot live_view_fhost.png is the test's artifact.

Usage: browser_fhost_test.py RS4SIM REPO OUTDIR. Exit 77 (skipped) without selenium or chromium.
"""
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from browser_test import CHROMIUM, DRIVER, call, listening_among, no_unserved_calls  # noqa: E402
from selenium import webdriver  # noqa: E402
from selenium.webdriver.chrome.service import Service  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402
from selenium.webdriver.support.ui import WebDriverWait  # noqa: E402


def main():
    rs4sim, repo, outdir = sys.argv[1], sys.argv[2], sys.argv[3]
    for path in (CHROMIUM, DRIVER):
        if not os.path.exists(path):
            print(f"skipped: {path} is missing (chromium, chromium-driver)")
            return 77
    bus = os.path.join(repo, "tests", "gsd", "corpus", "bus_rs4_f_devices.json")
    # The browser first: its start loads the machine, which would starve the two processes on
    # the pty (a lost slave is a DP restart, and the F-host passivates).
    driver = headless_chromium()
    run = subprocess.Popen([rs4sim, "run", "--bus", bus, "--link", "pty", "--http", "127.0.0.1:0",
                            "--duration", "90"],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    procs = [run]
    try:
        path = run.stdout.readline().strip()
        assert path.startswith("/dev/"), f"first line: {path!r}"
        run_base = listening_among(run)
        master = subprocess.Popen(
            [rs4sim, "master", "--bus-file", bus, "--link", "serial", "--port", path,
             "--no-proxy", "--manual-ack", "--f-wd-time", "1000", "--dp-watchdog", "2000",
             "--http", "127.0.0.1:0", "--duration", "90"],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        procs.append(master)
        base = listening_among(master)
        driver.get(base)
        wait = WebDriverWait(driver, 30)
        row = '#gsd-fhost tr.gsd-fhost[data-address="{}"][data-slot="0"]'
        # A loaded machine may still lose a slave in the first seconds (a DP restart passivates
        # its F-host): such an ACK_REQ is acknowledged through the API before the test starts.
        for address in (5, 6):
            wait.until(lambda d, a=address: d.find_elements(
                By.CSS_SELECTOR, row.format(a) + '[data-state="run"], ' + row.format(a) +
                '[data-state="ack-required"]'))
            if driver.find_elements(By.CSS_SELECTOR, row.format(address) +
                                    '[data-state="ack-required"]'):
                call(base, "rs4sim.v1.GsdMaster/AcknowledgeF", {"address": address, "slot": 0})
            wait.until(lambda d, a=address: d.find_elements(
                By.CSS_SELECTOR, row.format(a) + '[data-state="run"]'))
        modes = [driver.find_element(By.CSS_SELECTOR, row.format(a) + " td:nth-child(3)").text
                 for a in (5, 6)]
        assert modes == ["V1", "V2"], modes
        assert not driver.find_element(By.CSS_SELECTOR, row.format(5) + " .ack-rei").is_enabled()
        # Off the bus for 2 s (F_WD_Time 1 s): passivated, then ACK_REQ once back.
        call(run_base, "rs4sim.v1.GsdStations/SetOnline", {"address": 5, "online": False})
        wait.until(lambda d: d.find_elements(
            By.CSS_SELECTOR, row.format(5) + '[data-state="passivated"]'))
        call(run_base, "rs4sim.v1.GsdStations/SetOnline", {"address": 5, "online": True})
        wait.until(lambda d: d.find_elements(
            By.CSS_SELECTOR, row.format(5) + '[data-state="ack-required"]'))
        fault = driver.find_element(By.CSS_SELECTOR, row.format(5) + " td:nth-child(7)").text
        assert fault == "watchdog F_WD_Time expired", fault
        shot = os.path.join(outdir, "live_view_fhost.png")
        driver.execute_script("document.getElementById('gsd-fhost-panel').scrollIntoView()")
        driver.save_screenshot(shot)
        button = driver.find_element(By.CSS_SELECTOR, row.format(5) + " .ack-rei")
        assert button.is_enabled()
        button.click()
        wait.until(lambda d: d.find_elements(By.CSS_SELECTOR, row.format(5) + '[data-state="run"]'))
        no_unserved_calls(driver, "the master's F-hosts")
        print(f"ok: F-hosts of GSD slaves 5 (V1) and 6 (V2) in RUN, 5 passivated off the bus, "
              f"ACK_REQ, ACK_REI from the page; screenshot {shot}")
        return 0
    finally:
        stop_all(driver, procs)
        # What the master reported (its PROFIsafe and DP lines), for a failure's reader.
        if len(procs) > 1:
            print("\n".join(line for line in procs[1].stdout.read().splitlines()
                            if "PROFIsafe" in line or "DP " in line))


def headless_chromium():
    """Debian's chromium, headless, its console kept (no_unserved_calls reads it)."""
    options = webdriver.ChromeOptions()
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    args = "--headless=new --no-sandbox --disable-gpu --disable-dev-shm-usage --window-size=1400,1000"
    for arg in args.split():
        options.add_argument(arg)
    options.binary_location = CHROMIUM
    return webdriver.Chrome(service=Service(DRIVER), options=options)


def stop_all(driver, procs):
    """Closes the browser and ends the processes: SIGTERM, SIGKILL for those still running
    10 s later."""
    if driver is not None:
        driver.quit()
    for p in procs:
        p.terminate()
    deadline = time.monotonic() + 10
    while any(p.poll() is None for p in procs) and time.monotonic() < deadline:
        time.sleep(0.1)
    for p in (p for p in procs if p.poll() is None):
        p.kill()

if __name__ == "__main__":
    sys.exit(main())
