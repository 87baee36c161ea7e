"""Ctrl-C at any moment: `cartan solve`, `sweep` and `merge` leave their output whole or absent.
An interrupted command exits 130 with "<command>: interrupted (no output written)" and leaves no
file at --output (nor a .partial beside it); one that finished before the signal exits as usual
with its whole output. Each command is signalled at several moments and the outcome is checked
either way, so that no assertion depends on how fast the machine is; the solves are signalled once
their own progress report shows them solving, not after a sleep.

Run by ctest (the `cli` test) with CARTAN_BIN pointing at the built `cartan` executable."""
import csv
import io
import json
import os
import signal
import subprocess
import time

import pytest

from cli_support import CARTAN, run
OSCILLATOR_ENDS = ["--a0", "-0.7,-1,-0.7", "--aT", "0.8,0.8,1"]
# The paper's two-level scheme on the oscillator with 2e6 steps: many seconds of solving.
LONG_SOLVE = ["--model", "oscillator", "--lambda", "0.5", "--T", "12", "--N", "2000000", "--method", "two-level",
              *OSCILLATOR_ENDS]
# Collocation at tol 1e-12 from the geodesic guess refines for seconds before it fails (max_nodes).
LONG_COLLOCATION = ["--model", "oscillator", "--lambda", "0.5", "--T", "12", "--N", "800", "--method", "collocation",
                    "--tol", "1e-12", *OSCILLATOR_ENDS]

# The variational method at N = 2000: its first iteration (a difference Hessian of 5997 columns and
# its dense LU) takes about 17 s; issue 44 measured a sweep of it still running 15 s after SIGINT.
LONG_VARIATIONAL = ["--model", "oscillator", "--T", "12", "--N", "2000", "--method", "variational", "--tol", "1e-13",
                    *OSCILLATOR_ENDS]


