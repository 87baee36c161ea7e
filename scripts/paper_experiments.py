#!/usr/bin/python3
"""Reproduces the paper's numerical experiments with the cartan Python module and draws its
(empty) figures: the six SO(3) cases (free rigid body, harmonic oscillator; lambda = 0, 1/2, 1)
and the H3 oscillator for several endpoints. Writes out/*.png, out/paper_experiments.json and
prints a summary table.

Usage: /usr/bin/python3 scripts/paper_experiments.py BUILD_DIR OUT_DIR
(BUILD_DIR/python holds the built package; see docs/reference.md "The Python module").
"""
import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402

LAMBDAS = (0.0, 0.5, 1.0)
LABELS = {0.0: r"$\lambda = 0$", 0.5: r"$\lambda = \frac{1}{2}$", 1.0: r"$\lambda = 1$"}
# The paper's styles: red dashed (0), green solid (1/2), blue dotted (1) on the sphere;
# dashed blue (0), solid green (1/2), dash-dotted red (1) for H3.
SPHERE_STYLE = {0.0: ("#d62728", "--"), 0.5: ("#2ca02c", "-"), 1.0: ("#1f77b4", ":")}
H3_STYLE = {0.0: ("#1f77b4", "--"), 0.5: ("#2ca02c", "-"), 1.0: ("#d62728", "-.")}
INERTIA = (2.0, 3.0, 4.0)
SO3_CASES = {
    "free-rigid-body": dict(title="Free rigid body", T=50, N=1000, tol=1e-8, a0=(-1, -1, -1), aT=(0.9, 1.0, 1.0)),
    "oscillator": dict(title="Harmonic oscillator", T=12, N=800, tol=1e-6, a0=(-0.7, -1.0, -0.7), aT=(0.8, 0.8, 1.0)),
}
H3_ENDPOINTS = [(1.0, 0.5, 0.8), (-0.6, 1.0, 0.4), (0.8, -0.7, -0.5)]

plt.rcParams.update({"font.size": 11, "axes.titlesize": 12, "legend.fontsize": 10, "mathtext.fontset": "cm"})


def unit(x):
    x = np.asarray(x, dtype=float)
    return x / np.linalg.norm(x)


def clean_panes(ax):
    """White panes and light grid lines (print-friendly)."""
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        axis.set_pane_color((1.0, 1.0, 1.0, 0.0))
        axis._axinfo["grid"].update(color="0.9", linewidth=0.5)


def sphere_axes(fig, position):
    ax = fig.add_subplot(position, projection="3d")
    clean_panes(ax)
    u, v = np.mgrid[0:2 * np.pi:37j, 0:np.pi:19j]
    ax.plot_wireframe(np.cos(u) * np.sin(v), np.sin(u) * np.sin(v), np.cos(v), color="0.82", linewidth=0.35)
    ax.set_box_aspect((1, 1, 1))
    for axis in "xyz":
        getattr(ax, f"set_{axis}lim")(-1, 1)
        getattr(ax, f"set_{axis}ticks")([-1, 0, 1])
    ax.set_xlabel("$x$"), ax.set_ylabel("$y$"), ax.set_zlabel("$z$")
    return ax


def finish_sphere_figure(fig, ax, endpoints, title, path, view, legend_size=None):
    """Marks and names the endpoints (name -> point on the sphere), sets view, title and legend, saves."""
    ax.scatter(*np.array(list(endpoints.values())).T, color="black", s=36, depthshade=False, zorder=5)
    for name, point in endpoints.items():
        ax.text(*(1.12 * np.asarray(point)), name, fontsize=12)
    ax.view_init(elev=view[0], azim=view[1])
    ax.set_title(title)
    ax.legend(loc="upper left", frameon=False, fontsize=legend_size)
    fig.tight_layout()
    fig.savefig(path, dpi=160)
    plt.close(fig)


