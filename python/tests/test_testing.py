"""cartan.testing: the checks a user runs on their own connections and charts pass on the built-in
ones and on correct user objects, and name the identity a broken object breaks."""
import numpy as np
import pytest

import cartan
import cartan.testing as ct


def random_table(dim, seed):
    return np.random.default_rng(seed).uniform(-1.0, 1.0, (dim, dim * dim))


@pytest.mark.parametrize("group", cartan.GROUPS, ids=lambda g: g.name)
@pytest.mark.parametrize("side", ["left", "right"])
def test_bound_connections_pass(group, side):
    for connection in (group.cartan_schouten(0.3, side), group.Connection(side, random_table(group.dim, 5))):
        report = ct.check_connection(connection)
        assert report.ok, str(report)
        assert [c["callback"] for c in report.checks] == ["torsion", "torsion antisymmetry", "curvature",
                                                          "curvature antisymmetry", "Bianchi identity"]
        # Exact identities: rounding of sums of products of the O(1) coefficients, ~1e-15.
        assert max(c["discrepancy"] for c in report.checks) < 1e-12, str(report)


class PythonConnection:
    """A user's connection in Python from a table (nabla_{E_i} E_j = table[:, i n + j]), with the
    torsion and curvature written out by hand (cur-tor-left), and optional mistakes."""

    def __init__(self, group, table, torsion_mistake=False, curvature_mistake=False):
        self.group, self.side = group, "left"
        n = group.dim
        self.gamma = np.asarray(table).reshape(n, n, n)  # gamma[k, i, j]
        self.torsion_mistake, self.curvature_mistake = torsion_mistake, curvature_mistake

    def nabla(self, u, w):
        return np.einsum("kij,i,j->k", self.gamma, u, w)

    def torsion(self, v, w):
        t = self.nabla(v, w) - self.nabla(w, v)
        return t if self.torsion_mistake else t - self.group.bracket(v, w)  # mistake: the bracket term left out

    def curvature(self, u, v, w):
        r = self.nabla(u, self.nabla(v, w)) - self.nabla(v, self.nabla(u, w))
        sign = 1.0 if self.curvature_mistake else -1.0  # mistake: + nabla_[u,v] w (the right side's sign)
        return r + sign * self.nabla(self.group.bracket(u, v), w)


def test_user_connection_passes_and_mistakes_are_named():
    table = random_table(3, 7)
    good = ct.check_connection(PythonConnection(cartan.SO3, table))
    assert good.ok, str(good)
    # The same connection bound in C++ gives the same torsion and curvature (to rounding).
    bound = cartan.SO3.Connection("left", table)
    u, v, w = np.eye(3)
    np.testing.assert_allclose(PythonConnection(cartan.SO3, table).curvature(u, v, w), bound.curvature(u, v, w),
                               atol=1e-14)

    torsion = ct.check_connection(PythonConnection(cartan.SO3, table, torsion_mistake=True))
    # Leaving out -[v, w] keeps T antisymmetric: only the formula and the Bianchi identity fail.
    assert torsion.failing == ["torsion", "Bianchi identity"], str(torsion)
    assert "check_connection: FAIL (torsion, Bianchi identity)" in str(torsion)

    curvature = ct.check_connection(PythonConnection(cartan.SO3, table, curvature_mistake=True))
    assert curvature.failing == ["curvature", "Bianchi identity"], str(curvature)
    entry = next(c for c in curvature.checks if c["callback"] == "curvature")
    assert entry["discrepancy"] > 0.01 and entry["sample"] >= 0


def test_connection_needs_a_group():
    with pytest.raises(ValueError, match="has no group"):
        ct.check_connection(object())


def hyperbolic_christoffel(q):
    """Levi-Civita connection of the upper half-plane metric (dx^2 + dy^2) / y^2, with a torsion
    added: Gamma^x_xy = -1/y + s, Gamma^x_yx = -1/y - s (s = 0.3 x, a point-dependent torsion)."""
    x, y = q
    g = np.zeros((2, 2, 2))
    g[0, 0, 1], g[0, 1, 0] = -1.0 / y + 0.3 * x, -1.0 / y - 0.3 * x
    g[1, 0, 0], g[1, 1, 1] = 1.0 / y, -1.0 / y
    return g


POINTS = [[0.2, 1.0], [-0.5, 2.5], [1.0, 0.7]]


def test_charts_pass():
    for chart in (cartan.Chart(hyperbolic_christoffel, dim=2), cartan.Euclidean(random_table(3, 3).reshape(3, 3, 3))):
        points = POINTS if chart.dim == 2 else [[0.0, 0.0, 0.0], [1.0, -2.0, 0.5]]
        report = ct.check_chart(chart, points)
        assert report.ok, str(report)
        assert report.samples == 4 * len(points)


class HandWrittenHalfPlane:
    """A user's own hyperbolic half-plane (torsion-free) with the curvature written out as a
    constant-curvature formula R(x, y) z = K (<y, z> x - <x, z> y) in the metric <a, b> = a.b / y^2."""
    dim = 2

    def __init__(self, curvature_sign):
        self.k = curvature_sign

    def christoffel(self, q, x, y):
        g = hyperbolic_christoffel([0.0, q[1]])  # the torsion-free symbols
        return np.einsum("kij,i,j->k", g, x, y)

    def torsion(self, q, x, y):
        return self.christoffel(q, x, y) - self.christoffel(q, y, x)

    def curvature(self, q, x, y, z):
        metric = 1.0 / q[1] ** 2
        return self.k * metric * ((y @ z) * x - (x @ z) * y)


def test_chart_with_a_wrong_curvature_fails_curvature():
    assert ct.check_chart(HandWrittenHalfPlane(-1.0), POINTS).ok   # K = -1: the half-plane's curvature
    report = ct.check_chart(HandWrittenHalfPlane(+1.0), POINTS)
    # The wrong sign keeps R antisymmetric and, without torsion, cyc R = 0: only "curvature" sees it.
    assert report.failing == ["curvature"], str(report)
    entry = next(c for c in report.checks if c["callback"] == "curvature")
    # |R - (-R)| = 2 |R|, relative to the largest of R and the terms it is made of (measured 1.86).
    assert 1.0 < entry["discrepancy"] <= 2.0
    assert "check_chart: FAIL (curvature)" in str(report)


def test_chart_rejects_embedded_manifolds():
    with pytest.raises(ValueError, match="not given in coordinates"):
        ct.check_chart(cartan.Sphere(), [[0.0, 0.0, 1.0]])


def test_check_lagrangian_is_re_exported():
    assert ct.check_lagrangian is cartan.check_lagrangian
