"""Builds the rs4sim wheel from the folder CMake staged, offline: the target
rs4sim_python_wheel (python/package.cmake) and the tests' venv fixture run it, so both make the
same file the README installs. Run by Debian's /usr/bin/python3, which has pip, setuptools and
wheel from python3-pip, python3-setuptools and python3-wheel.
Usage: build_wheel.py PACKAGE_DIR DIST_DIR   (prints the wheel's path)"""
import glob
import importlib.util
import os
import shutil
import subprocess
import sys

package, dist = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
missing = [m for m in ("pip", "setuptools", "wheel") if importlib.util.find_spec(m) is None]
if missing:
    sys.exit(f"build_wheel.py: {sys.executable} has no {', '.join(missing)}: the wheel is built "
             "by Debian's /usr/bin/python3 with python3-pip, python3-setuptools and "
             "python3-wheel (apt install python3-pip python3-setuptools python3-wheel)")
# setuptools builds in the tree: nothing an earlier build left there may slip into the wheel.
for leftover in ("build", "rs4sim.egg-info"):
    shutil.rmtree(os.path.join(package, leftover), ignore_errors=True)
for old in glob.glob(os.path.join(dist, "rs4sim-*.whl")):
    os.remove(old)
build = subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation",
                        "--no-index", "--no-cache-dir", "--disable-pip-version-check", "--quiet",
                        "--wheel-dir", dist, package], capture_output=True, text=True)
if build.returncode != 0:
    sys.exit(f"build_wheel.py: pip wheel {package} failed:\n{build.stdout}{build.stderr}")
wheels = glob.glob(os.path.join(dist, "rs4sim-*.whl"))
if len(wheels) != 1:
    sys.exit(f"build_wheel.py: expected one rs4sim wheel in {dist}, found {wheels}")
print(wheels[0])