def so3_figure(cartan, model_name, case, out, rows):
    model = {"free-rigid-body": cartan.RigidBody, "oscillator": cartan.SO3Oscillator}[model_name](INERTIA)
    a0, aT = unit(case["a0"]), unit(case["aT"])
    gT = cartan.SO3.minimal_rotation(a0, aT)
    fig = plt.figure(figsize=(6.2, 6.0))
    ax = sphere_axes(fig, 111)
    for lam in LAMBDAS:
        r = cartan.solve(model, lam=lam, T=case["T"], N=case["N"], gT=gT, tol=case["tol"])
        rows.append((f"SO(3) {model_name}", lam, r))
        a = r.g @ a0  # a(t) = g(t) a0: the body-fixed direction seen in space
        color, style = SPHERE_STYLE[lam]
        ax.plot(*a.T, color=color, linestyle=style, linewidth=2.0, label=LABELS[lam])
    finish_sphere_figure(fig, ax, {"$a_0$": a0, "$a_T$": aT}, f"{case['title']} on SO(3): $a(t) = g(t)\\,a_0$, $T = {case['T']}$",
                         out / f"fig_so3_{model_name}.png", view=(18, -58))


def heisenberg_figure(cartan, out, rows):
    model = cartan.H3Oscillator()
    fig = plt.figure(figsize=(5.6 * len(H3_ENDPOINTS), 5.4))
    for i, gT in enumerate(H3_ENDPOINTS):
        ax = fig.add_subplot(1, len(H3_ENDPOINTS), i + 1, projection="3d")
        clean_panes(ax)
        for lam in LAMBDAS:
            r = cartan.solve(model, lam=lam, T=1, N=400, gT=gT, tol=1e-10, order=2)
            rows.append((f"H3 oscillator gT={gT}", lam, r))
            color, style = H3_STYLE[lam]
            ax.plot(*r.g.T, color=color, linestyle=style, linewidth=2.0, label=LABELS[lam])
        ax.scatter([0], [0], [0], marker="o", facecolors="white", edgecolors="black", s=55, depthshade=False,
                   label="start $e$", zorder=5)
        ax.scatter(*np.array(gT)[:, None], marker="s", color="black", s=45, depthshade=False, label="target $g_T$",
                   zorder=5)
        ax.set_xlabel("$a$"), ax.set_ylabel("$b$"), ax.set_zlabel("$c$")
        for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
            axis.set_major_locator(matplotlib.ticker.MaxNLocator(4))
        ax.set_title(f"$g_T = ({gT[0]:g},\\ {gT[1]:g},\\ {gT[2]:g})$", pad=0)
        ax.view_init(elev=22, azim=-50)
    handles, labels = ax.get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=len(labels), frameon=False)
    fig.suptitle("Harmonic oscillator on the Heisenberg group, $T = 1$ (second-order scheme, $N = 400$)")
    fig.tight_layout(rect=(0, 0.07, 1, 1))
    fig.savefig(out / "fig_heisenberg.png", dpi=160)
    plt.close(fig)


def main():
    build, out = Path(sys.argv[1]), Path(sys.argv[2])
    sys.path.insert(0, str(build / "python"))
    import cartan

    out.mkdir(parents=True, exist_ok=True)
    rows = []
    for model_name, case in SO3_CASES.items():
        so3_figure(cartan, model_name, case, out, rows)
    heisenberg_figure(cartan, out, rows)

    print(f"{'problem':<34} {'lambda':>6} {'status':<10} {'outer':>5} {'inner':>5} {'sweeps':>6} "
          f"{'terminal error':>14} {'time [s]':>9}  branch")
    for name, lam, r in rows:
        print(f"{name:<34} {lam:>6g} {r.status:<10} {r.outer_iterations:>5} {r.inner_iterations:>5} {r.sweeps:>6} "
              f"{r.terminal_error:>14.2e} {r.solve_time:>9.4f}  {r.branch}")
    summary = [dict(problem=name, lam=lam, status=r.status, method=r.method, branch=r.branch,
                    outer=r.outer_iterations, inner=r.inner_iterations, sweeps=r.sweeps,
                    terminal_error=r.terminal_error, solve_time_s=r.solve_time, v0=r.v0.tolist())
               for name, lam, r in rows]
    (out / "paper_experiments.json").write_text(json.dumps(summary, indent=1) + "\n")
    print(f"figures: {out}/fig_so3_free-rigid-body.png, {out}/fig_so3_oscillator.png, {out}/fig_heisenberg.png")
    if any(r.status != "converged" for _, _, r in rows):
        raise SystemExit("some experiments did not converge")


if __name__ == "__main__":
    main()
