"""Manifolds with a connection and cartan.solve_general (include/cartan/manifolds, kernels/manifold/) from Python:
geometry against closed forms, solutions against independent results, and errors.

Tolerances (theory):
* Geometry: closed forms evaluated in floating point: 1e-12 (finite-difference derivatives of the
  Christoffel map do not occur: every built-in manifold has them analytically).
* Spherical pendulum: with A = I and V = G z on S^2 the transported action is the classical one, so
  the discrete solution converges to the classical pendulum at the scheme's order; integrating the
  classical equation from q0 with the solver's q'(0) = frame0 @ v0 (solve_ivp, rtol 1e-12) misses qT
  by the scheme's error in v0: O(h^2) at order 2 (measured 3.9e-4 at N = 200, 9.6e-5 at N = 400: ratio
  4.00); the whole curve differs by as much (8.6e-5 at N = 400).
* SO(3), Cartan-Schouten lambda: solve_general runs the Lie-group kernel there, and the general
  scheme and the Lie-group lambda solver solve the same discrete equations
  (docs/general-connections.md#reduction): frame = P = Ad(h), C(Xi) = xi. Both stop at |r| <= 1e-12
  on a problem whose root has O(1) sensitivity, so they agree to ~1e-10 (measured 6e-15: both
  converge past tol; docs/design/lie-kernel.md §2.1 measured the frame against P and C(Xi) against xi
  to 3e-15 and 8e-15); asserted 1e-10.
* Energy 1/2 v.A v + V is conserved by the exact flow for every connection; the scheme's drift is
  O(h^p): the ratio at N and 2N is 2 at order 1 and 4 at order 2 (measured 2.00 and 4.00 on the
  anisotropic sphere A = diag(1, 3) from N = 150 to 1200; asserted within 15%).
* A Python potential computes the same numbers as the built-in gravity (G q[2] and its gradient),
  so the solutions agree to rounding: 1e-12.
"""
import os
import signal
import threading
import time

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.linalg import expm

import cartan
from cartan import Euclidean, GroupManifold, HyperbolicPlane, Sphere
from python_models import SphereKinetic

SO3 = cartan.SO3
A0, AT = np.array([-1.0, -1, -1]), np.array([0.9, 1.0, 1.0])
GT = SO3.minimal_rotation(A0, AT)
E3 = np.eye(3)


def minkowski(a, b):
    return a[0] * b[0] + a[1] * b[1] - a[2] * b[2]


# ---- geometry ----------------------------------------------------------------------------------

def test_sphere_geometry_closed_forms():
    s = Sphere()
    q = Sphere.point([0.3, -0.4, 0.8])
    e = s.tangent_basis(q)
    assert e.shape == (3, 2) and s.dim == 2 and s.ambient_dim == 3 and s.point_shape == (3,)
    np.testing.assert_allclose(e.T @ e, np.eye(2), atol=1e-14)
    np.testing.assert_allclose(q @ e, 0, atol=1e-14)
    x, y, z = e @ [0.7, -0.2], e @ [0.1, 0.5], e @ [-0.3, 0.4]
    np.testing.assert_allclose(s.christoffel(q, x, y), q * (x @ y), atol=1e-14)
    np.testing.assert_allclose(s.torsion(q, x, y), 0, atol=1e-14)
    np.testing.assert_allclose(s.curvature(q, x, y, z), (y @ z) * x - (x @ z) * y, atol=1e-14)  # K = 1
    p = s.step(q, x)
    assert np.linalg.norm(p) == pytest.approx(1, abs=1e-14)
    assert np.arccos(p @ q) == pytest.approx(np.linalg.norm(x), abs=1e-12)  # a great circle of length |x|
    np.testing.assert_allclose(s.difference(q, p), x, atol=1e-12)
    P = s.transport_along_step(q, x)
    np.testing.assert_allclose(P.T @ P, E3, atol=1e-13)  # a rotation
    a = np.linalg.norm(x)
    # The velocity of the geodesic is parallel along it.
    np.testing.assert_allclose(P @ x, np.cos(a) * x - a * np.sin(a) * q, atol=1e-12)
    np.testing.assert_allclose(P @ q, p, atol=1e-12)  # the rotation moves q to p
    R = s.curvature_components(q)
    assert R.shape == (2, 2, 2, 2)
    assert R[0, 1, 1, 0] == pytest.approx(1) and R[0, 1, 0, 1] == pytest.approx(-1)
    np.testing.assert_allclose(s.torsion_components(q), 0, atol=1e-14)
    np.testing.assert_allclose(s.metric(q), E3)
    assert s.has_parallel_torsion_and_curvature()


def test_hyperbolic_plane_geometry_closed_forms():
    h = HyperbolicPlane()
    q = HyperbolicPlane.point(0.3, -0.5)
    assert minkowski(q, q) == pytest.approx(-1, abs=1e-14)
    e = h.tangent_basis(q)
    gram = np.array([[minkowski(a, b) for b in e.T] for a in e.T])
    np.testing.assert_allclose(gram, np.eye(2), atol=1e-13)
    x, y, z = e @ [0.7, -0.2], e @ [0.1, 0.5], e @ [-0.3, 0.4]
    np.testing.assert_allclose(h.christoffel(q, x, y), -q * minkowski(x, y), atol=1e-14)
    np.testing.assert_allclose(h.curvature(q, x, y, z), -(minkowski(y, z) * x - minkowski(x, z) * y), atol=1e-13)
    p = h.step(q, x)
    assert minkowski(p, p) == pytest.approx(-1, abs=1e-12) and p[2] > 0
    assert np.arccosh(-minkowski(p, q)) == pytest.approx(np.sqrt(minkowski(x, x)), abs=1e-12)
    np.testing.assert_allclose(h.difference(q, p), x, atol=1e-12)
    assert h.curvature_components(q)[0, 1, 1, 0] == pytest.approx(-1)


def test_euclidean_christoffel_index_convention():
    rng = np.random.default_rng(3)
    gamma = rng.normal(scale=0.5, size=(3, 3, 3))  # gamma[k, i, j] = Gamma^k_ij
    r3 = Euclidean(gamma)
    assert r3.dim == 3 and r3.point_shape == (3,)
    np.testing.assert_array_equal(r3.christoffel_symbols, gamma)
    q = np.array([0.1, 0.2, 0.3])
    for i in range(3):
        for j in range(3):
            # nabla_{e_i} e_j = Gamma^k_ij e_k
            np.testing.assert_allclose(r3.christoffel(q, E3[i], E3[j]), gamma[:, i, j], atol=1e-15)
            np.testing.assert_allclose(r3.torsion(q, E3[i], E3[j]), gamma[:, i, j] - gamma[:, j, i], atol=1e-15)
    x = np.array([0.3, -0.1, 0.4])
    np.testing.assert_allclose(r3.transport_along_step(q, x), expm(-np.einsum("i,kij->kj", x, gamma)), atol=1e-13)
    np.testing.assert_allclose(r3.step(q, x), q + x)
    # R(x, y) z = Gamma(x, Gamma(y, z)) - Gamma(y, Gamma(x, z)) for constant symbols.
    G = lambda a, b: np.einsum("kij,i,j->k", gamma, a, b)  # noqa: E731
    y, z = np.array([1.0, 0, -1]), np.array([0.5, 2, 0])
    np.testing.assert_allclose(r3.curvature(q, x, y, z), G(x, G(y, z)) - G(y, G(x, z)), atol=1e-13)
    T = r3.torsion_components(q)  # T[i, j, k] = T_ij^k in the standard basis
    np.testing.assert_allclose(T, np.transpose(gamma - np.transpose(gamma, (0, 2, 1)), (1, 2, 0)), atol=1e-15)
    flat = Euclidean(dim=2)
    assert flat.dim == 2 and flat.has_parallel_torsion_and_curvature() and flat.metric([0, 0]) is None
    np.testing.assert_array_equal(flat.christoffel_symbols, np.zeros((2, 2, 2)))