def start(args):
    return subprocess.Popen([CARTAN, *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def wait_for_line(process, words):
    """Reads stderr until a line holding `words` (the solve's progress); returns the lines read."""
    lines = []
    for line in process.stderr:
        lines.append(line)
        if words in line:
            return lines
    return lines


def check_outcome(process, out, command, lines=()):
    """The process's end is one of the two honest ones; returns whether it was interrupted. A signal
    that comes before main() has installed its handler (while the program loads) ends the process
    by the signal, before it did anything: the shell's exit status 130 too, and nothing written."""
    stdout, stderr = process.communicate(timeout=120)
    stderr = "".join(lines) + stderr
    assert not os.path.exists(str(out) + ".partial"), stderr
    if process.returncode == -signal.SIGINT:
        assert not out.exists() and stdout == ""
        return True
    if process.returncode == 130:
        assert f"{command}: interrupted (no output written)" in stderr
        assert not out.exists() and stdout == ""
        return True
    assert process.returncode in (0, 1), stderr
    text = out.read_text()
    assert text.endswith("\n")
    if out.suffix == ".json":
        json.loads(text)  # whole
    return False


@pytest.mark.parametrize("args", [LONG_SOLVE, LONG_COLLOCATION], ids=["two-level", "collocation"])
def test_solve_interrupted_while_solving_writes_nothing(tmp_path, args):
    out = tmp_path / "r.json"
    process = start(["solve", *args, "--progress", "--output", str(out)])
    lines = wait_for_line(process, "iteration 1,")  # solving, past its first iteration
    started = time.monotonic()
    process.send_signal(signal.SIGINT)
    assert check_outcome(process, out, "cartan solve", lines)
    assert time.monotonic() - started < 30  # stopped at its next iteration, not at the end of the solve


def test_variational_solve_interrupted_inside_an_iteration_ends_within_2_s(tmp_path):
    # One second in, the solve is inside its first iteration (no progress line before it ends).
    out = tmp_path / "r.json"
    process = start(["solve", *LONG_VARIATIONAL[:2], "--lambda", "0.5", *LONG_VARIATIONAL[2:], "--output", str(out)])
    time.sleep(1.0)
    started = time.monotonic()
    process.send_signal(signal.SIGINT)
    assert check_outcome(process, out, "cartan solve")
    assert time.monotonic() - started < 2


@pytest.mark.parametrize("delay", [0.0, 0.02, 0.1, 0.3])
def test_solve_interrupted_at_any_moment_leaves_whole_output_or_none(tmp_path, delay):
    out = tmp_path / "r.json"
    process = start(["solve", "--model", "oscillator", "--lambda", "0.5", "--T", "3", "--N", "300", *OSCILLATOR_ENDS,
                     "--output", str(out)])
    time.sleep(delay)
    process.send_signal(signal.SIGINT)
    check_outcome(process, out, "cartan solve")


@pytest.mark.parametrize("args, bound", [([*LONG_SOLVE[:2], *LONG_SOLVE[4:]], 30), (LONG_VARIATIONAL, 2)],
                         ids=["two-level", "variational"])
def test_sweep_interrupted_stops_its_running_solves_and_writes_nothing(tmp_path, args, bound):
    # Two long solves at once: the signal stops both at their next iteration (the variational
    # method inside its first); the sweep then writes no table (it would be a table of interrupted
    # rows) and leaves no empty file.
    out = tmp_path / "table.json"
    process = start(["sweep", *args, "--lambdas", "0.25,0.5", "--jobs", "2", "--output", str(out)])
    time.sleep(1.0)  # the sweep takes many seconds; the outcome is checked whatever the moment
    started = time.monotonic()
    process.send_signal(signal.SIGINT)
    assert check_outcome(process, out, "cartan sweep")
    assert time.monotonic() - started < bound


@pytest.mark.parametrize("delay", [0.0, 0.05, 0.3])
def test_sweep_interrupted_at_any_moment_leaves_whole_output_or_none(tmp_path, delay):
    out = tmp_path / "table.csv"
    process = start(["sweep", "--model", "oscillator", "--T", "3", "--N", "300", "--a0=-1,-1,-1", "--aT", "1,0.2,0.1",
                     "--lambda-range", "0:1:6", "--format", "csv", "--quiet", "--output", str(out)])
    time.sleep(delay)
    process.send_signal(signal.SIGINT)
    check_outcome(process, out, "cartan sweep")


def test_sweep_output_is_checked_without_creating_it(tmp_path):
    out = tmp_path / "missing-directory" / "table.json"
    result = run("sweep", "--model", "oscillator", "--T", "3", "--N", "300", "--a0=-1,-1,-1", "--aT", "1,0.2,0.1",
                 "--lambdas", "0", "--output", str(out), timeout=60)
    assert result.returncode == 2 and "--output" in result.stderr and "cannot be written" in result.stderr
    assert not out.parent.exists()


def big_shards(tmp_path, rows_per_shard=60000):
    """Two CSV shards of a sweep of 2 rows_per_shard points (one real row, copied under new indices)."""
    result = run("sweep", "--model", "oscillator", "--T", "3", "--N", "300", "--a0=-1,-1,-1", "--aT", "1,0.2,0.1",
                 "--lambdas", "0.5", "--format", "csv", "--quiet")
    header, row = list(csv.reader(io.StringIO(result.stdout)))
    index = header.index("index")
    paths = []
    for shard in range(2):
        path = tmp_path / f"part{shard}.csv"
        text = io.StringIO()
        writer = csv.writer(text, lineterminator="\n")
        writer.writerow(header)
        for i in range(shard, 2 * rows_per_shard, 2):
            row[index] = str(i)
            writer.writerow(row)
        path.write_text(text.getvalue())
        paths.append(str(path))
    return paths


def test_merge_interrupted_at_any_moment_leaves_whole_output_or_none(tmp_path):
    paths = big_shards(tmp_path)
    for delay in [0.0, 0.05, 0.2, 0.5]:
        out = tmp_path / "all.csv"
        if out.exists():
            out.unlink()
        process = start(["merge", *paths, "--output", str(out)])
        time.sleep(delay)
        process.send_signal(signal.SIGINT)
        check_outcome(process, out, "cartan merge")


def test_time_limit_stops_the_solve_with_its_status(tmp_path):
    # N = 4e5: about 11 s of solving, and a written iterate of 0.14 GB (LONG_SOLVE's 2e6 steps
    # wrote 0.68 GB, 5 s of CPU spent on the file alone).
    out = tmp_path / "r.json"
    started = time.monotonic()
    timed = [*LONG_SOLVE[:LONG_SOLVE.index("--N") + 1], "400000", *LONG_SOLVE[LONG_SOLVE.index("--N") + 2:]]
    result = run("solve", *timed, "--time-limit", "0.5", "--output", str(out))
    assert result.returncode == 1, result.stderr  # a failure, whose result is written
    d = json.loads(out.read_text())
    assert d["status"] == "time-limit" and "time limit of 0.5 s reached" in d["message"]
    assert 0.25 <= d["solve_time_s"] < time.monotonic() - started  # about the limit (bench/README.md)
    assert d["action"] is None  # a stopped result's action is not computed (NaN, written as null)


@pytest.mark.parametrize("args", [[*LONG_VARIATIONAL[:2], "--lambda", "0.5", *LONG_VARIATIONAL[2:]],
                                  [*LONG_COLLOCATION[:7], "2000", *LONG_COLLOCATION[8:]]],
                         ids=["variational", "collocation"])
def test_time_limit_ends_the_dense_methods_within_ten_percent_at_N_2000(tmp_path, args):
    """Issue 44: --time-limit 1 ended the variational method at N = 2000 after 16.5 s (its first
    iteration polled nothing). The solve now ends within 10 % of the limit; the command within
    0.3 s more (loading the program, writing the file: about 0.05 s on an idle machine)."""
    out = tmp_path / "r.json"
    started = time.monotonic()
    result = run("solve", *args, "--time-limit", "1", "--output", str(out))
    spent = time.monotonic() - started
    assert result.returncode == 1, result.stderr
    d = json.loads(out.read_text())
    assert d["status"] == "time-limit", d["message"]
    assert d["solve_time_s"] <= 1.1 and spent <= 1.1 + 0.3, (d["solve_time_s"], spent)
