#!/usr/bin/python3
"""cartan.solve_bvp against scipy.integrate.solve_bvp (issue 14), side by side in one process, in
CPU time, warm, alternating the two case by case and round by round.

The problems (bench/python/bvp_cases.py, from SciPy's own tests and the contract suite
python/tests/test_solve_bvp_contract.py): small systems (exp, Ascher's y'' = 3/2 y^2, Bratu's
upper branch), unknown parameters (Bratu's and the Sturm-Liouville eigenvalue, Mathieu's a_4(5)),
the singular term S (Emden), the shock layer at tol 1e-3 .. 1e-6 (108 .. 645 nodes), nonlinear
boundary conditions (Butler-Volmer), big systems (SciPy's 60 components; Bratu on the unit square
by the method of lines, 32 coupled components) and a complex problem. Every fun is vectorised
(x (m,), y (n, m)); most cases give fun_jac and bc_jac, the "no Jacobians" ones leave both to
finite differences. Both sides get identical inputs (fresh copies of the same arrays, the same
functions, tol and max_nodes) and SciPy's default for everything else.

Timing: CPU time (time.process_time) of the solve call alone. One untimed warm-up solve of every
case on each side (also the screening: a case where a side raises is reported, not timed; its
time sets how many solves make one sample, at least --min-time of CPU time, so that a 1 ms solve
is not measured by one clock reading). Then --rounds rounds; each visits every case and times
both sides, SciPy first when round + case index is even, cartan first otherwise, so that both see
the same machine load. Per case and side: the median of the rounds' samples (each sample the mean
over its solves). Reported per case: both medians, the ratio SciPy / cartan, both final node
counts (res.x.size) and statuses, and how far the two solutions are apart: max over 201 uniform
points of [a, b] and over components of |y_cartan - y_scipy| / (1 + |y_scipy|) (and likewise
for p), in units of tol (both solutions are within K tol of the exact one, K of order 1-10 for
these problems, so a figure above ~10 means they disagree). Summary: the median and minimum ratio
over the cases both sides solve (status 0), and over those whose final mesh (SciPy's) has >= 100
nodes; issue 14's goal is a ratio > 1 on every case and >= 3 on those.

BLAS: limited to one thread (OPENBLAS_NUM_THREADS, OMP_NUM_THREADS, MKL_NUM_THREADS = 1 unless
already set, before NumPy is imported), so that process_time is the solve's own work; the header
names the BLAS library loaded and warns when a thread variable says otherwise.

Usage: /usr/bin/python3 bench/compare_solve_bvp.py [--module build/python] [--rounds 5]
       [--min-time 0.05] [--markdown FILE] [--quick]
"""
import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import argparse  # noqa: E402
import math  # noqa: E402
import platform  # noqa: E402
import statistics  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
import scipy  # noqa: E402
import scipy.integrate  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "bench" / "python"))
import bvp_cases  # noqa: E402

SAMPLES = 201
BLAS_THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")


def blas_note():
    """The BLAS libraries mapped into this process and the thread variables; a warning when one of
    them allows more than one thread (process_time then counts BLAS's helper threads too)."""
    libraries = set()
    try:
        with open("/proc/self/maps") as maps:
            for line in maps:
                base = os.path.basename(line.split()[-1]).lower()
                if base.startswith("lib") and ("blas" in base or "lapack" in base):
                    libraries.add(os.path.realpath(line.split()[-1]))
    except OSError:
        pass
    variables = ", ".join(f"{v}={os.environ.get(v)}" for v in BLAS_THREAD_VARIABLES)
    text = f"BLAS: {', '.join(sorted(libraries)) or 'unknown'}; {variables}"
    if any(os.environ.get(v, "1") != "1" for v in BLAS_THREAD_VARIABLES):
        text += (" - CAVEAT: more than one BLAS thread allowed; CPU time then includes idle-spinning helper "
                 "threads (unset them or set them to 1)")
    return text