def test_euclidean_takes_its_dimension_positionally():
    """Euclidean(m) is the flat R^m, Euclidean(dim=m): the integer was read as Christoffel symbols
    ("christoffel = array of shape () must have shape (2, 2, 2) or (3, 3, 3)")."""
    for m in (2, 3, np.int64(3)):
        flat = Euclidean(m)
        assert flat.dim == m and repr(flat) == f"Euclidean(dim={m})"
        np.testing.assert_array_equal(flat.christoffel_symbols, np.zeros((m, m, m)))


def test_group_manifold_alpha_index_convention_and_cartan_schouten():
    lam = 0.3
    cs = GroupManifold("so3", "cartan-schouten", lam=lam)
    assert cs.lam == lam and cs.group is SO3 and cs.point_shape == (3, 3) and cs.dim == 3
    g = SO3.exp([0.2, -0.4, 0.5])
    x, y, z = np.array([0.3, 0.1, -0.2]), np.array([-0.5, 0.4, 0.2]), np.array([0.1, 0.9, 0.3])
    np.testing.assert_allclose(cs.christoffel(g, x, y), lam * SO3.bracket(x, y), atol=1e-15)
    np.testing.assert_allclose(cs.torsion(g, x, y), (2 * lam - 1) * SO3.bracket(x, y), atol=1e-15)  # tor-cur-lie-alg
    np.testing.assert_allclose(cs.curvature(g, x, y, z), -lam * (1 - lam) * SO3.bracket(SO3.bracket(x, y), z),
                               atol=1e-15)
    np.testing.assert_allclose(cs.step(g, x), g @ SO3.exp(x), atol=1e-15)
    np.testing.assert_allclose(cs.difference(g, cs.step(g, x)), x, atol=1e-14)
    np.testing.assert_allclose(cs.transport_along_step(g, x), expm(-lam * SO3.ad(x)), atol=1e-14)
    assert cs.has_parallel_torsion_and_curvature()
    # alpha(e_i, e_j) = sum_k alpha[i, j, k] e_k: alpha[i, j, :] = lam [e_i, e_j].
    alpha = np.array([[lam * SO3.bracket(E3[i], E3[j]) for j in range(3)] for i in range(3)])
    np.testing.assert_allclose(cs.alpha, alpha, atol=1e-15)
    rng = np.random.default_rng(5)
    generic = rng.normal(size=(3, 3, 3))
    c = GroupManifold("so3", "coefficients", alpha=generic)
    np.testing.assert_array_equal(c.alpha, generic)
    for i in range(3):
        for j in range(3):
            np.testing.assert_allclose(c.christoffel(g, E3[i], E3[j]), generic[i, j], atol=1e-15)
    assert c.lam is None and not c.has_parallel_torsion_and_curvature()
    # The same connection given by its Connection object, or by the group class.
    via_object = GroupManifold(SO3, SO3.cartan_schouten(lam))
    np.testing.assert_allclose(via_object.alpha, alpha, atol=1e-15)
    np.testing.assert_allclose(via_object.connection.nabla(x, y), lam * SO3.bracket(x, y), atol=1e-15)


def test_levi_civita_of_a_bi_invariant_metric_is_cartan_schouten_one_half():
    lc = GroupManifold("so3", "levi-civita", metric=[1.0, 1.0, 1.0])
    np.testing.assert_allclose(lc.alpha, GroupManifold("so3", lam=0.5).alpha, atol=1e-15)
    np.testing.assert_allclose(lc.metric(E3), E3)
    anisotropic = GroupManifold("so3", "levi-civita", metric=np.diag([2.0, 3.0, 4.0]))
    assert not anisotropic.has_parallel_torsion_and_curvature()
    np.testing.assert_allclose(anisotropic.torsion(E3, [1, 0, 0], [0, 1, 0]), 0, atol=1e-15)  # Levi-Civita


@pytest.mark.parametrize("group", [cartan.Heisenberg, cartan.SE2, cartan.SE3])
def test_other_group_manifolds(group):
    gm = GroupManifold(group.name, "cartan-schouten", lam=0.5)
    assert gm.point_shape == group.element_shape and gm.dim == group.dim and gm.group is group
    rng = np.random.default_rng(1)
    g, x, y = group.exp(rng.normal(size=group.dim)), rng.normal(size=group.dim), rng.normal(size=group.dim)
    np.testing.assert_allclose(gm.step(g, x), group.compose(g, group.exp(x)), atol=1e-13)
    np.testing.assert_allclose(gm.torsion(g, x, y), 0, atol=1e-13)  # lam = 1/2
    np.testing.assert_allclose(gm.frame_bracket(x, y), group.bracket(x, y), atol=1e-14)


# ---- solve_general -----------------------------------------------------------------------------

def classical_pendulum_end(q0, velocity, G, T, t_eval=None):
    def f(_, y):
        q, p = y[:3], y[3:]
        return np.concatenate([p, -G * (np.array([0, 0, 1.0]) - q[2] * q) - (p @ p) * q])
    sol = solve_ivp(f, (0, T), np.concatenate([q0, velocity]), method="DOP853", rtol=1e-12, atol=1e-12,
                    t_eval=t_eval)
    assert sol.success
    return sol.y[:3].T


def test_spherical_pendulum_is_the_classical_one():
    G, T = 9.81, 1.0
    q0, qT = Sphere.point([1, 0, -0.3]), Sphere.point([0, 1, -0.5])
    miss, curve_gap = [], []
    for N in (200, 400):
        r = cartan.solve_general(Sphere(), T=T, N=N, q0=q0, qT=qT, gravity=G, order=2, tol=1e-12)
        assert r.converged and r.status == "converged", r.message
        assert r.q.shape == (N + 1, 3) and r.v.shape == (N + 1, 2) and r.frame.shape == (N + 1, 3, 2)
        assert r.Xi.shape == (N + 1, 2, 2) and r.terminal_error < 1e-10
        np.testing.assert_allclose(r.frame[0], Sphere().default_frame(q0, qT))
        np.testing.assert_allclose(r.t, np.linspace(0, T, N + 1), atol=1e-12)
        curve = classical_pendulum_end(q0, r.frame[0] @ r.v0, G, T, t_eval=np.linspace(0, T, N + 1))
        miss.append(np.linalg.norm(curve[-1] - qT))
        curve_gap.append(np.abs(curve - r.q).max())
    assert miss[1] < 2e-4 and curve_gap[1] < 2e-4
    assert miss[0] / miss[1] == pytest.approx(4.0, abs=0.8)
    assert curve_gap[0] / curve_gap[1] == pytest.approx(4.0, abs=0.8)


