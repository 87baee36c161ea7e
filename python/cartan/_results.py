"""Results that travel: what a :class:`cartan.SolveResult` says about itself, the CLI's JSON
(``to_json`` and :func:`cartan.load`), the rebuilt model (:func:`cartan.model_of`), dense output
(``sol``) and a plot (``plot``).

The JSON is exactly what ``cartan solve --output`` writes for a problem on a group
(apps/cartan/solve_command.cpp, result_json): the keys, the element rows (a matrix row-major, a Heisenberg
element as (a, b, c)), NaN and infinities as null. What the file lacks (v0, xi0: the first rows;
residual_history: empty) and what is derived from it (u, P, energy, cumulative_action) is
rebuilt on loading, by the same library code as after a solve.
"""
import json
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


# ---- The CLI's JSON ------------------------------------------------------------------------------

def _plain(x):
    """Lists of Python floats with NaN and infinities as None (JSON lacks them; the CLI writes null)."""
    if isinstance(x, (list, tuple, np.ndarray)):
        return [_plain(y) for y in x]
    if isinstance(x, (float, np.floating)):
        return float(x) if math.isfinite(x) else None
    if isinstance(x, np.integer):
        return int(x)
    return x


def _inertia_json(inertia):
    """The diagonal when the matrix is diagonal (as the CLI echoes a diagonal), else its rows."""
    if inertia is None:
        return []
    inertia = np.asarray(inertia, dtype=float)
    return np.diag(inertia) if np.array_equal(inertia, np.diag(np.diag(inertia))) else inertia


def to_json_dict(r):
    """The keys `cartan solve --output` writes, from a SolveResult."""
    rows = len(r.t)
    out = {
        "status": r.status, "message": r.message, "method": r.method, "order": r.order, "branch": r.branch,
        "group": _group_class(r.group, "SolveResult.to_json").name, "model": r.model,
        "inertia": _inertia_json(r.inertia), "lambda": r.lam, "T": r.T, "N": r.N, "tol": r.tol,
        "g0": np.ravel(r.g0), "gT": np.ravel(r.gT), "connection": r.connection, "side": r.side,
        "t": r.t, "g": np.reshape(r.g, (rows, int(np.prod(np.shape(r.g)[1:])))), "v": r.v, "mu": r.mu, "xi": r.xi,
        "terminal_error": r.terminal_error, "xi_terminal": r.xi_terminal,
        "iterations": {"outer": r.outer_iterations, "inner": r.inner_iterations, "sweeps": r.sweeps},
        "action": r.action, "solve_time_s": r.solve_time,
    }
    if r.mesh_size is not None:
        out["mesh_size"], out["max_residual"] = r.mesh_size, r.max_residual
        if r.group_defect is not None and math.isfinite(r.group_defect):
            out["group_defect"] = r.group_defect
    return {key: _plain(value) for key, value in out.items()}


def to_json(r, path):
    """Writes `r` to `path` as the CLI's JSON (one line, as `cartan solve --output`)."""
    with open(path, "w", encoding="utf-8") as f:
        json.dump(to_json_dict(r), f, allow_nan=False)
        f.write("\n")


_MISSING = object()


