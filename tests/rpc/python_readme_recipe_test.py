"""Runs the README's two-process recipe (`rs4sim run --address 4 --link pty ...` and
`rs4sim master --slave 4 --link serial --port /dev/pts/3 --restart-pulse 300`) as written,
with the built rs4sim and the pty path the run printed in place of /dev/pts/3, the master's
default archive in a temporary $XDG_DATA_HOME: the master must print OSSD 1 (before
--restart-pulse it stayed at OSSD 0, the RS4 waiting in its start interlock).
Usage: python_readme_recipe_test.py RS4SIM REPO"""
import os
import re
import signal
import subprocess
import sys
import tempfile
import threading

rs4sim, repo = sys.argv[1], sys.argv[2]
readme = open(os.path.join(repo, "README.md"), encoding="utf-8").read()
blocks = [b for b in re.findall(r"```sh\n(.*?)```", readme, flags=re.S) if "--restart-pulse" in b]
assert len(blocks) == 1, f"{len(blocks)} sh blocks with the recipe in README.md"
commands = [line.split("#")[0].split() for line in blocks[0].strip().splitlines()]
assert [c[:2] for c in commands] == [["rs4sim", "run"], ["rs4sim", "master"]], commands
assert "/dev/pts/3" in commands[1], commands[1]


def lines_until(proc, wanted, timeout_s):
    """The stdout lines of proc until one contains `wanted` (None when it did not come)."""
    seen, found = [], threading.Event()

    def read():
        for line in proc.stdout:
            seen.append(line)
            if wanted in line:
                found.set()
                return
    threading.Thread(target=read, daemon=True).start()
    return seen if found.wait(timeout_s) else None, seen


with tempfile.TemporaryDirectory() as home:
    env = dict(os.environ, XDG_DATA_HOME=home)
    run = subprocess.Popen([rs4sim] + commands[0][1:], stdout=subprocess.PIPE, text=True, env=env)
    master = None
    try:
        pty = run.stdout.readline().strip()
        assert pty.startswith("/dev/"), f"the run printed {pty!r}, not its pty"
        argv = [rs4sim] + [pty if a == "/dev/pts/3" else a for a in commands[1][1:]]
        master = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                  text=True, env=env)
        reached, seen = lines_until(master, "OSSD 1", 60)
        if reached is None:
            print("FAILED: the master printed no OSSD 1 within 60 s:\n" + "".join(seen))
            sys.exit(1)
    finally:
        for p in (master, run):
            if p is not None and p.poll() is None:
                p.send_signal(signal.SIGTERM)
                p.wait(15)
print("ok: the README's two-process recipe reaches OSSD 1")