def aux_to_xi(manifold, Xi):
    """C(Xi)_i = sum_{k,n} Xi[k, n] [e_k, e_i]^n (docs/general-connections.md#reduction), row by row of Xi."""
    e = np.eye(manifold.dim)
    brackets = np.array([[manifold.frame_bracket(ek, ei) for ei in e] for ek in e])  # [k, i] = [e_k, e_i]
    return np.einsum("...kn,kin->...i", Xi, brackets)


@pytest.mark.parametrize("order", [1, 2])
def test_so3_cartan_schouten_equals_the_lambda_solver(order):
    """solve_general on GroupManifold("so3", "cartan-schouten", lam) runs the Lie-group kernel
    (include/cartan/methods/lie_group_as_manifold.hpp): its frame is the lambda solver's P = Ad(h) and C(Xi) its
    xi, and verify_general passes the result."""
    kwargs = dict(T=5.0, N=200, order=order, tol=1e-12, method="shooting")
    manifold = GroupManifold("so3", "cartan-schouten", lam=0.3)
    lie = cartan.solve(cartan.RigidBody([2.0, 3.0, 4.0]), lam=0.3, gT=GT, **kwargs)
    gen = cartan.solve_general(manifold, q0=np.eye(3), qT=GT, inertia=[2.0, 3.0, 4.0], **kwargs)
    assert lie.converged and gen.converged, (lie.message, gen.message)
    assert "Lie-group kernel" in gen.message and gen.method == "shooting"
    np.testing.assert_allclose(gen.v0, lie.v0, atol=1e-10)
    np.testing.assert_allclose(gen.q, lie.g, atol=1e-10)
    np.testing.assert_allclose(gen.v, lie.v, atol=1e-10)
    np.testing.assert_allclose(gen.mu, lie.mu, atol=1e-10)
    np.testing.assert_allclose(gen.t, lie.t, atol=1e-14)
    np.testing.assert_allclose(gen.frame, lie.P, atol=1e-10)
    np.testing.assert_allclose(aux_to_xi(manifold, gen.Xi), lie.xi, atol=1e-10)
    assert cartan.verify_general(gen, manifold, inertia=[2.0, 3.0, 4.0]).passed


@pytest.mark.parametrize("method, options", [("multiple-shooting", dict(segments=4)), ("two-level", {}),
                                             ("shooting", dict(continuation="lambda"))])
def test_the_lie_group_methods_are_the_kernels_on_cartan_schouten(method, options):
    """The Lie-group kernel's own methods through solve_general on GroupManifold("so3", lam): the
    nodes of cartan.solve by the same method (both stop at tol 1e-10 on the same discrete equations;
    the two-level scheme on the change of xi, hence 1e-7), the frame P and C(Xi) = xi rebuilt, and
    verify_general passes; on the sphere the same method is refused by name, and "variational" (the
    Lie-group solve's only) on every manifold."""
    kwargs = dict(T=3.0, N=100, method=method, **options)
    manifold = GroupManifold("so3", "cartan-schouten", lam=0.3)
    lie = cartan.solve(cartan.RigidBody([2.0, 3.0, 4.0]), lam=0.3, gT=GT, **kwargs)
    gen = cartan.solve_general(manifold, q0=np.eye(3), qT=GT, inertia=[2.0, 3.0, 4.0], **kwargs)
    assert lie.converged and gen.converged, (lie.message, gen.message)
    assert "Lie-group kernel" in gen.message and gen.method == lie.method == method
    atol = 1e-7 if method == "two-level" else 1e-8
    np.testing.assert_allclose(gen.q, lie.g, atol=atol)
    np.testing.assert_allclose(gen.mu, lie.mu, atol=atol)
    np.testing.assert_allclose(gen.frame, lie.P, atol=atol)
    np.testing.assert_allclose(aux_to_xi(manifold, gen.Xi[-1]), lie.xi[-1], atol=atol)
    assert cartan.verify_general(gen, manifold, inertia=[2.0, 3.0, 4.0]).passed
    with pytest.raises(ValueError, match="not available for a general connection|continuation = lambda"):
        cartan.solve_general(Sphere(), **{**SPHERE_ARGS, "method": method, **options})
    with pytest.raises(ValueError, match="the Lie-group solve only"):
        cartan.solve_general(manifold, q0=np.eye(3), qT=GT, T=3.0, N=100, method="variational")


def test_verify_is_one_entry_point_for_both_kinds_of_result():
    """cartan.verify checks a GeneralSolveResult on its manifold exactly as verify_general does (the
    same call underneath: every figure equal), a SolveResult as before, and names the keyword or the
    argument that belongs to the other kind."""
    manifold = GroupManifold("so3", "cartan-schouten", lam=0.3)
    kwargs = dict(T=3.0, N=100, tol=1e-10)
    gen = cartan.solve_general(manifold, q0=np.eye(3), qT=GT, inertia=[2.0, 3.0, 4.0], **kwargs)
    lie = cartan.solve(cartan.RigidBody([2.0, 3.0, 4.0]), lam=0.3, gT=GT, **kwargs)
    assert gen.converged and lie.converged
    one = cartan.verify(gen, manifold, inertia=[2.0, 3.0, 4.0])
    other = cartan.verify_general(gen, manifold, inertia=[2.0, 3.0, 4.0])
    assert one.passed and [c["figure"] for c in one.checks] == [c["figure"] for c in other.checks]
    sphere = cartan.solve_general(Sphere(), gravity=1.0, **SPHERE_ARGS)
    assert cartan.verify(sphere, Sphere(), gravity=1.0).passed
    assert cartan.verify(lie, cartan.RigidBody([2.0, 3.0, 4.0])).passed
    with pytest.raises(ValueError, match="inertia = .* applies to a manifold"):
        cartan.verify(lie, cartan.RigidBody([2.0, 3.0, 4.0]), inertia=[2.0, 3.0, 4.0])
    with pytest.raises(ValueError, match="RigidBody is not a manifold"):
        cartan.verify(gen, cartan.RigidBody([2.0, 3.0, 4.0]))
    with pytest.raises(ValueError, match="group = 'SO3' applies to a group model"):
        cartan.verify(gen, manifold, group="SO3", inertia=[2.0, 3.0, 4.0])


