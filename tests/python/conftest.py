"""Shared set-up of the Python tests (run by ctest's python_tests with PYTHONPATH=build/python).

HLENS_CLI, HLENS_SOURCE_DIR and HLENS_SHARED_MESHES come from CMake; the CLI is the oracle the
module's results are compared with.
"""
import json
import os
import subprocess
from pathlib import Path

import pytest

SOURCE_DIR = Path(os.environ.get("HLENS_SOURCE_DIR", Path(__file__).resolve().parents[2]))
CLI = os.environ.get("HLENS_CLI", str(SOURCE_DIR / "build" / "bin" / "hlens-cli"))
SHARED = Path(os.environ.get("HLENS_SHARED_MESHES", SOURCE_DIR.parent / "shared" / "meshes"))
DEMO_A = str(SOURCE_DIR / "assets" / "demo_a.obj")
DEMO_B = str(SOURCE_DIR / "assets" / "demo_b.obj")


def run_cli(*args):
    """(exit code, stdout lines, stderr) of hlens-cli."""
    p = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=600)
    return p.returncode, p.stdout.splitlines(), p.stderr


def cli_json(*args):
    code, out, err = run_cli(*args)
    assert code == 0, err
    return [json.loads(line) for line in out]


def write_obj(path, V, F):
    """17 significant digits: the file reads back to the same doubles."""
    with open(path, "w") as f:
        for p in V:
            f.write("v %.17g %.17g %.17g\n" % tuple(p))
        for t in F:
            f.write("f %d %d %d\n" % tuple(int(i) + 1 for i in t))
    return str(path)


# The fast mode's work counters depend on the threads' schedule: a thread that raises the shared lower
# bound first lets the others skip more targets. Runs on several threads agree on every other number.
SCHEDULED = ("exact_targets", "exact_solves")


def without(d, *keys):
    """A copy of a report without fields that legitimately differ between runs (times, paths)."""
    if isinstance(d, dict):
        return {k: without(v, *keys) for k, v in d.items() if k not in keys}
    if isinstance(d, list):
        return [without(v, *keys) for v in d]
    return d


@pytest.fixture(scope="session")
def demo():
    import hlens
    return hlens.load(DEMO_A) + hlens.load(DEMO_B)
