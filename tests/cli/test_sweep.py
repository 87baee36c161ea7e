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
from functools import partial

import pytest

import cli_support

# Short cases (T <= 3, N <= 300) that converge directly from the geodesic guess.
SO3_BASE = ["--model", "oscillator", "--T", "3", "--N", "300", "--a0=-1,-1,-1", "--tol", "1e-10"]
H3_BASE = ["--group", "heisenberg", "--model", "oscillator", "--T", "1", "--N", "200"]
GRID = ["--lambdas", "0,0.5", "--lambda-range", "0.75:1:2", "--aT-list", "1,0.2,0.1;0,1,0"]  # 4 x 2 points
# Keys that must agree bit for bit with `cartan solve` (the computation is deterministic).
SAME_AS_SOLVE = ["status", "message", "method", "branch", "terminal_error", "iterations"]


TIMEOUT = 300  # a hang guard; a sweep runs many solves, so more than cli_support.run's default
run = partial(cli_support.run, timeout=TIMEOUT)


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


# A manifold's problems sweep as a group model's do (the grid's endpoint is --qT): the spherical
# pendulum at two final points, and SO(3) as a manifold with Cartan-Schouten connections.
SPHERE_BASE = ["--manifold", "sphere", "--q0", "1,0,-0.3", "--gravity", "9.81", "--T", "1", "--N", "100"]
SO3_MANIFOLD_BASE = ["--manifold", "so3", "--qT", "0.36,-0.48,0.8,0.8,0.6,0,-0.48,0.64,0.6", "--mass", "2,3,4",
                     "--T", "1", "--N", "100"]


def test_rows_equal_cartan_solve_on_a_manifold_qT_list_with_trajectories():
    table = sweep(*SPHERE_BASE, "--qT-list", "0,1,-0.5;0,1,0.5", "--trajectories", "--jobs", "2", "--quiet")
    assert table["points"] == 2 and table["converged"] == 2
    for row, qT in zip(table["rows"], [[0, 1, -0.5], [0, 1, 0.5]]):
        assert row["manifold"] == "sphere" and row["lambda"] is None and row["connection"] == "levi-civita"
        unit = [x / sum(y * y for y in qT) ** 0.5 for x in qT]
        assert row["qT"] == pytest.approx(unit, abs=1e-15)  # the point as the solve took it: on the sphere
        solved = solve(*SPHERE_BASE, "--qT", numbers(qT))
        assert_row_is_solve(row, solved)
        for key in ["t", "q", "v"]:
            assert row[key] == solved[key], key
        assert "g" not in row and len(row["t"]) == 101


def test_lambdas_sweep_a_cartan_schouten_manifold_like_the_group_model():
    table = sweep(*SO3_MANIFOLD_BASE, "--connection", "cartan-schouten", "--lambdas", "0,0.5,1", "--quiet")
    assert [row["lambda"] for row in table["rows"]] == [0, 0.5, 1] and table["converged"] == 3
    for row in table["rows"]:
        assert row["manifold"] == "so3" and "connection" not in row
        assert_row_is_solve(row, solve(*SO3_MANIFOLD_BASE, "--connection", "cartan-schouten", "--lambda", repr(row["lambda"])))
    csv_text = run("sweep", *SO3_MANIFOLD_BASE, "--lambdas", "0,1", "--quiet", "--format", "csv").stdout
    lines = list(csv.DictReader(io.StringIO(csv_text)))
    assert [line["endpoint_key"] for line in lines] == ["qT", "qT"]
    assert [float(x) for x in lines[0]["endpoint"].split()] == pytest.approx([0.36, -0.48, 0.8, 0.8, 0.6, 0, -0.48, 0.64, 0.6], abs=1e-15)


