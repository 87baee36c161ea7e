"""cartan.verify: the library's checks and verdict (include/cartan/kernels/lie_group/verify.hpp) from Python,
on results of built-in and Python-defined Lagrangians; the same report as `cartan verify`.

Tolerances (theory):
* Python vs CLI report: the same C++ checks on the same samples, up to the JSON round trip of the
  CLI's file (17 significant digits); the figures are relative sizes of order rho = h omega
  computed from those samples, so they agree to 1e-9 relative.
* Python-defined vs built-in Lagrangian: the same formulas in the callbacks, so the same figures to
  rounding (1e-9 relative: the checks difference the samples, losing up to 1e6 of 1e-16)."""
import dataclasses
import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import cartan
from python_models import PyRigidBody

ROOT = Path(__file__).resolve().parents[2]
CARTAN_BIN = os.environ.get("CARTAN_BIN", str(ROOT / "build" / "cartan"))
A0, AT = np.array([1.0, 0, 0]), np.array([0.0, 1, 0.3])
GT = cartan.SO3.minimal_rotation(A0, AT)


@pytest.mark.parametrize("lam", [-1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0])
def test_honest_results_pass_for_every_lambda(lam):
    model = cartan.SO3Oscillator([1.0, 5.0, 9.0])
    r = cartan.solve(model, lam=lam, T=3, N=200, gT=GT, tol=1e-11)
    assert r.success, r.message
    report = cartan.verify(r, model)
    assert report.passed and report.verdict == "PASS", str(report)
    assert [c["name"] for c in report.checks] == ["boundary", "legendre", "energy", "residual", "stationarity"]
    assert str(report).endswith("VERDICT: PASS\n")
    # a = 1 on [0, 1] here (kappa <= 2); outside, at least |2 lambda - 1|.
    assert report.amplification == pytest.approx(1.0) if 0 <= lam <= 1 else report.amplification >= abs(2 * lam - 1)


