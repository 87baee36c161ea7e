"""Cartan-Schouten connections and parallel transport against closed forms and SciPy.

Torsion and curvature: (tor-cur-lie-alg) T(v, w) = (2 lam - 1)[v, w], R(u, v)w =
lam (lam - 1)[[u, v], w], for the left (CS-conn) and right (CS-conn-right) descriptions alike,
with brackets from matrix commutators (independent of cartan's ad). Both sides are a handful of
products of O(1) numbers: tolerance 1e-12.

Transport (cor-parr, parr-tran-Cartan-lambda): for constant u the ordered exponential is
expm(-lam T ad_u) exactly (every method is exact for a constant generator), so 1e-12; for a
time-varying u the reference is SciPy's solve_ivp at rtol 1e-12 and Magnus4 with 200 steps has
error ~ C h^4 ~ 1e-9 (h = 1/200), checked at 1e-8, and its measured order must be ~4."""
import numpy as np
import pytest
import scipy.integrate
import scipy.linalg

import cartan

LAMBDAS = (0.0, 0.25, 0.5, 1.0, 1.7)


def commutator_bracket(group, u, v):
    hu, hv = group.hat(u), group.hat(v)
    return group.vee(hu @ hv - hv @ hu)


@pytest.mark.parametrize("group", cartan.GROUPS, ids=lambda g: g.name)
@pytest.mark.parametrize("side", ["left", "right"])
def test_torsion_and_curvature_closed_forms(group, side):
    rng = np.random.default_rng(7)
    for lam in LAMBDAS:
        conn = group.cartan_schouten(lam, side)
        assert conn.side == side and conn.is_cartan()
        for _ in range(3):
            u, v, w = rng.normal(size=(3, group.dim))
            br = commutator_bracket(group, v, w)
            np.testing.assert_allclose(conn.torsion(v, w), (2 * lam - 1) * br, atol=1e-12)
            expected = lam * (lam - 1) * commutator_bracket(group, commutator_bracket(group, u, v), w)
            np.testing.assert_allclose(conn.curvature(u, v, w), expected, atol=1e-12)
            np.testing.assert_allclose(conn.nabla(v, w), (lam if side == "left" else lam - 1) * br, atol=1e-12)


def test_connection_from_table_equals_cartan_schouten():
    group, lam = cartan.SO3, 0.3
    n = group.dim
    table = np.zeros((n, n * n))
    for i in range(n):
        for j in range(n):
            table[:, i * n + j] = lam * commutator_bracket(group, np.eye(n)[i], np.eye(n)[j])
    conn = group.Connection("left", table)
    np.testing.assert_allclose(conn.coefficients, group.cartan_schouten(lam).coefficients, atol=1e-15)


@pytest.mark.parametrize("group", cartan.GROUPS, ids=lambda g: g.name)
def test_transport_constant_velocity_is_expm(group):
    u = np.linspace(0.3, -0.8, group.dim)
    for lam in (0.0, 0.5, 1.0):
        expected = scipy.linalg.expm(-lam * 2.0 * group.ad(u))
        for method in ("lie-euler", "magnus2", "magnus4"):
            p = group.cartan_schouten(lam).transport(lambda t: u, 0.0, 2.0, steps=7, method=method)
            np.testing.assert_allclose(p, expected, atol=1e-12)
            q = group.cartan_schouten_transport(lam, lambda t: u, 0.0, 2.0, steps=7, method=method)
            np.testing.assert_allclose(q, expected, atol=1e-12)


def test_transport_time_varying_velocity_against_solve_ivp():
    group, lam = cartan.SO3, 0.5

    def u(t):
        return np.array([np.cos(t), np.sin(2 * t), 0.5 + t])

    def rhs(t, y):
        return (-lam * group.ad(u(t)) @ y.reshape(3, 3)).ravel()

    ref = scipy.integrate.solve_ivp(rhs, (0.0, 1.0), np.eye(3).ravel(), rtol=1e-12, atol=1e-14).y[:, -1].reshape(3, 3)
    conn = group.cartan_schouten(lam)
    errors = [np.abs(conn.transport(u, 0.0, 1.0, steps=n, method="magnus4") - ref).max() for n in (25, 50, 100, 200)]
    assert errors[-1] < 1e-8
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all(orders > 3.7), orders
    # The sampled form (Simpson with midpoints) agrees with the function form to O(h^4) as well.
    t = np.linspace(0.0, 1.0, 201)
    p = conn.transport_sampled([u(s) for s in t], 0.0, 1.0, method="magnus4",
                               u_midpoints=[u(s + 0.0025) for s in t[:-1]])
    assert np.abs(p - ref).max() < 1e-8
    nodes = conn.transport(u, 0.0, 1.0, steps=200, method="magnus4", nodes=True)
    assert nodes.shape == (201, 3, 3)
    np.testing.assert_allclose(nodes[0], np.eye(3), atol=0)
    # A left CS transport on so(3) is a rotation (P = Ad(Y), Y in SO(3)).
    np.testing.assert_allclose(nodes[-1] @ nodes[-1].T, np.eye(3), atol=1e-13)


def test_heisenberg_transport_closed_form():
    # (para-trans-heis): for u = const the left CS transport is I - lam t ad_u (ad_u^2 = 0 on h3).
    group, lam, u = cartan.Heisenberg, 0.5, np.array([0.4, -1.2, 0.7])
    p = group.cartan_schouten(lam).transport(lambda t: u, 0.0, 3.0, steps=1, method="lie-euler")
    np.testing.assert_allclose(p, np.eye(3) - lam * 3.0 * group.ad(u), atol=1e-14)


def test_connection_errors():
    with pytest.raises(ValueError, match=r'^SO3\.cartan_schouten: side = "up" is not one of: left, right$'):
        cartan.SO3.cartan_schouten(0.5, "up")
    with pytest.raises(ValueError, match=r"^cartan_schouten: lambda = nan is not finite$"):
        cartan.SO3.cartan_schouten(float("nan"))
    conn = cartan.SO3.cartan_schouten(0.5)
    with pytest.raises(ValueError, match=r"^transport_operator: steps = 0 must be at least 1$"):
        conn.transport(lambda t: np.zeros(3), 0.0, 1.0, steps=0)
    with pytest.raises(ValueError, match=r"^SO3\.Connection\.transport: u\([0-9.e-]+\) = array of shape \(2,\) must have shape"):
        conn.transport(lambda t: np.zeros(2), 0.0, 1.0)
    with pytest.raises(ValueError, match=r'method = "rk4" is not one of: lie-euler, magnus2, magnus4'):
        conn.transport(lambda t: np.zeros(3), 0.0, 1.0, method="rk4")
    with pytest.raises(ZeroDivisionError):
        conn.transport(lambda t: 1 / 0, 0.0, 1.0)
