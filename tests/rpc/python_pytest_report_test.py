"""What the pytest plugin reports when something goes wrong, run by the venv's pytest on test
files written to a temporary directory: a failing test's report carries the rs4sim process's
command, stdout (with its `grpc: listening on` line) and stderr; a missing executable ($RS4SIM
naming no file, no rs4sim on the PATH), a process that dies before listening (its exit
status and its stderr), one that never prints the line (killed after start_timeout) and one
that ends badly at teardown (its exit status, and its output in the teardown's report) are
named as such. The bad processes are shell scripts standing in for rs4sim.
Usage: python_pytest_report_test.py RS4SIM REPO (exit 77: no python3-grpcio, python3-pytest)"""
import os
import re
import subprocess
import sys
import tempfile

try:
    import grpc  # noqa: F401
    import pytest  # noqa: F401
except ImportError as missing:
    print(f"{missing.name} cannot be imported (python3-grpcio, python3-pytest): skipped")
    sys.exit(77)

rs4sim = os.path.abspath(sys.argv[1])

FAKES = {
    "dies.sh": "#!/bin/sh\necho 'rs4sim: cannot open the link' >&2\nexit 3\n",
    "silent.sh": "#!/bin/sh\nexec sleep 30\n",
    "ends_badly.sh": "#!/bin/sh\ntrap 'echo \"stopping badly\" >&2; exit 4' TERM\n"
                     "echo 'grpc: listening on 127.0.0.1:1'\n"
                     "while :; do sleep 0.1; done\n",
}

TESTS = '''
import os


def test_fails_after_boot(rs4sim_memory):
    rs4sim_memory.boot()
    assert not rs4sim_memory.ossd(), "the failure whose report shows rs4sim's output"


def test_rs4sim_names_no_file(monkeypatch, request):
    monkeypatch.setenv("RS4SIM", "/nonexistent/rs4sim")
    request.getfixturevalue("rs4sim_memory")


def test_no_rs4sim_on_the_path(monkeypatch, request, tmp_path):
    monkeypatch.delenv("RS4SIM")
    monkeypatch.setenv("PATH", str(tmp_path))
    request.getfixturevalue("rs4sim_memory")


def test_dies_before_listening(monkeypatch, request):
    monkeypatch.setenv("RS4SIM", os.path.join(os.path.dirname(__file__), "dies.sh"))
    request.getfixturevalue("rs4sim_memory")


def test_never_listens(monkeypatch, rs4sim_run):
    monkeypatch.setenv("RS4SIM", os.path.join(os.path.dirname(__file__), "silent.sh"))
    rs4sim_run("run", "--link", "memory", "--grpc", "127.0.0.1:0", start_timeout=1)


def test_ends_badly(monkeypatch, rs4sim_run):
    monkeypatch.setenv("RS4SIM", os.path.join(os.path.dirname(__file__), "ends_badly.sh"))
    assert rs4sim_run("run").address == "127.0.0.1:1"
'''

with tempfile.TemporaryDirectory(prefix="rs4sim_user_") as directory:
    for name, text in FAKES.items():
        path = os.path.join(directory, name)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        os.chmod(path, 0o755)
    with open(os.path.join(directory, "test_report.py"), "w", encoding="utf-8") as f:
        f.write(TESTS)
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["RS4SIM"] = rs4sim
    result = subprocess.run([sys.executable, "-m", "pytest", "-p", "no:cacheprovider",
                             "test_report.py"], cwd=directory, env=env, capture_output=True,
                            text=True, timeout=100)
    out = result.stdout + result.stderr

# One report per header line: "____ test_x ____" (a failure) or "____ ERROR at teardown of
# test_x ____"; the text up to the next header.
reports, name = {}, None
for line in out.splitlines():
    header = re.match(r"^_{3,} (.+?) _{3,}$", line)
    if header:
        name = header.group(1)
        reports[name] = ""
    elif name is not None:
        reports[name] += line + "\n"
    if line.startswith("=") and "short test summary" in line:
        name = None


def report(test):
    assert test in reports, (test, sorted(reports), out)
    return reports[test]


assert result.returncode == 1, (result.returncode, out)
assert re.search(r"5 failed, 1 passed, 1 error", out), out

failed = report("test_fails_after_boot")
assert "the failure whose report shows rs4sim's output" in failed, failed
stdout = re.search(r"-+ Captured stdout call: rs4sim pid \d+, running -+\n(.*?)\n-+ Captured",
                   failed, flags=re.S)
assert stdout, failed
assert stdout.group(1).startswith(f"$ {rs4sim} run --link memory --grpc 127.0.0.1:0\n"), failed
assert re.search(r"^grpc: listening on 127\.0\.0\.1:\d+$", stdout.group(1), flags=re.M), failed
assert re.search(r"-+ Captured stderr call: rs4sim pid \d+, running -+", failed), failed
print("ok: a failing test's report has rs4sim's command, stdout and stderr")

text = report("test_rs4sim_names_no_file")
assert "RS4SIM=/nonexistent/rs4sim: no such file" in text, text
text = report("test_no_rs4sim_on_the_path")
assert "no rs4sim executable: RS4SIM is not set and there is no rs4sim on the PATH" in text, text
text = report("test_dies_before_listening")
assert "ended (exit status 3) before 'grpc: listening on ADDRESS'" in text, text
assert "rs4sim: cannot open the link" in text, text
text = report("test_never_listens")
assert "printed no 'grpc: listening on ADDRESS' line within 1 s" in text, text
print("ok: a missing executable, a death before listening and a silent process are named")

text = report("ERROR at teardown of test_ends_badly")
assert re.search(r"rs4sim \(pid \d+\) ended with exit status 4: \S*ends_badly\.sh run", text), text
assert re.search(r"Captured stderr teardown: rs4sim pid \d+, exit status 4 -+\nstopping badly",
                 text), text
assert "grpc: listening on 127.0.0.1:1" in text, text
print("ok: a process that ends badly fails the teardown, with its output")