def test_solve_is_one_entry_point_for_both_kinds_of_problem():
    """cartan.solve on a manifold is solve_general (the same call underneath: every array equal), on a
    GroupManifold with Cartan-Schouten it reaches the Lie-group kernel by itself (the same nodes as the
    group model's solve, to the tolerance both stop at), and each kind's keywords are refused by name
    on the other, as cartan.verify does."""
    sphere = cartan.solve(Sphere(), gravity=1.0, **SPHERE_ARGS)
    same = cartan.solve_general(Sphere(), gravity=1.0, **SPHERE_ARGS)
    assert isinstance(sphere, cartan.GeneralSolveResult) and sphere.converged
    assert isinstance(sphere, cartan.Result)  # one result type: the fields every solve returns
    for name in ("t", "q", "frame", "v", "mu", "Xi"):
        np.testing.assert_array_equal(getattr(sphere, name), getattr(same, name))
    manifold = GroupManifold("so3", "cartan-schouten", lam=0.3)
    gen = cartan.solve(manifold, T=3.0, N=100, q0=np.eye(3), qT=GT, inertia=[2.0, 3.0, 4.0], tol=1e-10)
    lie = cartan.solve(cartan.RigidBody([2.0, 3.0, 4.0]), T=3.0, N=100, lam=0.3, gT=GT, tol=1e-10)
    assert gen.converged and lie.converged and "Lie-group kernel" in gen.message
    assert isinstance(lie, cartan.Result) and np.array_equal(gen.t, lie.t) and gen.N == lie.N
    np.testing.assert_allclose(gen.q, lie.g, atol=1e-8)  # both stop at tol 1e-10 on the same equations
    with pytest.raises(ValueError, match=r"^cartan\.solve: lam = 0\.3 applies to a group model's problem, not on "
                                         r"the manifold Sphere"):
        cartan.solve(Sphere(), lam=0.3, **SPHERE_ARGS)
    with pytest.raises(ValueError, match=r"^cartan\.solve: gT = array\(\[\[1\., 0\., 0\.\], \[0\., 1\."):
        cartan.solve(Sphere(), gT=np.eye(3), **SPHERE_ARGS)
    with pytest.raises(ValueError, match=r"^cartan\.solve: gravity = 1\.0 applies to a problem on a manifold"):
        cartan.solve(cartan.RigidBody([2.0, 3.0, 4.0]), T=3.0, N=100, lam=0.3, gT=GT, gravity=1.0)
    with pytest.raises(TypeError, match=r"^cartan\.solve: missing a required argument: 'gT'"):
        cartan.solve(cartan.RigidBody([2.0, 3.0, 4.0]), T=3.0, N=100, lam=0.3)
    swept = cartan.sweep([dict(lagrangian=Sphere(), **SPHERE_ARGS)])  # a sweep takes what cartan.solve takes
    np.testing.assert_array_equal(swept[0].q, cartan.solve(Sphere(), **SPHERE_ARGS).q)
    with pytest.raises(ValueError, match=r"^cartan\.sweep: problems\[0\]: cartan\.solve: q0 = .* applies to a problem "
                                         r"on a manifold"):
        cartan.sweep([dict(lagrangian=cartan.RigidBody([2.0, 3.0, 4.0]), T=3.0, N=100, lam=0.3, gT=GT, q0=np.eye(3))])
    with pytest.raises(TypeError, match=r"^cartan\.sweep: problems\[0\]: missing a required argument: 'lam'"):
        cartan.sweep([dict(lagrangian=cartan.RigidBody([2.0, 3.0, 4.0]), T=3.0, N=100, gT=GT)])


def sphere_energy(r, A, G):
    return 0.5 * np.einsum("ki,ij,kj->k", r.v, A, r.v) + G * r.q[:, 2]


@pytest.mark.parametrize("order", [1, 2])
def test_energy_is_conserved_at_the_schemes_order(order):
    A, G = np.diag([1.0, 3.0]), 2.0
    q0, qT = Sphere.point([1, 0, 0.2]), Sphere.point([0, 1, -0.3])
    drift = []
    for N in (300, 600):
        r = cartan.solve_general(Sphere(), T=1.5, N=N, q0=q0, qT=qT, inertia=A, gravity=G, order=order, tol=1e-12)
        assert r.converged, r.message
        e = sphere_energy(r, A, G)
        drift.append(np.abs(e - e[0]).max())
    assert drift[1] < 1e-2
    assert drift[0] / drift[1] == pytest.approx(2.0 ** order, rel=0.15), drift


def test_python_potential_equals_builtin_gravity():
    A, G = [1.0, 2.5], 3.0
    kwargs = dict(T=1.2, N=200, q0=Sphere.point([1, 0.2, 0.1]), qT=Sphere.point([-0.2, 1, -0.4]), inertia=A,
                  order=2, tol=1e-12)
    builtin = cartan.solve_general(Sphere(), gravity=G, **kwargs)
    python = cartan.solve_general(Sphere(), potential=lambda q: G * q[2],
                                  potential_gradient=lambda q: np.array([0, 0, G]), **kwargs)
    assert builtin.converged and python.converged
    np.testing.assert_allclose(python.v0, builtin.v0, atol=1e-12)
    np.testing.assert_allclose(python.q, builtin.q, atol=1e-12)
    # Without gravity the solution differs: the potential is really used.
    free = cartan.solve_general(Sphere(), **kwargs)
    assert np.abs(free.v0 - builtin.v0).max() > 1e-2


def test_python_lagrangian_object_equals_kinetic_potential():
    A, G = np.diag([1.0, 2.5]), 3.0
    kwargs = dict(T=1.2, N=150, q0=Sphere.point([1, 0.2, 0.1]), qT=Sphere.point([-0.2, 1, -0.4]), tol=1e-12)
    builtin = cartan.solve_general(Sphere(), inertia=A, gravity=G, **kwargs)
    python = cartan.solve_general(Sphere(), lagrangian=SphereKinetic(A, G), **kwargs)
    assert builtin.converged and python.converged
    np.testing.assert_allclose(python.v0, builtin.v0, atol=1e-12)
    np.testing.assert_allclose(python.Xi0, builtin.Xi0, atol=1e-10)


def test_a_lagrangian_whose_velocity_does_not_invert_its_momentum_is_refused():
    """The schemes recover v from mu with `velocity` at every step: a Python Lagrangian whose
    velocity is off (here by 1e-4) would converge to a wrong answer, so it is refused first."""
    class Broken(SphereKinetic):
        def velocity(self, t, q, mu):
            return super().velocity(t, q, mu) + np.array([1e-4, 0.0])

    kwargs = dict(T=1.2, N=50, q0=Sphere.point([1, 0.2, 0.1]), qT=Sphere.point([-0.2, 1, -0.4]))
    with pytest.raises(ValueError, match="lagrangian .* does not invert its momentum"):
        cartan.solve_general(Sphere(), lagrangian=Broken(np.eye(2), 3.0), **kwargs)
    assert cartan.solve_general(Sphere(), lagrangian=SphereKinetic(np.eye(2), 3.0), **kwargs).converged


def test_flat_plane_gives_newtons_equations():
    """R^2, Gamma = 0, l = 1/2 |v|^2 - k/2 |q|^2: q(t) = q0 cos wt + c sin wt, v0 = w c exactly;
    the scheme of order 2 reaches it at O(h^2)."""
    k, T = 2.0, 1.3
    w = np.sqrt(k)
    q0, qT = np.array([0.4, -0.2]), np.array([-0.3, 0.5])
    exact = w * (qT - q0 * np.cos(w * T)) / np.sin(w * T)
    errors = []
    for N in (200, 400):
        r = cartan.solve_general(Euclidean(dim=2), T=T, N=N, q0=q0, qT=qT, potential=lambda q: 0.5 * k * q @ q,
                                 potential_gradient=lambda q: k * q, order=2, tol=1e-13)
        assert r.converged, r.message
        errors.append(np.linalg.norm(r.v0 - exact))
    assert errors[1] < 1e-4 and errors[0] / errors[1] == pytest.approx(4.0, rel=0.15)


