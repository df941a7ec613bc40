"""The pytest plugin of the rs4sim package (entry point `pytest11`: installing the package
is enough, no conftest.py). Each fixture starts rs4sim for one test, the executable from
$RS4SIM, else `rs4sim` on the PATH, and ends it at the test's teardown (SIGTERM; killed if it
has not ended within 10 s). A failing test's report gets each process's stdout and stderr
as sections of their own; a process that ends badly (an exit status other than 0, a signal)
fails the test's teardown with its output.

    def test_restart_interlock(rs4sim_memory):
        rs4sim_memory.boot()
        obstacle = rs4sim_memory.violate_field("protective")
        assert rs4sim_memory.run_until("OSSD_OFF", 0.5)
        rs4sim_memory.remove(obstacle)
        assert not rs4sim_memory.run_until("OSSD_ON", 1)

Fixtures:
  rs4sim_memory    Rs4 (station 4) of `rs4sim run --link memory --grpc 127.0.0.1:0`: the RS4
                   and our master on the simulated bus, the manual clock
  rs4sim_gridscan  GridScan of `rs4sim run --device gridscan --link pty --grpc 127.0.0.1:0`
  rs4sim_metron    Metron, the same with --device metron
  rs4sim_polaris   Polaris (Modbus address 1), the same with --device polaris --address 1
  rs4sim_run       a factory: rs4sim_run("run", "--device", "polaris", "--link", "pty",
                   "--model", "PL10", "--grpc", "127.0.0.1:0") -> rs4sim.Rs4simProcess
                   (`address`, `pty`, `output()`), ended at teardown like the others
The device fixtures' `.process` is their Rs4simProcess (e.g. `rs4sim_polaris.process.pty`,
the line's pty to open as the master). The harness is imported when a fixture is first used,
so a pytest run that uses none of them does not need grpc.
"""

import pytest

from .process import Rs4simError, Rs4simProcess

_STARTED = pytest.StashKey[list]()
_STOP_TIMEOUT_S = 10.0


@pytest.fixture
def rs4sim_run(request):
    """A factory that starts `rs4sim ARGS...` (see the module's docstring): keyword
    arguments go to Rs4simProcess (env, start_timeout, listening)."""
    started = request.node.stash.setdefault(_STARTED, [])
    mine = []

    def start(*args, **kwargs):
        try:
            process = Rs4simProcess(args, **kwargs)
        except Rs4simError as error:
            failure = str(error)
        else:
            failure = None
        if failure:  # the message says it all: no traceback into the plugin
            pytest.fail(failure, pytrace=False)
        started.append(process)
        mine.append(process)
        return process

    yield start
    problems = []
    for process in reversed(mine):
        process.stop(_STOP_TIMEOUT_S)
        problem = process.problem()
        if problem:
            problems.append(problem)
    if problems:
        pytest.fail("\n\n".join(problems), pytrace=False)


def _connected(cls, process, *args):
    device = cls(process.address, *args)
    device.process = process
    return device


@pytest.fixture
def rs4sim_memory(rs4sim_run):
    """The RS4 (station 4) of `rs4sim run --link memory --grpc 127.0.0.1:0`."""
    from .harness import Rs4
    rs4 = _connected(Rs4, rs4sim_run("run", "--link", "memory", "--grpc", "127.0.0.1:0"))
    yield rs4
    rs4.close()


def _line_device(rs4sim_run, cls, *args):
    return _connected(cls, rs4sim_run("run", *args, "--link", "pty", "--grpc", "127.0.0.1:0"))


@pytest.fixture
def rs4sim_gridscan(rs4sim_run):
    """The GridScan of `rs4sim run --device gridscan --link pty --grpc 127.0.0.1:0`."""
    from .harness import GridScan
    device = _line_device(rs4sim_run, GridScan, "--device", "gridscan")
    yield device
    device.close()


@pytest.fixture
def rs4sim_metron(rs4sim_run):
    """The METRON of `rs4sim run --device metron --link pty --grpc 127.0.0.1:0`."""
    from .harness import Metron
    device = _line_device(rs4sim_run, Metron, "--device", "metron")
    yield device
    device.close()


@pytest.fixture
def rs4sim_polaris(rs4sim_run):
    """The Polaris (Modbus address 1) of `rs4sim run --device polaris --address 1 --link pty
    --grpc 127.0.0.1:0`."""
    from .harness import Polaris
    device = _line_device(rs4sim_run, Polaris, "--device", "polaris", "--address", "1")
    yield device
    device.close()


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    """A failed setup, call or teardown: each rs4sim process's output so far, as sections
    of the report (printed under the failure like pytest's captured output; named
    `Captured stdout ...`/`Captured stderr ...` so --show-capture and JUnit XML see them)."""
    outcome = yield
    report = outcome.get_result()
    if not report.failed:
        return
    for process in item.stash.get(_STARTED, []):
        out, err = process.output()
        name = f"rs4sim pid {process.pid}, {process.status()}"
        report.sections.append((f"Captured stdout {report.when}: {name}",
                                f"$ {' '.join(process.command)}\n" + (out or "(nothing)\n")))
        report.sections.append((f"Captured stderr {report.when}: {name}", err or "(nothing)\n"))
