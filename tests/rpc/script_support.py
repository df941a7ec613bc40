"""What the Python test scripts of tests/rpc share (each runs as `SCRIPT RS4SIM REPO`, with this
folder first on sys.path): the skip without python3-grpcio and the check that fails a script
with its message."""
import contextlib
import sys


def require_grpc():
    """Exit 77 (ctest's SKIP_RETURN_CODE) when python3-grpcio is not installed."""
    try:
        import grpc  # noqa: F401  (only whether it imports)
    except ImportError:
        print("python3-grpcio is not installed: skipped")
        sys.exit(77)


def check(cond, what):
    """Fail the script (exit 1) with `what` unless `cond`."""
    if not cond:
        print("FAILED:", what)
        sys.exit(1)


@contextlib.contextmanager
def memory_rs4(executable):
    """`rs4sim run --link memory --grpc 127.0.0.1:0` (our master and the RS4 on the simulated
    bus) and an rs4sim.Rs4 on station 4, both ended when the block ends."""
    from rs4sim import Rs4
    from rs4sim.process import Rs4simProcess
    with Rs4simProcess(["run", "--link", "memory", "--grpc", "127.0.0.1:0"],
                       executable=executable) as proc, Rs4(proc.address) as rs4:
        yield rs4
