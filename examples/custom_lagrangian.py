#!/usr/bin/python3
"""A Lagrangian written in Python on a group without built-in models: a planar rigid body on SE(2)
held by a spring at the origin,

    l(g, v) = 1/2 v.M v - k/2 |p|^2,   g = [[R, p], [0, 1]],   v = (x, y, theta) (body velocity),

solved by cartan's transported-velocity solvers (eq:reduced-system), with and without the optional
analytic `hessian`, and checked against the classical Euler-Poincare motion at lambda = 0.
docs/user-guide.md "A new Lagrangian in Python" walks through this file. Run from a build tree with
    PYTHONPATH=build/python /usr/bin/python3 examples/custom_lagrangian.py
It exits non-zero when one of its checks fails (python/tests/test_example.py runs it).
"""
import sys

import numpy as np

import cartan
from cartan import SE2


class SpringBody:
    """The four required methods take and return NumPy arrays: g is (3, 3), v and mu are (3,)."""
    group = SE2

    def __init__(self, mass, inertia, stiffness):
        self.M = np.diag([mass, mass, inertia])
        self.k = stiffness

    def value(self, t, g, v):
        p = g[:2, 2]
        return 0.5 * v @ self.M @ v - 0.5 * self.k * p @ p

    def momentum(self, t, g, v):  # mu = dl/dv
        return self.M @ v

    def group_gradient(self, t, g, v):
        # zeta . w = d/de l(g exp(e w), v): g exp(e w) moves p by e R (w_x, w_y), so zeta = -k (R^T p, 0).
        R, p = g[:2, :2], g[:2, 2]
        return np.append(-self.k * R.T @ p, 0.0)

    def velocity(self, t, g, mu):  # the inverse Legendre map
        return np.linalg.solve(self.M, mu)


class SpringBodyWithHessian(SpringBody):
    """The optional second derivatives, a dict of (3, 3) arrays (keys as cartan.lagrangian_hessian).
    g exp(e w) turns R^T p into R^T p + e ((w_x, w_y) - w_theta J R^T p), J = [[0, -1], [1, 0]]."""

    def hessian(self, t, g, v):
        q = g[:2, :2].T @ g[:2, 2]
        gradient_g = np.zeros((3, 3))
        gradient_g[:2, :2] = -self.k * np.eye(2)
        gradient_g[:2, 2] = self.k * np.array([-q[1], q[0]])
        zero = np.zeros((3, 3))
        return dict(momentum_v=self.M, momentum_g=zero, gradient_v=zero, gradient_g=gradient_g)


def check(ok, what, failures):
    print(f"  [{'ok' if ok else 'FAILED'}] {what}")
    if not ok:
        failures.append(what)


def main():
    failures = []
    body, body_hessian = SpringBody(1.0, 0.5, 1.0), SpringBodyWithHessian(1.0, 0.5, 1.0)
    gT = SE2.exp([1.0, 0.5, 1.2])
    tol = 1e-10

    # The analytic hessian against the library's central differences of momentum and
    # group_gradient (step 1e-5, accurate to ~1e-10); a wrong formula would be off by O(1).
    g, v = SE2.exp([0.3, -0.7, 0.9]), np.array([0.2, 0.1, -0.4])
    analytic = cartan.lagrangian_hessian(body_hessian, 0.0, g, v)
    differences = cartan.lagrangian_hessian(body, 0.0, g, v)
    gap = max(np.abs(analytic[key] - differences[key]).max() for key in analytic)
    print(f"SpringBody on SE(2): analytic hessian - central differences = {gap:.2e}")
    check(gap < 1e-7, "the analytic hessian matches central differences", failures)

    print("Transported-velocity BVP, lambda = 1/2, T = 2, N = 200, order 2")
    results = {}
    for name, model in (("differences", body), ("analytic", body_hessian)):
        r = cartan.solve(model, lam=0.5, T=2.0, N=200, gT=gT, order=2, tol=tol)
        print(f"  {name:11s}: {r.status}, v0 = {np.round(r.v0, 8)}, terminal error {r.terminal_error:.2e}, "
              f"{r.sweeps} sweeps, {r.solve_time:.2f} s ({r.branch})")
        check(r.success and r.terminal_error <= tol, f"converged ({name})", failures)
        results[name] = r
    # Same discrete equations solved to tol = 1e-10: the solutions agree to tol x conditioning.
    v0_gap = np.abs(results["differences"].v0 - results["analytic"].v0).max()
    print(f"  |v0(differences) - v0(analytic)| = {v0_gap:.2e}")
    check(v0_gap < 1e-8, "both reach the same solution", failures)

    # lambda = 0: the transport is trivial and eq:reduced-system is eq:EP-left, so the classical
    # Euler-Poincare flow (RKMK4, exact to ~1e-12 with 2000 steps) from v0 must end at gT, up to
    # the order-2 scheme's O(h^2) error (h = 0.01, measured 4e-5); an O(h) error would be ~1e-2.
    r0 = cartan.solve(body_hessian, lam=0.0, T=2.0, N=200, gT=gT, order=2, tol=tol)
    ep = cartan.euler_poincare(body_hessian, SE2.identity(), r0.v0, 2.0, 2000)
    gap = np.linalg.norm(SE2.log(SE2.compose(SE2.inverse(gT), ep.g[-1])))
    print(f"lambda = 0: Euler-Poincare from v0 ends {gap:.2e} from gT (scheme error O(h^2))")
    check(r0.success and gap < 1e-3, "lambda = 0 solution is the classical Euler-Poincare motion", failures)

    print("all checks passed" if not failures else "SOME CHECKS FAILED")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
