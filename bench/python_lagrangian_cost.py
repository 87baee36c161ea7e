"""What a Lagrangian written in Python costs cartan.solve, side by side in one process (CPU time,
median of rounds; each round solves with every variant once, so that the machine's load cancels):
the built-in SO3Oscillator, the same model in Python point by point (finite-difference Hessians:
8 n callbacks a node), with an analytic `hessian`, and vectorised (`vectorized = True`: the
stencil in 2 callbacks a node). Also counts the callbacks of one solve.

    PYTHONPATH=build/python OPENBLAS_NUM_THREADS=1 /usr/bin/python3 bench/python_lagrangian_cost.py
"""
import argparse
import collections
import os
import statistics
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "python", "tests"))
import cartan  # noqa: E402
from python_models import PySO3Oscillator, PySO3OscillatorWithHessian  # noqa: E402
from test_vectorized import VectorizedOscillator  # noqa: E402


class Counted:
    """Counts the calls of each method of a model (by wrapping it)."""

    def __init__(self, model):
        self._model, self.calls = model, collections.Counter()

    def __getattr__(self, name):
        attribute = getattr(self._model, name)
        if not callable(attribute):
            return attribute

        def counted(*args):
            self.calls[name] += 1
            return attribute(*args)
        return counted


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--N", type=int, default=200)
    args = parser.parse_args()
    inertia = [2.0, 3.0, 4.0]
    problem = dict(lam=0.5, T=3.0, N=args.N, gT=cartan.SO3.exp([0.4, -0.3, 0.5]), method="shooting", order=2, tol=1e-10)
    variants = {
        "built-in": cartan.SO3Oscillator(inertia),
        "python, differences": PySO3Oscillator(inertia),
        "python, hessian": PySO3OscillatorWithHessian(inertia),
        "python, vectorized": VectorizedOscillator(inertia),
    }
    times = {name: [] for name in variants}
    for _ in range(args.rounds):
        for name, model in variants.items():
            start = time.process_time()
            r = cartan.solve(model, **problem)
            times[name].append(time.process_time() - start)
            assert r.success, (name, r.status)
    base = statistics.median(times["built-in"])
    print(f"SO(3) oscillator, lambda = 1/2, T = 3, N = {args.N}, order 2, shooting; CPU time, median of {args.rounds}")
    print(f"{'variant':<22} {'ms':>9} {'/ built-in':>11} {'callbacks':>10}")
    for name, model in variants.items():
        calls = 0
        if name != "built-in":
            counted = Counted(model)
            cartan.solve(counted, group=cartan.SO3, **problem)
            calls = sum(counted.calls.values())
        median = statistics.median(times[name])
        print(f"{name:<22} {1e3 * median:9.2f} {median / base:11.1f} {calls:10d}")
    return 0


if __name__ == "__main__":
    np.seterr(all="raise")
    sys.exit(main())
