#!/usr/bin/python3
"""The transported-velocity problem on manifolds with a connection from Python (cartan.solve on a manifold;
docs/general-connections.md): the spherical pendulum checked against the classical equation, a rigid
body under a Cartan-Schouten connection against the Lie-group solver, a potential written in
Python on R^2 with torsion, and a manifold of your own (the Poincare half-plane as a cartan.Chart). docs/user-guide.md "General manifolds and connections" quotes this file.
Run from a build tree with
    PYTHONPATH=build/python /usr/bin/python3 examples/general_connections.py
It exits non-zero when one of its checks fails (python/tests/test_example.py runs it).
"""
import sys

import numpy as np

import cartan
from cartan import Euclidean, GroupManifold, Sphere

failures = []


def check(name, ok):
    print(f"{name}: {'ok' if ok else 'FAILED'}")
    if not ok:
        failures.append(name)


def classical_pendulum(q0, velocity, G, T, steps=20000):
    """RK4 for q'' = -G (e_z - z q) - |q'|^2 q, the pendulum on the unit sphere in R^3."""
    def f(y):
        q, p = y[:3], y[3:]
        return np.concatenate([p, -G * (np.array([0, 0, 1.0]) - q[2] * q) - (p @ p) * q])
    y, h = np.concatenate([q0, velocity]), T / steps
    for _ in range(steps):
        k1 = f(y)
        k2 = f(y + h / 2 * k1)
        k3 = f(y + h / 2 * k2)
        k4 = f(y + h * k3)
        y = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return y[:3]


def main():
    # The spherical pendulum: S^2 with its Levi-Civita connection, l = 1/2 |v|^2 - G z.
    sphere = Sphere()
    q0, qT = Sphere.point([1, 0, -0.3]), Sphere.point([0, 1, -0.5])
    r = cartan.solve(sphere, T=1.0, N=400, q0=q0, qT=qT, gravity=9.81, order=2, tol=1e-12)
    print(r, cartan.verify(r).verdict)  # the result carries its problem: verify needs nothing else
    velocity = r.frame[0] @ r.v0  # q'(0): the components v0 in frame0 = sphere.default_frame(q0, qT)
    miss = np.linalg.norm(classical_pendulum(q0, velocity, 9.81, 1.0) - qT)
    print(f"classical pendulum from q0 with q'(0) = frame0 @ v0 misses qT by {miss:.1e}")
    check("pendulum converged and verified", r.converged and cartan.verify(r).passed)
    check("pendulum is the classical one (to the scheme's O(h^2))", miss < 2e-4)

    # SO(3) with the Cartan-Schouten connection lambda = 0.3 (alpha = lambda ad): the Lie-group solver's problem.
    gT = cartan.SO3.minimal_rotation([-1, -1, -1], [0.9, 1, 1])
    so3 = GroupManifold("so3", "cartan-schouten", lam=0.3)
    general = cartan.solve(so3, T=5.0, N=200, q0=np.eye(3), qT=gT, inertia=[2.0, 3.0, 4.0], method="shooting",
                           tol=1e-12)
    lie = cartan.solve(cartan.RigidBody([2.0, 3.0, 4.0]), lam=0.3, T=5.0, N=200, gT=gT, method="shooting",
                       tol=1e-12)
    gap = np.abs(general.q - lie.g).max()
    print(f"SO(3), lambda = 0.3: general and Lie-group solvers differ by {gap:.1e}")
    check("same curve as cartan.solve", general.converged and lie.converged and gap < 1e-10)

    # R^2 with constant Christoffel symbols christoffel[k, i, j] = Gamma^k_ij (torsion T^1_12 = 0.6), a
    # potential written in Python and an anisotropic inertia; the energy 1/2 v.A v + V is conserved.
    gamma = np.zeros((2, 2, 2))
    gamma[0, 0, 1] = 0.3
    gamma[0, 1, 0] = -0.3
    plane = Euclidean(gamma)
    A = np.diag([1.0, 2.0])
    r = cartan.solve(plane, T=2.0, N=400, q0=[0.5, 0.0], qT=[-0.3, 0.4], inertia=A,
                     potential=lambda q: 0.5 * q @ q, potential_gradient=lambda q: q, order=2)
    energy = 0.5 * np.einsum("ki,ij,kj->k", r.v, A, r.v) + 0.5 * np.einsum("ki,ki->k", r.q, r.q)
    print(f"R^2 with torsion: {r.status}, energy drift {np.abs(energy - energy[0]).max():.1e}")
    check("energy conserved (to the scheme's order)", r.converged and np.abs(energy - energy[0]).max() < 1e-4)

    # A manifold of your own: the Poincare half-plane y > 0 from its Christoffel symbols alone
    # (christoffel[k, i, j] = Gamma^k_ij of g = (dx^2 + dy^2) / y^2). With l = 1/2 |v|^2 in a
    # g-orthonormal frame (a chart's default frame when it has a metric) the solution is the hyperbolic
    # geodesic, at speed d(q0, qT) / T.
    def half_plane(q):
        g = np.zeros((2, 2, 2))
        g[0, 0, 1] = g[0, 1, 0] = g[1, 1, 1] = -1 / q[1]
        g[1, 0, 0] = 1 / q[1]
        return g

    chart = cartan.Chart(half_plane, dim=2, metric=lambda q: np.eye(2) / q[1] ** 2, parallel=True)  # K = -1
    q0, qT, T = np.array([-0.5, 0.8]), np.array([1.2, 1.6]), 2.0
    r = cartan.solve(chart, T=T, N=20, q0=q0, qT=qT, method="collocation")
    distance = np.arccosh(1 + np.sum((qT - q0) ** 2) / (2 * q0[1] * qT[1]))
    print(f"half-plane geodesic: speed {np.linalg.norm(r.v0):.12f}, d / T = {distance / T:.12f}")
    check("half-plane geodesic at the hyperbolic speed", r.converged and abs(np.linalg.norm(r.v0) - distance / T) < 1e-8)

    print("all checks passed" if not failures else f"FAILED: {', '.join(failures)}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
