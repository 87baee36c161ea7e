"""`cartan sweep`: each row equals the `cartan solve` run of its point, rows do not depend on
--jobs, failures are rows (exit 1) while bad input is exit 2 naming the grid index, CSV matches
JSON, and the progress report stays on stderr.

Run by ctest (the `cli` test) with CARTAN_BIN pointing at the built `cartan` executable."""
import csv
import io
import json
import os
import pty
import subprocess

import pytest

CARTAN = os.environ.get("CARTAN_BIN", "build/cartan")

# Short cases (T <= 3, N <= 300) that converge directly from the geodesic guess.
SO3_BASE = ["--model", "oscillator", "--T", "3", "--N", "300", "--a0=-1,-1,-1", "--tol", "1e-10"]
H3_BASE = ["--group", "heisenberg", "--model", "oscillator", "--T", "1", "--N", "200"]
GRID = ["--lambdas", "0,0.5", "--lambda-range", "0.75:1:2", "--aT-list", "1,0.2,0.1;0,1,0"]  # 4 x 2 points
# Keys that must agree bit for bit with `cartan solve` (the computation is deterministic).
SAME_AS_SOLVE = ["status", "message", "method", "branch", "terminal_error", "iterations"]


def run(*args, timeout=300):
    return subprocess.run([CARTAN, *args], capture_output=True, text=True, timeout=timeout)


def sweep(*args, expect=0):
    result = run("sweep", *args)
    assert result.returncode == expect, result.stderr + result.stdout[:500]
    return json.loads(result.stdout)


def solve(*args):
    result = run("solve", *args)
    assert result.returncode in (0, 1), result.stderr
    return json.loads(result.stdout)


def numbers(values):
    return ",".join(repr(float(x)) for x in values)  # repr round-trips a double exactly


def without_timing(row):
    return {k: v for k, v in row.items() if k != "solve_time_s"}


def assert_row_is_solve(row, solved):
    for key in SAME_AS_SOLVE:
        assert row[key] == solved[key], key
    assert row["v0"] == solved["v"][0]  # exact: same inputs, same arithmetic


