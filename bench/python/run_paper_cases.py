#!/usr/bin/python3
"""Run the paper's SO(3) cases with paper_scheme.py and print a Markdown table.

Cases: free body (T = 50, N = 1000, tol 1e-8) and oscillator (T = 12, N = 800, tol 1e-6) for
lambda = 0, 1/2, 1 from the paper's initial guess v0 = log(gT)/T, plus the oscillator at T = 3
(N = 200, same h). With --continuation also the oscillator continued in T from 3 to 12 at fixed
h = 0.015 (warm start of v0 and xi from the previous horizon; not part of the paper's scheme).

    /usr/bin/python3 bench/python/run_paper_cases.py [--jacobian forward] [--repeat 3]
                                                      [--continuation] [--json FILE]
"""
import argparse
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paper_scheme as ps  # noqa: E402

LAMBDAS = (0.0, 0.5, 1.0)


def run_case(name, case, lam, jacobian, repeat, max_outer, **over):
    kw = dict(case)
    kw.update(over)
    tol = kw.pop("tol")
    best = None
    for _ in range(repeat):
        p = ps.Problem(lam=lam, **kw)
        res = ps.solve(p, tol=tol, max_outer=max_outer, jacobian=jacobian)
        if best is None or res["solve_time_s"] < best["solve_time_s"]:
            best = res
    res = best
    return dict(case=name, model=kw["model"], lam=lam, T=kw["T"], N=kw["N"], tol=tol,
                status=res["status"], message=res["message"], outer=res["outer"],
                inner=res["inner"], jacobians=res["jacobians"], sweeps=res["sweeps"],
                terminal_error=res["terminal_error"], solve_time_s=res["solve_time_s"],
                cpu_time_s=res["cpu_time_s"], v0=res["v"][0].tolist(),
                ms_per_sweep=1e3 * res["cpu_time_s"] / max(res["sweeps"], 1))


def continuation(lam, jacobian, h=0.015, T_start=3.0, T_end=12.0, dT=0.5, max_outer=50):
    """Oscillator: solve at T_start, then at T + dT, up to T_end, warm-starting v0 and {xi_k}
    (xi interpolated in normalised time t/T; with xi restarted at 0 instead, lambda = 1/2 fails at
    T = 10)."""
    v0 = None
    xi_prev = None
    total_sweeps, total_time, total_cpu, steps = 0, 0.0, 0.0, 0
    T = T_start
    res = None
    while T <= T_end + 1e-12:
        p = ps.Problem(model="oscillator", lam=lam, T=T, N=int(round(T / h)),
                       a0=ps.PAPER_OSCILLATOR["a0"], aT=ps.PAPER_OSCILLATOR["aT"])
        xi0 = None
        if xi_prev is not None:
            s_old = np.linspace(0.0, 1.0, len(xi_prev))
            s_new = np.linspace(0.0, 1.0, p.N + 1)
            xi0 = np.column_stack([np.interp(s_new, s_old, xi_prev[:, i]) for i in range(3)])
        res = ps.solve(p, tol=ps.PAPER_OSCILLATOR["tol"], max_outer=max_outer, v0_guess=v0,
                       xi_guess=xi0, jacobian=jacobian)
        total_sweeps += res["sweeps"]
        total_time += res["solve_time_s"]
        total_cpu += res["cpu_time_s"]
        steps += 1
        if res["status"] != "converged":
            break
        v0 = res["v"][0]
        xi_prev = res["xi"]
        T += dT
    return dict(case="oscillator, continuation in T", model="oscillator", lam=lam,
                T=p.T, N=p.N, tol=ps.PAPER_OSCILLATOR["tol"], status=res["status"],
                message=res["message"] + f" ({steps} horizons, dT = {dT})",
                outer=res["outer"], inner=res["inner"], jacobians=res["jacobians"],
                sweeps=total_sweeps, terminal_error=res["terminal_error"],
                solve_time_s=total_time, cpu_time_s=total_cpu, v0=res["v"][0].tolist(),
                ms_per_sweep=1e3 * total_cpu / max(total_sweeps, 1))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--jacobian", choices=ps.JACOBIANS, default="minpack")
    ap.add_argument("--repeat", type=int, default=1, help="keep the fastest of R runs")
    ap.add_argument("--max-outer", type=int, default=50)
    ap.add_argument("--continuation", action="store_true")
    ap.add_argument("--only", choices=("free", "osc", "osc3"), default=None)
    ap.add_argument("--json", default=None, help="also write the rows as JSON here")
    args = ap.parse_args()

    rows = []
    todo = []
    if args.only in (None, "free"):
        todo += [("free body", ps.PAPER_FREE_BODY, {})]
    if args.only in (None, "osc"):
        todo += [("oscillator", ps.PAPER_OSCILLATOR, {})]
    if args.only in (None, "osc3"):
        todo += [("oscillator T=3", ps.PAPER_OSCILLATOR, dict(T=3.0, N=200))]
    for name, case, over in todo:
        for lam in LAMBDAS:
            rows.append(run_case(name, case, lam, args.jacobian, args.repeat, args.max_outer,
                                 **over))
            print(f"# done {name} lambda={lam}: {rows[-1]['status']}", file=sys.stderr)
    if args.continuation:
        for lam in LAMBDAS:
            rows.append(continuation(lam, args.jacobian, max_outer=args.max_outer))
            print(f"# done continuation lambda={lam}: {rows[-1]['status']}", file=sys.stderr)

    print(f"jacobian = {args.jacobian}; times: wall (perf_counter) of the solve, fastest of "
          f"{args.repeat}\n")
    print("| case | λ | T | N | status | outer | inner (nfev) | sweeps | terminal error "
          "| solve time [s] | CPU ms/sweep | v0 |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        v0 = ", ".join(f"{x:.10f}" for x in r["v0"])
        print(f"| {r['case']} | {r['lam']:g} | {r['T']:g} | {r['N']} | {r['status']} | "
              f"{r['outer']} | {r['inner']} | {r['sweeps']} | {r['terminal_error']:.2e} | "
              f"{r['solve_time_s']:.2f} | {r['ms_per_sweep']:.1f} | ({v0}) |")
    for r in rows:
        if r["status"] != "converged":
            print(f"\n* {r['case']}, λ = {r['lam']:g}: {r['message']}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
