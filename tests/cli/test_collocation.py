"""`cartan solve --method collocation` (the H3 transported BVP): the output contract, exit codes,
bad input, and agreement with SciPy's solve_bvp on the paper's printed system (appendix
sec-app-H3, g0 = e) at sample times.

Run by ctest (the `cli` test) with CARTAN_BIN pointing at the built `cartan` executable."""
import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

CARTAN = os.environ.get("CARTAN_BIN", "build/cartan")
sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "bench" / "python"))
import h3_scipy  # noqa: E402

H3 = ["--group", "heisenberg", "--model", "oscillator", "--method", "collocation", "--T", "1"]


def run(*args, timeout=120):
    return subprocess.run([CARTAN, "solve", *args], capture_output=True, text=True, timeout=timeout)


def collocation(lam, gT, tol="1e-8", samples="11", extra=()):
    result = run(*H3, "--lambda", str(lam), "--gT", ",".join(map(str, gT)), "--tol", tol, "--samples", samples, *extra)
    assert result.returncode == 0, result.stderr + result.stdout[:500]
    return json.loads(result.stdout)


def scipy_solution(lam, gT, tol):
    sol = h3_scipy.solve(lam, gT, tol)
    assert sol.status == 0, sol.message
    return sol


def test_output_contract():
    d = collocation(0.5, (1, 0.5, 0.8))
    for key in ["status", "message", "group", "model", "lambda", "T", "N", "method", "order", "t", "g", "v", "mu",
                "xi", "terminal_error", "iterations", "solve_time_s", "mesh_size"]:
        assert key in d, key
    assert d["status"] == "converged" and d["method"] == "collocation" and d["order"] == 4
    assert set(d["iterations"]) == {"outer", "inner", "sweeps"}
    assert np.allclose(d["t"], np.linspace(0, 1, 11), atol=1e-15)
    for key in ["g", "v", "mu", "xi"]:
        assert np.array(d[key]).shape == (11, 3), key
    assert d["g"][0] == [0, 0, 0]
    assert np.allclose(d["g"][-1], [1, 0.5, 0.8], atol=1e-10) and d["terminal_error"] < 1e-10
    assert np.allclose(d["xi"][-1], 0, atol=1e-10) and d["mesh_size"] > 11
    assert np.allclose(d["mu"], d["v"])  # unit inertia


def test_samples_zero_reports_the_mesh_and_g0_is_respected():
    d = collocation(0.25, (1, 0.5, 0.8), samples="0", extra=("--g0", "0.3,-0.2,0.5"))
    assert len(d["t"]) == d["mesh_size"]
    assert np.allclose(d["g"][0], [0.3, -0.2, 0.5], atol=1e-12)


@pytest.mark.parametrize("gT", [(1, 0.5, 0.8), (-1, 1, 0.5), (0.5, -1, -1)])
def test_agrees_with_scipy_solve_bvp(gT):
    """Two independent solvers of the paper's BVP. Both control the relative residual to 1e-8,
    which for this well-conditioned problem (T = 1) bounds the error by about 1e-8 (the
    residual is O(h^3), the error O(h^4), so the error is far smaller: measured max difference
    6.5e-12 over all 15 cases); 1e-6 is the issue's acceptance bound."""
    t = np.linspace(0, 1, 11)
    for lam in [0, 0.25, 0.5, 0.75, 1]:
        d = collocation(lam, gT)
        sol = scipy_solution(lam, gT, 1e-8)
        y = sol.sol(t)
        assert np.max(np.abs(np.array(d["g"]) - y[:3].T)) <= 1e-6, lam
        assert np.max(np.abs(np.array(d["v"]) - y[3:].T)) <= 1e-6, lam


def test_solver_failure_exit_code_1_with_json():
    result = run(*H3, "--lambda", "0.5", "--gT", "5,5,5", "--N", "10", "--max-iterations", "1", "--samples", "3")
    assert result.returncode == 1, result.stderr
    d = json.loads(result.stdout)
    assert d["status"] == "not-converged"
    assert "Newton" in d["message"] and "nodes" in d["message"]


@pytest.mark.parametrize("args,needle", [
    (["--group", "so3", "--a0", "1,0,0", "--aT", "0,1,0"], "collocation\" is available for --group heisenberg only"),
    (["--group", "heisenberg", "--model", "oscillator", "--gT", "1,0.5,0.8", "--samples", "1"], "samples = 1"),
    (["--group", "heisenberg", "--model", "oscillator", "--gT", "1,0.5,0.8", "--samples", "-2"], "samples = -2"),
    (["--group", "heisenberg", "--model", "oscillator", "--gT", "1,0.5,0.8", "--tol", "0"], "tol = 0"),
    (["--group", "heisenberg", "--model", "oscillator", "--gT", "1,0.5"], "gT = 1,0.5"),
])
def test_bad_input_exit_code_2(args, needle):
    result = run("--method", "collocation", "--T", "1", *args)
    assert result.returncode == 2, (result.returncode, result.stderr)
    assert needle in result.stderr, result.stderr
