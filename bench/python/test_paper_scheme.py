"""Checks of bench/python/paper_scheme.py.   /usr/bin/python3 -m pytest bench/python -q

What is checked (about 20 s):
  * the SO(3) helpers (Rodrigues against SciPy, log round trip, minimal rotation);
  * the oscillator force zeta = -vee(Skew g) against a finite difference of l (docs/paper-notes.md#erratum-1);
  * the vectorised (disc-aux) recursion against the loop written as in the pseudocode;
  * the free-body paper case: converged, terminal error < tol, 2 outer iterations at lambda = 0, 1;
  * energy 1/2 v.Iv: non-decreasing along the explicit scheme, and its drift over [0, T] halves
    when h halves (O(h));
  * the symmetry lambda -> 1 - lambda, v -> R v, xi -> -R xi, g -> R g^{-1} R, R = diag(-1,1,1),
    which holds *exactly* for the discrete scheme (see README): v(lambda=1) = R v(lambda=0) at every
    node to rounding, and v_k,1 = 0 for lambda = 1/2;
  * the oscillator at T = 3 converges for lambda = 1/2;
  * the CLI: both spellings of negative vectors, and the JSON fields.
"""
import json
import math
import os
import sys

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paper_scheme as ps  # noqa: E402

R_REFL = np.diag([-1.0, 1.0, 1.0])
FREE = {k: v for k, v in ps.PAPER_FREE_BODY.items() if k != "tol"}
FREE_TOL = ps.PAPER_FREE_BODY["tol"]


def solve_free(lam, jacobian="minpack", **over):
    p = ps.Problem(lam=lam, **{**FREE, **over})
    return p, ps.solve(p, tol=FREE_TOL, jacobian=jacobian)


@pytest.fixture(scope="module")
def free0():
    return solve_free(0.0)


@pytest.fixture(scope="module")
def free1():
    return solve_free(1.0)


@pytest.fixture(scope="module")
def free_half():
    # our absolute-step Jacobian: MINPACK's relative step breaks on v0_1 ~ 1e-11 (see README)
    return solve_free(0.5, jacobian="forward")


# ------------------------------------------------------------------------------------ helpers
@pytest.mark.parametrize("w", [np.zeros(3), np.array([1e-10, -2e-10, 3e-11]),
                               np.array([0.3, -0.2, 0.9]), np.array([0.0, 0.0, math.pi - 1e-9]),
                               np.array([2.0, -1.0, 0.5])])
def test_rodrigues_against_scipy(w):
    assert np.allclose(ps.expm_so3(w), Rotation.from_rotvec(w).as_matrix(), atol=1e-14)


def test_log_roundtrip():
    rng = np.random.default_rng(7)
    for _ in range(50):
        w = rng.normal(size=3)
        w *= rng.uniform(0.0, math.pi - 1e-6) / np.linalg.norm(w)
        assert np.allclose(ps.logm_so3(ps.expm_so3(w)), w, atol=1e-12)


def test_minimal_rotation():
    a0 = np.array([-1.0, -1.0, -1.0]) / math.sqrt(3)
    aT = np.array([0.9, 1.0, 1.0]) / math.sqrt(2.81)
    gT = ps.minimal_rotation(a0, aT)
    assert np.allclose(gT @ a0, aT, atol=1e-15)
    assert np.allclose(gT.T @ gT, np.eye(3), atol=1e-15)
    w = ps.logm_so3(gT)
    assert abs(np.linalg.norm(w) - math.acos(a0 @ aT)) < 1e-12     # angle between a0 and aT
    assert abs(w @ a0) < 1e-12 and abs(w @ aT) < 1e-12             # axis a0 x aT
    # the free-body endpoints: axis along (0, 1, -1), so R gT R = gT^{-1}
    assert np.allclose(R_REFL @ gT @ R_REFL, gT.T, atol=1e-15)
    assert np.array_equal(ps.minimal_rotation(a0, 2 * a0), np.eye(3))
    with pytest.raises(ValueError):
        ps.minimal_rotation(a0, -a0)


def test_oscillator_force_is_restoring_derivative_of_l():
    """zeta.w = d/de l(g exp(e w)) with l = -V(g) + kinetic, V = (3 - tr g)/2
    (docs/paper-notes.md#erratum-1)."""
    p = ps.Problem(model="oscillator")
    rng = np.random.default_rng(3)
    for _ in range(10):
        g = ps.expm_so3(rng.normal(size=3))
        w = rng.normal(size=3)
        e = 1e-6
        dl = (-p.potential(g @ ps.expm_so3(e * w)) + p.potential(g @ ps.expm_so3(-e * w))) / (2 * e)
        assert abs(p.zeta(g) @ w - dl) < 1e-9
    # restoring: for g = exp(theta x^), zeta = -sin(theta) x
    x = np.array([0.0, 0.0, 1.0])
    assert np.allclose(p.zeta(ps.expm_so3(0.1 * x)), -math.sin(0.1) * x)