def test_geodesic_of_the_hyperbolic_plane():
    """A = I, V = 0 on H^2: the solution is the geodesic (the curvature term vanishes on Xi ~ v v^T),
    so v is constant and equals the geodesic guess."""
    h = HyperbolicPlane()
    q0, qT = HyperbolicPlane.point(0.2, -0.1), HyperbolicPlane.point(-0.8, 0.6)
    r = cartan.solve_general(h, T=2.0, N=100, q0=q0, qT=qT, tol=1e-12)
    assert r.converged, r.message
    np.testing.assert_allclose(r.v, np.broadcast_to(r.v0, r.v.shape), atol=1e-10)
    u = r.frame[0] @ r.v0
    assert np.sqrt(minkowski(u, u)) * 2.0 == pytest.approx(np.arccosh(-minkowski(q0, qT)), abs=1e-10)
    np.testing.assert_allclose(r.q[50], h.step(q0, u), atol=1e-10)  # the midpoint of the geodesic


def test_guess_frame_and_progress():
    q0, qT = Sphere.point([1, 0, -0.3]), Sphere.point([0, 1, -0.5])
    seen = []
    r = cartan.solve_general(Sphere(), T=1.0, N=100, q0=q0, qT=qT, gravity=9.81, tol=1e-12,
                             progress=lambda stage, it, res: seen.append((stage, it, res)))
    # The default strategy's first step reports as the Lie-group solve's does (solvers/strategy.hpp).
    assert r.converged and seen and seen[0][0] == "shooting"
    again = cartan.solve_general(Sphere(), T=1.0, N=100, q0=q0, qT=qT, gravity=9.81, tol=1e-12, method="shooting",
                                 v0=r.v0, Xi0=r.Xi0)
    assert again.converged and again.iterations <= 2 and again.branch == "direct from the given guess"
    # Another frame: v0 are components in it, the curve is the same.
    e = Sphere().tangent_basis(q0)
    frame0 = e @ np.array([[0.0, 2.0], [1.0, 0.0]])
    # With inertia F^T F = diag(1, 4) in these components, l is the same function of q' (transport is an
    # isometry), so the curve is the same.
    other = cartan.solve_general(Sphere(), T=1.0, N=100, q0=q0, qT=qT, gravity=9.81, tol=1e-12, frame0=frame0,
                                 inertia=[1.0, 4.0])
    assert other.converged
    np.testing.assert_allclose(other.q, r.q, atol=1e-9)
    np.testing.assert_allclose(frame0 @ other.v0, r.frame[0] @ r.v0, atol=1e-9)  # the same q'(0)


def test_failed_solve_reports_its_status():
    r = cartan.solve_general(Sphere(), T=1.0, N=100, q0=Sphere.point([1, 0, -0.3]), qT=Sphere.point([0, 1, -0.5]),
                             gravity=9.81, tol=1e-12, method="shooting", max_iterations=1)
    assert not r.converged and not r.success
    assert r.status != "converged" and r.status in cartan.STATUSES
    assert r.terminal_error > 1e-12


# ---- errors ------------------------------------------------------------------------------------

SPHERE_ARGS = dict(T=1.0, N=20, q0=[0, 0, 1.0], qT=Sphere.point([1, 0, 1]))


@pytest.mark.parametrize("make, words", [
    (lambda: cartan.solve_general(Sphere(), **{**SPHERE_ARGS, "q0": [1.0, 1, 1]}), ["q0", "not on the unit sphere"]),
    (lambda: cartan.solve_general(Sphere(), potential=lambda q: q[2], **SPHERE_ARGS),
     ["potential_gradient", "both or neither"]),
    (lambda: cartan.solve_general(Sphere(), potential_gradient=lambda q: q, **SPHERE_ARGS), ["potential = None"]),
    (lambda: cartan.solve_general(Sphere(), potential=1.0, potential_gradient=lambda q: q, **SPHERE_ARGS),
     ["potential = 1.0 is not callable"]),
    (lambda: cartan.solve_general(Sphere(), inertia=[1.0, 2, 3], **SPHERE_ARGS), ["inertia", "(3,)", "(2, 2) or (2,)"]),
    (lambda: cartan.solve_general(Sphere(), inertia=[1.0, -1], **SPHERE_ARGS), ["inertia", "positive definite"]),
    (lambda: cartan.solve_general(Sphere(), gravity=1.0, lagrangian=SphereKinetic(np.eye(2), 1), **SPHERE_ARGS),
     ["gravity", "lagrangian"]),
    (lambda: cartan.solve_general(Sphere(), lagrangian=object(), **SPHERE_ARGS), ["has no method value"]),
    (lambda: cartan.solve_general(Sphere(), gravity="strong", **SPHERE_ARGS), ["gravity", "not a number"]),
    (lambda: cartan.solve_general(Sphere(), gravity=np.inf, **SPHERE_ARGS), ["gravity = inf"]),
    (lambda: cartan.solve_general(Sphere(), v0=[0.0, 0, 0], **SPHERE_ARGS), ["v0", "(2,)"]),
    (lambda: cartan.solve_general(Sphere(), Xi0=np.full((2, 2), np.nan), **SPHERE_ARGS), ["Xi0"]),
    (lambda: cartan.solve_general(Sphere(), method="two-level", **SPHERE_ARGS),
     ["two-level", "not available for a general connection"]),
    (lambda: cartan.solve_general(Sphere(), method="nope", **SPHERE_ARGS), ["method", "nope"]),
    (lambda: cartan.solve_general(Sphere(), order=3, **SPHERE_ARGS), ["order = 3"]),
    (lambda: cartan.solve_general(Sphere(), frame0=[[1.0, 0], [0, 0], [0, 1]], **SPHERE_ARGS), ["frame0", "tangent"]),
    (lambda: cartan.solve_general(Sphere(), **{**SPHERE_ARGS, "T": -1.0}), ["T = -1"]),
    (lambda: cartan.solve_general(GroupManifold("so3", lam=0.5), gravity=1.0, T=1.0, N=10, q0=np.eye(3), qT=np.eye(3)),
     ["gravity", "the sphere, the hyperbolic plane and Euclidean space only"]),
    (lambda: cartan.solve_general("sphere", **SPHERE_ARGS), ["manifold", "is not a manifold"]),
    (lambda: cartan.solve_general(GroupManifold("so3", lam=0.5), T=1.0, N=10, q0=np.ones((3, 3)), qT=np.eye(3)),
     ["q0", "orthogonal"]),
    (lambda: GroupManifold("so3", "affine"), ["connection", "affine", "cartan-schouten"]),
    (lambda: GroupManifold("so4", lam=0.5), ["group", "so4"]),
    (lambda: GroupManifold("so3"), ["lam = None", "must be given"]),
    (lambda: GroupManifold("so3", lam="half"), ["lam", "not a number"]),
    (lambda: GroupManifold("so3", lam=np.nan), ["lam = nan"]),
    (lambda: GroupManifold("so3", lam=0.5, metric=[1, 1, 1]), ["metric", "does not apply"]),
    (lambda: GroupManifold("so3", "levi-civita", metric=[1.0, -1, 1]), ["metric", "positive definite"]),
    (lambda: GroupManifold("so3", "coefficients", alpha=np.zeros((3, 3))), ["alpha", "(3, 3, 3)"]),
    (lambda: GroupManifold("so3", SO3.cartan_schouten(0.5, side="right")), ["right"]),
    (lambda: Euclidean(np.zeros((4, 4, 4))), ["christoffel", "(2, 2, 2) or (3, 3, 3)"]),
    (lambda: Euclidean(), ["dim = None"]),
    (lambda: Euclidean(dim=2.5), ["dim", "not an integer"]),
    (lambda: Euclidean(np.zeros((2, 2, 2)), dim=3), ["dim = 3", "does not match"]),
    (lambda: Euclidean(2, dim=3), ["dim = 3", "is given twice", "Euclidean(2) is Euclidean(dim=2)"]),
    (lambda: Euclidean(4), ["dim = 4", "must be 2 or 3"]),
    (lambda: Sphere().torsion([1.0, 1, 0], [0, 0, 1], [0, 1, 0]), ["not on the unit sphere"]),
    (lambda: Sphere().step([1.0, 0, 0], [0, np.nan, 1]), ["x", "finite"]),
])
def test_bad_input_raises_value_error_naming_the_value(make, words):
    with pytest.raises(ValueError) as error:
        make()
    for word in words:
        assert word in str(error.value), str(error.value)


