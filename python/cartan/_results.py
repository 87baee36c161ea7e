"""Results that travel: what a :class:`cartan.Result` says about itself, the result file
(``to_json`` and :func:`cartan.load`), the rebuilt model (:func:`cartan.model_of`), dense output
(``sol``) and a plot (``plot``).

The file is written and read by the library's one writer and reader of result files
(include/cartan/api/result_file.hpp), the ones ``cartan solve --output`` and ``cartan verify``
use: the same keys, element rows (a matrix row-major, a Heisenberg element as (a, b, c)), NaN and
infinities as null. What the file lacks (v0, xi0: the first rows; residual_history: empty) and
what is derived from it (u, P, energy, cumulative_action) is rebuilt on loading, by the same
library code as after a solve.
"""
import math
from typing import NamedTuple

import numpy as np

from . import _cartan

#: The built-in models, by Python class name: (CLI group, CLI model), from the library's catalogue
#: (include/cartan/models/catalogue.hpp).
BUILTIN_MODELS = {m["type"]: (m["group"], m["model"]) for m in _cartan.models}
#: The prefix of the model name of a Lagrangian defined in Python (not reconstructible from a file).
PYTHON_MODEL = "python:"
_GROUPS = {g.name: g for g in (_cartan.SO3, _cartan.Heisenberg, _cartan.SE3, _cartan.SE2)}


def describe_model(lagrangian, group):
    """(model, inertia): the CLI's model name and the (n, n) inertia of a built-in model, or
    "python:<type name>" and the object's `inertia` attribute (None without one) for a Lagrangian
    defined in Python."""
    name = type(lagrangian).__name__
    builtin = BUILTIN_MODELS.get(name)
    if builtin is not None and type(lagrangian) is getattr(_cartan, name) and builtin[0] == group.name:
        return builtin[1], np.array(lagrangian.inertia, dtype=float)
    inertia = getattr(lagrangian, "inertia", None)
    return PYTHON_MODEL + name, None if inertia is None else np.array(inertia, dtype=float)


def model_of(result):
    """The built-in model a result was solved for, rebuilt from its group, model and inertia (e.g.
    of a :func:`load`-ed file, for :func:`cartan.verify`). Raises ValueError for a Lagrangian defined
    in Python (model "python:<type name>"): a file records its name, not its code."""
    group = _group_class(result.group, "cartan.model_of")
    for cls, (g, m) in BUILTIN_MODELS.items():
        if g == group.name and m == result.model:
            return getattr(_cartan, cls)(result.inertia)
    raise ValueError(f"cartan.model_of: model = {result.model!r} is not a built-in model of group {group.name} "
                     "(a Lagrangian defined in Python is not reconstructible: pass it to cartan.verify yourself)")


def _group_class(group, where):
    for g in _GROUPS.values():
        if group in (g.name, g.__name__):
            return g
    raise ValueError(f"{where}: group = {group!r} is not one of: {', '.join(_GROUPS)}")


# ---- The result file ----------------------------------------------------------------------------

def _inertia_numbers(inertia):
    """The numbers a file records of an (n, n) inertia: its diagonal when the matrix is diagonal
    (as the CLI echoes a diagonal), else its n^2 entries row-major; none for None."""
    if inertia is None:
        return np.zeros(0)
    inertia = np.asarray(inertia, dtype=float)
    return np.diag(inertia) if np.array_equal(inertia, np.diag(np.diag(inertia))) else inertia.ravel()


