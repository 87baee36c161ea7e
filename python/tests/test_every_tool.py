"""Every tool on every kind of result (issue 44, "one door, one result"): a group model's solve and
a manifold's, on each shipped space and connection, return the one cartan.Result carrying its
problem, on which verify(r) alone, energy, action, cumulative action, dense output, plot, pickling
and model_of work alike.

Tolerances: the energy E = mu.v - l is conserved by the exact flow of every problem here (none
depends on t); the order-2 scheme's drift is O(h^2): below 1e-3 relative at these resolutions
(measured up to 2e-4). cumulative_action ends on action exactly (the same sum). Dense output at a
node returns the sample itself, bit for bit."""
import math
import os
import pickle
import subprocess
from pathlib import Path

import numpy as np
import pytest

import cartan

ROOT = Path(__file__).resolve().parents[2]
CARTAN_BIN = os.environ.get("CARTAN_BIN", str(ROOT / "build" / "cartan"))
GT = cartan.SO3.minimal_rotation([-1.0, -1, -1], [0.9, 1.0, 1.0])
S2_Q0, S2_QT = cartan.Sphere.point([1, 0, -0.3]), cartan.Sphere.point([0, 1, -0.5])


def hyperbolic(x, y):
    return np.array([x, y, np.sqrt(1 + x * x + y * y)])


def half_plane_christoffel(q):
    g = np.zeros((2, 2, 2))
    g[0, 0, 1] = g[0, 1, 0] = g[1, 1, 1] = -1 / q[1]
    g[1, 0, 0] = 1 / q[1]
    return g


PROBLEMS = {
    "so3-model": lambda: dict(lagrangian=cartan.SO3Oscillator([2.0, 3.0, 4.0]), lam=0.5, T=3.0, N=200, gT=GT),
    "heisenberg-model": lambda: dict(lagrangian=cartan.H3Oscillator(), lam=0.3, T=1.0, N=200,
                                     gT=np.array([0.5, -0.3, 0.2])),
    "se2-model": lambda: dict(lagrangian=cartan.SE2FreeBody([3.0, 3.0, 0.7]), lam=0.5, T=1.0, N=200,
                              gT=cartan.SE2.exp([0.3, -0.2, 0.4])),
    "sphere": lambda: dict(lagrangian=cartan.Sphere(), T=1.0, N=200, q0=S2_Q0, qT=S2_QT, inertia=[1.0, 2.0], gravity=3.0),
    "hyperbolic-plane": lambda: dict(lagrangian=cartan.HyperbolicPlane(), T=1.0, N=200, q0=hyperbolic(0.1, 0.2),
                                     qT=hyperbolic(-0.4, 0.5)),
    "euclidean-torsion": lambda: dict(lagrangian=cartan.Euclidean(np.array([[[0, 0.3], [-0.3, 0]], [[0, 0], [0, 0]]])),
                                      T=2.0, N=200, q0=[0.5, 0.0], qT=[-0.3, 0.4], inertia=[1.0, 2.0]),
    "so3-cartan-schouten": lambda: dict(lagrangian=cartan.GroupManifold("so3", "cartan-schouten", lam=0.3), T=3.0,
                                        N=200, q0=np.eye(3), qT=GT, inertia=[2.0, 3.0, 4.0]),
    "so3-levi-civita": lambda: dict(lagrangian=cartan.GroupManifold("so3", "levi-civita", metric=[2.0, 3.0, 4.0]),
                                    T=3.0, N=200, q0=np.eye(3), qT=GT, inertia=[2.0, 3.0, 4.0]),
    "chart": lambda: dict(lagrangian=cartan.Chart(half_plane_christoffel, dim=2, metric=lambda q: np.eye(2) / q[1] ** 2,
                                                  parallel=True), T=1.0, N=40, q0=[-0.5, 0.8], qT=[0.6, 1.2]),
}


@pytest.fixture(scope="module", params=list(PROBLEMS))
def solved(request):
    problem = PROBLEMS[request.param]()
    return request.param, cartan.solve(**problem, order=2, tol=1e-10)


