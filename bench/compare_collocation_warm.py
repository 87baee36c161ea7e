#!/usr/bin/python3
"""Collocation against SciPy's solve_bvp on a varied set of H3 oscillator BVPs (appendix
sec-app-H3: g0 = e, unit inertia), both in process and warm, in CPU time, alternating the two sides
case by case in one run.

The set: --cases problems from a seeded generator (numpy default_rng(--seed)): gT uniform in
[-1.5, 1.5]^3, lambda uniform in [-0.5, 1.5], T uniform in [0.2, 2], each rounded to 3 decimals
(--set readme: the README's earlier 3 endpoints x lambda in {0, 1/2, 1} at T = 1 instead).
Both sides start from the same guess (cartan's geodesic guess, h3_scipy.geodesic_guess) on the same
11 uniform nodes and control the relative RMS residual of the cubic interpolant to tol = 1e-8.
SciPy solves the printed six-equation system with its finite-difference Jacobian (as in the paper);
cartan the same system in its closed form (kernels/lie_group/heisenberg_collocation.hpp) with the
analytic Jacobian.

Timing: cartan runs in a long-lived process (bench/collocation_timer, built with
`cmake --build BUILD --target collocation_timer`) that answers one request per case with the
process CPU time of each of --cartan-repeats solves after an untimed warm-up solve; SciPy runs in
this process, --scipy-repeats solves after an untimed warm-up, each timed with time.process_time
(BLAS limited to one thread, so process time is the solve's own). Each of --rounds rounds visits
every case, the two sides one after the other (SciPy first in even rounds, cartan first in odd
ones), so both see the same machine load; a case where either side fails in a first screening
solve is reported and not timed. Per case: median of all of SciPy's solves over the
median of all of cartan's; reported: every case's ratio, their median and minimum. The solutions
are compared at 11 uniform times (max |difference| column).

Usage: /usr/bin/python3 bench/compare_collocation_warm.py --timer BUILD/bench/collocation_timer
       [--cases 24] [--seed 12] [--rounds 3] [--markdown FILE]
"""
import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import argparse  # noqa: E402
import json  # noqa: E402
import statistics  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent / "python"))
import h3_scipy  # noqa: E402

TOL = 1e-8
NODES = 11
SAMPLES = 11


def varied_cases(count, seed):
    rng = np.random.default_rng(seed)
    cases = []
    for _ in range(count):
        gT = tuple(round(float(x), 3) for x in rng.uniform(-1.5, 1.5, 3))
        lam = round(float(rng.uniform(-0.5, 1.5)), 3)
        T = round(float(rng.uniform(0.2, 2.0)), 3)
        cases.append((gT, lam, T))
    return cases


def readme_cases():
    return [(gT, lam, 1.0) for gT in [(1, 0.5, 0.8), (-1, 1, 0.5), (0.5, -1, -1)] for lam in (0, 0.5, 1)]


class Cartan:
    """The long-lived timer process (serve mode of bench/collocation_timer.cpp)."""

    def __init__(self, binary):
        self.proc = subprocess.Popen([binary], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)

    def solve(self, case, repeats):
        (a, b, c), lam, T = case
        self.proc.stdin.write(f"{a} {b} {c} {lam} {T} {NODES} {TOL} {repeats} {SAMPLES}\n")
        self.proc.stdin.flush()
        return json.loads(self.proc.stdout.readline())

    def close(self):
        self.proc.stdin.write("\n")
        self.proc.stdin.close()
        self.proc.wait()


def scipy_solve(case):
    gT, lam, T = case
    return h3_scipy.solve(lam, gT, TOL, T=T, nodes=NODES, guess=h3_scipy.geodesic_guess)


def scipy_times(case, repeats):
    sol = scipy_solve(case)  # warm-up
    times = []
    for _ in range(repeats):
        start = time.process_time()
        sol = scipy_solve(case)
        times.append(time.process_time() - start)
    return sol, times


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--timer", required=True, help="bench/collocation_timer binary")
    parser.add_argument("--set", choices=["varied", "readme"], default="varied")
    parser.add_argument("--cases", type=int, default=24)
    parser.add_argument("--seed", type=int, default=12)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--scipy-repeats", type=int, default=3)
    parser.add_argument("--cartan-repeats", type=int, default=20)
    parser.add_argument("--markdown")
    args = parser.parse_args()
    cases = varied_cases(args.cases, args.seed) if args.set == "varied" else readme_cases()
    cartan = Cartan(args.timer)
    # Screening (also both sides' first solve of each case): a case where either side fails is
    # reported, not timed (a failing solve_bvp runs to max_nodes, seconds per solve).
    skipped, timed = [], []
    for i, case in enumerate(cases):
        sol, out = scipy_solve(case), cartan.solve(case, 0)
        if sol.status != 0 or out["status"] != "converged":
            gT, lam, T = case
            skipped.append(f"{gT}, λ = {lam}, T = {T}: SciPy status {sol.status} ({sol.message}), "
                           f"cartan {out['status']}")
        else:
            timed.append(i)
    sp = {i: [] for i in timed}
    ct = {i: [] for i in timed}
    last = {}
    for r in range(args.rounds):
        for i in timed:
            case = cases[i]
            sides = ["scipy", "cartan"] if r % 2 == 0 else ["cartan", "scipy"]
            for side in sides:
                if side == "scipy":
                    sol, times = scipy_times(case, args.scipy_repeats)
                    sp[i] += times
                    last.setdefault(i, {})["scipy"] = sol
                else:
                    out = cartan.solve(case, args.cartan_repeats)
                    ct[i] += out["cpu_s"]
                    last.setdefault(i, {})["cartan"] = out
    cartan.close()
    header = ("| gT | λ | T | SciPy [ms] (nodes) | cartan [ms] (nodes, Newton, Jacobians) | ratio | max diff |")
    lines = [header, "|" + "---|" * 7]
    ratios = []
    for i in timed:
        gT, lam, T = cases[i]
        sol, out = last[i]["scipy"], last[i]["cartan"]
        times = np.linspace(0, T, SAMPLES)
        y_cartan = np.array(out["y"]).reshape(SAMPLES, 6)
        diff = float(np.max(np.abs(sol.sol(times).T - y_cartan)))
        s, c = statistics.median(sp[i]), statistics.median(ct[i])
        ratios.append(s / c)
        lines.append(f"| {gT} | {lam} | {T} | {s * 1e3:.2f} ({sol.x.size}) | {c * 1e3:.3f} ({out['nodes']}, "
                     f"{out['newton']}, {out['jacobians']}) | {s / c:.1f} | {diff:.1e} |")
    lines.append("")
    if ratios:
        lines.append(f"Ratio SciPy / cartan (CPU time, medians per case): median **{statistics.median(ratios):.1f}×**, "
                     f"minimum **{min(ratios):.1f}×**, maximum {max(ratios):.1f}× over {len(ratios)} cases "
                     f"({args.set} set, seed {args.seed}); {args.rounds} alternating rounds, "
                     f"{args.scipy_repeats} SciPy and {args.cartan_repeats} cartan solves per case a round, tol {TOL}.")
    for s in skipped:
        lines.append(f"Not compared (a side failed): {s}")
    text = "\n".join(lines)
    print(text)
    if args.markdown:
        Path(args.markdown).write_text(text + "\n")


if __name__ == "__main__":
    main()
