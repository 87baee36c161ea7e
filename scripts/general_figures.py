#!/usr/bin/python3
"""Figures of the general theory (docs/general-connections.md) with cartan.solve on manifolds:

* fig_sphere_particle.png: the particle l = 1/2 v.A v - G z on S^2 with its Levi-Civita connection
  between the same endpoints, for A = I (the classical spherical pendulum) and two anisotropic A
  (new dynamics: the Lagrangian sees the direction of the transported velocity);
* fig_so3_connections.png: the free rigid body (inertia 2, 3, 4; the paper's endpoints a0 -> aT)
  under the Cartan-Schouten connections lambda = 0, 1/2, 1 (the Lie-group solver) and under the
  Levi-Civita connections of two left-invariant metrics (the general solver): the first metric is
  the inertia, whose curve is the classical (lambda = 0) one.

Writes out/general_figures.json with every solve's status and prints a table.
Usage: /usr/bin/python3 scripts/general_figures.py BUILD_DIR OUT_DIR
"""
import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from paper_experiments import LABELS, SPHERE_STYLE, finish_sphere_figure, sphere_axes, unit  # noqa: E402

SPHERE = dict(T=1.5, N=600, q0=(1.0, 0.0, -0.3), qT=(0.0, 1.0, -0.5), gravity=9.81)
MASSES = [((1.0, 1.0), "#2ca02c", "-", r"$A = I$ (spherical pendulum)"),
          ((1.0, 4.0), "#d62728", "--", r"$A = \mathrm{diag}(1, 4)$"),
          ((4.0, 1.0), "#1f77b4", ":", r"$A = \mathrm{diag}(4, 1)$")]
INERTIA = (2.0, 3.0, 4.0)
SO3 = dict(T=5.0, N=500, a0=(-1.0, -1.0, -1.0), aT=(0.9, 1.0, 1.0))
METRICS = [((2.0, 3.0, 4.0), "#9467bd", "-.", r"Levi-Civita of $\mathbb{I}$ = diag(2, 3, 4)"),
           ((1.0, 2.0, 3.0), "#8c564b", (0, (5, 1, 1, 1)), r"Levi-Civita of diag(1, 2, 3)")]


def sphere_figure(cartan, out, rows):
    sphere = cartan.Sphere()
    q0, qT = unit(SPHERE["q0"]), unit(SPHERE["qT"])
    fig = plt.figure(figsize=(6.2, 6.0))
    ax = sphere_axes(fig, 111)
    for mass, color, style, label in MASSES:
        r = cartan.solve(sphere, T=SPHERE["T"], N=SPHERE["N"], q0=q0, qT=qT, inertia=list(mass),
                         gravity=SPHERE["gravity"], order=2)
        rows.append((f"S^2 particle A = diag{mass}", r))
        ax.plot(*r.q.T, color=color, linestyle=style, linewidth=2.0, label=label)
    title = f"Particle on $S^2$, $l = \\frac{{1}}{{2}} v^T A v - G z$, $G = {SPHERE['gravity']}$, $T = {SPHERE['T']}$"
    finish_sphere_figure(fig, ax, {"$q_0$": q0, "$q_T$": qT}, title, out / "fig_sphere_particle.png", view=(12, -40))


def so3_figure(cartan, out, rows):
    a0, aT = unit(SO3["a0"]), unit(SO3["aT"])
    gT = cartan.SO3.minimal_rotation(a0, aT)
    fig = plt.figure(figsize=(6.2, 6.0))
    ax = sphere_axes(fig, 111)
    for lam in (0.0, 0.5, 1.0):
        r = cartan.solve(cartan.RigidBody(INERTIA), lam=lam, T=SO3["T"], N=SO3["N"], gT=gT, order=2)
        rows.append((f"SO(3) Cartan-Schouten lambda = {lam:g}", r))
        color, style = SPHERE_STYLE[lam]
        ax.plot(*(r.g @ a0).T, color=color, linestyle=style, linewidth=2.0, label="Cartan–Schouten " + LABELS[lam])
    for metric, color, style, label in METRICS:
        manifold = cartan.GroupManifold("so3", "levi-civita", metric=list(metric))
        r = cartan.solve(manifold, T=SO3["T"], N=SO3["N"], q0=np.eye(3), qT=gT, inertia=list(INERTIA), order=2)
        rows.append((f"SO(3) Levi-Civita metric diag{metric}", r))
        ax.plot(*(r.q @ a0).T, color=color, linestyle=style, linewidth=2.0, label=label)
    finish_sphere_figure(fig, ax, {"$a_0$": a0, "$a_T$": aT},
                         f"Free rigid body, $a(t) = g(t)\\,a_0$, $T = {SO3['T']}$, five connections",
                         out / "fig_so3_connections.png", view=(18, -58), legend_size=8)


def main():
    build, out = Path(sys.argv[1]), Path(sys.argv[2])
    sys.path.insert(0, str(build / "python"))
    import cartan

    out.mkdir(parents=True, exist_ok=True)
    rows = []
    sphere_figure(cartan, out, rows)
    so3_figure(cartan, out, rows)
    print(f"{'problem':<44} {'status':<10} {'terminal error':>14} {'time [s]':>9}  branch")
    for name, r in rows:
        print(f"{name:<44} {r.status:<10} {r.terminal_error:>14.2e} {r.solve_time:>9.4f}  {r.branch}")
    (out / "general_figures.json").write_text(json.dumps(
        [dict(problem=name, status=r.status, branch=r.branch, terminal_error=r.terminal_error) for name, r in rows],
        indent=1) + "\n")
    print(f"figures: {out}/fig_sphere_particle.png, {out}/fig_so3_connections.png")
    if any(r.status != "converged" for _, r in rows):
        raise SystemExit("some solves did not converge")


if __name__ == "__main__":
    main()
