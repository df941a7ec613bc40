"""ctest fixture `rs4sim_python_venv`: a virtual environment in the build directory that sees
Debian's packages (python3-grpcio, python3-protobuf, python3-pytest), with the rs4sim wheel
installed by pip offline, as the README and docs/rpc.md tell a user to: the wheel built from
the package CMake staged (<build>/python) by python/build_wheel.py, the script of the target
rs4sim_python_wheel, into <build>/python/dist; the project's Python tests run with its python. The venv is made without a pip of its own
(ensurepip would copy one into it, most of the setup's time): its python runs Debian's
python3-pip, the same pip that `V/bin/pip` would be.
Usage: python_venv_setup.py PACKAGE_DIR VENV_DIR"""
import os
import subprocess
import sys
import time
import venv

package, target = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
start = time.monotonic()


def fail(message):
    print(f"FAIL: {message}")
    sys.exit(1)


if not os.path.isfile(os.path.join(package, "rs4sim", "v1", "rs4_pb2.py")):
    fail(f"{package} has no generated stubs: build the target rs4sim_python first")
probe = subprocess.run([sys.executable, "-c", "import importlib.util as u; print(*(m for m in "
                        "('pip', 'setuptools', 'wheel') if u.find_spec(m) is None))"],
                       capture_output=True, text=True)
if probe.returncode != 0 or probe.stdout.split():
    fail("the offline install needs Debian's python3-pip, python3-setuptools and python3-wheel; "
         f"missing: {probe.stdout.strip() or probe.stderr.strip()}")
builder = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python",
                       "build_wheel.py")
built = subprocess.run([sys.executable, builder, package, os.path.join(package, "dist")],
                       capture_output=True, text=True)
if built.returncode != 0:
    fail(f"build_wheel.py {package}:\n{built.stdout}{built.stderr}")
wheel = built.stdout.strip().splitlines()[-1]
venv.EnvBuilder(system_site_packages=True, clear=True, with_pip=False, symlinks=True).create(target)
python = os.path.join(target, "bin", "python")
install = subprocess.run([python, "-m", "pip", "install", "--no-deps", "--no-index",
                          "--no-cache-dir", "--disable-pip-version-check", "--quiet", wheel],
                         capture_output=True, text=True)
if install.returncode != 0:
    fail(f"pip install {wheel}:\n{install.stdout}{install.stderr}")

check = subprocess.run([python, "-c", "import rs4sim, rs4sim.harness, rs4sim.pytest_plugin; "
                        "print(rs4sim.__file__, rs4sim.__version__)"],
                       capture_output=True, text=True, cwd=target)
if check.returncode != 0:
    fail(f"the installed package does not import:\n{check.stderr}")
where, version = check.stdout.split()
if not os.path.realpath(where).startswith(os.path.realpath(target)):
    fail(f"rs4sim imported from {where}, not from the venv {target}")
print(f"ok: rs4sim {version} from {os.path.basename(wheel)} installed into {target} in "
      f"{time.monotonic() - start:.1f} s")