def test_callback_errors_are_reraised_unchanged():
    class Boom(Exception):
        pass

    def V(q):
        return q[2]

    def gradient(q):
        raise Boom("from the gradient")

    with pytest.raises(Boom, match="from the gradient"):
        cartan.solve_general(Sphere(), potential=V, potential_gradient=gradient, **SPHERE_ARGS)

    class BadMomentum(SphereKinetic):
        def momentum(self, t, q, v):
            return np.zeros(3)  # wrong shape

    with pytest.raises(ValueError, match=r"Lagrangian.momentum: return value .* must have shape \(2,\)"):
        cartan.solve_general(Sphere(), lagrangian=BadMomentum(np.eye(2), 1.0), **SPHERE_ARGS)

    def progress(stage, iteration, residual):
        raise Boom("from progress")

    with pytest.raises(Boom, match="from progress"):
        cartan.solve_general(Sphere(), gravity=1.0, progress=progress, **SPHERE_ARGS)


def test_ctrl_c_interrupts_a_solve_that_runs_without_the_gil():
    """A built-in model runs without the GIL, so the timer thread can send SIGINT during the solve, and
    the monitor's stop check raises KeyboardInterrupt within one iteration. (This solve runs ~6 s to
    "stalled" uninterrupted; were the GIL held, the timer could only fire after it.)"""
    timer = threading.Timer(0.3, os.kill, (os.getpid(), signal.SIGINT))
    start = time.perf_counter()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            cartan.solve_general(Sphere(), T=1.0, N=200000, q0=Sphere.point([1, 0, -0.3]),
                                 qT=Sphere.point([0, 1, -0.5]), gravity=9.81, tol=2.3e-14, method="shooting",
                                 max_iterations=100000)
    finally:
        timer.cancel()
    assert time.perf_counter() - start < 3


@pytest.mark.parametrize("manifold, q0, qT", [
    (Sphere(), [0, 0, 1], [0, 0, -1]),  # the antipode: the cut locus of q0
    (Sphere(), [0.6, 0, 0.8], [-0.6, 1e-9, -0.8]),  # next to it
    (GroupManifold("so3", "levi-civita", metric=[1, 2, 3]), np.eye(3), np.diag([1.0, -1, -1])),  # a rotation by pi
    (GroupManifold("se2", "cartan-schouten", lam=0.5), np.eye(3), np.array([[-1.0, 0, 1], [0, -1, 0.5], [0, 0, 1]])),
], ids=["antipode", "near-antipode", "so3-pi", "se2-pi"])
@pytest.mark.parametrize("options", [{}, {"gravity": 9.81}, {"inertia": "anisotropic"}, {"method": "collocation"}],
                         ids=["free", "gravity", "inertia", "collocation"])
def test_endpoints_on_the_cut_locus_never_give_a_wrong_convergence(manifold, q0, qT, options):
    """Issue 29: the sphere's difference(q0, qT) was 0 at antipodal points, so a solve that stayed at
    q0 reported converged and verify_general passed it. Whatever the solver does there, a converged
    result, and a result the verifier passes, ends at qT in the embedding (the point's storage):
    within 100 tol (the length of the logarithm bounds the storage distance up to the embedding's
    Lipschitz constant, at most 2 here)."""
    options = dict(options)
    if options.get("gravity") and not isinstance(manifold, Sphere):
        pytest.skip("gravity is the sphere's")
    if options.get("inertia") == "anisotropic":
        options["inertia"] = np.linspace(1, 3, manifold.dim)
    if options.get("method") == "collocation":
        options["samples"] = 101  # uniform samples, which the verifier needs
    q0, qT = np.asarray(q0, dtype=float), np.asarray(qT, dtype=float)
    if isinstance(manifold, Sphere):
        q0, qT = Sphere.point(q0), Sphere.point(qT)
    tol = 1e-10
    if "inertia" in options and isinstance(manifold, Sphere) and np.linalg.norm(q0 + qT) == 0:
        # At the antipode the default frame's e1 (towards qT) is undefined and an anisotropic inertia
        # sees the frame: the problem is not defined without frame0, and the solve says so.
        with pytest.raises(ValueError, match=r"q0/qT = .* are antipodal: .* give frame0"):
            cartan.solve_general(manifold, T=1, N=100, q0=q0, qT=qT, tol=tol, **options)
        options["frame0"] = manifold.tangent_basis(q0)
    r = cartan.solve_general(manifold, T=1, N=100, q0=q0, qT=qT, tol=tol, **options)
    checks = {k: v for k, v in options.items() if k in ("gravity", "inertia")}
    passed = len(r.t) >= 3 and cartan.verify_general(r, manifold, **checks).passed
    miss = np.linalg.norm(r.q[-1] - qT) if len(r.t) else np.inf
    if r.success or passed:
        assert miss <= 100 * tol, (r.status, r.message, miss)
    else:
        assert r.status != "converged"


class FrameInvariantSphereKinetic(SphereKinetic):
    """SphereKinetic saying that it does not depend on the frame (true for A = c I)."""
    frame_invariant = True


class FrameInvariantByMethod(SphereKinetic):
    def frame_invariant(self):
        return True


class FrameDependent(SphereKinetic):
    frame_invariant = False


def test_a_python_lagrangian_may_say_it_does_not_depend_on_the_frame():
    """At equal endpoints the default frame's e1 is undefined and the fallback frame serves only a
    Lagrangian that does not depend on the frame. The built-in particle with A = I says so; a
    Lagrangian written in Python is taken to depend on it unless its `frame_invariant` (an attribute
    or a method) is True. It was refused whatever it declared."""
    q0 = Sphere.point([1, 0, -0.3])
    kwargs = dict(space=Sphere(), q0=q0, qT=q0, T=1.0, N=50)
    builtin = cartan.solve(gravity=9.81, **kwargs)
    assert builtin.converged, builtin.message
    for declared in (FrameInvariantSphereKinetic(np.eye(2), 9.81), FrameInvariantByMethod(np.eye(2), 9.81)):
        r = cartan.solve(declared, **kwargs)
        assert r.converged, r.message
        np.testing.assert_allclose(r.v0, builtin.v0, atol=1e-8)  # the same problem, the same frame
        np.testing.assert_array_equal(r.frame[0], Sphere().tangent_basis(q0))
    for undeclared in (SphereKinetic(np.eye(2), 9.81), FrameDependent(np.eye(2), 9.81)):
        with pytest.raises(ValueError, match=r"q0/qT = .* are equal: .* give frame0"):
            cartan.solve(undeclared, **kwargs)


