"""Short paths: endpoints a few ulps to 1e-4 rad apart, or a small motion far from the origin.

Before 2026-12-07 every case below failed one way or another: verify's residual and stationarity
were relative to the path's own terms with no account of the samples' roundoff (a step of 1e-9 on
the unit sphere is 1e7 ulps of a point: q' by differences is 1e-7 off, relatively), and the
auxiliary's scale shrank like |v|^2 while v0's unit stayed 1/T, so Levenberg-Marquardt stalled on
SO(3) (max-iterations at |log gT| = 1e-5) and on S^2 traded the boundary for Xi (a constant path,
"converged" within tol, at endpoints 1e-10 apart).
"""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import cartan

TOL = 1e-10  # the solve's default tolerance (radians at the end point)


def _small_rotation(model, lam, size, method):
    """The model's solve at T = 1, N = 50 from e to a rotation by `size` about a fixed axis."""
    axis = np.array([0.3, -0.2, 0.5]) / np.linalg.norm([0.3, -0.2, 0.5])
    return cartan.solve(model, lam=lam, T=1, N=50, gT=cartan.SO3.exp(size * axis), method=method)


def _passes(result):
    report = cartan.verify(result)
    failed = [(c["name"], c["figure"], c["threshold"]) for c in report.checks if c["result"] == "FAIL"]
    return report.passed, failed


@pytest.mark.parametrize("N", [50, 400])
@pytest.mark.parametrize("angle", [1e-4, 1e-7, 3e-9, 1e-10, 1e-12])
def test_a_short_geodesic_on_the_sphere(angle, N):
    q0 = np.array([0.0, 0.0, 1.0])
    qT = np.array([np.sin(angle), 0.0, np.cos(angle)])
    r = cartan.solve(space=cartan.Sphere(), T=1, N=N, q0=q0, qT=qT)
    assert r.status == "converged"
    # The geodesic: speed angle / T towards qT. The solve meets |q_N - qT| <= TOL, so v0 is right to
    # TOL / T absolutely whatever the angle (not the constant path of before, off by the angle).
    speed = np.linalg.norm(r.v0)
    assert abs(speed - angle) <= 2 * TOL
    assert np.linalg.norm(np.asarray(r.q)[-1] - qT) <= TOL
    assert _passes(r) == (True, [])


@pytest.mark.parametrize("lam", [0.0, 0.5, 1.0])
@pytest.mark.parametrize("size", [1e-2, 1e-5, 1e-8, 1e-10])
def test_a_small_rotation_of_a_rigid_body(size, lam):
    rotation = size * np.array([1.0, 0.3, 0.0])
    gT = Rotation.from_rotvec(rotation).as_matrix()
    for method in ("shooting", "auto"):
        r = cartan.solve(cartan.RigidBody([1, 2, 3]), lam=lam, T=1, N=50, gT=gT, method=method)
        assert r.status == "converged", (method, r.message)
        # A motion this small is a free rotation to first order: v0 = rotvec / T up to O(size^2)
        # (the gyroscopic term), and the end point is met to TOL.
        assert np.linalg.norm(r.v0 - rotation) <= 2 * TOL + 10 * size**2
        assert _passes(r) == (True, []), method


@pytest.mark.parametrize("offset", [1e-4, 1e-7])
def test_a_small_motion_far_from_the_origin_of_the_plane(offset):
    # Coordinates of 1e3: each carries 1e-13 of roundoff, against steps of offset / N = 1e-9 at
    # the smallest. (At 1e6 the end point itself is known to an ulp of 1.2e-10 only, and tol =
    # 1e-10 cannot be met: the solve fails, saying |r| did not decrease.)
    q0 = np.array([1e3, -1e3])
    qT = q0 + np.array([offset, 0.5 * offset])
    r = cartan.solve(space=cartan.Euclidean(dim=2), T=1, N=100, q0=q0, qT=qT)
    assert r.status == "converged"
    assert _passes(r) == (True, [])


def test_the_roundoff_floor_does_not_pass_a_wrong_path():
    # 1e-7 rad on the sphere: the floor is ~1e-7 of the terms; a velocity 1 % off is far above it.
    angle = 1e-7
    q0, qT = np.array([0.0, 0.0, 1.0]), np.array([np.sin(angle), 0.0, np.cos(angle)])
    r = cartan.solve(space=cartan.Sphere(), T=1, N=50, q0=q0, qT=qT)
    assert _passes(r)[0]
    r.v = np.asarray(r.v) * 1.01
    r.mu = np.asarray(r.mu) * 1.01
    passed, failed = _passes(r)
    assert not passed and "residual" in [name for name, _, _ in failed]


