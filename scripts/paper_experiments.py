#!/usr/bin/python3
"""Reproduces the paper's numerical experiments with the `cartan` CLI and draws its (empty)
figures: the six SO(3) cases (free rigid body, harmonic oscillator; lambda = 0, 1/2, 1) and the
H3 oscillator for several endpoints. Writes out/*.json, out/*.png and prints a summary table.

Usage: /usr/bin/python3 scripts/paper_experiments.py BUILD_DIR OUT_DIR
"""
import json
import subprocess
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

LAMBDAS = (0.0, 0.5, 1.0)
# The paper's styles: red dashed (0), green solid (1/2), blue dotted (1) on the sphere;
# dashed blue (0), solid green (1/2), dash-dotted red (1) for H3.
SPHERE_STYLE = {0.0: ("tab:red", "--"), 0.5: ("tab:green", "-"), 1.0: ("tab:blue", ":")}
H3_STYLE = {0.0: ("tab:blue", "--"), 0.5: ("tab:green", "-"), 1.0: ("tab:red", "-.")}
SO3_CASES = {
    "free-rigid-body": dict(T=50, N=1000, tol=1e-8, a0=(-1, -1, -1), aT=(0.9, 1.0, 1.0)),
    "oscillator": dict(T=12, N=800, tol=1e-6, a0=(-0.7, -1.0, -0.7), aT=(0.8, 0.8, 1.0)),
}
H3_ENDPOINTS = [(1.0, 0.5, 0.8), (-0.6, 1.0, 0.4), (0.8, -0.7, -0.5)]


def solve(cartan, out_file, *args):
    result = subprocess.run([cartan, "solve", *args, "--output", str(out_file)], capture_output=True, text=True)
    if result.returncode == 2:
        raise SystemExit(result.stderr)
    return json.loads(Path(out_file).read_text())


def csv(x):
    return ",".join(repr(float(v)) for v in x)


def sphere_axes(ax):
    u, v = np.mgrid[0:2 * np.pi:40j, 0:np.pi:20j]
    ax.plot_wireframe(np.cos(u) * np.sin(v), np.sin(u) * np.sin(v), np.cos(v), color="0.85", linewidth=0.4)
    ax.set_box_aspect((1, 1, 1))
    ax.set_xlabel("$x$"), ax.set_ylabel("$y$"), ax.set_zlabel("$z$")


def main():
    build, out = Path(sys.argv[1]), Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    cartan = str(build / "cartan")
    rows = []
    for model, case in SO3_CASES.items():
        fig = plt.figure(figsize=(6, 6))
        ax = fig.add_subplot(projection="3d")
        sphere_axes(ax)
        a0 = np.array(case["a0"]) / np.linalg.norm(case["a0"])
        for lam in LAMBDAS:
            name = f"so3_{model}_lambda{lam:g}"
            d = solve(cartan, out / f"{name}.json", "--model", model, "--lambda", str(lam), "--T", str(case["T"]),
                      "--N", str(case["N"]), f"--a0={csv(case['a0'])}", f"--aT={csv(case['aT'])}",
                      "--tol", str(case["tol"]))
            rows.append((f"SO(3) {model}", lam, d))
            g = np.array(d["g"]).reshape(-1, 3, 3)
            a = g @ a0  # a(t) = g(t) a0, the body-fixed vector in space
            color, style = SPHERE_STYLE[lam]
            ax.plot(a[:, 0], a[:, 1], a[:, 2], color=color, linestyle=style, linewidth=1.6, label=f"$\\lambda={lam:g}$")
        aT = np.array(case["aT"]) / np.linalg.norm(case["aT"])
        ax.scatter(*np.array([a0, aT]).T, color="black", s=30, depthshade=False)
        ax.set_title({"free-rigid-body": "Free rigid body", "oscillator": "Harmonic oscillator"}[model] +
                     f" on SO(3), $T={case['T']}$")
        ax.legend(loc="upper left")
        fig.tight_layout()
        fig.savefig(out / f"fig_so3_{model}.png", dpi=150)
        plt.close(fig)

    fig = plt.figure(figsize=(6 * len(H3_ENDPOINTS), 5.5))
    for i, gT in enumerate(H3_ENDPOINTS):
        ax = fig.add_subplot(1, len(H3_ENDPOINTS), i + 1, projection="3d")
        for lam in LAMBDAS:
            name = f"h3_oscillator_end{i}_lambda{lam:g}"
            d = solve(cartan, out / f"{name}.json", "--group", "heisenberg", "--model", "oscillator", "--lambda",
                      str(lam), "--T", "1", "--N", "400", "--gT", csv(gT), "--tol", "1e-10", "--order", "2")
            rows.append((f"H3 oscillator gT={gT}", lam, d))
            g = np.array(d["g"])
            color, style = H3_STYLE[lam]
            ax.plot(g[:, 0], g[:, 1], g[:, 2], color=color, linestyle=style, linewidth=1.6, label=f"$\\lambda={lam:g}$")
        ax.scatter([0], [0], [0], marker="o", facecolors="none", edgecolors="black", s=40, depthshade=False)
        ax.scatter([gT[0]], [gT[1]], [gT[2]], marker="s", color="black", s=30, depthshade=False)
        ax.set_xlabel("$a$"), ax.set_ylabel("$b$"), ax.set_zlabel("$c$")
        ax.set_title(f"$g_T = ({gT[0]:g}, {gT[1]:g}, {gT[2]:g})$")
        ax.legend(loc="upper left")
    fig.suptitle("Harmonic oscillator on the Heisenberg group, $T = 1$")
    fig.tight_layout()
    fig.savefig(out / "fig_heisenberg.png", dpi=150)
    plt.close(fig)

    print(f"{'problem':<34} {'lambda':>6} {'status':<10} {'sweeps':>6} {'terminal error':>14} {'time [s]':>9}  branch")
    for name, lam, d in rows:
        print(f"{name:<34} {lam:>6g} {d['status']:<10} {d['iterations']['sweeps']:>6} {d['terminal_error']:>14.2e} "
              f"{d['solve_time_s']:>9.4f}  {d['branch']}")
    print(f"figures: {out}/fig_so3_free-rigid-body.png, {out}/fig_so3_oscillator.png, {out}/fig_heisenberg.png")
    if any(d["status"] != "converged" for _, _, d in rows):
        raise SystemExit("some experiments did not converge")


if __name__ == "__main__":
    main()
