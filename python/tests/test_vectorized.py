"""Vectorised Python Lagrangians (python/src/python_models.hpp): a model whose attribute
`vectorized` is true receives stacked points, and the finite-difference Hessian's 4 n points go
in one call of momentum and one of group_gradient. Checked against the same model written point
by point: identical stencils, so identical solves; the callbacks counted; wrong shapes named."""
import collections

import numpy as np
import pytest

import cartan
from python_models import PySO3Oscillator, vee_skew


class CountingOscillator(PySO3Oscillator):
    """The point-by-point oscillator, counting its callbacks."""

    def __init__(self, inertia):
        super().__init__(inertia)
        self.calls = collections.Counter()

    def momentum(self, t, g, v):
        self.calls["momentum"] += 1
        return super().momentum(t, g, v)

    def group_gradient(self, t, g, v):
        self.calls["group_gradient"] += 1
        return super().group_gradient(t, g, v)


class VectorizedOscillator:
    """The same l = 1/2 v.I v - 1/2 (3 - tr g) for stacked points: t (K,), g (K, 3, 3), v (K, 3)."""
    group = cartan.SO3
    vectorized = True

    def __init__(self, inertia):
        self.inertia = np.diag(inertia).astype(float)
        self.inverse_inertia = np.diag(1.0 / np.asarray(inertia, dtype=float))
        self.calls = collections.Counter()
        self.points = collections.Counter()

    def _count(self, name, t):
        self.calls[name] += 1
        self.points[name] += len(t)

    def value(self, t, g, v):
        self._count("value", t)
        return 0.5 * np.sum((v @ self.inertia) * v, axis=1) - 0.5 * (3.0 - np.trace(g, axis1=1, axis2=2))

    def momentum(self, t, g, v):
        self._count("momentum", t)
        return v @ self.inertia  # I symmetric: row k is I v_k

    def group_gradient(self, t, g, v):
        self._count("group_gradient", t)
        # -vee(Skew g) row by row: entries (2,1), (0,2), (1,0) minus their transposes, halved
        return -0.5 * (g[:, (2, 0, 1), (1, 2, 0)] - g[:, (1, 2, 0), (2, 0, 1)])

    def velocity(self, t, g, mu):
        self._count("velocity", t)
        return mu @ self.inverse_inertia


PROBLEM = dict(lam=0.5, T=3.0, N=60, gT=cartan.SO3.exp([0.4, -0.3, 0.5]), method="shooting", order=2, tol=1e-12)


def test_vectorized_group_gradient_matches_pointwise_formula():
    g = np.stack([cartan.SO3.exp(w) for w in np.random.default_rng(1).normal(size=(5, 3))])
    batch = VectorizedOscillator([2, 3, 4]).group_gradient(np.zeros(5), g, np.zeros((5, 3)))
    # The two formulas are the same arithmetic on the same numbers: equal to rounding.
    np.testing.assert_allclose(batch, [-vee_skew(x) for x in g], rtol=0, atol=1e-15)


def test_vectorized_model_solves_as_the_pointwise_model_with_two_hessian_calls_a_node():
    pointwise, vectorized = CountingOscillator([2, 3, 4]), VectorizedOscillator([2, 3, 4])
    a = cartan.solve(pointwise, **PROBLEM)
    b = cartan.solve(vectorized, **PROBLEM)
    assert a.success and b.success
    # Same stencil points, same difference formulas, the same Newton path: the solutions agree to
    # the rounding of the callbacks' arithmetic (einsum and @ may sum in another order), far below tol.
    np.testing.assert_allclose(b.v, a.v, rtol=0, atol=1e-12)
    np.testing.assert_allclose(b.g, a.g, rtol=0, atol=1e-12)
    assert b.sweeps == a.sweeps
    # Every Hessian of the point-by-point model costs 4 n = 12 calls of momentum and 12 of
    # group_gradient; the vectorised model makes one call of each with 12 points.
    hessians = vectorized.points["group_gradient"] - vectorized.calls["group_gradient"]
    assert hessians > 0 and hessians % 11 == 0  # each 12-point call adds 11 points beyond its one call
    hessian_calls = hessians // 11
    assert pointwise.calls["group_gradient"] >= 12 * hessian_calls
    assert vectorized.calls["group_gradient"] + vectorized.calls["momentum"] < \
        (pointwise.calls["group_gradient"] + pointwise.calls["momentum"]) / 4


def test_vectorized_model_verifies_like_the_pointwise_model():
    vectorized = VectorizedOscillator([2, 3, 4])
    r = cartan.solve(vectorized, **PROBLEM)
    report = cartan.verify(r, vectorized)
    assert report.passed, str(report)
    assert report.checks == cartan.verify(r, PySO3Oscillator([2, 3, 4])).checks


class WrongRows(VectorizedOscillator):
    def momentum(self, t, g, v):
        return super().momentum(t, g, v)[0]  # one row whatever the batch: the model's mistake


def test_wrong_number_of_rows_is_named():
    with pytest.raises(ValueError, match=r"Lagrangian\.momentum: return value = array of shape \(3,\) must have shape \((1|12), 3\)"):
        cartan.solve(WrongRows([2, 3, 4]), **PROBLEM)


class NotVectorized(PySO3Oscillator):
    vectorized = False  # an explicit False is the point-by-point interface


def test_vectorized_false_is_pointwise():
    assert cartan.solve(NotVectorized([2, 3, 4]), **PROBLEM).success
