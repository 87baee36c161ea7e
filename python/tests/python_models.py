"""The paper's SO(3) models written in Python against cartan's Lagrangian interface, as a user
would write them: l(g, v) = 1/2 v.I v - V(g) with V = 0 (free rigid body) or V = 1/2 (3 - tr g)
(the oscillator), left-reduced. Independent of the C++ models: plain NumPy formulas."""
import numpy as np

import cartan


def vee_skew(m):
    """vee of the skew-symmetric part of a 3 x 3 matrix."""
    return 0.5 * np.array([m[2, 1] - m[1, 2], m[0, 2] - m[2, 0], m[1, 0] - m[0, 1]])


class PyRigidBody:
    """l = 1/2 v.I v - V(g) with V = 0; `group` any group of dimension 3 (SE(2) too: a kinetic energy)."""

    def __init__(self, inertia, group=cartan.SO3):
        self.group = group
        self.inertia = np.diag(inertia).astype(float)

    def potential(self, g):
        return 0.0

    def value(self, t, g, v):
        return 0.5 * v @ self.inertia @ v - self.potential(g)

    def momentum(self, t, g, v):
        return self.inertia @ v

    def group_gradient(self, t, g, v):
        return np.zeros(3)

    def velocity(self, t, g, mu):
        return np.linalg.solve(self.inertia, mu)


class PySO3Oscillator(PyRigidBody):
    def potential(self, g):
        return 0.5 * (3.0 - np.trace(g))

    def group_gradient(self, t, g, v):
        # zeta . w = d/de -V(g exp(e w)) = 1/2 tr(g hat(w)) = -vee(Skew g) . w (docs/paper-notes.md#erratum-1)
        return -vee_skew(g)


class PySO3OscillatorWithHessian(PySO3Oscillator):
    """The oscillator with analytic second derivatives (the optional `hessian` callback):
    d mu/dv = I, and d zeta/d gamma has columns -vee(Skew(g hat(e_i))) (g -> g exp(e gamma))."""

    def hessian(self, t, g, v):
        gradient_g = -np.column_stack([vee_skew(g @ cartan.SO3.hat(e)) for e in np.eye(3)])
        zero = np.zeros((3, 3))
        return dict(momentum_v=self.inertia, momentum_g=zero, gradient_v=zero, gradient_g=gradient_g)


class PyH3Oscillator:
    """l = 1/2 |v|^2 - 1/2 (a^2 + b^2 + c^2) on the Heisenberg group; dV . w = (a, b, c) .
    (w1, w2, w3 + a w2) by (left-Heis)."""
    group = cartan.Heisenberg

    def value(self, t, g, v):
        return 0.5 * v @ v - 0.5 * g @ g

    def momentum(self, t, g, v):
        return np.array(v, dtype=float)

    def group_gradient(self, t, g, v):
        a, b, c = g
        return -np.array([a, b + a * c, c])

    def velocity(self, t, g, mu):
        return np.array(mu, dtype=float)


class SphereKinetic:
    """l = 1/2 v.A v - G q[2] on S^2 written in Python (a manifold's lagrangian= object)."""

    def __init__(self, A, G):
        self.A, self.G = np.asarray(A, float), G

    def value(self, t, q, v):
        return 0.5 * v @ self.A @ v - self.G * q[2]

    def momentum(self, t, q, v):
        return self.A @ v

    def velocity(self, t, q, mu):
        return np.linalg.solve(self.A, mu)

    def point_gradient(self, t, q, v):
        return np.array([0.0, 0.0, -self.G])