# ---- verify_general -----------------------------------------------------------------------------

def test_verify_general_passes_honest_results_and_fails_another_problem():
    """The library's general verifier (include/cartan/kernels/manifold/verify.hpp) from Python: a sphere
    result passes at both orders; the same data under another gravity fail; a Python-callable
    potential is checked like the built-in one; a failed solve fails."""
    sphere = cartan.Sphere()
    q0, qT = cartan.Sphere.point([1, 0, 0.2]), cartan.Sphere.point([0, 1, -0.3])
    for order in (1, 2):
        r = cartan.solve_general(sphere, T=1.2, N=300, q0=q0, qT=qT, inertia=[1, 2.5], gravity=3.0, order=order)
        assert r.converged
        report = cartan.verify_general(r, sphere, inertia=[1, 2.5], gravity=3.0)
        assert report.passed and report.verdict == "PASS", report.text
        assert not cartan.verify_general(r, sphere, inertia=[1, 2.5], gravity=3.5).passed
        same = cartan.verify_general(r, sphere, inertia=[1, 2.5], potential=lambda q: 3.0 * q[2],
                                     potential_gradient=lambda q: np.array([0, 0, 3.0]))
        assert same.passed and [c["figure"] for c in same.checks] == [c["figure"] for c in report.checks]
    failed = cartan.solve_general(sphere, T=1.2, N=300, q0=q0, qT=qT, inertia=[1, 2.5], gravity=3.0, method="shooting",
                                  max_iterations=1)
    assert not failed.converged
    assert not cartan.verify_general(failed, sphere, inertia=[1, 2.5], gravity=3.0).passed


def test_verify_general_on_a_group_connection():
    gT = cartan.SO3.minimal_rotation([-1, -1, -1], [0.9, 1, 1])
    lc = cartan.GroupManifold("so3", "levi-civita", metric=[1, 2, 3])
    r = cartan.solve_general(lc, T=3, N=200, q0=np.eye(3), qT=gT, inertia=[2, 3, 4], order=2)
    assert r.converged
    assert cartan.verify_general(r, lc, inertia=[2, 3, 4]).passed
    other = cartan.GroupManifold("so3", "cartan-schouten", lam=0.3)
    assert not cartan.verify_general(r, other, inertia=[2, 3, 4]).passed
    with pytest.raises(ValueError, match="has no field"):
        cartan.verify_general(object(), lc, inertia=[2, 3, 4])


# ---- collocation ----------------------------------------------------------------------------------

def test_collocation_is_the_classical_pendulum_and_restarts_from_a_result():
    """method="collocation": the continuous system to tol (relative residual 1e-10), so SciPy's
    pendulum from (q0, E0 v0) reaches qT to ~1e-9 (the order-2 scheme at N = 400: 1e-5). A result
    given as `guess` starts it again (one Newton iteration); verify_general passes the samples."""
    sphere, G, T = Sphere(), 9.81, 1.0
    q0, qT = Sphere.point([1, 0, -0.3]), Sphere.point([0, 1, -0.5])
    r = cartan.solve_general(sphere, T=T, N=40, q0=q0, qT=qT, gravity=G, method="collocation", continuation="T",
                             tol=1e-10, samples=101)
    assert r.converged and r.method == "collocation" and r.order == 4, r.message
    assert r.mesh_size >= 41 and r.max_residual <= 1e-10 and r.t.shape == (101,)
    assert np.linalg.norm(classical_pendulum_end(q0, r.frame[0] @ r.v0, G, T)[-1] - qT) < 1e-8
    again = cartan.solve_general(sphere, T=T, N=40, q0=q0, qT=qT, gravity=G, method="collocation", tol=1e-10,
                                 guess=r)
    assert again.converged and again.branch == "from the given trajectory"
    np.testing.assert_allclose(again.v0, r.v0, atol=1e-9)
    assert cartan.verify_general(r, sphere, gravity=G).passed
    shooting = cartan.solve_general(sphere, T=T, N=40, q0=q0, qT=qT, gravity=G)
    assert shooting.mesh_size is None and shooting.max_residual is None
    with pytest.raises(ValueError, match="guess"):
        cartan.solve_general(sphere, T=T, N=40, q0=q0, qT=qT, method="collocation", guess=object())
    with pytest.raises(ValueError, match="samples"):
        cartan.solve_general(sphere, T=T, N=40, q0=q0, qT=qT, samples=5)


# ---- a manifold of your own: Chart ---------------------------------------------------------------

def half_plane_christoffel(q):
    """The Poincare half-plane's Levi-Civita symbols, christoffel[k, i, j] = Gamma^k_ij (nan for y <= 0)."""
    y = q[1] if q[1] > 0 else np.nan
    g = np.zeros((2, 2, 2))
    g[0, 0, 1] = g[0, 1, 0] = g[1, 1, 1] = -1 / y
    g[1, 0, 0] = 1 / y
    return g


def test_chart_half_plane_geometry_and_geodesics():
    """A Chart from Python callables: curvature -1 from Gamma alone (central-difference D Gamma),
    transport preserves the metric, and the geodesic problem (l = 1/2 |v|^2 in a g-orthonormal
    frame) has |v0| = d(q0, qT) / T, d the closed-form hyperbolic distance: by collocation to its
    tolerance, by order-2 shooting to O(h^2); verify_general passes the collocation result."""
    half = cartan.Chart(half_plane_christoffel, dim=2, metric=lambda q: np.eye(2) / q[1] ** 2, name="half-plane",
                        parallel=True)  # constant curvature: nabla R = 0 (the solver's fast path)
    assert half.name == "half-plane" and half.dim == 2 and half.point_shape == (2,)
    q, x, y = np.array([0.3, 0.7]), np.array([0.4, -0.2]), np.array([0.1, 0.5])
    g = half.metric(q)
    area2 = (x @ g @ x) * (y @ g @ y) - (x @ g @ y) ** 2
    assert x @ g @ half.curvature(q, x, y, y) / area2 == pytest.approx(-1.0, abs=1e-6)
    P = half.transport_along_step(q, np.array([0.2, 0.3]))
    np.testing.assert_allclose(P.T @ half.metric(q + [0.2, 0.3]) @ P, g, atol=1e-10)

    q0, qT, T = np.array([-0.5, 0.8]), np.array([1.2, 1.6]), 2.0
    d = np.arccosh(1 + np.sum((qT - q0) ** 2) / (2 * q0[1] * qT[1]))
    frame0 = q0[1] * np.eye(2)
    c = cartan.solve_general(half, T=T, N=20, q0=q0, qT=qT, frame0=frame0, method="collocation", tol=1e-10,
                             samples=81)
    assert c.converged, c.message
    assert np.linalg.norm(c.v0) == pytest.approx(d / T, abs=1e-8)
    errors = []
    for N in (100, 200):
        s = cartan.solve_general(half, T=T, N=N, q0=q0, qT=qT, frame0=frame0, order=2, tol=1e-12)
        assert s.converged, s.message
        errors.append(abs(np.linalg.norm(s.v0) - d / T))
    assert errors[0] / errors[1] == pytest.approx(4.0, abs=0.6)
    assert cartan.verify_general(c, half).passed


