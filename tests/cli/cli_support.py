"""What the tests of the `cartan` command line share: the executable, how it is run, and the
bad-input contract. conftest.py puts this directory on sys.path, so test files import it by name.

ctest's `cli` test sets CARTAN_BIN to the built executable; by hand, run from the source tree
(build/cartan) or set it."""
import json
import os
import subprocess
from pathlib import Path

CARTAN = os.environ.get("CARTAN_BIN", "build/cartan")
ROOT = Path(__file__).resolve().parents[2]  # the source tree


def run(*args, timeout=120):
    """`cartan ARGS` with its output captured. The timeout only stops a hung command; files whose
    commands take longer pass a larger one."""
    return subprocess.run([CARTAN, *args], capture_output=True, text=True, timeout=timeout)


def solve_json(*args, timeout=120):
    """`cartan solve ARGS`, which must succeed (exit 0): its JSON result from stdout."""
    result = run("solve", *args, timeout=timeout)
    assert result.returncode == 0, result.stderr + result.stdout[:500]
    return json.loads(result.stdout)


def solve_to(path, *args, timeout=120):
    """`cartan solve ARGS --output PATH`, which must succeed (exit 0): the JSON result read back."""
    result = run("solve", *args, "--output", str(path), timeout=timeout)
    assert result.returncode == 0, result.stderr
    return json.loads(Path(path).read_text())


def assert_rejected(result, needle, max_length=None):
    """Bad input's contract (issue 5): exit 2 (not 1, not a signal), nothing on stdout and one
    line on stderr naming the problem (`needle`), of fewer than `max_length` characters if given."""
    assert result.returncode == 2, (result.returncode, result.stderr)  # < 0 would be a signal
    assert needle in result.stderr, result.stderr
    assert result.stdout == ""
    assert result.stderr.count("\n") == 1, result.stderr  # one clear line
    if max_length is not None:
        assert len(result.stderr) < max_length, len(result.stderr)