def fun_call_width(cartan):
    """The largest number of points cartan passed to fun in one call on a 5-node exp solve: 5 or
    more for a module calling fun on whole mesh sweeps, 1 for an older one (point by point)."""
    widths = []

    def fun(x, y):
        widths.append(np.shape(x)[0] if np.ndim(x) else 1)
        return bvp_cases.exp_fun(x, y)

    cartan.solve_bvp(fun, bvp_cases.exp_bc, np.linspace(0, 1, 5), np.zeros((2, 5)))
    return max(widths)


def timed(solver, case, solves):
    """CPU time per solve (mean over `solves` solves, each on fresh copies of the inputs made before
    the clock starts) and the last result."""
    inputs = [bvp_cases.arguments(case) for _ in range(solves)]
    start = time.process_time()
    for args, kwargs in inputs:
        res = solver(*args, **kwargs)
    return (time.process_time() - start) / solves, res


def agreement(case, rs, rc):
    """(max |y_c - y_s|, max |y_c - y_s| / (1 + |y_s|) / tol) at SAMPLES uniform points of [a, b],
    with p's difference included likewise."""
    grid = np.linspace(case["x"][0], case["x"][-1], SAMPLES)
    ys, yc = rs.sol(grid), rc.sol(grid)
    diff = np.abs(yc - ys)
    scaled = float(np.max(diff / (1 + np.abs(ys))))
    absolute = float(np.max(diff))
    if rs.p is not None and rc.p is not None:
        dp = np.abs(np.asarray(rc.p) - np.asarray(rs.p))
        absolute = max(absolute, float(np.max(dp)))
        scaled = max(scaled, float(np.max(dp / (1 + np.abs(rs.p)))))
    return absolute, scaled / case["tol"]


def size_label(case):
    n = case["y"].shape[0]
    k = 0 if case["p"] is None else len(case["p"])
    return f"{n}" + (f" + {k}" if k else "")