def test_chart_callback_errors_and_bad_input():
    calls = []

    def broken(q):
        calls.append(1)
        if len(calls) > 50:
            raise ArithmeticError("boom")
        return half_plane_christoffel(q)

    # An exception in a chart's field during a solve marks the point outside the chart, as NaN does
    # (the documented rule): the solve fails with a status and names the first one; outside a solve
    # every exception passes through.
    chart = cartan.Chart(broken, dim=2)
    r = cartan.solve(chart, T=1.0, N=20, q0=[0, 1.0], qT=[1, 1.0], method="shooting")
    assert not r.converged and "Chart.christoffel raised ArithmeticError" in r.message and "boom" in r.message
    with pytest.raises(ArithmeticError, match="boom"):
        chart.christoffel([0, 1.0], [1, 0], [0, 1])
    calls.clear()
    assert chart.christoffel([0, 1.0], [1, 0], [0, 1]).shape == (2,)  # usable again after the failed solve
    with pytest.raises(ValueError, match="outside the chart"):
        cartan.Chart(half_plane_christoffel, dim=2).validate([0.0, -1.0])
    with pytest.raises(ValueError, match="dim = 4"):
        cartan.Chart(half_plane_christoffel, dim=4)
    with pytest.raises(ValueError, match="not callable"):
        cartan.Chart(np.zeros((2, 2, 2)), dim=2)
    with pytest.raises(ValueError, match=r"\(2, 2, 2\)"):
        cartan.Chart(lambda q: np.zeros((3, 3, 3)), dim=2).christoffel([0, 1.0], [1, 0], [0, 1])


# ---- Dense output ------------------------------------------------------------------------------

def test_sol_of_the_free_particle_runs_the_great_circle_with_its_frame():
    # l = 1/2 |v|^2 on S^2 without gravity: q(t) = cos(w t) q0 + sin(w t) e1, w = angle / T, and the
    # frame parallel along the great circle: e1(t) = q'(t) / w, e2 = q0 x e1 fixed. The library's
    # pieces are great circles, so sol is exact between nodes too (rounding: 1e-14; the solve: 1e-10).
    q0, qT = np.array([1.0, 0, 0]), np.array([0, 0.6, 0.8])
    r = cartan.solve_general(Sphere(), T=2.0, N=20, q0=q0, qT=qT, tol=1e-12)
    assert r.success, r.message
    w = np.pi / 2 / r.T
    d = qT  # the unit tangent at q0 towards qT (q0 . qT = 0 here); n = q0 x d is normal to the circle
    n = np.cross(q0, d)
    frame0 = r.frame[0]  # tangent_basis(q0), orthonormal: each column's parts along d and n
    along, normal = d @ frame0, n @ frame0
    times = np.linspace(0, r.T, 77)
    s = r.sol(times)
    for t, q, frame in zip(times, s.q, s.frame):
        assert np.allclose(q, np.cos(w * t) * q0 + np.sin(w * t) * d, atol=1e-10)
        tangent = -np.sin(w * t) * q0 + np.cos(w * t) * d
        assert np.allclose(frame, np.outer(tangent, along) + np.outer(n, normal), atol=1e-10)
    assert np.allclose(s.v, w * along, atol=1e-10)  # the velocity w d in the components of frame0
    one = r.sol(r.t[3])
    assert one.q.shape == (3,) and np.array_equal(one.q, r.q[3]) and np.array_equal(one.Xi, r.Xi[3])
    with pytest.raises(ValueError, match="outside"):
        r.sol(r.T * (1 + 1e-9))


def test_sol_of_a_general_collocation_result_has_scipys_splines():
    # v and mu by the library's not-a-knot splines: SciPy's CubicSpline through the same nodes
    # gives the same cubics (to the rounding of two tridiagonal solves, 1e-12).
    from scipy.interpolate import CubicSpline
    r = cartan.solve_general(Sphere(), method="collocation", gravity=1.0, **SPHERE_ARGS)
    assert r.success, r.message
    points = np.linspace(0, r.T, 123)
    s = r.sol(points)
    assert np.max(np.abs(s.v - CubicSpline(r.t, r.v, axis=0)(points))) < 1e-12
    assert np.max(np.abs(s.mu - CubicSpline(r.t, r.mu, axis=0)(points))) < 1e-12
    assert np.allclose(np.linalg.norm(s.q, axis=1), 1, atol=1e-14)  # on the sphere


def test_a_group_manifold_pickles_with_its_connection():
    """Issue 44 (found by a new-user trial): GroupManifold did not pickle, so its results lost their
    space (r.lam, r.connection, r.group None; cartan.verify refused them) and cartan.sweep on
    processes refused its problems. It pickles as its constructor's arguments: the connection
    comes back the same, bit for bit, with its kind (the kernel it chooses)."""
    import pickle
    rng = np.random.default_rng(7)
    for group, connection, parameter in [("so3", "cartan-schouten", dict(lam=0.3)), ("se2", "levi-civita", dict(metric=[1, 2, 3])),
                                         ("heisenberg", "coefficients", dict(alpha=rng.normal(size=(3, 3, 3)))),
                                         ("se3", "cartan-schouten", dict(lam=0.0))]:
        space = cartan.GroupManifold(group, connection, **parameter)
        back = pickle.loads(pickle.dumps(space))
        assert repr(back) == repr(space) and back.lam == space.lam and np.array_equal(back.alpha, space.alpha)
        e = space.group.identity()
        assert (back.metric(e) is None) == (space.metric(e) is None)
    gT = cartan.SO3.exp([0.4, -0.9, 1.1])
    r = cartan.solve(cartan.GroupManifold("so3", "cartan-schouten", lam=0.3), T=2, N=50, q0=np.eye(3), qT=gT,
                     inertia=[1.5, 2.5, 5])
    back = pickle.loads(pickle.dumps(r))
    assert (back.lam, back.connection, back.group) == (0.3, "cartan-schouten", r.group) and cartan.verify(back).passed
    with pytest.raises(ValueError, match="pickled state"):
        cartan.GroupManifold.__new__(cartan.GroupManifold).__setstate__(("so3", "levi-civita"))


def test_a_general_result_pickles_with_its_manifold_when_it_pickles():
    # A result travels (pickle, processes) with its arrays and its problem; a manifold that pickles
    # (the sphere) travels with it, one built from Python callbacks that do not (a Chart of a lambda)
    # stays behind: sol then asks for it by name.
    import pickle
    r = cartan.solve(Sphere(), gravity=1.0, **SPHERE_ARGS)
    back = pickle.loads(pickle.dumps(r))
    assert isinstance(back.space, Sphere) and np.array_equal(back.q, r.q) and back.status == r.status
    assert np.array_equal(back.sol(0.5).q, r.sol(0.5).q) and cartan.verify(back).passed
    chart = cartan.Chart(lambda q: np.zeros((2, 2, 2)), dim=2)
    c = cartan.solve(chart, T=1.0, N=10, q0=[0.0, 0.0], qT=[1.0, 0.5])
    back = pickle.loads(pickle.dumps(c))
    assert back.space is None and c.space is not None and np.array_equal(back.q, c.q)
    with pytest.raises(ValueError, match="space = None"):
        back.sol(0.5)
    back.space = chart
    assert np.array_equal(back.sol(0.5).q, c.sol(0.5).q)
