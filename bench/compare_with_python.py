#!/usr/bin/python3
"""Side-by-side timing of cartan (C++, through its Python module, in process) and the
Python/NumPy/SciPy baseline (bench/python) on the paper's six SO(3) cases, in one run,
alternating the two so that both see the same machine load.

For each case: the Python two-level scheme (for the oscillator at T = 12, where it does not
converge from the paper's guess, the Python continuation in T that reaches it), cartan's two-level
scheme (the same algorithm) and cartan's default method (`method="auto"`: augmented shooting
with an analytic Jacobian, then continuation in T, ... as include/cartan/methods/lie_group/solve.hpp).
Times are CPU time of the solve alone (the baseline's time.process_time, which counts NumPy's
threads; cartan's time.thread_time around `cartan.solve`, which runs in the calling thread), so
that the figures do not depend on the load of the shared machine; each is the fastest of
--repeat runs. Ratios = Python time / cartan time.

Usage: /usr/bin/python3 bench/compare_with_python.py [--module build/python] [--repeat 3] [--markdown FILE]
"""
import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "bench" / "python"))
import paper_scheme as ps  # noqa: E402
import run_paper_cases as rpc  # noqa: E402

CASES = [("free body", "free-rigid-body", ps.PAPER_FREE_BODY), ("oscillator", "oscillator", ps.PAPER_OSCILLATOR)]


def direction(a):
    a = np.asarray(a, dtype=float)
    return a / np.linalg.norm(a)


def cartan_solve(cartan, model, case, lam, method):
    """One solve through the module; CPU time of the call (thread_time) and the result."""
    inertia = np.diag([2.0, 3.0, 4.0])  # the paper's
    lagrangian = cartan.RigidBody(inertia) if model == "free-rigid-body" else cartan.SO3Oscillator(inertia)
    gT = cartan.SO3.minimal_rotation(direction(case["a0"]), direction(case["aT"]))
    start = time.thread_time()
    r = cartan.solve(lagrangian, lam=lam, T=case["T"], N=case["N"], gT=gT, tol=case["tol"], method=method)
    cpu = time.thread_time() - start
    return dict(status=r.status, cpu_time_s=cpu, sweeps=r.sweeps)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--module", default=str(ROOT / "build" / "python"), help="directory of the cartan module")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--markdown", default=None)
    args = ap.parse_args()
    sys.path.insert(0, args.module)
    import cartan  # noqa: E402
    rows = []
    for name, model, case in CASES:
        for lam in (0.0, 0.5, 1.0):
            py_runs, two_runs, auto_runs = [], [], []
            for _ in range(args.repeat):
                if model == "oscillator":
                    py_runs.append(rpc.continuation(lam, "minpack"))
                    py_runs[-1]["method"] = "continuation in T (two-level per horizon)"
                else:
                    res = ps.solve(ps.Problem(model=model, lam=lam, T=case["T"], N=case["N"], a0=case["a0"],
                                              aT=case["aT"]), tol=case["tol"])
                    py_runs.append(dict(status=res["status"], cpu_time_s=res["cpu_time_s"], sweeps=res["sweeps"],
                                        method="two-level"))
                two_runs.append(cartan_solve(cartan, model, case, lam, "two-level"))
                auto_runs.append(cartan_solve(cartan, model, case, lam, "auto"))
            py, two, auto = (min(runs, key=lambda r: r["cpu_time_s"]) for runs in (py_runs, two_runs, auto_runs))
            rows.append(dict(case=name, lam=lam, py=py, two=two, auto=auto))
            print(f"# {name} lambda={lam}: python {py['status']} {py['cpu_time_s']:.3f}s, "
                  f"cartan two-level {two['status']} {two['cpu_time_s']:.5f}s, "
                  f"default (auto) {auto['status']} {auto['cpu_time_s']:.5f}s", file=sys.stderr)

    def ratio(py, c):
        ok = py["status"] == "converged" and c["status"] == "converged"
        return f"{py['cpu_time_s'] / c['cpu_time_s']:.0f}×" if ok else "n/a"

    lines = ["| case | λ | Python (method, status) | Python CPU s | sweeps | cartan two-level CPU ms | sweeps | ratio | "
             "cartan default (auto) CPU ms | sweeps | ratio |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        py, two, auto = r["py"], r["two"], r["auto"]
        lines.append(f"| {r['case']} | {r['lam']:g} | {py['method']}, {py['status']} | {py['cpu_time_s']:.3f} | "
                     f"{py['sweeps']} | {1e3 * two['cpu_time_s']:.2f} ({two['status']}) | {two['sweeps']} | "
                     f"{ratio(py, two)} | {1e3 * auto['cpu_time_s']:.2f} | {auto['sweeps']} | {ratio(py, auto)} |")
    text = "\n".join(lines)
    print(text)
    if args.markdown:
        Path(args.markdown).write_text(text + "\n")


if __name__ == "__main__":
    main()