class _Reader:
    """Typed values of a result file; every error is a ValueError naming the key."""

    def __init__(self, data, path):
        if not isinstance(data, dict):
            raise ValueError(f"cartan.load: {path}: result file must be a JSON object, not {type(data).__name__}")
        self.data, self.path = data, path

    def bad(self, key, value, problem):
        text = repr(value) if not isinstance(value, (list, dict)) else f"({type(value).__name__} of {len(value)})"
        raise ValueError(f"cartan.load: {key} = {text} {problem} (in {self.path})")

    def get(self, key):
        if key not in self.data:
            raise ValueError(f"cartan.load: {key} = (missing) is required in a result file (in {self.path})")
        return self.data[key]

    def text(self, key, choices=None):
        value = self.get(key)
        if not isinstance(value, str):
            self.bad(key, value, "must be a string")
        if choices is not None and value not in choices:
            self.bad(key, value, "is not one of: " + ", ".join(choices))
        return value

    def number(self, key, value=_MISSING, integer=False):
        value = self.get(key) if value is _MISSING else value
        if value is None and not integer:
            return math.nan  # the CLI's null: NaN or an infinity
        if isinstance(value, bool) or not isinstance(value, (int, float)) or (integer and value != int(value)):
            self.bad(key, value, "must be an integer" if integer else "must be a number")
        return int(value) if integer else float(value)

    def array(self, key, shape):
        """An array of `shape` (None: any length) from nested lists of numbers or null (NaN)."""
        value = self.get(key)
        if value == [] and shape[0] == 0:  # a failed solve without an iterate: no rows
            return np.zeros((0, *shape[1:]))
        try:
            a = np.array(value, dtype=float)  # None becomes NaN
        except (TypeError, ValueError):
            self.bad(key, value, "must be a list of numbers")
        want = tuple(a.shape[i] if n is None else n for i, n in enumerate(shape)) if a.ndim == len(shape) else shape
        if a.shape != want:
            self.bad(key, value, f"must have shape {tuple('M' if n is None else n for n in shape)}, not {a.shape}")
        return a


def _read(data, path):
    r = _Reader(data, path)
    if "manifold" in data:
        r.bad("manifold", data["manifold"], "is a solve_general problem; cartan.load reads cartan.solve's results")
    connection = r.text("connection", ("cartan-schouten",)) if "connection" in data else "cartan-schouten"
    if "side" in data:
        r.text("side", ("left",))
    group = _GROUPS[r.text("group", tuple(_GROUPS))]
    models = [m for g, m in BUILTIN_MODELS.values() if g == group.name]
    model = r.text("model")
    if model not in models and not model.startswith(PYTHON_MODEL):
        r.bad("model", model, f"is not one of: {', '.join(models)} (the models of group {group.name}), "
              f"nor {PYTHON_MODEL}<name> (a Lagrangian defined in Python)")
    n, shape = group.dim, tuple(group.element_shape)
    raw = r.get("inertia")
    inertia = None
    if raw != []:
        rows_given = isinstance(raw, list) and any(isinstance(x, list) for x in raw)
        inertia = r.array("inertia", (n, n)) if rows_given else np.diag(r.array("inertia", (n,)))
    elif not model.startswith(PYTHON_MODEL):
        r.bad("inertia", [], f"must have {n} or {n * n} numbers for model {model}")
    t = r.array("t", (None,))
    rows = len(t)
    out = {
        "status": r.text("status", tuple(_cartan.statuses)), "message": r.text("message"),
        "method": r.text("method", tuple(group.methods)), "order": r.number("order", integer=True),
        "branch": r.text("branch"), "group": group.__name__, "model": model, "inertia": inertia,
        "connection": connection, "side": "left", "lam": r.number("lambda"), "T": r.number("T"),
        "N": r.number("N", integer=True), "tol": r.number("tol"),
        "g0": r.array("g0", (int(np.prod(shape)),)).reshape(shape), "gT": r.array("gT", (int(np.prod(shape)),)).reshape(shape),
        "t": t, "g": r.array("g", (rows, int(np.prod(shape)))).reshape((rows, *shape)),
        "v": r.array("v", (rows, n)), "mu": r.array("mu", (rows, n)), "xi": r.array("xi", (rows, n)),
        "terminal_error": r.number("terminal_error"), "xi_terminal": r.number("xi_terminal"),
        "action": r.number("action"), "solve_time": r.number("solve_time_s"),
        "residual_history": np.zeros(0),
    }
    out["success"] = out["status"] == "converged"
    out["v0"] = out["v"][0] if rows else np.zeros(n)
    out["xi0"] = out["xi"][0] if rows else np.zeros(n)
    iterations = r.get("iterations")
    if not isinstance(iterations, dict):
        r.bad("iterations", iterations, "must be an object with outer, inner and sweeps")
    for key in ("outer", "inner", "sweeps"):
        if key not in iterations:
            r.bad("iterations." + key, "(missing)", "is required in a result file")
        value = r.number("iterations." + key, iterations[key], integer=True)
        out[key + "_iterations" if key != "sweeps" else "sweeps"] = value
    if "mesh_size" in data:
        out["mesh_size"], out["max_residual"] = r.number("mesh_size", integer=True), r.number("max_residual")
        out["group_defect"] = r.number("group_defect") if "group_defect" in data else math.nan
    return out