@pytest.mark.parametrize("args, message", [
    ([*SPHERE_BASE, "--gT-list", "0,1,0"], "--gT-list = \"0,1,0\" is a group model's endpoint; a manifold's final point is --qT"),
    ([*SPHERE_BASE, "--aT-list", "0,1,0"], "--aT-list = \"0,1,0\" is a group model's endpoint"),
    ([*SO3_BASE, "--qT-list", "0,1,0"], "--qT-list = \"0,1,0\" is a manifold's final point (with --manifold)"),
    ([*SPHERE_BASE, "--qT-list", "0,1,0", "--gT-list", "0,1,0"], "conflict: give one"),
    ([*SPHERE_BASE, "--qT-list", "0,1,0;1,0,0,0"], "grid point 1: "),
    ([*SPHERE_BASE, "--qT-list", "0,1,0", "--lambdas", "0.5"], "grid point 0: "),  # lambda is Cartan-Schouten's
])
def test_bad_manifold_grids_exit_2_naming_the_value(args, message):
    result = run("sweep", *args)
    assert result.returncode == 2 and result.stdout == "", result.stderr
    assert len(result.stderr.strip().splitlines()) == 1 and message in result.stderr, result.stderr


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
        assert float(line["lambda"]) == row["lambda"]  # the shortest round-trip digits read back exactly
        assert line["endpoint_key"] == "aT" and [float(x) for x in line["endpoint"].split()] == row["aT"]
        for key in ["status", "message", "method", "branch"]:
            assert line[key] == row[key], key
        assert float(line["terminal_error"]) == row["terminal_error"]
        for key in ["outer", "inner", "sweeps"]:
            assert int(line["iterations_" + key]) == row["iterations"][key]
        assert [float(line[f"v0_{k}"]) for k in (1, 2, 3)] == row["v0"]


def test_csv_has_a_column_for_every_component_of_v0():
    # se3's algebra has dimension 6: the CSV carries all six components of v0, as the JSON does
    # (it once had three columns, whatever the group).
    base = ["--group", "se3", "--T", "1", "--N", "20"]
    grid = ["--gT-list", "1,0,0,0.5,0,1,0,0,0,0,1,0,0,0,0,1;1,0,0,0,0,1,0,0.3,0,0,1,0,0,0,0,1", "--lambdas", "0.5"]
    table = sweep(*base, *grid, "--quiet")
    result = run("sweep", *base, *grid, "--quiet", "--format", "csv")
    assert result.returncode == 0, result.stderr
    lines = list(csv.DictReader(io.StringIO(result.stdout)))
    assert [f"v0_{k}" for k in range(1, 7)] == list(lines[0])[-6:]
    for line, row in zip(lines, table["rows"]):
        assert len(row["v0"]) == 6
        assert [float(line[f"v0_{k}"]) for k in range(1, 7)] == row["v0"]


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
        result = subprocess.run([cli_support.CARTAN, "sweep", *SO3_BASE, *GRID], stdout=subprocess.PIPE,
                                stderr=terminal, timeout=TIMEOUT)
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


# --shard K/M and `cartan merge`: the shards' tables merged are the unsharded table, byte for byte
# but for the timings (the solve_time_s column, and wall_time_s of a JSON table).
SHARD_GRID = [*SO3_BASE, "--lambda-range", "0:1:4", "--aT-list", "1,0.2,0.1;0,1,0", "--quiet"]  # 8 points


def without_csv_timing(text):
    """The records without the solve_time_s column; the rest compared as text is byte for byte."""
    header, *records = list(csv.reader(io.StringIO(text)))
    column = header.index("solve_time_s")
    return [[f for k, f in enumerate(record) if k != column] for record in [header, *records]]


def with_timing_of(text, timed):
    """`text` (a CSV table) with the solve_time_s fields of `timed`, as bytes."""
    column = next(csv.reader(io.StringIO(text))).index("solve_time_s")
    rows, times = list(csv.reader(io.StringIO(text))), list(csv.reader(io.StringIO(timed)))
    for row, other in zip(rows, times):
        row[column] = other[column]
    out = io.StringIO()
    csv.writer(out, lineterminator="\n").writerows(rows)
    return out.getvalue()


def json_without_timing(text):
    table = json.loads(text)
    table.pop("wall_time_s")
    table["rows"] = [without_timing(row) for row in table["rows"]]
    return table


def shard_files(tmp_path, fmt, m=3):
    paths = []
    for k in range(1, m + 1):
        path = tmp_path / f"part{k}.{fmt}"
        result = run("sweep", *SHARD_GRID, "--format", fmt, "--shard", f"{k}/{m}", "--output", str(path))
        assert result.returncode == 0, result.stderr
        paths.append(str(path))
    return paths