def test_same_report_as_the_cli(tmp_path):
    path = tmp_path / "r.json"
    out = subprocess.run([CARTAN_BIN, "solve", "--model", "oscillator", "--inertia", "1,5,9", "--lambda", "2", "--T",
                          "3", "--N", "200", "--a0", "1,0,0", "--aT", "0,1,0.3", "--tol", "1e-11", "--output",
                          str(path)], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    cli = json.loads(subprocess.run([CARTAN_BIN, "verify", "--json", str(path)], capture_output=True, text=True,
                                    timeout=120).stdout)
    data = json.loads(path.read_text())
    result = dict(lam=data["lambda"], T=data["T"], g0=np.array(data["g0"]).reshape(3, 3),
                  gT=np.array(data["gT"]).reshape(3, 3), order=data["order"], tol=data["tol"],
                  status=data["status"], t=data["t"], g=np.array(data["g"]).reshape(-1, 3, 3), v=data["v"],
                  mu=data["mu"], xi=data["xi"])
    report = cartan.verify(type("Result", (), result), cartan.SO3Oscillator([1.0, 5.0, 9.0]))
    assert report.verdict == cli["verdict"] == "PASS"
    assert report.amplification == pytest.approx(cli["amplification"], rel=1e-9)
    for mine, theirs in zip(report.checks, cli["checks"]):
        assert mine["name"] == theirs["name"] and mine["result"] == theirs["result"]
        assert mine["figure"] == pytest.approx(theirs["figure"], rel=1e-9, abs=1e-15)
        assert mine["threshold"] == pytest.approx(theirs["threshold"], rel=1e-9)


def test_python_lagrangian_gives_the_builtin_figures():
    builtin = cartan.RigidBody([2.0, 3.0, 4.0])
    r = cartan.solve(builtin, lam=0.5, T=2, N=100, gT=GT, tol=1e-11)
    a, b = cartan.verify(r, builtin), cartan.verify(r, PyRigidBody([2.0, 3.0, 4.0]))
    assert a.passed and b.passed
    for x, y in zip(a.checks, b.checks):
        assert x["figure"] == pytest.approx(y["figure"], rel=1e-9, abs=1e-15), x["name"]


def test_tampered_results_fail():
    model = cartan.SO3Oscillator([2.0, 3.0, 4.0])
    r = cartan.solve(model, lam=0.0, T=3, N=200, gT=GT, tol=1e-11)
    assert cartan.verify(r, model).passed
    # The transported action of lambda = 0 is not stationary for lambda = 1: residual and action see it.
    wrong = cartan.verify(r.replace(lam=1.0), model)
    failed = {c["name"] for c in wrong.checks if c["result"] == "FAIL"}
    assert not wrong.passed and {"residual", "stationarity"} <= failed, str(wrong)
    # An oscillator solution is not a free body's: 1/2 v.I v alone is not conserved.
    as_free_body = cartan.verify(r, cartan.RigidBody([2.0, 3.0, 4.0]))
    assert "energy" in {c["name"] for c in as_free_body.checks if c["result"] == "FAIL"}


def test_a_manifolds_collocation_mesh_is_verified_and_a_wrong_one_fails():
    """Issue 44: cartan.verify refused every converged collocation result of the general solver on
    its own mesh (non-uniform after refinement): "trajectory.t ... must be uniform". The residual
    now takes the three-point derivative of any mesh (second order, as the thresholds assume);
    the discrete action's stationarity needs a uniform grid and is N/A, as on a group."""
    S = cartan.Sphere
    r = cartan.solve(S(), T=1.3, N=300, q0=S.point([1, 0.2, -0.3]), qT=S.point([-0.2, 1, 0.5]), inertia=[1, 2],
                     gravity=3.0, method="collocation", tol=1e-10)
    assert r.success and np.ptp(np.diff(r.t)) > 1e-3 * r.T / (len(r.t) - 1), r.message  # a non-uniform mesh
    report = cartan.verify(r)
    by_name = {c["name"]: c for c in report.checks}
    assert report.passed, str(report)
    assert by_name["stationarity"]["result"] == "N/A" and "not uniform" in by_name["stationarity"]["note"]
    # The same samples with mu off by 1e-4 (relative to |mu| ~ 1) break the mu equation: the
    # residual's figure (1.2e-7 honest) grows by orders of magnitude past its threshold (4.8e-6).
    wrong = cartan.verify(r.replace(mu=r.mu + 1e-4 * np.sin(7 * r.t)[:, None]))
    assert not wrong.passed and "residual" in {c["name"] for c in wrong.checks if c["result"] == "FAIL"}, str(wrong)


def test_a_failed_solve_never_passes():
    model = cartan.SO3Oscillator([2.0, 3.0, 4.0])
    gT = cartan.SO3.minimal_rotation([-0.7, -1, -0.7], [0.8, 0.8, 1])
    r = cartan.solve(model, lam=0.5, T=12, N=800, gT=gT, method="shooting", max_iterations=3)
    assert not r.success
    report = cartan.verify(r, model)
    assert not report.passed and report.checks[0]["name"] == "converged" and report.checks[0]["result"] == "FAIL"
    assert r.status in report.checks[0]["note"]
    empty = r.replace(t=np.zeros(0), g=np.zeros((0, 3, 3)), v=np.zeros((0, 3)), mu=np.zeros((0, 3)),
                      xi=np.zeros((0, 3)))
    unchecked = cartan.verify(empty, model)
    assert not unchecked.passed and "not checked" in str(unchecked)


def test_bad_input_raises_value_error():
    model = cartan.RigidBody([2.0, 3.0, 4.0])
    r = cartan.solve(model, lam=0.5, T=2, N=20, gT=GT)
    with pytest.raises(ValueError, match="status"):
        cartan.verify(dataclasses.replace(r, status="done"), model)
    with pytest.raises(ValueError, match="needs g, v, mu and xi at every time"):
        cartan.verify(dataclasses.replace(r, v=r.v[:-1]), model)
    # The samples are read as whole arrays: a wrong row shape names the field and both shapes.
    with pytest.raises(ValueError, match=r"^SO3\.verify: result\.g = array of shape \(21, 9\) must have shape "
                                         r"\(21, 3, 3\)$"):
        cartan.verify(r.replace(g=r.g.reshape(21, 9)), model)
    with pytest.raises(ValueError, match="must run from 0 to T"):
        cartan.verify(dataclasses.replace(r, T=3.0), model)
    with pytest.raises(ValueError, match="group"):
        cartan.verify(r, object())


def test_an_isometry_of_the_hyperbolic_plane_does_not_change_the_verdict():
    """A boost of H^2 moves a geodesic problem onto another of the same geometry: the solution, its
    resolution h omega and the verdict are the same (omega from the metric speed). With the
    representation's norm, which grows like cosh of the distance from the vertex, h omega went
    from 0.012 at b = 0 to 1.4 at b = 6, and the exact geodesic failed as unresolved."""
    H = cartan.HyperbolicPlane
    resolutions = []
    # b <= 6: further out the hyperboloid's coordinates (~cosh b) round the endpoint residual above
    # the default tol (at b = 7 shooting stalls at |r| = 5e-10 and says so).
    for b in (0.0, 3.0, 6.0):
        boost = np.array([[np.cosh(b), 0, np.sinh(b)], [0, 1, 0], [np.sinh(b), 0, np.cosh(b)]])
        r = cartan.solve(H(), T=1.0, N=100, q0=boost @ H.point(-0.4, 0.2), qT=boost @ H.point(0.5, -0.1))
        report = cartan.verify(r)
        assert r.success and report.passed, (b, str(report))
        resolutions.append(report.resolution)
    # The same problem up to rounding in coordinates of size cosh(6) ~ 2e2: equal to 1e-9.
    assert max(resolutions) - min(resolutions) < 1e-9 * max(resolutions), resolutions


def test_a_failed_result_off_the_manifold_is_a_failing_report_and_a_converged_one_bad_input():
    """A diverged iterate's points may leave the manifold (collocation's Newton on the sphere: q up
    to 1.5 off it): verify reports FAIL, saying why nothing else was checked, as `cartan verify`
    does; it raised ValueError. The same samples in a result that says "converged" are bad input."""
    S = cartan.Sphere
    r = cartan.solve(S(), T=1.0, N=50, q0=S.point([1, 0, -0.3]), qT=S.point([0, 1, -0.5]), gravity=9.81)
    assert r.success, r.message
    q = r.q.copy()
    q[1] *= 1.5
    report = cartan.verify(r.replace(q=q, status="max-iterations", success=False))
    assert not report.passed and report.verdict == "FAIL", str(report)
    assert "not checked" in str(report) and "not on the unit sphere" in str(report)
    with pytest.raises(ValueError, match="not on the unit sphere"):
        cartan.verify(r.replace(q=q))