@pytest.mark.parametrize("group, q0", [("heisenberg", np.zeros(3)), ("so3", np.eye(3))])
@pytest.mark.parametrize("size", [1e-6, 1e-9])
def test_a_small_motion_on_a_curved_group_manifold(group, q0, size):
    # The first variation of a path 1e-9 long is ~1e-9: the stationarity check's three-point
    # difference of the action had an absolute truncation error of ~4e-13 (figure 4.1e-4 against
    # 1.1e-9 on the Heisenberg group before); the five-point one's is ~1e-24.
    M = cartan.GroupManifold(group, "levi-civita", metric=[1, 2, 3])
    qT = M.step(q0, M.tangent_basis(q0) @ (size * np.array([0.3, -0.2, 0.5])))
    r = cartan.solve(M, T=1, N=50, q0=q0, qT=qT, method="shooting")
    assert r.status == "converged", r.message
    assert _passes(r) == (True, [])


@pytest.mark.parametrize("lam", [2.0, -1.0])
def test_two_level_converged_means_the_end_point_meets_tol(lam):
    # Strong anisotropy and lambda (1 - lambda) = -2: the outer change fell below tol while the end
    # point of the updated sequence was 1.7e-8 off, and two-level said "converged".
    r = cartan.solve(cartan.SE2FreeBody([1, 100, 1e4]), lam=lam, T=1, N=50, gT=cartan.SE2.exp([0.3, -0.2, 0.5]),
                     method="two-level")
    assert r.status == "converged", r.message
    assert r.terminal_error <= TOL
    assert _passes(r) == (True, [])


@pytest.mark.parametrize("lam", [0.5, 2.0])
@pytest.mark.parametrize("size", [1e-6, 1e-9])
def test_collocation_solves_a_small_motion_rather_than_returning_its_guess(size, lam):
    # The geodesic guess (xi = 0) met the collocation target's absolute floor tol h (1 + |f|), so
    # Newton took no step and xi ~ size^2 stayed 0 (verify: residual on xi' 0.25). Newton now takes
    # at least one step from the guess, as SciPy's solve_newton does.
    r = _small_rotation(cartan.RigidBody([1, 2, 3]), lam, size, "collocation")
    assert r.status == "converged", r.message
    assert np.abs(np.asarray(r.xi)).max() > 0
    assert _passes(r) == (True, [])


@pytest.mark.parametrize("size", [1e-6, 1e-9])
def test_the_oscillators_energy_of_a_small_motion(size):
    # V = 1/2 (3 - tr g) cancelled to roundoff at these sizes (E ~ size^2): the energy drifted by
    # 0.34 of E at 1e-9 with every method. Evaluated as 1/4 |g - I|^2 its roundoff is relative.
    # (Collocation is left out: its Newton stops at the absolute floor of its target after one step
    # from the geodesic guess, which leaves xi ~1 % off under a potential; the closing note of
    # 2026-12-07 says what would fix it.)
    for method in ("shooting", "auto", "two-level"):
        r = _small_rotation(cartan.SO3Oscillator([1, 2, 3]), 0.5, size, method)
        assert r.status == "converged", (method, r.message)
        assert _passes(r) == (True, []), method


@pytest.mark.parametrize("method", ["auto", "shooting", "collocation", "variational"])
def test_a_body_at_rest_away_from_the_identity(method):
    # g0 = gT != e: the solution is rest, its steps log(g_k^-1 g_k+1) are roundoff. Variational
    # reported "stalled" at it (delta and correction both ~1e-32 failed the monotonicity test), and
    # verify's residual on roundoff v and mu read 0.996 against a floor of 0.49.
    g0 = cartan.SO3.exp([0.3, -0.2, 0.5])
    r = cartan.solve(cartan.RigidBody([1, 2, 3]), lam=0.5, T=1, N=50, g0=g0, gT=g0.copy(), method=method)
    assert r.status == "converged", r.message
    assert np.abs(np.asarray(r.v)).max() <= 1e-12
    assert _passes(r) == (True, [])


@pytest.mark.parametrize("lam", [0.0, 0.5])
@pytest.mark.parametrize("size", [1e-6, 1e-9])
def test_shootings_xi_of_a_short_path_is_right_to_its_own_size(size, lam):
    # xi's unit is floored at a speed of 1/T (so that Levenberg-Marquardt is well conditioned), so
    # LM met xi_N = 0 only to tol in that unit: for a rotation of 1e-6, xi ran from 0 to -2.6e-13
    # instead of from 2.6e-13 to 0. Newton steps then bring |xi_N| to tol times xi's own size.
    r = _small_rotation(cartan.RigidBody([1, 2, 3]), lam, size, "shooting")
    assert r.status == "converged", r.message
    xi = np.asarray(r.xi)
    own_size = np.linalg.norm(r.v0) * np.linalg.norm(np.asarray(r.mu)[0])  # T |v| |mu|, T = 1
    assert np.linalg.norm(xi[-1]) <= 10 * TOL * own_size
    assert np.linalg.norm(xi[0]) > 0.1 * own_size  # xi(0) = int ad*_v mu dt, of the size of |v| |mu| T
    assert _passes(r) == (True, [])