def test_csv_shards_merged_are_the_unsharded_table(tmp_path):
    whole = run("sweep", *SHARD_GRID, "--format", "csv")
    assert whole.returncode == 0, whole.stderr
    paths = shard_files(tmp_path, "csv")
    part2 = list(csv.DictReader(open(paths[1])))
    assert [int(line["index"]) for line in part2] == [1, 4, 7]  # interleaved: index mod 3 = 2 - 1
    merged = run("merge", paths[2], paths[0], paths[1])  # any order of the files
    assert merged.returncode == 0 and merged.stderr == "", merged.stderr
    assert without_csv_timing(merged.stdout) == without_csv_timing(whole.stdout)
    assert with_timing_of(merged.stdout, whole.stdout) == with_timing_of(whole.stdout, whole.stdout)
    assert len(without_csv_timing(merged.stdout)) == 9
    out = tmp_path / "all.csv"
    to_file = run("merge", "--points", "8", *paths, "--output", str(out))
    assert to_file.returncode == 0 and to_file.stdout == "" and out.read_text() == merged.stdout


def test_json_shards_merged_are_the_unsharded_table(tmp_path):
    whole = run("sweep", *SHARD_GRID)
    assert whole.returncode == 0, whole.stderr
    paths = shard_files(tmp_path, "json")
    part3 = json.loads(open(paths[2]).read())
    assert part3["shard"] == {"k": 3, "m": 3, "grid_points": 8} and part3["points"] == 2
    assert [row["index"] for row in part3["rows"]] == [2, 5]
    merged = run("merge", *paths)
    assert merged.returncode == 0, merged.stderr
    assert json_without_timing(merged.stdout) == json_without_timing(whole.stdout)
    assert "shard" not in json.loads(merged.stdout)
    # Byte for byte once the timings are set equal: same keys, order and number formatting.
    timings = json.loads(whole.stdout)
    again = json.loads(merged.stdout)
    again["wall_time_s"] = timings["wall_time_s"]
    for row, timed in zip(again["rows"], timings["rows"]):
        row["solve_time_s"] = timed["solve_time_s"]
    assert json.dumps(again) == json.dumps(timings)


def test_more_shards_than_points(tmp_path):
    paths = []
    for k in (1, 2, 3):  # a grid of 2 points: shard 3/3 is empty
        path = tmp_path / f"p{k}.json"
        result = run("sweep", *SO3_BASE, "--aT", "1,0.2,0.1", "--lambdas", "0,1", "--quiet", "--shard", f"{k}/3",
                     "--output", str(path))
        assert result.returncode == 0, result.stderr
        paths.append(str(path))
    assert json.loads(open(paths[2]).read())["rows"] == []
    merged = run("merge", *paths)
    assert merged.returncode == 0, merged.stderr
    assert [row["index"] for row in json.loads(merged.stdout)["rows"]] == [0, 1]
    missing = run("merge", *paths[:2])  # the empty shard is still a shard of the grid
    assert missing.returncode == 2 and "cartan merge: shard = 3/3 is missing" in missing.stderr


@pytest.mark.parametrize("spec", ["0/3", "4/3", "1/0", "3", "1/3/3", "a/3", "-1/3", "1/2000000", " 1/3", "1.0/3", ""])
def test_bad_shard_exits_2_naming_it(spec):
    result = run("sweep", *SO3_BASE, "--aT", "1,0.2,0.1", "--lambdas", "0,1", "--shard", spec)
    assert result.returncode == 2 and result.stdout == ""
    assert result.stderr == f'cartan sweep: --shard = "{spec}" must be K/M, two integers with 1 <= K <= M <= 1000000 (the K-th of M shards)\n'


