"""The pytest plugin as a user outside the repository meets it: the README's fixture test (its
one ```py block) written as it stands into a temporary directory and run there by the venv's
pytest, with rs4sim from $RS4SIM, then from the PATH; then the line devices' fixtures and the
rs4sim_run factory in a file of their own. Nothing of the repository is on sys.path: the
package and its plugin come from the venv (installed by tests/rpc/python_venv_setup.py).
Usage: python_pytest_fixture_test.py RS4SIM REPO (exit 77: no python3-grpcio, python3-pytest)"""
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

rs4sim, repo = os.path.abspath(sys.argv[1]), os.path.realpath(sys.argv[2])
readme = open(os.path.join(repo, "README.md"), encoding="utf-8").read()
blocks = re.findall(r"```py\n(.*?)```", readme, flags=re.S)
assert len(blocks) == 1, f"{len(blocks)} ```py blocks in README.md (the fixture test)"
assert "rs4sim_memory" in blocks[0], "the README's fixture test does not use rs4sim_memory"

LINE_DEVICES = '''
from rs4sim import Polaris


def test_polaris(rs4sim_polaris):
    assert rs4sim_polaris.process.pty.startswith("/dev/"), rs4sim_polaris.process.lines
    rs4sim_polaris.set_blocked([3, 4])
    state = rs4sim_polaris.state()
    assert list(state.blocked) == [3, 4] and state.pn1, state


def test_gridscan(rs4sim_gridscan):
    assert rs4sim_gridscan.process.pty.startswith("/dev/")
    rs4sim_gridscan.set_blocked([2])
    assert list(rs4sim_gridscan.state().blocked) == [2]


def test_metron(rs4sim_metron):
    assert rs4sim_metron.process.pty.startswith("/dev/")
    rs4sim_metron.set_blocked([1, 2])
    assert list(rs4sim_metron.state().blocked) == [1, 2]


def test_run_factory(rs4sim_run):
    run = rs4sim_run("run", "--device", "polaris", "--link", "pty", "--model", "PL10",
                     "--beams", "40", "--address", "7", "--grpc", "127.0.0.1:0")
    assert run.address.startswith("127.0.0.1:") and run.returncode is None, run
    with Polaris(run.address, 7) as polaris:
        assert polaris.state().beams == 40
'''


def pytest_in(directory, env, *files):
    result = subprocess.run([sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-q",
                             *files], cwd=directory, env=env, capture_output=True, text=True,
                            timeout=100)
    return result.returncode, result.stdout + result.stderr


with tempfile.TemporaryDirectory(prefix="rs4sim_user_") as directory:
    assert not os.path.realpath(directory).startswith(repo + os.sep), directory
    with open(os.path.join(directory, "test_readme.py"), "w", encoding="utf-8") as f:
        f.write(blocks[0])
    with open(os.path.join(directory, "test_line_devices.py"), "w", encoding="utf-8") as f:
        f.write(LINE_DEVICES)
    user = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "RS4SIM")}

    code, out = pytest_in(directory, dict(user, RS4SIM=rs4sim), "test_readme.py")
    assert code == 0 and "1 passed" in out, out
    print("ok: the README's fixture test passes outside the repository (RS4SIM)")

    on_path = dict(user, PATH=os.path.dirname(rs4sim) + os.pathsep + user.get("PATH", ""))
    code, out = pytest_in(directory, on_path, "test_readme.py")
    assert code == 0 and "1 passed" in out, out
    print("ok: the same with rs4sim found on the PATH")

    code, out = pytest_in(directory, dict(user, RS4SIM=rs4sim), "test_line_devices.py")
    assert code == 0 and "4 passed" in out, out
    print("ok: rs4sim_polaris, rs4sim_gridscan, rs4sim_metron and rs4sim_run")
