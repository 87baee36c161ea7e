#!/usr/bin/python3
"""Parallel scaling of `cartan sweep`: the same lambda sweep run with --jobs 1 and --jobs J side by
side, alternating the two in each repeat so that both see the same machine load; the median of
--repeat runs of each and the ratio of the medians.

Default case: the paper's free rigid body (T = 50, N = 1000, a0 = -(1,1,1), aT = (0.9,1,1),
tol 1e-8) at 16 evenly spaced lambdas in [0, 1]. Times are the sweep's own wall_time_s (thread
pool start to last row, no process start-up or output), the whole process's wall time, and its
CPU time (user + system); CPU / wall is how many cores the process actually got, which on a
loaded machine can be less than --jobs (then no wall-time speed-up is possible); the sum of the
rows' solve_time_s over wall_time_s is how many solves were in progress at once on average. The
rows of the two runs must agree (status, v0, terminal_error), else the script fails: a speed-up
that changes results is no speed-up.

Usage: /usr/bin/python3 bench/sweep_scaling.py [--cartan build/cartan] [--jobs 2] [--points 16]
       [--repeat 3] [--N 1000]
"""
import argparse
import json
import resource
import statistics
import subprocess
import sys
import time


def sweep(binary, jobs, points, n):
    args = [binary, "sweep", "--model", "free-rigid-body", "--T", "50", "--N", str(n), "--a0=-1,-1,-1",
            "--aT", "0.9,1,1", "--tol", "1e-8", "--lambda-range", f"0:1:{points}", "--jobs", str(jobs), "--quiet"]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    result = subprocess.run(args, capture_output=True, text=True, check=False)
    process_s = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu_s = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if result.returncode != 0:
        sys.exit(f"cartan sweep --jobs {jobs} failed (exit {result.returncode}): {result.stderr.strip()}")
    table = json.loads(result.stdout)
    return table, process_s, cpu_s


def essentials(table):
    return [(r["status"], r["v0"], r["terminal_error"]) for r in table["rows"]]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cartan", default="build/cartan")
    parser.add_argument("--jobs", type=int, default=2, help="compared with --jobs 1")
    parser.add_argument("--points", type=int, default=16)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--N", type=int, default=1000)
    options = parser.parse_args()

    times = {1: [], options.jobs: []}
    reference = None
    for _ in range(options.repeat):
        for jobs in (1, options.jobs):
            table, process_s, cpu_s = sweep(options.cartan, jobs, options.points, options.N)
            if reference is None:
                reference = essentials(table)
            elif essentials(table) != reference:
                sys.exit(f"rows differ between runs (--jobs {jobs})")
            in_progress = sum(r["solve_time_s"] for r in table["rows"]) / table["wall_time_s"]
            times[jobs].append((table["wall_time_s"], process_s, cpu_s, in_progress))

    print(f"free body T = 50, N = {options.N}, {options.points} lambdas in [0, 1], median of {options.repeat}")
    print("| --jobs | sweep wall_time_s | process wall time | process CPU time | cores used (CPU / wall) "
          "| solves in progress | runs (sweep s) |")
    print("|---|---|---|---|---|---|---|")
    medians = {}
    for jobs, runs in times.items():
        medians[jobs] = [statistics.median(r[k] for r in runs) for k in range(4)]
        sweep_s, process_s, cpu_s, in_progress = medians[jobs]
        listed = ", ".join(f"{r[0]:.3f}" for r in runs)
        print(f"| {jobs} | {sweep_s:.3f} s | {process_s:.3f} s | {cpu_s:.3f} s | {cpu_s / process_s:.2f} | {in_progress:.2f} | {listed} |")
    one, many = medians[1], medians[options.jobs]
    print(f"speed-up --jobs {options.jobs} over --jobs 1: {one[0] / many[0]:.2f}x (sweep), "
          f"{one[1] / many[1]:.2f}x (process)")

if __name__ == "__main__":
    main()
