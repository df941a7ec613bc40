"""Runs the Python examples of the README ("The harness API" first, then the GSD F-devices') as
written, with the built rs4sim as $RS4SIM (Rs4simProcess's executable), from the repository's
root, so the README's examples cannot rot. Usage: readme_example_test.py RS4SIM REPO (exit 77:
no python3-grpcio)"""
import os
import re
import subprocess
import sys

from script_support import require_grpc

require_grpc()

rs4sim, repo = sys.argv[1], sys.argv[2]
readme = open(os.path.join(repo, "README.md"), encoding="utf-8").read()
blocks = re.findall(r"```python\n(.*?)```", readme, flags=re.S)
assert len(blocks) == 2, f"{len(blocks)} python blocks in README.md, expected 2"
assert 'with Rs4simProcess(["run"' in blocks[0], "the example no longer starts `rs4sim run` in a with"
assert "GsdStations(run.address)" in blocks[1], "the F-device example no longer uses GsdStations"
env = dict(os.environ, RS4SIM=rs4sim)
for n, code in enumerate(blocks, 1):
    result = subprocess.run([sys.executable, "-c", code], cwd=repo, capture_output=True,
                            text=True, timeout=100, env=env)
    if result.returncode != 0:
        print(f"README python block {n}:", result.stdout, result.stderr)
        sys.exit(1)
print(f"ok: the README's {len(blocks)} Python examples ran as written")