def test_merge_rejects_tables_that_are_not_one_grid(tmp_path):
    csvs = shard_files(tmp_path, "csv")
    jsons = shard_files(tmp_path, "json")
    other = tmp_path / "other.csv"
    other.write_text(open(csvs[0]).read().replace("index,lambda,", "index,lam,", 1))
    garbage = tmp_path / "garbage.csv"
    garbage.write_text("hello\n")
    shard_of_4 = tmp_path / "of4.json"
    assert run("sweep", *SHARD_GRID, "--shard", "1/4", "--output", str(shard_of_4)).returncode == 0
    cases = [
        ([csvs[0], csvs[1]], "cartan merge: grid index = 2 is missing: 2 of 8 points are in none of the tables"),
        (["--points", "9", *csvs], "cartan merge: grid index = 8 is missing: 1 of 9 points"),
        (["--points", "7", *csvs], "cartan merge: grid index = 7 (in "),
        ([*csvs, csvs[1]], "cartan merge: grid index = 1 appears twice (in "),
        ([csvs[0], str(other), csvs[2]], f"cartan merge: table = {other} has another CSV header than {csvs[0]}"),
        ([str(garbage)], f"cartan merge: table = {garbage} is not a table of cartan sweep"),
        ([csvs[0], jsons[1]], f"cartan merge: table = {jsons[1]} is in another format (JSON or CSV) than {csvs[0]}"),
        ([jsons[0], jsons[2]], "cartan merge: shard = 2/3 is missing"),
        ([jsons[0], jsons[1], jsons[1], jsons[2]], "cartan merge: shard = 2/3 appears twice ("),
        ([*jsons, str(shard_of_4)], f"cartan merge: table = {shard_of_4} is shard 1/4 of a grid of 8 points; "),
        (["--points", "9", *jsons], "cartan merge: --points = 9 disagrees with the shards' grid of 8 points"),
        ([str(tmp_path / "absent.csv")], "cannot be opened"),
        ([], "tables is required"),
    ]
    for args, message in cases:
        result = run("merge", *args)
        assert result.returncode == 2 and result.stdout == "", (args, result.stderr)
        assert message in result.stderr and result.stderr.count("\n") == 1, (args, result.stderr)


def test_csv_of_a_surface_has_its_two_components_of_v0():
    """v0 on the sphere has 2 components: the table had an always-empty v0_3 column."""
    result = run("sweep", "--manifold", "sphere", "--q0", "1,0,-0.3", "--qT-list", "0,1,-0.5;0,1,0.5", "--T", "1",
                 "--N", "50", "--quiet", "--format", "csv")
    assert result.returncode == 0, result.stderr
    lines = list(csv.DictReader(io.StringIO(result.stdout)))
    assert list(lines[0])[-2:] == ["v0_1", "v0_2"] and "v0_3" not in lines[0]
    assert all(line["v0_1"] and line["v0_2"] for line in lines)


def test_a_surface_row_holds_its_frame_and_action_as_cartan_solve_writes_them():
    """v0 of a manifold's row is in the frame at q0, which turns with each point's qT: the row holds
    it (frame0), and the action, as the solve's file does (neither was there)."""
    base = ["--manifold", "sphere", "--q0", "1,0,-0.3", "--mass", "1,2", "--T", "1", "--N", "50"]
    table = json.loads(run("sweep", *base, "--qT-list", "0,1,-0.5;0,1,0.5", "--quiet").stdout)
    for row in table["rows"]:
        solved = json.loads(run("solve", *base, "--qT", ",".join(repr(x) for x in row["qT"])).stdout)
        assert row["frame0"] == solved["frame0"] and row["action"] == solved["action"] and row["v0"] == solved["v"][0]
        assert isinstance(row["action"], float)
    assert table["rows"][0]["frame0"] != table["rows"][1]["frame0"]


def test_csv_holds_a_surface_rows_frame():
    """v0 of a manifold's row is in the frame at q0, which turns with qT: the CSV has it too
    (frame0, its rows one after the other, as the endpoint's numbers), empty on a group (it had no
    such column, so the CSV's v0 could not be read)."""
    base = ["--manifold", "sphere", "--q0", "1,0,-0.3", "--mass", "1,2", "--T", "1", "--N", "50",
            "--qT-list", "0,1,-0.5;0,1,0.5", "--quiet"]
    table = sweep(*base)
    result = run("sweep", *base, "--format", "csv")
    assert result.returncode == 0, result.stderr
    lines = list(csv.DictReader(io.StringIO(result.stdout)))
    assert len(lines) == 2 and list(lines[0])[-3:] == ["frame0", "v0_1", "v0_2"]
    for line, row in zip(lines, table["rows"]):
        assert [float(x) for x in line["frame0"].split()] == [x for e in row["frame0"] for x in e]  # exact
    group = run("sweep", *SO3_BASE, "--lambdas", "0.5", "--aT-list", "0,1,0", "--quiet", "--format", "csv")
    assert group.returncode == 0, group.stderr
    assert [line["frame0"] for line in csv.DictReader(io.StringIO(group.stdout))] == [""]
