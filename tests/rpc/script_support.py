"""What the Python test scripts beside this file (and tests/integration/*_pty.py) share: the
skip without python3-grpcio, reading rs4sim's stdout, waiting on the wall clock, free UDP
ports, stopping a process, a gRPC error's status, a pty opened raw and read until the line
stays quiet, the Modbus RTU CRC, the state changes of an event stream, a check that fails a script with its message, an RS4 on
the simulated bus.
Standard library only: the scripts import it before the rs4sim package."""
import contextlib
import os
import signal
import socket
import subprocess
import sys
import termios
import time


def require_grpc():
    """The grpc module; exits with 77 (the test is skipped) when python3-grpcio is missing."""
    try:
        import grpc
    except ImportError:
        print("python3-grpcio is not installed: skipped")
        sys.exit(77)
    return grpc


def check(cond, what):
    """Fails the script (exit 1) with `what` unless `cond`."""
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


def first_lines(proc, *prefixes):
    """The values of the first stdout lines that start with each prefix, in any order."""
    found = {}
    while len(found) < len(prefixes):
        line = proc.stdout.readline()
        assert line, f"rs4sim printed no {set(prefixes) - set(found)} line"
        for p in prefixes:
            if line.startswith(p):
                found[p] = line[len(p):].strip()
    return [found[p] for p in prefixes]


def first_line(proc, prefix):
    """The value of the first stdout line that starts with prefix (stderr too, if it ended)."""
    while True:
        line = proc.stdout.readline()
        assert line, (f"rs4sim printed no {prefix!r} line: "
                      f"{proc.stderr.read() if proc.stderr and proc.poll() is not None else ''}")
        if line.startswith(prefix):
            return line[len(prefix):].strip()


def wait_for(what, condition, timeout_s):
    end = time.monotonic() + timeout_s
    while time.monotonic() < end:
        if condition():
            return
        time.sleep(0.05)
    raise AssertionError(f"timed out waiting for {what}")


def free_udp_port():
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def stop(proc, sig=signal.SIGTERM, timeout=20):
    """Sends sig and waits: (return code, stdout, stderr)."""
    proc.send_signal(sig)
    out, err = proc.communicate(timeout=timeout)
    return proc.returncode, out, err


def stop_ok(proc, sig=signal.SIGTERM):
    """stop(), prints its stderr, asserts that it ended with 0: its stdout."""
    code, out, err = stop(proc, sig)
    print(err, end="")
    assert code == 0, (code, out, err)
    return out


def expect_error(call, code, field=None):
    """call() fails with the status named code (and field as its first violation): the details."""
    grpc = require_grpc()
    from rs4sim import error_details
    try:
        call()
    except grpc.RpcError as e:
        name, violations, _ = error_details(e)
        assert name == code, (name, e.details())
        if field is not None:
            assert violations and violations[0][0] == field, violations
        return e.details()
    raise AssertionError(f"no {code}")


def open_raw(path, vtime=3):
    """The pty at path opened raw: 8 bits, no translation, no echo; a read() gives up after
    vtime tenths of a second of silence."""
    fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
    attrs = termios.tcgetattr(fd)
    attrs[0] = 0                                   # iflag: no translation
    attrs[1] = 0                                   # oflag: raw output
    attrs[2] = termios.CS8 | termios.CREAD | termios.CLOCAL
    attrs[3] = 0                                   # lflag: no echo, not canonical
    attrs[6][termios.VMIN] = 0
    attrs[6][termios.VTIME] = vtime
    termios.tcsetattr(fd, termios.TCSANOW, attrs)
    return fd


def read_quiet(fd):
    """Everything that arrives until the line stays quiet (VTIME) once."""
    out = b""
    while True:
        chunk = os.read(fd, 256)
        if not chunk:
            return out
        out += chunk


def transact(fd, request):
    """Sends a request and returns everything that arrives until the line stays quiet."""
    termios.tcflush(fd, termios.TCIFLUSH)
    os.write(fd, request)
    return read_quiet(fd)


def crc16(frame):
    """CRC-16/Modbus [Modbus serial line V1.02 §6.2.2]: init 0xFFFF, reflected polynomial
    0xA001, sent low byte first."""
    crc = 0xFFFF
    for byte in frame:
        crc ^= byte
        for _ in range(8):
            crc = (crc >> 1) ^ 0xA001 if crc & 1 else crc >> 1
    return bytes([crc & 0xFF, crc >> 8])


def with_crc(frame):
    return bytes(frame) + crc16(frame)


def state_changes(events, what, n, address=False):
    """The first n changes of state `what` in an event stream as (from, to), or (address, from,
    to) with address=True; cancels the stream."""
    out = []
    for event in events:
        if event.HasField("state") and event.state.what == what:
            change = (event.state.previous, event.state.to)
            out.append((event.address, *change) if address else change)
            if len(out) == n:
                break
    events.cancel()
    return out


def spawn(*command, **popen_args):
    """The command started with its stdout and stderr as text pipes (unless popen_args say
    otherwise)."""
    popen_args = {"stdout": subprocess.PIPE, "stderr": subprocess.PIPE, "text": True,
                  **popen_args}
    return subprocess.Popen(list(command), **popen_args)


def pty_path(proc):
    """The pty path a byte device's `rs4sim run --link pty` prints first."""
    path = proc.stdout.readline().strip()
    assert path.startswith("/dev/"), path
    return path