def test_rows_equal_cartan_solve_so3_grid():
    table = sweep(*SO3_BASE, *GRID, "--quiet")
    assert table["points"] == 8 and table["converged"] == 8 and table["failed"] == []
    lambdas = [0, 0.5, 0.75, 1]
    endpoints = [[1, 0.2, 0.1], [0, 1, 0]]
    for row in table["rows"]:
        i = row["index"]
        assert row["lambda"] == lambdas[i // 2] and row["aT"] == endpoints[i % 2]  # lambda-major order
        solved = solve(*SO3_BASE, "--lambda", repr(row["lambda"]), "--aT", numbers(row["aT"]))
        assert_row_is_solve(row, solved)
        assert "t" not in row and "g" not in row  # trajectories are opt-in


def test_rows_equal_cartan_solve_heisenberg_gT_list_with_trajectories():
    table = sweep(*H3_BASE, "--gT-list", "1,0.5,0.8;0,1,0", "--lambdas", "0,1", "--trajectories", "--quiet")
    assert [row["gT"] for row in table["rows"]] == [[1, 0.5, 0.8], [0, 1, 0]] * 2
    for row in table["rows"]:
        solved = solve(*H3_BASE, "--lambda", repr(row["lambda"]), "--gT", numbers(row["gT"]))
        assert_row_is_solve(row, solved)
        for key in ["t", "g", "v"]:
            assert row[key] == solved[key], key
        assert len(row["t"]) == 201


@pytest.mark.parametrize("problem", [
    [*SO3_BASE, *GRID],
    [*SO3_BASE, "--method", "two-level", "--lambdas", "0,0.5,1", "--aT", "1,0.2,0.1"],
    ["--group", "heisenberg", "--model", "oscillator", "--method", "collocation", "--T", "1", "--N", "10",
     "--lambdas", "0,0.5,1", "--gT-list", "1,0.5,0.8;0,1,0"],
])
def test_jobs_do_not_change_the_rows(problem):
    one = sweep(*problem, "--jobs", "1", "--quiet")
    two = sweep(*problem, "--jobs", "2", "--quiet")
    many = sweep(*problem, "--jobs", "16", "--quiet")  # more threads than points and cores
    assert [without_timing(r) for r in one["rows"]] == [without_timing(r) for r in two["rows"]]
    assert [without_timing(r) for r in one["rows"]] == [without_timing(r) for r in many["rows"]]


def test_failed_points_are_rows_and_exit_1(tmp_path):
    # Point 1 stops after one iteration (a solver failure), point 2's gT is not a rotation (solve()
    # throws); the others are fine and must equal their own solve runs.
    grid = tmp_path / "grid.json"
    grid.write_text(json.dumps([
        {"lambda": 0, "aT": [1, 0.2, 0.1]},
        {"lambda": 0.5, "aT": [1, 0.2, 0.1], "max_iterations": 1, "method": "shooting"},
        {"lambda": 0.5, "a0": [], "gT": [1, 0, 0, 0, 2, 0, 0, 0, 1]},
        {"lambda": 1, "aT": [0, 1, 0], "T": 2},
    ]))
    table = sweep(*SO3_BASE, "--grid", str(grid), "--jobs", "2", "--quiet", expect=1)
    assert table["points"] == 4 and table["converged"] == 2 and table["failed"] == [1, 2]
    rows = table["rows"]
    assert rows[1]["status"] == "max-iterations" and rows[1]["terminal_error"] > 1e-3
    assert rows[2]["status"] == "error" and rows[2]["v0"] is None
    assert rows[2]["message"].startswith("cartan sweep: grid point 2: gT = ") and "not orthogonal" in rows[2]["message"]
    assert rows[3]["overrides"] == {"lambda": 1, "aT": [0, 1, 0], "T": 2}
    assert_row_is_solve(rows[0], solve(*SO3_BASE, "--lambda", "0", "--aT", "1,0.2,0.1"))
    base_at_T2 = [("2" if SO3_BASE[k - 1] == "--T" else arg) for k, arg in enumerate(SO3_BASE)]
    assert_row_is_solve(rows[3], solve(*base_at_T2, "--lambda", "1", "--aT", "0,1,0"))


def test_csv_matches_json():
    table = sweep(*SO3_BASE, *GRID, "--quiet")
    result = run("sweep", *SO3_BASE, *GRID, "--quiet", "--format", "csv")
    assert result.returncode == 0, result.stderr
    lines = list(csv.DictReader(io.StringIO(result.stdout)))
    assert len(lines) == len(table["rows"])
    for line, row in zip(lines, table["rows"]):
        assert int(line["index"]) == row["index"]
        assert float(line["lambda"]) == row["lambda"]  # 17 significant digits round-trip exactly
        assert line["endpoint_key"] == "aT" and [float(x) for x in line["endpoint"].split()] == row["aT"]
        for key in ["status", "message", "method", "branch"]:
            assert line[key] == row[key], key
        assert float(line["terminal_error"]) == row["terminal_error"]
        for key in ["outer", "inner", "sweeps"]:
            assert int(line["iterations_" + key]) == row["iterations"][key]
        assert [float(line[f"v0_{k}"]) for k in (1, 2, 3)] == row["v0"]


def test_csv_error_row_has_empty_diagnostics():
    result = run("sweep", "--model", "oscillator", "--gT-list", "1,0,0,0,1,0,0,0,1;1,0,0,0,2,0,0,0,1",
                 "--lambdas", "0.5", "--quiet", "--format", "csv")
    assert result.returncode == 1, result.stderr
    lines = list(csv.DictReader(io.StringIO(result.stdout)))
    assert [line["status"] for line in lines] == ["converged", "error"]
    assert lines[1]["v0_1"] == "" and lines[1]["terminal_error"] == "" and "not orthogonal" in lines[1]["message"]


def test_progress_goes_to_stderr_only(tmp_path):
    result = run("sweep", *SO3_BASE, *GRID, "--jobs", "2")
    assert result.returncode == 0, result.stderr
    json.loads(result.stdout)  # stdout is one JSON document and nothing else
    lines = result.stderr.splitlines()  # not a terminal: one line per tenth done, the last one complete
    assert lines and lines[-1].startswith("[##########] 8/8 done, 0 failed, ")
    quiet = run("sweep", *SO3_BASE, *GRID, "--quiet")
    assert quiet.stderr == ""
    out = tmp_path / "table.csv"
    to_file = run("sweep", *SO3_BASE, *GRID, "--quiet", "--format", "csv", "--output", str(out))
    assert to_file.returncode == 0 and to_file.stdout == ""
    assert out.read_text().startswith("index,lambda,")


def test_progress_on_a_terminal_is_redrawn_in_place():
    controller, terminal = pty.openpty()
    try:
        result = subprocess.run([CARTAN, "sweep", *SO3_BASE, *GRID], stdout=subprocess.PIPE, stderr=terminal,
                                timeout=300)
    finally:
        os.close(terminal)
    shown = b""
    while True:
        try:
            chunk = os.read(controller, 4096)
        except OSError:  # EIO once the terminal side is closed and drained
            break
        if not chunk:
            break
        shown += chunk
    os.close(controller)
    assert result.returncode == 0
    json.loads(result.stdout)
    text = shown.decode()
    assert text.startswith("\r[") and text.count("\n") == 1  # redrawn with \r, one newline at the end
    assert text.rstrip().split("\r")[-1].startswith("[##########] 8/8 done, 0 failed, ")


@pytest.mark.parametrize("args, message", [
    (["--grid", "GRID:[{\"lambda\": 0}, {\"lambda\": \"x\"}]"], "--grid entry 1: lambda = \"x\""),
    (["--grid", "GRID:[{\"lambda\": 0}, {\"bogus\": 1}]"], "--grid entry 1: key \"bogus\""),
    (["--grid", "GRID:[{\"lambda\": 0}, {\"T\": 0.5}, {\"T\": -1}]"], "grid point 2: T = -1"),
    (["--grid", "GRID:[{\"output\": \"x.json\"}]"], "--grid entry 0: key \"output\""),
    (["--grid", "GRID:{\"lambda\": 0}"], "must hold a non-empty JSON array"),
    (["--grid", "GRID:[]"], "must hold a non-empty JSON array"),
    (["--grid", "GRID:[{\"lambda\": 0}", ], "is not valid JSON"),
    (["--aT-list", "0,1,0;1,1,1"], "grid point 1: a0/aT = -1,-1,-1 / 1,1,1 are antiparallel"),
    (["--aT-list", "0,1,0;1,1"], "grid point 1: aT = 1,1 must have 3 numbers"),
    (["--lambdas", "0,nan"], "grid point 1: lambda = nan is not finite"),
    (["--lambdas", "0,x"], "lambdas = \"0,x\""),
    (["--lambda-range", "0:1"], "lambda-range = \"0:1\" must be START:STOP:COUNT"),
    (["--lambda-range", "0:1:2.5"], "has COUNT not an integer"),
    (["--lambdas", "0", "--grid", "GRID:[{}]"], "conflicts with --lambdas"),
    (["--aT-list", "1,0,0", "--gT-list", "1,0,0"], "conflict"),
    ([], "no grid"),
    (["--lambdas", "0", "--jobs", "0"], "--jobs"),
    (["--lambdas", "0", "--format", "xml"], "--format"),
])
def test_bad_input_exit_2_naming_the_point(tmp_path, args, message):
    args = list(args)
    for k, arg in enumerate(args):
        if arg.startswith("GRID:"):
            path = tmp_path / "grid.json"
            path.write_text(arg[len("GRID:"):])
            args[k] = str(path)
    endpoint = [] if "--aT-list" in args or "--gT-list" in args else ["--aT", "1,0.2,0.1"]
    result = run("sweep", *SO3_BASE, *endpoint, *args)
    assert result.returncode == 2, result.stderr + result.stdout[:300]
    assert result.stdout == ""  # nothing solved, nothing written
    assert len(result.stderr.strip().splitlines()) == 1 and message in result.stderr, result.stderr