def ratio_summary(label, rows):
    if not rows:
        return f"{label}: no case."
    ratios = [r["ratio"] for r in rows]
    worst = min(rows, key=lambda r: r["ratio"])
    return (f"{label}: median **{statistics.median(ratios):.2f}×**, minimum **{worst['ratio']:.2f}×** "
            f"({worst['name']}), maximum {max(ratios):.2f}× over {len(rows)} cases.")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--module", default=str(ROOT / "build" / "python"),
                        help="directory holding the cartan package (prepended to sys.path); default build/python")
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--min-time", type=float, default=0.05,
                        help="CPU seconds a sample should last at least (repeated solves, averaged)")
    parser.add_argument("--markdown", help="write the table and summary to this file")
    parser.add_argument("--quick", action="store_true", help="one round, short samples: a smoke test")
    args = parser.parse_args()
    if args.quick:
        args.rounds, args.min_time = 1, 0.01
    sys.path.insert(0, args.module)
    import cartan  # noqa: E402

    solvers = {"scipy": scipy.integrate.solve_bvp, "cartan": cartan.solve_bvp}
    cases = bvp_cases.cases()
    # Imports done on first use (cartan's solve_bvp imports scipy.optimize) and first-call costs
    # fall here, outside every case's figures.
    for solver in solvers.values():
        timed(solver, cases[0], 1)
    width = fun_call_width(cartan)

    # Warm-up and screening: one untimed solve per case and side; sets the solves per sample.
    solves, failed, timed_cases = {}, [], []
    for i, case in enumerate(cases):
        try:
            for side, solver in solvers.items():
                seconds, _ = timed(solver, case, 1)
                solves[i, side] = max(1, min(1000, math.ceil(args.min_time / max(seconds, 1e-6))))
            timed_cases.append(i)
        except Exception as error:  # noqa: BLE001 - reported, the case is not timed
            failed.append(f"{case['name']}: {side} raised {type(error).__name__}: {error}")
        print(f"# warm-up {i + 1}/{len(cases)}: {case['name']}", file=sys.stderr)

    samples = {(i, side): [] for i in timed_cases for side in solvers}
    last = {}
    for r in range(args.rounds):
        for i in timed_cases:
            order = ["scipy", "cartan"] if (r + i) % 2 == 0 else ["cartan", "scipy"]
            for side in order:
                seconds, res = timed(solvers[side], cases[i], solves[i, side])
                samples[i, side].append(seconds)
                last[i, side] = res
        print(f"# round {r + 1}/{args.rounds} done", file=sys.stderr)

    rows = []
    for i in timed_cases:
        case = cases[i]
        rs, rc = last[i, "scipy"], last[i, "cartan"]
        s, c = statistics.median(samples[i, "scipy"]), statistics.median(samples[i, "cartan"])
        absolute, relative = agreement(case, rs, rc)
        rows.append(dict(name=case["name"], size=size_label(case), tol=case["tol"], scipy=s, cartan=c, ratio=s / c,
                         nodes=(rs.x.size, rc.x.size), status=(rs.status, rc.status), diff=absolute,
                         diff_tol=relative, solves=(solves[i, "scipy"], solves[i, "cartan"])))

    lines = [
        f"cartan.solve_bvp ({Path(cartan.__file__).parent}) against scipy.integrate.solve_bvp (SciPy "
        f"{scipy.__version__}, NumPy {np.__version__}, Python {platform.python_version()}); CPU time "
        f"(time.process_time), warm, {args.rounds} alternating round{'s' if args.rounds != 1 else ''}, "
        "median per case and side.",
        "",
        f"cartan calls fun on up to {width} points at once"
        + (" (whole mesh sweeps)." if width > 1 else
           " - an older module calling fun point by point: its times are not issue 14's solver's."),
        "",
        blas_note() + ".",
        "",
        "| case | n (+ k) | tol | SciPy [ms] | cartan [ms] | SciPy / cartan | nodes SciPy / cartan "
        "| status SciPy / cartan | max abs diff | diff / tol |",
        "|" + "---|" * 10,
    ]
    for row in rows:
        lines.append(f"| {row['name']} | {row['size']} | {row['tol']:.0e} | {row['scipy'] * 1e3:.2f} | "
                     f"{row['cartan'] * 1e3:.2f} | {row['ratio']:.2f}× | {row['nodes'][0]} / {row['nodes'][1]} | "
                     f"{row['status'][0]} / {row['status'][1]} | {row['diff']:.1e} | {row['diff_tol']:.2g} |")
    lines.append("")
    lines.append(f"diff / tol: max over {SAMPLES} uniform points and the components of |y_cartan - y_scipy| / "
                 f"(1 + |y_scipy|) (p included), over tol. Solves per sample (SciPy, cartan): "
                 + ", ".join(f"{row['solves'][0]}/{row['solves'][1]}" for row in rows) + ".")
    lines.append("")
    solved = [row for row in rows if row["status"] == (0, 0)]
    big = [row for row in solved if row["nodes"][0] >= 100]
    lines.append(ratio_summary("Ratio SciPy / cartan (CPU time), every case both solve", solved))
    lines.append("")
    lines.append(ratio_summary("Ratio SciPy / cartan, final mesh (SciPy's) >= 100 nodes", big))
    lines.append("")
    slower = [row["name"] for row in solved if row["ratio"] <= 1]
    below3 = [row["name"] for row in big if row["ratio"] < 3]
    goal = not slower and not below3 and len(solved) == len(cases)
    lines.append(f"Issue 14's goal (faster than SciPy on every problem, >= 3× where the mesh has >= 100 nodes): "
                 f"{'met' if goal else 'not met'}"
                 + (f"; not faster: {'; '.join(slower)}" if slower else "")
                 + (f"; below 3× at >= 100 nodes: {'; '.join(below3)}" if below3 else "") + ".")
    disagree = [row["name"] for row in rows if not row["diff_tol"] <= 10]
    if disagree:
        lines.append("")
        lines.append(f"Solutions further apart than 10 tol: {'; '.join(disagree)}.")
    for row in rows:
        if row["status"] != (0, 0):
            lines.append("")
            lines.append(f"Not in the ratios (a side's status is not 0): {row['name']}, statuses {row['status']}.")
    for text in failed:
        lines.append("")
        lines.append(f"Not timed: {text}")
    text = "\n".join(lines)
    print(text)
    if args.markdown:
        Path(args.markdown).parent.mkdir(parents=True, exist_ok=True)
        Path(args.markdown).write_text(text + "\n")


if __name__ == "__main__":
    main()
