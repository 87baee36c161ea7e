"""`cartan solve --method collocation`: the output contract, exit codes, bad input, agreement with
SciPy's solve_bvp on the paper's printed H3 system (appendix sec-app-H3, g0 = e) at sample
times, and on SO(3) agreement with the shooting solvers' order-2 scheme.

Run by ctest (the `cli` test) with CARTAN_BIN pointing at the built `cartan` executable."""
import json
from functools import partial

import h3_scipy
import numpy as np
import pytest

from cli_support import run, solve_json

H3 = ["--group", "heisenberg", "--model", "oscillator", "--method", "collocation", "--T", "1"]
run_solve = partial(run, "solve")


def collocation(lam, gT, tol="1e-8", samples="11", extra=()):
    return solve_json(*H3, "--lambda", str(lam), "--gT", ",".join(map(str, gT)), "--tol", tol, "--samples", samples,
                      *extra)


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
    result = run_solve(*H3, "--lambda", "0.5", "--gT", "5,5,5", "--N", "10", "--max-iterations", "1", "--samples", "3")
    assert result.returncode == 1, result.stderr
    d = json.loads(result.stdout)
    assert d["status"] == "not-converged"
    assert "Newton" in d["message"] and "nodes" in d["message"]


@pytest.mark.parametrize("args,needle", [
    (["--group", "so3", "--a0", "1,0,0", "--aT", "-1,0,0"], "are antiparallel"),
    (["--group", "heisenberg", "--model", "oscillator", "--gT", "1,0.5,0.8", "--samples", "1"], "samples = 1"),
    (["--group", "heisenberg", "--model", "oscillator", "--gT", "1,0.5,0.8", "--samples", "-2"], "samples = -2"),
    (["--group", "heisenberg", "--model", "oscillator", "--gT", "1,0.5,0.8", "--tol", "0"], "tol = 0"),
    (["--group", "heisenberg", "--model", "oscillator", "--gT", "1,0.5"], "gT = 1,0.5"),
])
def test_bad_input_exit_code_2(args, needle):
    result = run_solve("--method", "collocation", "--T", "1", *args)
    assert result.returncode == 2, (result.returncode, result.stderr)
    assert needle in result.stderr, result.stderr


SO3_FREE_BODY = ["--group", "so3", "--model", "free-rigid-body", "--T", "5", "--a0=-1,-1,-1", "--aT", "0.9,1,1"]
A0 = -np.ones(3) / np.sqrt(3)
AT = np.array([0.9, 1, 1]) / np.sqrt(2.81)


def so3_solve(*args):
    return solve_json(*SO3_FREE_BODY, *args)


def so3_collocation(lam, samples="0"):
    return so3_solve("--method", "collocation", "--N", "20", "--tol", "1e-10", "--samples", samples,
                     "--lambda", str(lam))


@pytest.mark.parametrize("lam", [0, 0.5, 1])
def test_so3_free_body_reaches_the_continuous_solution_of_the_shooting_scheme(lam):
    """The paper's free body (T = 5). Collocation (residual 1e-10: error ~1e-12) and the order-2
    shooting scheme approximate the same continuous solution, so their difference at the shooting
    nodes (the collocation's dense output sampled there) shrinks by 4 when N doubles (order 2,
    within 2^0.25). g is row-major, takes a0 to aT, and stays orthogonal to the collocation
    accuracy."""
    c = so3_collocation(lam)
    assert c["status"] == "converged" and c["method"] == "collocation" and c["order"] == 4
    assert c["branch"].startswith("direct from the geodesic guess")
    assert np.linalg.norm(np.array(c["g"][-1]).reshape(3, 3) @ A0 - AT) < 1e-10
    assert c["group_defect"] < 1e-9 and c["terminal_error"] < 1e-10
    differences = []
    for N in [50, 100, 200]:
        shooting = so3_solve("--order", "2", "--tol", "1e-13", "--lambda", str(lam), "--N", str(N))
        dense = so3_collocation(lam, samples=str(N + 1))
        assert np.allclose(dense["t"], shooting["t"], atol=1e-12)
        differences.append(np.max(np.abs(np.array(dense["v"]) - np.array(shooting["v"]))))
    orders = np.log2(np.array(differences[:-1]) / np.array(differences[1:]))
    assert np.all(np.abs(orders - 2) < 0.25), (differences, orders)


def test_so3_symmetry_of_the_free_body_holds_for_the_collocation_solution():
    """Inversion maps lambda to 1 - lambda and the reflection diag(-1,1,1) fixes the inertia and
    maps gT to gT^-1 (the paper's endpoints): v0(1) = diag(-1,1,1) v0(0) and v0(1/2) has first
    component 0, to the collocation accuracy (tol 1e-10; errors ~1e-12)."""
    v0 = {lam: np.array(so3_collocation(lam)["v"][0]) for lam in [0, 0.5, 1]}
    assert np.max(np.abs(v0[1] - np.array([-1, 1, 1]) * v0[0])) < 1e-8
    assert abs(v0[0.5][0]) < 1e-8


def test_so3_long_horizon_falls_back_to_the_shooting_branch():
    """The paper's oscillator at T = 12: collocation from the geodesic guess fails (as shooting
    does), so with --continuation T the CLI starts again from the order-2 shooting solution
    continued in T; the result says so and is close to that solution (their difference is the
    order-2 discretisation error at N = 800, ~1e-5). Without a continuation (the default, none)
    the failure is reported (exit 1)."""
    oscillator = ["--group", "so3", "--model", "oscillator", "--T", "12", "--N", "800", "--a0=-0.7,-1,-0.7",
                  "--aT", "0.8,0.8,1", "--lambda", "0"]
    result = run_solve(*oscillator, "--method", "collocation", "--continuation", "T", "--tol", "1e-6",
                       "--samples", "801")
    assert result.returncode == 0, result.stderr
    c = json.loads(result.stdout)
    assert c["branch"].startswith("from the order-2 shooting solution (continued in T from T = 3"), c["branch"]
    result = run_solve(*oscillator, "--method", "shooting", "--continuation", "T", "--order", "2", "--tol", "1e-10")
    assert result.returncode == 0, result.stderr
    shooting = json.loads(result.stdout)
    assert np.max(np.abs(np.array(c["v"]) - np.array(shooting["v"]))) < 1e-3
    direct = run_solve(*oscillator, "--method", "collocation", "--tol", "1e-6", timeout=300)
    assert direct.returncode == 1 and json.loads(direct.stdout)["status"] != "converged"
