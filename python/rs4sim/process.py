"""An `rs4sim` process started for a test: the executable from $RS4SIM, else the PATH; the
API's address from its `grpc: listening on ADDRESS` line; its output collected while it
runs (two reader threads, so neither pipe fills up and blocks it); ended with SIGTERM, and
killed if it has not ended in time.

Use it as a context manager (a `with` block): the process is stopped however the block
ends, an exception included. And it never outlives the Python process that started it: the
child asks the kernel for SIGTERM when its parent dies (Linux's PR_SET_PDEATHSIG), so a
script killed with SIGKILL, or one that forgot to stop it, leaves no rs4sim behind.

    from rs4sim import Rs4, Rs4simProcess
    with Rs4simProcess(["run", "--link", "memory", "--grpc", "127.0.0.1:0"]) as run:
        rs4 = Rs4(run.address)
        rs4.boot()
    assert run.returncode == 0, run.describe()
"""

import ctypes
import os
import shutil
import signal
import subprocess
import threading

LISTENING = "grpc: listening on "
_PR_SET_PDEATHSIG = 1  # <linux/prctl.h>
try:
    _prctl = ctypes.CDLL(None, use_errno=True).prctl  # resolved here, not in the forked child
except (AttributeError, OSError):  # not Linux's C library: no parent-death signal
    _prctl = None


def _die_with_parent(parent):
    """Runs in the child between fork and exec: SIGTERM (rs4sim's orderly stop) when the
    thread that started it ends, which for a script is the Python process [prctl(2)
    PR_SET_PDEATHSIG, kept across execve]. The parent may have died before the call: then
    the child goes at once."""
    if _prctl is not None:
        _prctl(_PR_SET_PDEATHSIG, int(signal.SIGTERM), 0, 0, 0)
    if os.getppid() != parent:
        os._exit(1)


class Rs4simError(RuntimeError):
    """rs4sim was not found, did not start, or ended badly; the message says which, with
    the command and the process's output."""


def find_executable(env=None):
    """The rs4sim to run: $RS4SIM (a path, or a name looked up on the PATH), else `rs4sim`
    on the PATH. Raises Rs4simError naming what was looked for."""
    env = os.environ if env is None else env
    configured = env.get("RS4SIM", "")
    search = env.get("PATH", os.defpath)
    if configured:
        path = configured if os.sep in configured else shutil.which(configured, path=search)
        if path is None or not os.path.isfile(path):
            raise Rs4simError(f"RS4SIM={configured}: no such file (RS4SIM names the rs4sim "
                              "executable to test, e.g. build/app/rs4sim)")
        if not os.access(path, os.X_OK):
            raise Rs4simError(f"RS4SIM={configured}: not executable")
        return path
    path = shutil.which("rs4sim", path=search)
    if path is None:
        raise Rs4simError("no rs4sim executable: RS4SIM is not set and there is no rs4sim on "
                          f"the PATH ({search}); set RS4SIM to the built one, e.g. "
                          "RS4SIM=build/app/rs4sim")
    return path


def _signal_name(returncode):
    try:
        return signal.Signals(-returncode).name
    except ValueError:
        return f"signal {-returncode}"


