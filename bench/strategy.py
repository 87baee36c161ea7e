#!/usr/bin/env python3
"""The default solver (`method="auto"`, include/cartan/methods/lie_group/solve.hpp) on a varied set of
transported-velocity problems: inertias, horizons from 1e-4 to 100, lambda from -1 to 2,
near-antipodal endpoints, full inertias, SO(3), H3, SE(2) and SE(3) (built-in free bodies, and
two kinetic energies written in Python). For every problem the default strategy is run and its
result checked by cartan.verify (a converged result that verify fails counts as a failure); where
it fails, every single method is tried, so that the table says whether *some* cartan method
solves it. CPU s is the process's CPU time of the default solve (time.process_time). Prints a Markdown table and
the success rates (bench/README.md "Default solver: measured success").

    PYTHONPATH=build/python /usr/bin/python3 bench/strategy.py [--only NAME]
"""
import argparse
import sys
import time

import numpy as np

import cartan


class PyKinetic:
    """l = 1/2 v.I v on any group (a left-invariant kinetic energy), written in Python."""

    def __init__(self, group, inertia):
        self.group = group
        self.inertia = np.diag(np.asarray(inertia, dtype=float))

    def value(self, t, g, v):
        return 0.5 * v @ self.inertia @ v

    def momentum(self, t, g, v):
        return self.inertia @ v

    def group_gradient(self, t, g, v):
        return np.zeros(len(v))

    def velocity(self, t, g, mu):
        return np.linalg.solve(self.inertia, mu)

    def hessian(self, t, g, v):
        zero = np.zeros((len(v), len(v)))
        return dict(momentum_v=self.inertia, momentum_g=zero, gradient_v=zero, gradient_g=zero)


def rotation(axis, angle):
    axis = np.asarray(axis, dtype=float)
    return cartan.SO3.exp(angle * axis / np.linalg.norm(axis))


FREE_BODY_GT = cartan.SO3.minimal_rotation([-1, -1, -1], [0.9, 1, 1])
OSCILLATOR_GT = cartan.SO3.minimal_rotation([-0.7, -1, -0.7], [0.8, 0.8, 1])
I234 = [2.0, 3.0, 4.0]
_R = cartan.SO3.exp([0.3, -0.4, 0.5])
FULL_INERTIA = _R @ np.diag([1.0, 2.0, 4.0]) @ _R.T
SE2_INERTIA, SE2_GT = [1.0, 2.0, 0.5], cartan.SE2.exp([1.0, 0.5, 2.0])
SE3_INERTIA, SE3_GT = [1.0, 2.0, 3.0, 1.0, 1.0, 1.0], cartan.SE3.exp([0.5, 0.2, 1.0, 1.0, 0.0, 0.5])