def test_backward_xi_matches_pseudocode_loop():
    p = ps.Problem(N=37, T=2.0)
    rng = np.random.default_rng(1)
    v = rng.normal(size=(38, 3))
    mu = p.inertia * v
    xi = np.zeros((38, 3))
    for k in range(36, -1, -1):
        xi[k] = xi[k + 1] - p.h * np.cross(v[k], mu[k])   # xi_k = xi_{k+1} + h ad*_{v_k} mu_k
    assert np.allclose(p.backward_xi(v, mu), xi, atol=1e-15)


# ------------------------------------------------------------------------------ free body
def test_free_body_converges(free0, free1, free_half):
    for _, res in (free0, free1, free_half):
        assert res["status"] == "converged"
        assert res["terminal_error"] < FREE_TOL
    # lambda = 0, 1: xi does not enter the sweep, so the second outer iteration repeats the first
    assert free0[1]["outer"] == 2 and free1[1]["outer"] == 2


def test_free_body_energy_drift_is_first_order(free0):
    p1, r1 = free0
    E1 = p1.energy(r1["g"], r1["v"])
    # the explicit momentum step adds h^2/2 (v x m).I^{-1}(v x m) >= 0 per step
    assert np.all(np.diff(E1) >= -1e-15)
    p2, r2 = solve_free(0.0, N=2 * FREE["N"])
    assert r2["status"] == "converged"
    E2 = p2.energy(r2["g"], r2["v"])
    d1, d2 = E1[-1] - E1[0], E2[-1] - E2[0]
    assert d1 > 0 and d2 > 0
    assert 1.8 < d1 / d2 < 2.2, (d1, d2)           # measured 2.000


def test_lambda_symmetry_free_body_exact(free0, free1):
    """v_k(1) = R v_k(0), xi -> -R xi, g_k(1) = R g_k(0)^{-1} R: exact for the discrete scheme."""
    (_, a), (_, b) = free0, free1
    assert np.max(np.abs(b["v"][0] - R_REFL @ a["v"][0])) < 1e-13     # measured ~1e-16
    assert np.max(np.abs(b["v"] - a["v"] @ R_REFL)) < 1e-13
    assert np.max(np.abs(b["xi"] + a["xi"] @ R_REFL)) < 1e-13
    g_mapped = np.einsum("ij,kjl,lm->kim", R_REFL, np.transpose(a["g"], (0, 2, 1)), R_REFL)
    assert np.max(np.abs(b["g"] - g_mapped)) < 1e-12
    # and it is not a trivial statement: v0(0) has a nonzero first component
    assert abs(a["v"][0][0]) > 1e-2


def test_lambda_half_is_self_symmetric(free_half):
    _, r = free_half
    assert np.max(np.abs(r["v"][:, 0])) < 1e-12          # v_k = R v_k  (measured ~3e-17)
    assert np.max(np.abs(r["xi"][:, 1:])) < 1e-12        # xi_k = -R xi_k
    assert r["outer"] >= 3                                # the curvature term is active


# ----------------------------------------------------------------------------- oscillator
def test_oscillator_short_horizon_converges():
    p = ps.Problem(model="oscillator", lam=0.5, T=3.0, N=200, a0=ps.PAPER_OSCILLATOR["a0"],
                   aT=ps.PAPER_OSCILLATOR["aT"])
    r = ps.solve(p, tol=1e-6)
    assert r["status"] == "converged"
    assert r["terminal_error"] < 1e-6
    assert np.allclose(r["v"][0], [-1.4281693, 0.2734207, 0.3449138], atol=1e-6)


# ------------------------------------------------------------------------------------ CLI
@pytest.mark.parametrize("spelling", [["--a0=-1,-1,-1"], ["--a0", "-1,-1,-1"]])
def test_cli_negative_vectors_and_json(tmp_path, spelling):
    out = tmp_path / "r.json"
    rc = ps.main(["--model", "free-rigid-body", "--lambda", "0", "--T", "5", "--N", "50",
                  *spelling, "--aT", "0.9,1,1", "--inertia", "2,3,4", "--tol", "1e-8",
                  "--output", str(out)])
    d = json.loads(out.read_text())
    assert rc == 0 and d["status"] == "converged"
    assert np.allclose(d["a0"], -np.ones(3) / math.sqrt(3))
    for key in ("status", "message", "group", "model", "lambda", "T", "N", "method", "order", "t",
                "g", "v", "mu", "xi", "terminal_error", "iterations", "solve_time_s"):
        assert key in d
    assert d["group"] == "so3" and d["method"] == "two-level" and d["order"] == 1
    assert len(d["t"]) == len(d["g"]) == len(d["v"]) == len(d["xi"]) == 51
    assert all(len(row) == 9 for row in d["g"])
    assert set(d["iterations"]) >= {"outer", "inner", "sweeps"}
    g_N = np.array(d["g"][-1]).reshape(3, 3)
    assert np.allclose(g_N @ np.array(d["a0"]), d["aT"], atol=1e-12)


def test_cli_negative_scalar():
    args = ps.build_parser().parse_args(ps._join_negative_values(["--lambda", "-1e-3"]))
    assert args.lam == -1e-3
