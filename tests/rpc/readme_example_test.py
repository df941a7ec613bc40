"""Runs the Python example of the README ("The harness API") as written, with the built
rs4sim as $RS4SIM (Rs4simProcess's executable), from the repository's root, so the README's
example cannot rot. Usage: readme_example_test.py RS4SIM REPO (exit 77: no python3-grpcio)"""
import os
import re
import subprocess
import sys

from script_support import require_grpc

require_grpc()

rs4sim, repo = sys.argv[1], sys.argv[2]
readme = open(os.path.join(repo, "README.md"), encoding="utf-8").read()
blocks = re.findall(r"```python\n(.*?)```", readme, flags=re.S)
assert len(blocks) == 1, f"{len(blocks)} python blocks in README.md"
code = blocks[0]
assert 'with Rs4simProcess(["run"' in code, "the example no longer starts `rs4sim run` in a with"
env = dict(os.environ, RS4SIM=rs4sim)
result = subprocess.run([sys.executable, "-c", code], cwd=repo, capture_output=True, text=True,
                        timeout=100, env=env)
if result.returncode != 0:
    print(result.stdout, result.stderr)
    sys.exit(1)
print("ok: the README's harness example ran as written")
