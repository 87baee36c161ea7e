"""How promptly a solve stops (issue 29): `time_limit` against the time the call really took, for
every method, and the time from Ctrl-C to the end of `cartan.sweep` on threads, `cartan sweep` and
`cartan solve`. These are wall-clock figures by nature (the feature is about wall time): run them
on an otherwise idle machine and read the ratios.

    PYTHONPATH=build/python /usr/bin/python3 bench/interruption.py --cartan build/cartan
"""
import argparse
import os
import signal
import subprocess
import sys
import textwrap
import time

import cartan
import numpy as np

INERTIA = [2.0, 3.0, 4.0]
GT = cartan.SO3.minimal_rotation([-0.7, -1, -0.7], [0.8, 0.8, 1])
LONG = dict(lagrangian=cartan.SO3Oscillator(INERTIA), lam=0.5, T=12, gT=GT)
# Each runs far longer than the limits below; N sets the length of one iteration.
CASES = [
    ("auto", dict(N=2_000_000)),
    ("shooting", dict(N=2_000_000, tol=1e-13, continuation="T")),
    ("multiple-shooting", dict(N=2_000_000)),
    ("two-level", dict(N=2_000_000)),
    ("collocation", dict(N=800, tol=1e-12)),
    ("variational", dict(N=500, tol=1e-13)),
]
SPHERE = dict(T=1.0, N=2_000_000, q0=cartan.Sphere.point([1, 0, -0.3]), qT=cartan.Sphere.point([0, 1, -0.5]),
              gravity=9.81, tol=1e-13)


def half_plane_christoffel(q):
    """The Poincare half-plane's Levi-Civita symbols, christoffel[k, i, j] = Gamma^k_ij."""
    g = np.zeros((2, 2, 2))
    g[0, 0, 1] = g[0, 1, 0] = g[1, 1, 1] = -1 / q[1]
    g[1, 0, 0] = 1 / q[1]
    return g


# A space and a potential of Python callbacks (a step takes milliseconds, not microseconds): polls
# between steps must adapt to that pace (issue 44).
CHART = dict(T=50.0, N=2000, q0=[-0.5, 0.8], qT=[1.2, 1.6], frame0=0.8 * np.eye(2), tol=1e-13,
             potential=lambda q: 0.5 * q[0] ** 2, potential_gradient=lambda q: np.array([q[0], 0.0]))


def timed(solve, **kwargs):
    """The result and the wall time of the whole Python call (what time_limit bounds)."""
    start = time.perf_counter()
    r = solve(**kwargs)
    return r, time.perf_counter() - start


def time_limits(limits):
    print("| method | N | limit (s) | solve_time (s) | the call (s) | the call's overshoot |")
    print("|---|---|---|---|---|---|")
    for limit in limits:
        for method, extra in CASES:
            r, call = timed(cartan.solve, **LONG, method=method, time_limit=limit, **extra)
            if r.status != "time-limit":  # ended by itself before the limit: nothing to measure
                print(f"| {method} | {extra['N']} | {limit:g} | {r.solve_time:.3f} ({r.status}) | {call:.3f} | - |")
                continue
            print(f"| {method} | {extra['N']} | {limit:g} | {r.solve_time:.3f} | {call:.3f} | {call / limit - 1:+.1%} |")
        r, call = timed(cartan.solve_general, manifold=cartan.Sphere(), time_limit=limit, **SPHERE)
        assert r.status == "time-limit", r.status
        print(f"| solve_general (sphere, auto) | {SPHERE['N']} | {limit:g} | {r.solve_time:.3f} | {call:.3f} | "
              f"{call / limit - 1:+.1%} |")
        chart = cartan.Chart(half_plane_christoffel, dim=2, name="half-plane")
        for method in ("shooting", "collocation", "auto"):
            r, call = timed(cartan.solve, space=chart, method=method, time_limit=limit, **CHART)
            print(f"| Chart of Python callbacks, {method} | {CHART['N']} | {limit:g} | {r.solve_time:.3f} "
                  f"({r.status}) | {call:.3f} | {call / limit - 1:+.1%} |")


SWEEP_CHILD = textwrap.dedent("""
    import sys, time, cartan
    gT = cartan.SO3.minimal_rotation([-0.7, -1, -0.7], [0.8, 0.8, 1])
    problems = [dict(lagrangian=cartan.SO3Oscillator([2, 3, 4]), lam=lam, T=12, N=2_000_000, gT=gT,
                     method="two-level") for lam in (0.25, 0.5, 0.75, 1.0)]
    print("ready", flush=True)
    try:
        cartan.sweep(problems)
    except KeyboardInterrupt:
        print(time.monotonic(), flush=True)
""")


def sweep_latency(delay):
    child = subprocess.Popen([sys.executable, "-c", SWEEP_CHILD], stdout=subprocess.PIPE, text=True,
                             env=dict(os.environ))
    assert child.stdout.readline().strip() == "ready"
    time.sleep(delay)
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    raised = float(child.stdout.readline())
    child.wait(timeout=120)
    return raised - sent


def cli_latency(cartan_bin, args, delay):
    process = subprocess.Popen([cartan_bin, *args], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    time.sleep(delay)
    sent = time.monotonic()
    process.send_signal(signal.SIGINT)
    process.wait(timeout=120)
    assert process.returncode == 130, process.returncode
    return time.monotonic() - sent


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cartan", default="build/cartan")
    parser.add_argument("--limits", default="1,10")
    parser.add_argument("--skip-limits", action="store_true", help="only the Ctrl-C latencies")
    args = parser.parse_args()
    if not args.skip_limits:
        time_limits([float(x) for x in args.limits.split(",")])
        print()
    print("| after Ctrl-C at | cartan.sweep (threads) | cartan sweep | cartan solve |")
    print("|---|---|---|---|")
    long_cli = ["--model", "oscillator", "--lambda", "0.5", "--T", "12", "--N", "2000000", "--method", "two-level",
                "--a0", "-0.7,-1,-0.7", "--aT", "0.8,0.8,1"]
    sweep_cli = ["sweep", *long_cli[:2], *long_cli[4:], "--lambdas", "0.25,0.5", "--jobs", "2", "--quiet"]
    for delay in (1.0, 3.0):
        print(f"| {delay:g} s | {sweep_latency(delay):.3f} s | {cli_latency(args.cartan, sweep_cli, delay):.3f} s | "
              f"{cli_latency(args.cartan, ['solve', *long_cli], delay):.3f} s |")


if __name__ == "__main__":
    main()
