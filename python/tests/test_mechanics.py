"""Classical Euler-Poincare and Lie-Poisson integrators (RKMK4) against SciPy's solve_ivp of
Euler's rigid-body equations in matrix form, and Python-defined models against built-in ones.

Tolerances: RKMK4 with h = 0.01 over T = 5 has global error ~ C h^4 ~ 1e-8 for these O(1)
velocities; solve_ivp (DOP853, rtol 1e-12) is far more accurate, so 1e-7 checks the
integrator and its conventions (a sign or side error would be O(1)). A Python model with the same
formulas as the built-in one differs only by rounding in its callbacks (np.linalg.solve vs
Cholesky): 1e-12 after 500 steps."""
import numpy as np
import pytest
import scipy.integrate

import cartan
from python_models import PyRigidBody, PySO3Oscillator

INERTIA = np.array([2.0, 3.0, 4.0])
V0 = np.array([0.3, -0.7, 0.5])
G0 = cartan.SO3.exp([0.1, 0.2, -0.3])


def reference_rigid_body(T):
    """Body frame: I w' = (I w) x w, R' = R hat(w)."""
    def rhs(t, y):
        r, w = y[:9].reshape(3, 3), y[9:]
        return np.concatenate([(r @ cartan.SO3.hat(w)).ravel(), np.cross(INERTIA * w, w) / INERTIA])
    sol = scipy.integrate.solve_ivp(rhs, (0, T), np.concatenate([G0.ravel(), V0]), method="DOP853",
                                    rtol=1e-12, atol=1e-14)
    return sol.y[:9, -1].reshape(3, 3), sol.y[9:, -1]


def test_euler_poincare_left_matches_solve_ivp_and_conserves_energy():
    tr = cartan.euler_poincare(cartan.RigidBody(INERTIA), G0, V0, T=5.0, steps=500)
    assert tr.t.shape == (501,) and tr.g.shape == (501, 3, 3) and tr.v.shape == (501, 3)
    r, w = reference_rigid_body(5.0)
    np.testing.assert_allclose(tr.g[-1], r, atol=1e-7)
    np.testing.assert_allclose(tr.v[-1], w, atol=1e-7)
    energy = 0.5 * np.einsum("ki,i,ki->k", tr.v, INERTIA, tr.v)
    assert np.ptp(energy) < 1e-9


def test_lie_poisson_equals_euler_poincare_for_the_legendre_transform():
    ep = cartan.euler_poincare(cartan.RigidBody(INERTIA), G0, V0, T=5.0, steps=500)
    lp = cartan.lie_poisson(cartan.RigidBodyHamiltonian(INERTIA), G0, INERTIA * V0, T=5.0, steps=500)
    np.testing.assert_allclose(lp.g, ep.g, atol=1e-12)
    np.testing.assert_allclose(lp.mu, ep.mu, atol=1e-12)


def test_right_reduced_rigid_body_conserves_spatial_momentum():
    # eq:EP-right with l_+ of the free body: mu_+' = 0 (mechanics/right_reduced.hpp).
    v_spatial = G0 @ V0  # Ad_g v_body
    tr = cartan.euler_poincare(cartan.SpatialRigidBody(INERTIA), G0, v_spatial, T=5.0, steps=500, side="right")
    np.testing.assert_allclose(tr.mu, np.broadcast_to(tr.mu[0], tr.mu.shape), atol=1e-12)
    left = cartan.euler_poincare(cartan.RigidBody(INERTIA), G0, V0, T=5.0, steps=500)
    np.testing.assert_allclose(tr.g[-1], left.g[-1], atol=1e-7)  # the same motion, both O(h^4)


@pytest.mark.parametrize("builtin, python", [(cartan.RigidBody(INERTIA), PyRigidBody(INERTIA)),
                                             (cartan.SO3Oscillator(INERTIA), PySO3Oscillator(INERTIA))])
def test_python_model_integrates_like_builtin(builtin, python):
    a = cartan.euler_poincare(builtin, G0, V0, T=5.0, steps=500)
    b = cartan.euler_poincare(python, G0, V0, T=5.0, steps=500)
    np.testing.assert_allclose(b.g, a.g, atol=1e-12)
    np.testing.assert_allclose(b.v, a.v, atol=1e-12)


def test_python_hamiltonian():
    class PyHamiltonian:
        group = cartan.SO3

        def value(self, t, g, mu):
            return 0.5 * mu @ (mu / INERTIA)

        def velocity(self, t, g, mu):
            return mu / INERTIA

        def group_gradient(self, t, g, mu):
            return np.zeros(3)

    a = cartan.lie_poisson(cartan.RigidBodyHamiltonian(INERTIA), G0, INERTIA * V0, T=2.0, steps=200)
    b = cartan.lie_poisson(PyHamiltonian(), G0, INERTIA * V0, T=2.0, steps=200)
    np.testing.assert_allclose(b.g, a.g, atol=1e-12)


def test_builtin_models_match_python_formulas():
    g, v = cartan.SO3.exp([0.4, -0.2, 0.9]), np.array([0.1, 0.5, -0.3])
    for builtin, python in [(cartan.RigidBody(INERTIA), PyRigidBody(INERTIA)),
                            (cartan.SO3Oscillator(INERTIA), PySO3Oscillator(INERTIA))]:
        assert builtin.value(0.0, g, v) == pytest.approx(python.value(0.0, g, v), abs=1e-15)
        for name in ("momentum", "group_gradient"):
            np.testing.assert_allclose(getattr(builtin, name)(0.0, g, v), getattr(python, name)(0.0, g, v), atol=1e-15)
        np.testing.assert_allclose(builtin.velocity(0.0, g, v), python.velocity(0.0, g, v), atol=1e-15)


def test_model_errors():
    with pytest.raises(ValueError, match=r"^NaturalLagrangian<so3>: inertia = .* is not positive definite"):
        cartan.RigidBody([1.0, -1.0, 2.0])
    with pytest.raises(ValueError, match=r"^RigidBody: inertia = array of shape \(2,\) must have shape \(3,\)$"):
        cartan.RigidBody([1.0, 2.0])
    with pytest.raises(ValueError, match=r"^Lagrangian: object = .* has no method velocity"):
        class Incomplete:
            group = cartan.SO3
            value = momentum = group_gradient = None
        cartan.euler_poincare(Incomplete(), G0, V0, T=1.0, steps=10)
    with pytest.raises(ValueError, match=r"^euler_poincare: T = -1 must be positive$"):
        cartan.euler_poincare(cartan.RigidBody(INERTIA), G0, V0, T=-1.0, steps=10)
    with pytest.raises(ValueError, match=r'^SO3\.euler_poincare: side = "up" is not one of: left, right$'):
        cartan.euler_poincare(cartan.RigidBody(INERTIA), G0, V0, T=1.0, steps=10, side="up")