def test_one_result_type_verified_by_itself(solved):
    name, r = solved
    assert type(r) is cartan.Result and r.converged, r.message
    assert isinstance(r.problem, cartan.Problem)
    assert r.problem.kind == ("group" if name.endswith("-model") else "manifold")
    report = cartan.verify(r)  # nothing else: the result carries its problem
    assert report.passed, str(report)
    expected = {"sphere": "levi-civita", "hyperbolic-plane": "levi-civita", "euclidean-torsion": "christoffel",
                "chart": "christoffel", "so3-levi-civita": "levi-civita"}
    assert r.connection == expected.get(name, "cartan-schouten")


def test_energy_action_and_cumulative_action(solved):
    _, r = solved
    assert r.energy.shape == r.t.shape and r.cumulative_action.shape == r.t.shape
    drift = np.abs(r.energy - r.energy[0]).max() / max(1.0, np.abs(r.energy).max())
    assert drift < 1e-3
    assert r.cumulative_action[0] == 0 and r.cumulative_action[-1] == r.action and math.isfinite(r.action)
    assert r.u.shape[0] == r.t.size and r.frame.shape[0] == r.t.size


def test_dense_output_plot_and_pickling(solved):
    _, r = solved
    at_nodes = r.sol(r.t[[0, 7, -1]])
    points = at_nodes.g if r.problem.kind == "group" else at_nodes.q
    np.testing.assert_array_equal(points, r.q[[0, 7, -1]])
    middle = r.sol(0.5 * (r.t[3] + r.t[4]))
    assert np.all(np.isfinite(middle.v))
    fig = r.plot()
    assert len(fig.axes) >= 3
    back = pickle.loads(pickle.dumps(r))
    np.testing.assert_array_equal(back.q, r.q)
    assert back.status == r.status and back.problem.kind == r.problem.kind
    # What pickles travels (the built-in models, the group classes); a manifold object that does not
    # stays behind, and the result then asks for it by name.
    if back.problem.space is not None and (back.problem.kind == "manifold" or back.problem.lagrangian is not None):
        assert cartan.verify(back).passed
    else:
        assert r.problem.kind == "manifold" and back.problem.space is None


def test_model_of_and_files(solved, tmp_path):
    _, r = solved
    if r.problem.kind == "group":
        assert cartan.model_of(r) is r.problem.lagrangian
        r.to_json(tmp_path / "r.json")
        back = cartan.load(tmp_path / "r.json")
        np.testing.assert_array_equal(back.g, r.g)
        assert cartan.verify(back).passed  # a built-in model is rebuilt from the file
    elif isinstance(r.space, cartan.Chart):  # its geometry is Python code: the file names it, load takes it
        r.to_json(tmp_path / "r.json")
        with pytest.raises(ValueError, match=r"manifold = 'python:.*' is a Chart defined in Python.*space=chart"):
            cartan.load(tmp_path / "r.json")
        back = cartan.load(tmp_path / "r.json", space=r.space)
        np.testing.assert_array_equal(back.q, r.q)
        np.testing.assert_allclose(back.frame, r.frame, rtol=0, atol=1e-13)
        assert cartan.verify(back).passed
        out = subprocess.run([CARTAN_BIN, "verify", str(tmp_path / "r.json")], capture_output=True, text=True,
                             timeout=120)  # the CLI reads the file and says why it cannot check it
        assert out.returncode == 2 and "defined in Python" in out.stderr, out.stderr
    else:
        with pytest.raises(ValueError, match="given by its terms"):
            cartan.model_of(r)
        # Every space of the catalogue: the file describes the problem (space, connection, mass,
        # gravity, frame0), load rebuilds it, and the loaded result verifies by itself with the same
        # figures, its frame, u, energy and action recomputed by the library from the samples.
        r.to_json(tmp_path / "r.json")
        back = cartan.load(tmp_path / "r.json")
        assert back.manifold == r.manifold and back.connection == r.connection
        np.testing.assert_array_equal(back.q, r.q)
        np.testing.assert_array_equal(back.Xi, r.Xi)
        np.testing.assert_allclose(back.frame, r.frame, rtol=0, atol=1e-13)  # rebuilt from the same nodes
        np.testing.assert_allclose(back.energy, r.energy, rtol=1e-13, atol=1e-13)
        assert back.action == pytest.approx(r.action, rel=1e-13)
        assert cartan.verify(back).passed and cartan.verify(back).text == cartan.verify(r).text
        out = subprocess.run([CARTAN_BIN, "verify", str(tmp_path / "r.json")], capture_output=True, text=True,
                             timeout=120)  # the CLI reads the same file: the same problem, the same verdict
        assert out.returncode == 0 and "VERDICT: PASS" in out.stdout, out.stdout + out.stderr


