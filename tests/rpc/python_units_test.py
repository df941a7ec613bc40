"""One unit of time in the Python package: seconds as floats. Every public method of the
harness classes has a docstring, and one that takes a time names its unit (seconds). The
line devices' clock in seconds (now, advance, receive, exchange's timeout, power_cycle, the
LATE fault's delay), the RS4's restart press in seconds; the old spellings in ms/ns (ms=,
wait_ms=, timeout_ms=, off_ms=, late_ms=, now_ns()) still work and warn with a
DeprecationWarning pointing at the caller. Known answers: the GridScan's "ready" message
comes 1700 ms after its version message [GridScan manual §10.1.1]; the restart press lasts
what it was given ([RS4 manual §4.3]; on the simulated bus the call runs the clock through it).
Usage: python_units_test.py RS4SIM REPO   (exit 77 = skipped: no python3-grpcio)"""
import inspect
import sys
import warnings

from script_support import check, memory_rs4, require_grpc  # noqa: E402

require_grpc()

rs4sim = sys.argv[1]
import rs4sim as package  # noqa: E402
from rs4sim import GridScan  # noqa: E402
from rs4sim.process import Rs4simProcess  # noqa: E402

TIME_PARAMETERS = {"seconds", "timeout", "timeout_s", "wait", "off", "late", "delay", "cycle",
                   "scan_cycle", "t_response", "response_time"}


def public_methods():
    for name in ("Rs4", "Master", "GridScan", "Metron", "Polaris", "GsdStations", "GsdMaster",
                 "Rs4simProcess"):
        cls = getattr(package, name)
        for attr, member in inspect.getmembers(cls):
            if attr.startswith("_") or not (inspect.isfunction(member)
                                            or isinstance(member, property)):
                continue
            yield f"{name}.{attr}", member


def docstrings():
    for name, member in public_methods():
        doc = inspect.getdoc(member)
        check(doc, f"{name} has no docstring")
        if not inspect.isfunction(member):
            continue
        timed = TIME_PARAMETERS & set(inspect.signature(member).parameters)
        check(not timed or "second" in doc, f"{name}({', '.join(timed)}): no unit in '{doc}'")


def deprecated(call, fragment):
    """The call's result; it must warn once, with a DeprecationWarning naming `fragment`, at
    this file (the caller's line)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = call()
    check([w.category for w in caught] == [DeprecationWarning], f"warnings {caught}")
    check(fragment in str(caught[0].message), str(caught[0].message))
    check(caught[0].filename == __file__, f"warned at {caught[0].filename}")
    return result


def gridscan():
    with Rs4simProcess(["run", "--device", "gridscan", "--link", "memory",
                        "--grpc", "127.0.0.1:0"], executable=rs4sim) as proc:
        with GridScan(proc.address) as g:
            t0 = g.now()
            check(isinstance(t0, float) and 3600 <= t0 < 3700, f"now() in seconds: {t0}")
            frames = g.receive(1.702)
            check(len(frames) == 2, f"the power-up messages {frames}")
            check(frames[1].start_ns - frames[0].start_ns == 1_700_000_000, "ready 1.7 s later")
            check(abs(g.now() - (t0 + 1.702)) < 1e-9, f"receive(1.702) ran 1.702 s: {g.now()}")
            t1 = g.advance(0.25)
            check(abs(t1 - (t0 + 1.952)) < 1e-9, f"advance(0.25) returns seconds: {t1}")
            t2 = deprecated(lambda: g.advance(ms=50), "seconds=")
            check(abs(t2 - (t1 + 0.05)) < 1e-9, f"advance(ms=50) is 0.05 s: {t2}")
            ns = deprecated(g.now_ns, "now()")
            check(ns == round(t2 * 1e9), f"now_ns() {ns} vs {t2}")
            deprecated(lambda: g.receive(wait_ms=10), "wait=")
            check(abs(g.now() - (t2 + 0.01)) < 1e-9, "receive(wait_ms=10) ran 10 ms")
            x = g.exchange(b"\x00" * 10, timeout=0.005)
            check(x.answered or x.now_ns - x.sent_ns == 5_000_000, f"exchange(timeout=0.005): {x}")
            deprecated(lambda: g.exchange(b"\x00" * 10, timeout_ms=5), "timeout=")
            deprecated(lambda: g.power_cycle(off_ms=100), "off=")
            g.power_cycle(0.1)
            try:
                g.advance(0.0005)
                check(False, "half a millisecond accepted")
            except ValueError as e:
                check("whole number of ms" in str(e), str(e))


def rs4():
    with memory_rs4(rs4sim) as r:
        r.boot()
        # On the simulated bus a press runs the clock for its duration (the release is
        # part of the call): the time it took is the duration given.
        t0 = r.now()
        r.press_restart(0.3)
        check(abs(r.now() - (t0 + 0.3)) < 1e-9, f"press_restart(0.3) ran {r.now() - t0} s")
        check(not r.state().restart_button_held, "released after the press")
        t1 = r.now()
        deprecated(lambda: r.press_restart(ms=200), "seconds=")
        check(abs(r.now() - (t1 + 0.2)) < 1e-9, f"press_restart(ms=200) ran {r.now() - t1} s")

docstrings()
gridscan()
rs4()
print("ok")
