#!/usr/bin/python3
"""Side-by-side timing of cartan (C++) and the Python/NumPy/SciPy baseline (bench/python) on the
paper's six SO(3) cases, in one run, alternating the two so that both see the same machine load.

For each case: the Python two-level scheme (for the oscillator at T = 12, where it does not
converge from the paper's guess, the Python continuation in T that reaches it), cartan's two-level
scheme (the same algorithm) and cartan's default method (`--method auto`: augmented shooting
with an analytic Jacobian, then continuation in T, ... as include/cartan/transported/solve.hpp). Times are the solvers' own solve_time_s (no start-up, no
I/O); each figure is the fastest of --repeat runs. Ratios = Python time / cartan time.

Usage: /usr/bin/python3 bench/compare_with_python.py [--cartan build/cartan] [--repeat 3] [--markdown FILE]
"""
import argparse
import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "bench" / "python"))
import paper_scheme as ps  # noqa: E402
import run_paper_cases as rpc  # noqa: E402

CASES = [("free body", "free-rigid-body", ps.PAPER_FREE_BODY), ("oscillator", "oscillator", ps.PAPER_OSCILLATOR)]


def cartan(binary, model, case, lam, method):
    a0 = ",".join(str(x) for x in case["a0"])
    aT = ",".join(str(x) for x in case["aT"])
    args = [binary, "solve", "--model", model, "--lambda", str(lam), "--T", str(case["T"]), "--N", str(case["N"]),
            f"--a0={a0}", f"--aT={aT}", "--tol", str(case["tol"]), "--method", method]
    out = subprocess.run(args, capture_output=True, text=True, check=False)
    if out.returncode == 2:
        raise SystemExit(out.stderr)
    return json.loads(out.stdout)


def fastest(runs, key="solve_time_s"):
    return min(runs, key=lambda r: r[key])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cartan", default=str(ROOT / "build" / "cartan"))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--markdown", default=None)
    args = ap.parse_args()
    rows = []
    for name, model, case in CASES:
        for lam in (0.0, 0.5, 1.0):
            py_runs, two_runs, shoot_runs = [], [], []
            for _ in range(args.repeat):
                if model == "oscillator":
                    py_runs.append(rpc.continuation(lam, "minpack"))
                    py_runs[-1]["method"] = "continuation in T (two-level per horizon)"
                else:
                    res = ps.solve(ps.Problem(model=model, lam=lam, T=case["T"], N=case["N"], a0=case["a0"],
                                              aT=case["aT"]), tol=case["tol"])
                    py_runs.append(dict(status=res["status"], solve_time_s=res["solve_time_s"], sweeps=res["sweeps"],
                                        method="two-level"))
                two_runs.append(cartan(args.cartan, model, case, lam, "two-level"))
                shoot_runs.append(cartan(args.cartan, model, case, lam, "auto"))
            py, two, shoot = fastest(py_runs), fastest(two_runs), fastest(shoot_runs)
            rows.append(dict(case=name, lam=lam, py=py, two=two, shoot=shoot))
            print(f"# {name} lambda={lam}: python {py['status']} {py['solve_time_s']:.3f}s, "
                  f"cartan two-level {two['status']} {two['solve_time_s']:.4f}s, "
                  f"default (auto) {shoot['status']} {shoot['solve_time_s']:.4f}s", file=sys.stderr)

    def ratio(py, c):
        ok = py["status"] == "converged" and c["status"] == "converged"
        return f"{py['solve_time_s'] / c['solve_time_s']:.0f}x" if ok else "n/a"

    lines = ["| case | λ | Python (method, status) | Python s | sweeps | cartan two-level s | sweeps | ratio | "
             "cartan default (auto) s | sweeps | ratio |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        py, two, shoot = r["py"], r["two"], r["shoot"]
        lines.append(f"| {r['case']} | {r['lam']:g} | {py['method']}, {py['status']} | {py['solve_time_s']:.3f} | "
                     f"{py['sweeps']} | {two['solve_time_s']:.4f} ({two['status']}) | {two['iterations']['sweeps']} | "
                     f"{ratio(py, two)} | {shoot['solve_time_s']:.4f} | {shoot['iterations']['sweeps']} | "
                     f"{ratio(py, shoot)} |")
    text = "\n".join(lines)
    print(text)
    if args.markdown:
        Path(args.markdown).write_text(text + "\n")


if __name__ == "__main__":
    main()
