"""Rs4simProcess never outlives the Python process that started it: a parent python starts
`rs4sim run --link memory --grpc` through Rs4simProcess and is killed with SIGKILL (no
cleanup of its own can run); the rs4sim child must then end by itself (PR_SET_PDEATHSIG), where
before it ran on with PPID 1. Also: the class is a context manager that stops the child when
the block ends by an exception.
Usage: python_process_parent_test.py RS4SIM REPO"""
import os
import signal
import subprocess
import sys
import time

from rs4sim.process import Rs4simProcess
from script_support import check

rs4sim = sys.argv[1]
ARGS = ["run", "--link", "memory", "--grpc", "127.0.0.1:0"]
PARENT = f"""
import sys
from rs4sim.process import Rs4simProcess
run = Rs4simProcess({ARGS!r}, executable={rs4sim!r})
print(run.pid, flush=True)
sys.stdin.read()  # until the test kills us
"""


def running(pid):
    """True while the process exists and is not a zombie (a zombie has ended; its new parent
    reaps it)."""
    try:
        with open(f"/proc/{pid}/stat") as stat:
            return stat.read().rsplit(")", 1)[1].split()[0] != "Z"
    except FileNotFoundError:
        return False


def ends_within(pid, seconds):
    deadline = time.monotonic() + seconds
    while running(pid):
        if time.monotonic() > deadline:
            return False
        time.sleep(0.05)
    return True


parent = subprocess.Popen([sys.executable, "-c", PARENT], stdin=subprocess.PIPE,
                          stdout=subprocess.PIPE, text=True)
child = int(parent.stdout.readline())
try:
    check(running(child), f"rs4sim {child} runs under its parent")
    os.kill(parent.pid, signal.SIGKILL)
    parent.wait()
    check(ends_within(child, 10), f"rs4sim {child} still runs 10 s after its parent was killed")
finally:
    if running(child):
        os.kill(child, signal.SIGKILL)

# The context manager: an exception in the block still stops the child.
try:
    with Rs4simProcess(ARGS, executable=rs4sim) as run:
        pid = run.pid
        raise KeyError("the block fails")
except KeyError:
    pass
check(not running(pid) and run.returncode == 0, f"stopped by the with block: {run.status()}")
print("ok")