def test_a_manifold_lagrangian_object_goes_through_the_same_door():
    """cartan.solve(lagrangian, space=manifold): the spherical pendulum as an object gives the same
    solution as the same Lagrangian by its terms (the same numbers: rounding, 1e-12), and verify(r)
    checks it against that object."""
    class Pendulum:
        def value(self, t, q, v):
            return 0.5 * v @ v - 3.0 * q[2]

        def momentum(self, t, q, v):
            return np.array(v, dtype=float)

        def velocity(self, t, q, mu):
            return np.array(mu, dtype=float)

        def point_gradient(self, t, q, v):
            return np.array([0.0, 0.0, -3.0])

    sphere = cartan.Sphere()
    r = cartan.solve(Pendulum(), space=sphere, T=1.0, N=100, q0=S2_Q0, qT=S2_QT, tol=1e-12)
    terms = cartan.solve(sphere, T=1.0, N=100, q0=S2_Q0, qT=S2_QT, gravity=3.0, tol=1e-12)
    assert r.converged and terms.converged
    np.testing.assert_allclose(r.q, terms.q, atol=1e-12)
    assert isinstance(r.problem.lagrangian, Pendulum) and cartan.verify(r).passed
    with pytest.raises(ValueError, match="is a manifold, and space"):
        cartan.solve(sphere, space=sphere, T=1.0, N=10, q0=S2_Q0, qT=S2_QT)
    # The names of before stay one release, with a warning.
    with pytest.warns(DeprecationWarning, match="solve_general is deprecated"):
        old = cartan.solve_general(sphere, T=1.0, N=100, q0=S2_Q0, qT=S2_QT, gravity=3.0, tol=1e-12)
    np.testing.assert_array_equal(old.q, terms.q)
    with pytest.warns(DeprecationWarning, match="GeneralSolveResult is deprecated"):
        assert cartan.GeneralSolveResult is cartan.Result


def test_a_sweep_of_manifold_problems_is_the_same_as_their_solves():
    """cartan.sweep takes a manifold's problems as cartan.solve does (the sphere's pendulum at three
    gravities, a Euclidean projectile, a GroupManifold): the same results bit for bit (the solver is
    deterministic; threads change nothing), each verified by itself; a bad one is refused by index
    before anything is solved."""
    problems = [dict(lagrangian=cartan.Sphere(), T=1.0, N=100, q0=S2_Q0, qT=S2_QT, gravity=g) for g in (0.0, 1.0, 3.0)]
    problems.append(dict(lagrangian=cartan.Euclidean(dim=3), T=1.0, N=50, q0=[0.0, 0, 0], qT=[1.0, 0, 0], gravity=9.81))
    problems.append(dict(lagrangian=cartan.GroupManifold("so3", "levi-civita", metric=[1.0, 2.0, 3.0]), T=1.0, N=100,
                         q0=np.eye(3), qT=GT, inertia=[2.0, 3.0, 4.0]))
    swept = cartan.sweep(problems)
    for problem, r in zip(problems, swept):
        alone = cartan.solve(**problem)
        assert r.converged and cartan.verify(r).passed, r.message
        np.testing.assert_array_equal(r.q, alone.q)
        np.testing.assert_array_equal(r.v, alone.v)
    # The projectile: q(t) = c t - 1/2 g t^2 e3 with c = qT / T + 1/2 g T e3 (the schemes integrate a
    # constant force exactly; the shooting tolerance remains).
    t = swept[3].t
    expected = np.outer(t, [1.0, 0, 9.81 / 2]) - np.outer(0.5 * 9.81 * t**2, [0, 0, 1])
    np.testing.assert_allclose(swept[3].q, expected, atol=1e-9)
    with pytest.raises(ValueError, match=r"problems\[1\]: .*q0"):
        cartan.sweep([problems[0], dict(problems[0], q0=[0.0, 0, 0])])
    with pytest.raises(TypeError, match=r"problems\[0\]: missing a required argument: 'qT'"):
        cartan.sweep([{k: v for k, v in problems[0].items() if k != "qT"}])
