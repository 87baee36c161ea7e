"""The `cartan solve` command-line contract, table-driven bad input, and an independent
cross-check of the C++ two-level scheme against the Python/SciPy implementation in bench/python.

Run by ctest with CARTAN_BIN pointing at the built `cartan` executable."""
import json

import numpy as np
import pytest

from cli_support import ROOT, run, solve_json


def project_version():
    """The VERSION of the top-level CMakeLists.txt's project(), read from the source."""
    import re
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(cartan VERSION ([0-9.]+)", text).group(1)


def test_version_is_the_projects():
    result = run("--version")
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "cartan " + project_version()
    assert "--version" in run("--help").stdout


FREE_BODY = ["--model", "free-rigid-body", "--T", "50", "--N", "1000", "--a0=-1,-1,-1", "--aT", "0.9,1,1"]
OSCILLATOR = ["--model", "oscillator", "--T", "12", "--N", "800", "--a0", "-0.7,-1,-0.7", "--aT", "0.8,0.8,1"]


def test_output_contract_fields_and_shapes():
    d = solve_json(*FREE_BODY, "--lambda", "0.5", "--tol", "1e-8")
    for key in ["status", "message", "group", "model", "lambda", "T", "N", "method", "order", "t", "g", "v",
                "mu", "xi", "terminal_error", "iterations", "solve_time_s"]:
        assert key in d, key
    assert d["status"] == "converged"
    assert (d["connection"], d["side"]) == ("cartan-schouten", "left")  # self-description (python/cartan/_results.py)
    assert set(d["iterations"]) == {"outer", "inner", "sweeps"}
    for key in ["t", "g", "v", "mu", "xi"]:
        assert len(d[key]) == 1001, key
    assert len(d["g"][0]) == 9 and len(d["v"][0]) == 3
    g_last = np.array(d["g"][-1]).reshape(3, 3)  # row-major
    a0 = -np.ones(3) / np.sqrt(3)
    aT = np.array([0.9, 1, 1]) / np.sqrt(2.81)
    assert np.linalg.norm(g_last @ a0 - aT) < 1e-8  # the terminal condition, read back row-major
    assert d["terminal_error"] < 1e-8


@pytest.mark.parametrize("lam", ["0", "0.5", "1"])
def test_six_paper_cases_converge(lam):
    fb = solve_json(*FREE_BODY, "--lambda", lam, "--tol", "1e-8")
    assert fb["status"] == "converged" and fb["terminal_error"] < 1e-8
    osc = solve_json(*OSCILLATOR, "--lambda", lam, "--tol", "1e-6")
    assert osc["status"] == "converged" and osc["terminal_error"] < 1e-6
    # the default strategy: direct shooting gives up (no progress), continuation in T succeeds
    assert osc["branch"].startswith("continuation in T (continued in T from T = 3")
    assert osc["branch"].endswith("after shooting failed")


def test_negative_numbers_both_forms_and_problem_file(tmp_path):
    a = solve_json("--model", "oscillator", "--T", "2", "--N", "50", "--a0", "-1,-1,-1", "--aT", "1,0.2,0.1")
    b = solve_json("--model", "oscillator", "--T", "2", "--N", "50", "--a0=-1,-1,-1", "--aT=1,0.2,0.1")
    assert a["v"] == b["v"]
    problem = tmp_path / "p.json"
    problem.write_text(json.dumps({"model": "oscillator", "T": 2, "N": 50, "a0": [-1, -1, -1], "aT": [1, 0.2, 0.1]}))
    c = solve_json("--problem", str(problem))
    assert c["v"] == a["v"]
    d = solve_json("--problem", str(problem), "--lambda", "0")  # flags override the file
    assert d["lambda"] == 0 and d["v"] != a["v"]


def test_output_file_and_heisenberg(tmp_path):
    out = tmp_path / "r.json"
    result = run("solve", "--group", "heisenberg", "--model", "oscillator", "--lambda", "0.5", "--T", "1",
                 "--N", "200", "--gT", "1,0.5,0.8", "--output", str(out))
    assert result.returncode == 0, result.stderr
    d = json.loads(out.read_text())
    assert d["group"] == "heisenberg" and d["status"] == "converged"
    assert np.allclose(d["g"][-1], [1, 0.5, 0.8], atol=1e-9)
    assert d["g"][0] == [0, 0, 0]


def test_solver_failure_exit_code_1_with_json():
    result = run("solve", *OSCILLATOR, "--lambda", "0.5", "--method", "two-level", "--max-iterations", "3")
    assert result.returncode == 1
    d = json.loads(result.stdout)
    assert d["status"] != "converged"
    assert "iterations" in d["message"] or "after" in d["message"]


def test_multiple_shooting_reaches_the_shooting_solution():
    """Multiple shooting and single shooting solve the same discrete equations, so their
    trajectories agree to the solver tolerance amplified by the sweep's sensitivity (the free
    body at T = 50: |dv/dr| ~ 10, so 1e-9 for |r| <= 1e-10 each)."""
    args = [*FREE_BODY, "--lambda", "0.5", "--tol", "1e-10"]
    single = solve_json(*args, "--method", "shooting")
    multi = solve_json(*args, "--method", "multiple-shooting", "--segments", "5")
    assert multi["method"] == "multiple-shooting" and multi["status"] == "converged"
    assert multi["terminal_error"] < 1e-10
    assert np.max(np.abs(np.array(multi["v"]) - np.array(single["v"]))) < 1e-9
    assert np.max(np.abs(np.array(multi["g"]) - np.array(single["g"]))) < 1e-9


def test_continuation_choices_on_the_long_horizon_oscillator():
    """docs/paper-notes.md#erratum-4, measured through the CLI at T = 12 (200 iterations allowed):
    direct shooting from the geodesic guess fails for lambda = 0 and 1/2 (exit 1, JSON with the
    failure). Continuation in T and continuation in lambda from lambda = 0 reach the same branch
    (v0 within 1e-6: both stop at |r| <= 1e-8; other branches differ by O(0.1))."""
    for lam in ["0", "0.5"]:
        failed = run("solve", *OSCILLATOR, "--lambda", lam, "--tol", "1e-8", "--method", "shooting")
        assert failed.returncode == 1
        assert json.loads(failed.stdout)["status"] != "converged"
    args = [*OSCILLATOR, "--lambda", "0.5", "--tol", "1e-8", "--method", "shooting"]
    by_T = solve_json(*args, "--continuation", "T")
    by_lambda = solve_json(*args, "--continuation", "lambda")
    assert by_lambda["branch"].startswith("continued in lambda from lambda = 0 [continued in T from T = 3")
    assert np.max(np.abs(np.array(by_T["v"][0]) - np.array(by_lambda["v"][0]))) < 1e-6


BAD_INPUTS = [
    (["--lambda", "nan"], "lambda"),
    (["--T", "0"], "T = 0"),
    (["--T", "-1"], "T = -1"),
    (["--N", "0"], "N = 0"),
    (["--N", "1000000000"], "N = 1000000000"),
    (["--tol", "0"], "tol = 0"),
    (["--tol", "-1e-3"], "tol"),
    (["--order", "3"], "order = 3"),
    (["--method", "magic"], "method = \"magic\""),
    (["--group", "se7"], "group = \"se7\""),
    (["--inertia", "2,-3,4"], "inertia = 2,-3,4"),
    (["--inertia", "2,3"], "inertia = 2,3"),
    (["--inertia", "2,x,4"], "inertia = \"2,x,4\""),
    (["--a0", "0,0,0"], "a0"),
    (["--aT", "1,1,1", "--a0", "-1,-1,-1"], "antiparallel"),
    (["--a0", "1,1,inf"], "a0"),
    (["--gT", "1,0,0,0,2,0,0,0,1"], "gT = "),
    (["--gT", "-1,0,0,0,1,0,0,0,1"], "determinant"),
    (["--gT", "1,0,0"], "gT = 1,0,0"),
    (["--bogus", "1"], "bogus"),
    (["--method", "multiple-shooting", "--segments", "-2"], "segments = -2"),
    (["--continuation", "sideways"], "continuation = \"sideways\""),
    (["--method", "multiple-shooting", "--segments", "11"], "segments = 11"),
]


@pytest.mark.parametrize("args,needle", BAD_INPUTS)
def test_bad_input_exit_code_2_and_message(args, needle):
    base = [x for key in ("--T", "--N") if key not in args for x in (key, "1" if key == "--T" else "10")]
    if not any(a.startswith("--a0") or a.startswith("--gT") for a in args):
        base += ["--a0", "1,0,0", "--aT", "0,1,0"]
    elif any(a.startswith("--a0") for a in args) and not any(a.startswith("--aT") for a in args):
        base += ["--aT", "0,1,0"]
    result = run("solve", *base, *args)
    assert result.returncode == 2, (result.returncode, result.stderr)
    assert needle in result.stderr, result.stderr
    assert result.stderr.count("\n") == 1  # one clear line


@pytest.mark.parametrize("content,needle", [
    ("{not json", "not valid JSON"),
    ("[1, 2]", "must be a JSON object"),
    ('{"T": "long"}', "T = \"long\" must be a number"),
    ('{"lamda": 0.5}', "lamda"),
    ('{"inertia": [2, "3", 4]}', "inertia"),
    ('{"N": 2.5}', "N = 2.5 must be an integer"),
])
def test_bad_problem_files(tmp_path, content, needle):
    problem = tmp_path / "p.json"
    problem.write_text(content)
    result = run("solve", "--problem", str(problem), "--a0", "1,0,0", "--aT", "0,1,0")
    assert result.returncode == 2, result.stderr
    assert needle in result.stderr, result.stderr


def test_cpp_two_level_matches_python_implementation():
    """Two independent implementations of the paper's scheme (C++ and NumPy/SciPy) agree."""
    import paper_scheme as ps
    a0, aT = (-0.7, -1.0, -0.7), (0.8, 0.8, 1.0)
    for lam in [0.0, 0.5, 1.0]:
        d = solve_json("--model", "oscillator", "--lambda", str(lam), "--T", "3", "--N", "200", "--a0=-0.7,-1,-0.7",
                  "--aT", "0.8,0.8,1", "--method", "two-level", "--tol", "1e-11")
        py = ps.solve(ps.Problem(model="oscillator", lam=lam, T=3.0, N=200, a0=a0, aT=aT), tol=1e-11)
        assert py["status"] == "converged", py["message"]
        # Both outer loops stop at max|xi change| < 1e-11 and both inner loops reach ~1e-14, so the
        # trajectories agree far below the scheme's O(h) error; 1e-8 leaves room for the
        # finite-difference Jacobians' different paths.
        assert np.max(np.abs(np.array(d["v"]) - py["v"])) < 1e-8, lam
        assert np.max(np.abs(np.array(d["g"]) - py["g"].reshape(-1, 9))) < 1e-8, lam