class Rs4simProcess:
    """`rs4sim ARGS...` running, a context manager: `with Rs4simProcess([...]) as run:` stops
    it (stop()) when the block ends, however it ends. With listening=True (the default) the
    constructor returns once the process has printed `grpc: listening on ADDRESS` (so ARGS
    should have --grpc): `address` is ADDRESS, `lines` the stdout lines before it (a byte
    device on --link pty prints its pty path first: `pty`). Raises Rs4simError, with the
    output, when the process cannot be started, ends before that line or has not printed it
    within start_timeout seconds (then it is killed).

    The child gets SIGTERM when the thread that created this object ends (PR_SET_PDEATHSIG):
    for a script, when the Python process dies, SIGKILL included. Create it in a thread that
    lives as long as the process should (the main thread, a pytest fixture)."""

    def __init__(self, args, executable=None, env=None, start_timeout=10.0, listening=True):
        self.executable = executable or find_executable(env)
        self.command = [self.executable] + [str(a) for a in args]
        self.address = None
        self.lines = []
        self.killed = False
        self._stdout_closed = False
        self._stdout, self._stderr = [], []
        self._lock = threading.Lock()
        self._ready = threading.Event()
        try:
            parent = os.getpid()
            self._proc = subprocess.Popen(self.command, stdin=subprocess.DEVNULL,
                                          stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                          env=env, text=True, errors="replace",
                                          preexec_fn=lambda: _die_with_parent(parent))
        except OSError as e:
            raise Rs4simError(f"cannot start {self.executable}: {e.strerror}") from e
        self.pid = self._proc.pid
        self._readers = [
            threading.Thread(target=self._read, args=(self._proc.stdout, self._stdout, True),
                             daemon=True),
            threading.Thread(target=self._read, args=(self._proc.stderr, self._stderr, False),
                             daemon=True)]
        for reader in self._readers:
            reader.start()
        if not listening:
            return
        self._ready.wait(start_timeout)
        if self.address is None:
            if self._stdout_closed:  # it is ending: give it a moment to be reaped
                try:
                    self._proc.wait(2)
                except subprocess.TimeoutExpired:
                    pass
            if self._proc.poll() is None:
                self.stop(timeout=2)
                problem = (f"printed no '{LISTENING}ADDRESS' line within {start_timeout:g} s "
                           "(was --grpc given?); killed")
            else:
                self._join_readers()
                problem = f"ended ({self.status()}) before '{LISTENING}ADDRESS'"
            raise Rs4simError(f"{self.describe(problem)}")

    # ---- the output ------------------------------------------------------------------------
    def _read(self, stream, into, is_stdout):
        for line in stream:
            with self._lock:
                into.append(line)
            if is_stdout and self.address is None:
                if line.startswith(LISTENING):
                    self.address = line[len(LISTENING):].strip()
                    self._ready.set()
                else:
                    self.lines.append(line.rstrip("\n"))
        stream.close()
        if is_stdout:
            self._stdout_closed = True
            self._ready.set()  # ended without the line: the waiter looks at the exit status

    def _join_readers(self, timeout=5):
        for reader in self._readers:
            reader.join(timeout)

    def output(self):
        """(stdout, stderr) so far, as text."""
        with self._lock:
            return "".join(self._stdout), "".join(self._stderr)

    @property
    def pty(self):
        """The pty path a byte device on --link pty prints first, else None."""
        return self.lines[0] if self.lines and self.lines[0].startswith("/dev/") else None

    # ---- the end -----------------------------------------------------------------------------
    @property
    def returncode(self):
        """None while it runs; the exit status, or -N for signal N."""
        return self._proc.poll()

    def status(self):
        """"running", "exit status N" or "killed by SIGNAME"."""
        code = self._proc.poll()
        if code is None:
            return "running"
        if code < 0:
            return f"killed by {_signal_name(code)}"
        return f"exit status {code}"

    def stop(self, timeout=10.0):
        """SIGTERM (rs4sim's orderly stop), wait up to timeout seconds, else SIGKILL. Returns
        the exit status; a second call only returns it."""
        if self._proc.poll() is None:
            self._proc.send_signal(signal.SIGTERM)
            try:
                self._proc.wait(timeout)
            except subprocess.TimeoutExpired:
                self.killed = True
                self._proc.kill()
                self._proc.wait()
        self._join_readers()
        return self._proc.returncode

    def problem(self):
        """None if it ended as rs4sim does on SIGTERM (exit status 0) or still runs; else one
        line saying what went wrong (describe() adds the output)."""
        code = self._proc.poll()
        if code is None or (code == 0 and not self.killed):
            return None
        what = ("did not end within its time after SIGTERM: killed" if self.killed
                else f"ended with {self.status()}")
        return f"rs4sim (pid {self.pid}) {what}: {' '.join(self.command)}"

    def describe(self, what=None):
        """The command, its state (or `what`) and its output, for an error message."""
        out, err = self.output()
        text = f"rs4sim (pid {self.pid}) {what or self.status()}: {' '.join(self.command)}"
        text += "\n--- stdout\n" + (out or "(nothing)\n")
        text += "--- stderr\n" + (err or "(nothing)\n")
        return text.rstrip("\n")

    def __enter__(self):
        """The process itself (`with Rs4simProcess(...) as run`)."""
        return self

    def __exit__(self, *exc):
        """stop(): SIGTERM, up to 10 s, then SIGKILL; an exception of the block goes on."""
        self.stop()

    def __repr__(self):
        return f"<Rs4simProcess pid {self.pid} {self.status()} {self.address or ''}>".replace(
            " >", ">")