# name, lagrangian, lambda, T, N, gT, tol
PROBLEMS = [
    ("so3 free body, paper, lambda 1/2", cartan.RigidBody(I234), 0.5, 50, 1000, FREE_BODY_GT, 1e-8),
    ("so3 free body, T = 1e-4", cartan.RigidBody(I234), 0.5, 1e-4, 100, FREE_BODY_GT, 1e-10),
    ("so3 free body, inertia 1,5,9, T = 100", cartan.RigidBody([1.0, 5.0, 9.0]), 0.5, 100, 5000, FREE_BODY_GT, 1e-8),
    ("so3 free body, lambda -1", cartan.RigidBody(I234), -1.0, 5, 500, FREE_BODY_GT, 1e-10),
    ("so3 free body, lambda 2", cartan.RigidBody(I234), 2.0, 5, 500, FREE_BODY_GT, 1e-10),
    ("so3 free body, near-antipodal (pi - 0.01)", cartan.RigidBody(I234), 0.5, 2, 200,
     rotation([1, 1, 0], np.pi - 0.01), 1e-10),
    ("so3 free body, inertia 1,1,10, lambda 3/2", cartan.RigidBody([1.0, 1.0, 10.0]), 1.5, 10, 1000, FREE_BODY_GT,
     1e-10),
    ("so3 oscillator, paper, lambda 0", cartan.SO3Oscillator(I234), 0.0, 12, 800, OSCILLATOR_GT, 1e-6),
    ("so3 oscillator, paper, lambda 1/2", cartan.SO3Oscillator(I234), 0.5, 12, 800, OSCILLATOR_GT, 1e-6),
    ("so3 oscillator, paper, lambda 1", cartan.SO3Oscillator(I234), 1.0, 12, 800, OSCILLATOR_GT, 1e-6),
    ("so3 oscillator, lambda -1/2, T = 6", cartan.SO3Oscillator(I234), -0.5, 6, 600, OSCILLATOR_GT, 1e-8),
    ("so3 oscillator, lambda 2, T = 3", cartan.SO3Oscillator(I234), 2.0, 3, 300, OSCILLATOR_GT, 1e-8),
    ("so3 oscillator, T = 1e-3", cartan.SO3Oscillator(I234), 0.5, 1e-3, 50, OSCILLATOR_GT, 1e-10),
    ("so3 oscillator, inertia 1,5,9, T = 8", cartan.SO3Oscillator([1.0, 5.0, 9.0]), 0.5, 8, 800, OSCILLATOR_GT,
     1e-8),
    ("h3 oscillator, lambda 1/2, T = 1", cartan.H3Oscillator(), 0.5, 1, 200, [1, 0.5, 0.8], 1e-10),
    ("h3 oscillator, lambda 0.7, T = 3", cartan.H3Oscillator(), 0.7, 3, 300, [1, 0.5, 0.8], 1e-8),
    ("h3 oscillator, lambda -1, T = 1", cartan.H3Oscillator(), -1.0, 1, 200, [0.5, -1, 2], 1e-10),
    ("h3 oscillator, lambda 2, T = 2", cartan.H3Oscillator(), 2.0, 2, 400, [1, 0.5, 0.8], 1e-8),
    ("h3 oscillator, lambda 1/2, T = 5", cartan.H3Oscillator(), 0.5, 5, 500, [1, 0.5, 0.8], 1e-8),
    ("so3 free body, full inertia R diag(1,2,4) R^T, T = 3", cartan.RigidBody(FULL_INERTIA), 0.5, 3, 300,
     FREE_BODY_GT, 1e-10),
    ("so3 free body, inertia 1,1,1.01, T = 10", cartan.RigidBody([1.0, 1.0, 1.01]), 0.5, 10, 500, FREE_BODY_GT,
     1e-10),
    ("so3 free body, inertia 0.1,1,10, T = 5", cartan.RigidBody([0.1, 1.0, 10.0]), 0.5, 5, 500, FREE_BODY_GT,
     1e-10),
    ("so3 oscillator, T = 30", cartan.SO3Oscillator(I234), 0.5, 30, 2000, OSCILLATOR_GT, 1e-8),
    ("se2 free body, lambda 0", cartan.SE2FreeBody(SE2_INERTIA), 0.0, 2, 200, SE2_GT, 1e-10),
    ("se2 free body, lambda -1/2", cartan.SE2FreeBody(SE2_INERTIA), -0.5, 2, 200, SE2_GT, 1e-10),
    ("se2 free body, lambda 2", cartan.SE2FreeBody(SE2_INERTIA), 2.0, 2, 200, SE2_GT, 1e-10),
    ("se2 free body, lambda 1/2, T = 10", cartan.SE2FreeBody(SE2_INERTIA), 0.5, 10, 500,
     cartan.SE2.exp([3.0, -1.0, 3.0]), 1e-10),
    ("se2 free body, T = 1e-3", cartan.SE2FreeBody(SE2_INERTIA), 0.5, 1e-3, 100, cartan.SE2.exp([1e-3, 5e-4, 2e-3]),
     1e-10),
    ("se2 kinetic in Python, lambda 2", PyKinetic(cartan.SE2, SE2_INERTIA), 2.0, 2, 200, SE2_GT, 1e-10),
    ("se3 free body, lambda 1/2", cartan.SE3FreeBody(SE3_INERTIA), 0.5, 2, 200, SE3_GT, 1e-10),
    ("se3 free body, lambda 0", cartan.SE3FreeBody([1.0, 1.0, 1.0, 2.0, 3.0, 4.0]), 0.0, 2, 200,
     cartan.SE3.exp([0.5, -0.3, 0.8, 0.9, -0.7, 0.4]), 1e-10),
    ("se3 free body, lambda 3/2, T = 5", cartan.SE3FreeBody(SE3_INERTIA), 1.5, 5, 500, SE3_GT, 1e-10),
    ("se3 free body, lambda 2, T = 10", cartan.SE3FreeBody([1.0, 1.0, 1.0, 2.0, 3.0, 4.0]), 2.0, 10, 500,
     cartan.SE3.exp([0.5, -0.3, 0.8, 0.9, -0.7, 0.4]), 1e-10),
    ("se3 kinetic in Python, lambda 3/2, T = 5", PyKinetic(cartan.SE3, SE3_INERTIA), 1.5, 5, 500, SE3_GT, 1e-10),
]

ALTERNATIVES = [
    dict(method="shooting", continuation="none"),
    dict(method="shooting", continuation="T"),
    dict(method="shooting", continuation="lambda"),
    dict(method="multiple-shooting"),
    dict(method="two-level"),
    dict(method="collocation"),
    dict(method="collocation", continuation="T"),
]


def run(lagrangian, lam, T, N, gT, tol, **method):
    start = time.process_time()
    try:
        r = cartan.solve(lagrangian, lam=lam, T=T, N=N, gT=gT, tol=tol, **method)
    except ValueError as e:  # e.g. collocation of a Python Lagrangian
        return None, str(e), time.process_time() - start
    return r, r.status, time.process_time() - start


def label(method):
    return method["method"] + (f" ({method['continuation']})" if method.get("continuation", "none") != "none" else "")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", help="run only problems whose name contains this")
    args = parser.parse_args()
    rows, solved_default, solvable = [], 0, 0
    for name, lagrangian, lam, T, N, gT, tol in PROBLEMS:
        if args.only and args.only not in name:
            continue
        r, status, cpu = run(lagrangian, lam, T, N, gT, tol)
        others = []
        if r is not None and r.success and not cartan.verify(r, lagrangian).passed:
            status = "converged, but cartan.verify fails it"
            r = None
        if r is not None and r.success:
            solved_default += 1
            solvable += 1
        else:
            for method in ALTERNATIVES:
                a, a_status, _ = run(lagrangian, lam, T, N, gT, tol, **method)
                if a is not None and a.success:
                    others.append(label(method))
            solvable += bool(others)
        how = r.branch if r is not None and r.success else status
        rows.append(f"| {name} | {status} | {how} | {cpu:.3f} | {', '.join(others) or '-'} |")
        print(rows[-1], file=sys.stderr, flush=True)
    print("| problem | default status | path (or failure) | CPU s | other methods that solve it |")
    print("|---|---|---|---|---|")
    print("\n".join(rows))
    print(f"\nDefault solves {solved_default} of {len(rows)}; some cartan method solves {solvable}; "
          f"the default solves {solved_default} of those {solvable}.")


if __name__ == "__main__":
    main()
