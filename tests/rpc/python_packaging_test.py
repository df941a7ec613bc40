"""The Python package's install routes (README "The Python package", docs/rpc.md), run by
Debian's /usr/bin/python3: the wheel python/build_wheel.py makes from the staged package holds
the package and its generated stubs and nothing else; `pip wheel python/` (the source folder,
what a user tries first) stops at once and names the wheel to install; a Python without the
wheel module (not Debian's: pyenv, a bare venv) gets a sentence naming /usr/bin/python3
instead of setuptools' "invalid command 'bdist_wheel'".
Usage: python_packaging_test.py STAGED_PACKAGE_DIR REPO"""
import os
import subprocess
import sys
import tempfile
import venv
import zipfile

staged, repo = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
source = os.path.join(repo, "python")
env = dict(os.environ, PYTHONDONTWRITEBYTECODE="1", PIP_DISABLE_PIP_VERSION_CHECK="1")


def check(condition, what):
    if not condition:
        print("FAIL:", what)
        sys.exit(1)


with tempfile.TemporaryDirectory() as tmp:
    # 1. The wheel: the package, its stubs and version, no build backend or test.
    built = subprocess.run([sys.executable, os.path.join(source, "build_wheel.py"), staged,
                            os.path.join(tmp, "dist")], capture_output=True, text=True, env=env)
    check(built.returncode == 0, f"build_wheel.py: {built.stdout}{built.stderr}")
    wheel = built.stdout.strip().splitlines()[-1]
    check(os.path.basename(wheel).startswith("rs4sim-") and wheel.endswith("-py3-none-any.whl"),
          wheel)
    names = zipfile.ZipFile(wheel).namelist()
    for member in ("rs4sim/__init__.py", "rs4sim/_version.py", "rs4sim/v1/rs4_pb2.py",
                   "rs4sim/v1/rs4_pb2_grpc.py", "rs4sim/_googleapis/google/rpc/status_pb2.py",
                   "rs4sim/pytest_plugin.py"):
        check(member in names, f"{member} not in {wheel}: {names}")
    check(not any(n.startswith(("rs4sim_build_backend", "build_wheel")) for n in names), names)

    # 2. The source folder: refused before any build, with where to go (and nothing written
    # into it: no bytecode of the backend).
    bytecode = os.path.join(source, "__pycache__")
    had_bytecode = os.path.exists(bytecode)
    src = subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-index",
                          "--no-cache-dir", "--wheel-dir", os.path.join(tmp, "src"), source],
                         capture_output=True, text=True, env=env)
    out = src.stdout + src.stderr
    check(src.returncode != 0, f"pip built the source folder: {out}")
    check("is the rs4sim package's source folder" in out, out)
    check("cmake --build build --target rs4sim_python_wheel" in out, out)
    check("build/python/dist/rs4sim-*.whl" in out, out)
    check(had_bytecode or not os.path.exists(bytecode), "bytecode left in python/")

    # 3. A Python with neither setuptools nor wheel: the backend names Debian's python.
    bare = os.path.join(tmp, "bare")
    venv.EnvBuilder(system_site_packages=False, with_pip=False, symlinks=True).create(bare)
    probe = subprocess.run(
        [os.path.join(bare, "bin", "python"), "-c",
         "import sys; sys.path.insert(0, '.'); import rs4sim_build_backend as b\n"
         "try:\n    b.build_wheel(sys.argv[1])\nexcept b.PackagingError as e:\n    print(e)\n"
         "else:\n    print('built')", os.path.join(tmp, "w")],
        capture_output=True, text=True, cwd=staged, env=env)
    said = probe.stdout + probe.stderr
    check("has no setuptools and no wheel module" in said, said)
    check("invalid command 'bdist_wheel'" in said and "/usr/bin/python3" in said, said)
print("OK")
