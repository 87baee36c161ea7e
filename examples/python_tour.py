#!/usr/bin/python3
"""A short tour of the cartan Python module: group operations, a Cartan-Schouten connection and
its transport, and one solve of the transported-velocity problem with a Lagrangian written in
Python. Run from a build tree with
    PYTHONPATH=build/python /usr/bin/python3 examples/python_tour.py
"""
import numpy as np

import cartan
from cartan import SO3


def main():
    # Groups: SO(3) elements are rotation matrices, algebra vectors live in R^3 (hat(v) w = v x w).
    v = np.array([0.3, -0.2, 0.9])
    g = SO3.exp(v)
    print("SO(3): exp(v) =\n", np.round(g, 6))
    print("log(exp(v)) - v =", np.abs(SO3.log(g) - v).max())
    print("Ad_g v - g v =", np.abs(SO3.Ad(g) @ v - g @ v).max(), "(Ad is the rotation itself on so(3))")

    # A connection (CS-conn): torsion (2 lam - 1)[v, w], curvature lam (lam - 1)[[u, v], w] (tor-cur-lie-alg).
    conn = SO3.cartan_schouten(0.5)
    u, w = np.array([1.0, 0, 0]), np.array([0, 1.0, 0])
    print("lam = 1/2: torsion(u, w) =", conn.torsion(u, w), " curvature(u, w) u =", conn.curvature(u, w, u))
    # Parallel transport along the curve with body velocity u(t) (cor-parr), a rotation of so(3).
    p = conn.transport(lambda t: np.array([np.cos(t), np.sin(t), 0.5]), 0.0, 1.0, steps=50)
    print("transport P(0 -> 1) is orthogonal:", np.allclose(p @ p.T, np.eye(3)))

    # A Lagrangian written in Python: the free rigid body l = 1/2 v.I v on SO(3).
    class FreeRigidBody:
        group = SO3

        def __init__(self, inertia):
            self.inertia = np.asarray(inertia, dtype=float)

        def value(self, t, g, v):
            return 0.5 * v @ (self.inertia * v)

        def momentum(self, t, g, v):  # mu = dl/dv
            return self.inertia * v

        def group_gradient(self, t, g, v):  # left-trivialised dl/dg
            return np.zeros(3)

        def velocity(self, t, g, mu):  # inverse Legendre map
            return mu / self.inertia

    gT = SO3.minimal_rotation([-1, -1, -1], [0.9, 1, 1])  # the paper's endpoints
    result = cartan.solve(FreeRigidBody([2, 3, 4]), lam=0.5, T=50, N=1000, gT=gT, tol=1e-8)
    print(result)
    builtin = cartan.solve(cartan.RigidBody([2, 3, 4]), lam=0.5, T=50, N=1000, gT=gT, tol=1e-8)
    print("same solution as the built-in model:", np.abs(result.g - builtin.g).max() < 1e-7,
          f"(Python callbacks {result.solve_time:.2f} s, built-in {builtin.solve_time:.3f} s)")
    energy = 0.5 * np.einsum("ki,i,ki->k", result.v, [2.0, 3.0, 4.0], result.v)
    print(f"kinetic energy 1/2 v.I v along the solution: {energy[0]:.6f} -> {energy[-1]:.6f} "
          "(conserved for every lambda, up to the scheme's O(h))")
    if not result.success:
        raise SystemExit(result.message)


if __name__ == "__main__":
    main()