def to_json(r, path):
    """Writes `r` to `path` with the library's writer of result files (the CLI's: one line)."""
    if r.problem.kind != "group":
        raise ValueError(f"Result.to_json: manifold = {r.manifold!r}: the result file describes a group model's "
                         "problem (cartan solve --manifold writes the sphere's and hyperbolic plane's particle in "
                         "its own frame); a manifold's Result is not written yet (pickle it)")
    rows = len(r.t)
    fields = {
        "status": r.status, "message": r.message, "method": r.method, "order": r.order, "branch": r.branch,
        "group": _group_class(r.group, "Result.to_json").name, "model": r.model,
        "inertia": _inertia_numbers(r.inertia), "connection": r.connection, "lambda": r.lam, "T": r.T, "N": r.N,
        "tol": r.tol, "g0": np.ravel(r.g0), "gT": np.ravel(r.gT), "t": r.t,
        "g": np.reshape(r.g, (rows, int(np.prod(np.shape(r.g)[1:])))), "v": r.v, "mu": r.mu, "xi": r.xi,
        "terminal_error": r.terminal_error, "xi_terminal": r.xi_terminal, "outer_iterations": r.outer_iterations,
        "inner_iterations": r.inner_iterations, "sweeps": r.sweeps, "action": r.action, "solve_time": r.solve_time,
        "mesh_size": r.mesh_size, "max_residual": r.max_residual,
        "group_defect": math.nan if r.group_defect is None else r.group_defect,
    }
    with open(path, "w", encoding="utf-8") as f:
        f.write(_cartan._result_text(fields))


def load_dict(path):
    """The fields of a group model's Result read from the result file at `path` (see :func:`cartan.load`)
    by the library's reader, the one `cartan verify` uses; every error is a ValueError naming the
    key and the file."""
    where = "cartan.load"
    with open(path, encoding="utf-8") as f:
        text = f.read()
    try:
        d = _cartan._read_result(text, where, lie_kernel_only=True)
    except ValueError as e:
        raise ValueError(f"{e} (in {path})") from None
    group = _GROUPS[d["group"]]
    n, shape = group.dim, tuple(group.element_shape)
    inertia = np.asarray(d["inertia"], dtype=float)
    rows = len(d["t"])
    out = {key: d[key] for key in ("status", "success", "message", "method", "order", "branch", "model", "connection",
                                   "T", "N", "tol", "t", "v", "mu", "terminal_error", "xi_terminal", "outer_iterations",
                                   "inner_iterations", "sweeps", "action", "solve_time", "residual_history")}
    out.update({
        "group": group.__name__, "side": "left", "lam": d["lambda"],
        "inertia": None if inertia.size == 0 else np.diag(inertia) if inertia.size == n else inertia.reshape(n, n),
        "g0": np.reshape(d["g0"], shape), "gT": np.reshape(d["gT"], shape),
        "g": d["points"].reshape((rows, *shape)), "xi": d["aux"],
        "v0": d["v"][0] if rows else np.zeros(n), "xi0": d["aux"][0] if rows else np.zeros(n),
    })
    if d["mesh_size"] is not None:
        out["mesh_size"], out["max_residual"], out["group_defect"] = d["mesh_size"], d["max_residual"], d["group_defect"]
    return out


# ---- Dense output --------------------------------------------------------------------------------

class State(NamedTuple):
    """The solution at the times of :meth:`cartan.Result.sol` of a group model's problem: g (``*element_shape``), v, mu,
    xi (dim,) at a scalar time, each with a leading axis of the times' length for an array."""
    g: np.ndarray
    v: np.ndarray
    mu: np.ndarray
    xi: np.ndarray


def dense(r, t):
    """`r.sol(t)`: the library's dense output (include/cartan/transported/dense.hpp) at the time or
    times `t` (a leading axis for an array)."""
    times = np.asarray(t, dtype=float)
    group = _group_class(r.group, "Result.sol")
    out = group._dense(r, r.lam, r.method, np.atleast_1d(times).ravel())
    return State(*(out[key][0] if times.ndim == 0 else out[key] for key in ("g", "v", "mu", "xi")))


class GeneralState(NamedTuple):
    """The solution at the times of :meth:`cartan.Result.sol` on a manifold: q (``*point_shape``),
    frame (d, m), v, mu (m,), Xi (m, m), each with a leading axis of the times' length for an array."""
    q: np.ndarray
    frame: np.ndarray
    v: np.ndarray
    mu: np.ndarray
    Xi: np.ndarray