def load_dict(path):
    """The fields of a SolveResult read from the CLI's JSON at `path` (see :func:`cartan.load`)."""
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except json.JSONDecodeError as e:
        raise ValueError(f"cartan.load: {path} is not valid JSON ({e})") from None
    return _read(data, path)


# ---- Dense output --------------------------------------------------------------------------------

class State(NamedTuple):
    """The solution at the times of :meth:`cartan.SolveResult.sol`: g (``*element_shape``), v, mu,
    xi (dim,) at a scalar time, each with a leading axis of the times' length for an array."""
    g: np.ndarray
    v: np.ndarray
    mu: np.ndarray
    xi: np.ndarray


def dense(r, t):
    """`r.sol(t)`: the library's dense output (include/cartan/transported/dense.hpp) at the time or
    times `t` (a leading axis for an array)."""
    times = np.asarray(t, dtype=float)
    group = _group_class(r.group, "SolveResult.sol")
    out = group._dense(r, r.lam, r.method, np.atleast_1d(times).ravel())
    return State(*(out[key][0] if times.ndim == 0 else out[key] for key in ("g", "v", "mu", "xi")))


class GeneralState(NamedTuple):
    """The solution at the times of :meth:`cartan.GeneralSolveResult.sol`: q (``*point_shape``),
    frame (d, m), v, mu (m,), Xi (m, m), each with a leading axis of the times' length for an array."""
    q: np.ndarray
    frame: np.ndarray
    v: np.ndarray
    mu: np.ndarray
    Xi: np.ndarray


def general_dense(r, t):
    """`r.sol(t)` of a GeneralSolveResult: the library's dense output (include/cartan/general/dense.hpp)
    on the manifold `r.space`."""
    if r.space is None:
        raise ValueError("GeneralSolveResult.sol: space = None: the result does not carry the manifold it was "
                         "solved on (set `space` to it)")
    times = np.asarray(t, dtype=float)
    out = r.space._dense(r, r.method, np.atleast_1d(times).ravel())
    return GeneralState(*(out[key][0] if times.ndim == 0 else out[key] for key in ("q", "frame", "v", "mu", "Xi")))


# ---- Plotting ------------------------------------------------------------------------------------

def plot(r, path=None):
    """`r.plot(path)`: see :meth:`cartan.SolveResult.plot`."""
    from matplotlib.figure import Figure
    group = _group_class(r.group, "SolveResult.plot")
    fig = Figure(figsize=(12, 4), layout="constrained")
    three_d = group.name in ("so3", "se3")
    path_axes = fig.add_subplot(1, 3, 1, projection="3d" if three_d else None)
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
    path_axes.legend()
    for column, (name, values) in enumerate((("v", r.v), ("mu", r.mu)), start=2):
        axes = fig.add_subplot(1, 3, column)
        for i in range(values.shape[1]):
            axes.plot(r.t, values[:, i], label=f"{name}[{i}]")
        axes.set_xlabel("t")
        axes.set_title(f"{name}(t)")
        axes.legend(fontsize="small")
    fig.suptitle(f"{r.group} {r.model}, lambda = {r.lam:g}, T = {r.T:g}, N = {r.N}, {r.method} (order {r.order}): {r.status}")
    if path is not None:
        fig.savefig(path)
    return fig
