#!/usr/bin/python3
"""Side-by-side timing of `cartan solve --method collocation` and SciPy's solve_bvp (the paper's
method) on the H3 oscillator BVP (appendix sec-app-H3) at tol 1e-8, in one run, alternating the
two so that both see the same machine load.

Both start from the same geodesic guess on the same 11 uniform nodes (cartan: --N 10) and
control the same kind of residual to the same tol. SciPy solves the printed six-equation system
(vectorised NumPy, finite-difference Jacobian as in the paper); cartan solves eq:reduced-system
with xi as three more states (nine equations, analytic Jacobian). Reported per case, fastest of
--repeat runs: SciPy's in-process time; cartan's in-process solve_time_s (from its JSON) and the
wall time of the whole `cartan` process (start-up, solve, JSON output). Ratios = SciPy / cartan.
The last column is the largest difference between the two solutions at 11 sample times.
With --bench (build/bench/bench_collocation, Google Benchmark) the same cases are also timed warm
in-process (mean over repeated solves, no process start-up) and compared with SciPy's times.

Usage: /usr/bin/python3 bench/compare_collocation.py [--cartan build/cartan] [--bench BINARY] [--repeat 5]
       [--markdown FILE]
"""
import argparse
import json
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent / "python"))
import h3_scipy  # noqa: E402

ENDPOINTS = [(1, 0.5, 0.8), (-1, 1, 0.5), (0.5, -1, -1)]
LAMBDAS = [0, 0.5, 1]
TOL = 1e-8


def run_cartan(binary, lam, gT):
    args = [binary, "solve", "--group", "heisenberg", "--model", "oscillator", "--method", "collocation",
            "--lambda", str(lam), "--T", "1", "--N", "10", "--gT", ",".join(map(str, gT)), "--tol", str(TOL),
            "--samples", "11"]
    start = time.perf_counter()
    out = subprocess.run(args, capture_output=True, text=True, check=False)
    wall = time.perf_counter() - start
    if out.returncode != 0:
        raise SystemExit(out.stderr + out.stdout[:300])
    return json.loads(out.stdout), wall


def run_scipy(lam, gT):
    start = time.perf_counter()
    sol = h3_scipy.solve(lam, gT, TOL)
    seconds = time.perf_counter() - start
    if sol.status != 0:
        raise SystemExit(sol.message)
    return sol, seconds


def warm_comparison(binary, rows, repeat):
    """Google Benchmark's warm in-process time of the same solves against the SciPy times above: the
    fastest of `repeat` repetitions, each the mean over many solves."""
    out = subprocess.run([binary, "--benchmark_format=json", "--benchmark_min_time=0.2",
                          f"--benchmark_repetitions={repeat}"], capture_output=True, text=True, check=True)
    warm = {}
    for b in json.loads(out.stdout)["benchmarks"]:
        if b.get("run_type") == "aggregate":
            continue
        endpoint, lam2, reuse = (int(x) for x in b["name"].split("/")[1:4])
        key = (ENDPOINTS[endpoint], lam2 / 2, reuse)
        # Fastest repetition (each the mean of many solves), as SciPy's time is its fastest run.
        warm[key] = min(warm.get(key, float("inf")), b["real_time"] / 1e3)  # ms -> s
    scipy_total = sum(r[2] for r in rows)
    lines = []
    for reuse, label in [(1, "reusing the Newton matrix (default)"), (0, "a fresh Jacobian every Newton step")]:
        warm_total = sum(warm[(r[0], r[1], reuse)] for r in rows)
        per_case = ", ".join(f"{r[2] / warm[(r[0], r[1], reuse)]:.0f}" for r in rows)
        lines.append(f"Warm in-process (bench_collocation), {label}: cartan {warm_total * 1e3:.1f} ms for the "
                     f"{len(rows)} cases, ratio SciPy / cartan {scipy_total / warm_total:.1f} (per case: {per_case}).")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cartan", default="build/cartan")
    parser.add_argument("--bench", help="bench_collocation binary for warm in-process times")
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--markdown")
    args = parser.parse_args()
    rows = []
    for gT in ENDPOINTS:
        for lam in LAMBDAS:
            scipy_times, solve_times, wall_times = [], [], []
            for _ in range(args.repeat):
                sol, seconds = run_scipy(lam, gT)
                scipy_times.append(seconds)
                result, wall = run_cartan(args.cartan, lam, gT)
                solve_times.append(result["solve_time_s"])
                wall_times.append(wall)
            y = sol.sol(np.array(result["t"]))
            diff = max(np.max(np.abs(np.array(result["g"]) - y[:3].T)), np.max(np.abs(np.array(result["v"]) - y[3:].T)))
            rows.append((gT, lam, min(scipy_times), sol.x.size, min(solve_times), min(wall_times), result["mesh_size"],
                         diff))
    header = ("| gT | lambda | SciPy [ms] (nodes) | cartan solve [ms] (nodes) | cartan process [ms] | "
              "ratio solve | ratio process | max diff |")
    lines = [header, "|" + "---|" * 8]
    for gT, lam, sp, sp_nodes, cs, cw, c_nodes, diff in rows:
        lines.append(f"| {gT} | {lam} | {sp * 1e3:.2f} ({sp_nodes}) | {cs * 1e3:.3f} ({c_nodes}) | {cw * 1e3:.2f} | "
                     f"{sp / cs:.1f} | {sp / cw:.1f} | {diff:.1e} |")
    total = [sum(r[i] for r in rows) for i in (2, 4, 5)]
    lines.append(f"\nTotals: SciPy {total[0] * 1e3:.1f} ms, cartan solve {total[1] * 1e3:.1f} ms "
                 f"(ratio {total[0] / total[1]:.1f}), cartan process {total[2] * 1e3:.1f} ms "
                 f"(ratio {total[0] / total[2]:.1f}); fastest of {args.repeat} alternating runs each, tol {TOL}.")
    if args.bench:
        lines.append("\n" + warm_comparison(args.bench, rows, args.repeat))
    text = "\n".join(lines)
    print(text)
    if args.markdown:
        Path(args.markdown).write_text(text + "\n")


if __name__ == "__main__":
    main()