def general_dense(r, t):
    """`r.sol(t)` of a manifold's Result: the library's dense output (include/cartan/general/dense.hpp)
    on the manifold `r.space`."""
    if r.space is None:
        raise ValueError("Result.sol: space = None: the manifold did not travel with the result (set "
                         "`r.space` to it)")
    times = np.asarray(t, dtype=float)
    out = r.space._dense(r, r.method, np.atleast_1d(times).ravel())
    return GeneralState(*(out[key][0] if times.ndim == 0 else out[key] for key in ("q", "frame", "v", "mu", "Xi")))


# ---- Plotting ------------------------------------------------------------------------------------

def plot(r, path=None):
    """`r.plot(path)`: see :meth:`cartan.Result.plot`."""
    from matplotlib.figure import Figure
    fig = Figure(figsize=(12, 4), layout="constrained")
    group = None if r.group is None else _group_class(r.group, "Result.plot")
    points = np.reshape(r.q, (len(r.t), -1))
    three_d = (group.name in ("so3", "se3")) if group is not None else points.shape[1] == 3
    path_axes = fig.add_subplot(1, 3, 1, projection="3d" if three_d else None)
    if group is not None:
        _plot_group_path(path_axes, group, r)
    elif points.shape[1] in (2, 3):
        path_axes.plot(*points.T, label="q")
        path_axes.plot(*points[0], "ko")
        path_axes.plot(*points[-1], "ks")
        path_axes.set_title(f"path on {r.manifold}")
    else:
        for i in range(points.shape[1]):
            path_axes.plot(r.t, points[:, i], label=f"q[{i}]")
        path_axes.set_xlabel("t")
        path_axes.set_title(f"q(t) on {r.manifold}")
    path_axes.legend()
    for column, (name, values) in enumerate((("v", r.v), ("mu", r.mu)), start=2):
        axes = fig.add_subplot(1, 3, column)
        for i in range(values.shape[1]):
            axes.plot(r.t, values[:, i], label=f"{name}[{i}]")
        axes.set_xlabel("t")
        axes.set_title(f"{name}(t)")
        axes.legend(fontsize="small")
    what = (f"{r.group} {r.model}, lambda = {r.lam:g}" if r.problem.kind == "group"
            else f"{r.manifold}" + (f" (lambda = {r.lam:g})" if r.lam is not None else ""))
    fig.suptitle(f"{what}, T = {r.T:g}, N = {r.N}, {r.method} (order {r.order}): {r.status}")
    if path is not None:
        fig.savefig(path)
    return fig


def _plot_group_path(path_axes, group, r):
    """The path in a group: SO(3)'s body axes on the sphere, Heisenberg's (a, b, c), the translation."""
    if group.name == "so3":
        sphere = np.linspace(0, 2 * np.pi, 25), np.linspace(0, np.pi, 13)
        path_axes.plot_wireframe(np.outer(np.cos(sphere[0]), np.sin(sphere[1])),
                                 np.outer(np.sin(sphere[0]), np.sin(sphere[1])),
                                 np.outer(np.ones_like(sphere[0]), np.cos(sphere[1])), color="0.85", linewidth=0.5)
        for i, colour in enumerate("rgb"):
            path_axes.plot(*r.g[:, :, i].T, color=colour, label=f"g e{i + 1}")
        path_axes.set_box_aspect((1, 1, 1))  # the sphere round
        path_axes.set_title("body axes on the sphere")
    elif group.name == "heisenberg":
        for i, name in enumerate("abc"):
            path_axes.plot(r.t, r.g[:, i], label=name)
        path_axes.set_xlabel("t")
        path_axes.set_title("(a, b, c)")
    else:
        d = 2 if group.name == "se2" else 3
        path_axes.plot(*r.g[:, :d, d].T, label="translation")
        path_axes.set_title("translation path")
