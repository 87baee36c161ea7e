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

#: The catalogue of spaces a result file describes (include/cartan/api/spaces.hpp): name -> entry
#: (dims, point, connections, gravity, what).
SPACES = {s["name"]: s for s in _cartan.spaces}
#: The group models whose Lagrangian is the particle's 1/2 v.A v (A the inertia): a group record of
#: another connection reads as the particle on the GroupManifold.
_KINETIC_MODELS = ("free-rigid-body", "free-body")


def _inertia_numbers(inertia):
    """The numbers a file records of an (n, n) inertia (or its (n,) diagonal): its diagonal when the
    matrix is diagonal (as the CLI echoes a diagonal), else its n^2 entries row-major; none for None."""
    if inertia is None:
        return np.zeros(0)
    inertia = np.asarray(inertia, dtype=float)
    if inertia.ndim == 1:
        return inertia
    return np.diag(inertia) if np.array_equal(inertia, np.diag(np.diag(inertia))) else inertia.ravel()


def _connection_record(space):
    """(connection, lambda, metric numbers, alpha numbers) of a manifold the file can describe."""
    empty, nan = np.zeros(0), math.nan
    if hasattr(space, "group"):  # a GroupManifold
        if space.lam is not None:
            return "cartan-schouten", space.lam, empty, empty
        metric = space.metric(space.group.identity())
        if metric is not None:
            return "levi-civita", nan, _inertia_numbers(metric), empty
        return "coefficients", nan, empty, np.ravel(space.alpha)
    if hasattr(space, "christoffel_symbols"):  # Euclidean: alpha[i, j, k] = Gamma^k_ij = christoffel[k, i, j]
        alpha = np.transpose(space.christoffel_symbols, (1, 2, 0))
        return ("coefficients", nan, empty, np.ravel(alpha)) if np.any(alpha) else ("levi-civita", nan, empty, empty)
    return "levi-civita", nan, empty, empty


def _manifold_record(r):
    """The problem of a manifold's Result as the file's keys: the space, the particle's terms (or
    "python:<name>" for a Lagrangian or potential defined in Python), the connection, the points and
    the frame at q0."""
    p, space = r.problem, r.problem.space
    if space is None:
        raise ValueError("Result.to_json: space = None: the manifold did not travel with the result (set `r.space`)")
    chart = isinstance(space, _cartan.Chart)
    if p.lagrangian is not None:
        model = PYTHON_MODEL + type(p.lagrangian).__name__
    else:
        model = "particle" if p.potential is None else PYTHON_MODEL + "potential"
    m = np.shape(r.v)[1]
    frame0 = np.asarray(p.frame0 if p.frame0 is not None else space.default_frame(p.q0, p.qT), dtype=float)
    connection, lam, metric, alpha = (None, math.nan, np.zeros(0), np.zeros(0)) if chart else _connection_record(space)
    return {"kind": "manifold", "manifold": PYTHON_MODEL + space.name if chart else space.name, "model": model,
            "mass": _inertia_numbers(np.eye(m) if p.inertia is None else p.inertia),
            "gravity": 0.0 if p.gravity is None else float(p.gravity), "connection": connection, "lambda": lam,
            "metric": metric, "alpha": alpha, "q0": np.ravel(p.q0), "qT": np.ravel(p.qT), "frame0": frame0.T.ravel()}


def _rows(x):
    """`x` with one row per sample, its other axes flattened (also without samples: a failed
    solve's empty trajectory)."""
    return np.reshape(x, (len(x), int(np.prod(np.shape(x)[1:]))))


def to_json(r, path):
    """Writes `r` to `path` with the library's writer of result files (the CLI's: one line)."""
    rows = len(r.t)
    if r.problem.kind == "group":
        problem = {"kind": "group", "group": _group_class(r.group, "Result.to_json").name, "model": r.model,
                   "inertia": _inertia_numbers(r.inertia), "connection": r.connection, "lambda": r.lam,
                   "g0": np.ravel(r.g0), "gT": np.ravel(r.gT)}
        aux = r.xi
    else:
        problem = _manifold_record(r)
        aux = _rows(r.Xi)
    fields = {
        **problem, "status": r.status, "message": r.message, "method": r.method, "order": r.order,
        "branch": r.branch, "T": r.T, "N": r.N, "tol": r.tol, "t": r.t,
        "points": _rows(r.q), "v": r.v, "mu": r.mu, "aux": aux,
        "terminal_error": r.terminal_error, "xi_terminal": r.xi_terminal, "outer_iterations": r.outer_iterations,
        "inner_iterations": r.inner_iterations, "sweeps": r.sweeps, "action": r.action, "solve_time": r.solve_time,
        "mesh_size": r.mesh_size, "max_residual": r.max_residual,
        "group_defect": math.nan if r.group_defect is None else r.group_defect,
    }
    with open(path, "w", encoding="utf-8") as f:
        f.write(_cartan._result_text(fields))


def read_fields(path):
    """The library's fields of the result file at `path` (its reader, the one `cartan verify` uses);
    every error is a ValueError naming the key and the file."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    try:
        return _cartan._read_result(text, "cartan.load")
    except ValueError as e:
        raise ValueError(f"{e} (in {path})") from None


_CORE = ("status", "success", "message", "method", "order", "branch", "T", "N", "tol", "t", "v", "mu", "terminal_error",
         "xi_terminal", "outer_iterations", "inner_iterations", "sweeps", "action", "solve_time", "residual_history")


def _collocation_fields(d, out):
    if d["mesh_size"] is not None:
        out["mesh_size"], out["max_residual"], out["group_defect"] = d["mesh_size"], d["max_residual"], d["group_defect"]
    return out


def group_fields(d):
    """The fields of a group model's Result (Cartan-Schouten) from the library's fields of a file."""
    group = _GROUPS[d["group"]]
    n, shape = group.dim, tuple(group.element_shape)
    inertia = np.asarray(d["inertia"], dtype=float)
    rows = len(d["t"])
    out = {key: d[key] for key in _CORE + ("model", "connection")}
    out.update({
        "group": group.__name__, "side": "left", "lam": d["lambda"],
        "inertia": None if inertia.size == 0 else np.diag(inertia) if inertia.size == n else inertia.reshape(n, n),
        "g0": np.reshape(d["g0"], shape), "gT": np.reshape(d["gT"], shape),
        "g": d["points"].reshape((rows, *shape)), "xi": d["aux"],
        "v0": d["v"][0] if rows else np.zeros(n), "xi0": d["aux"][0] if rows else np.zeros(n),
    })
    return _collocation_fields(d, out)


def _square(numbers, m):
    numbers = np.asarray(numbers, dtype=float)
    return np.diag(numbers) if numbers.size == m else numbers.reshape(m, m)


def manifold_of_fields(d, space=None):
    """The space of a manifold record, or of a group record of another connection than
    Cartan-Schouten (a GroupManifold), built from its name and connection data; a Chart (manifold
    "python:<name>") is `space`, which must be given, of the file's dimension."""
    name = d.get("manifold") or d["group"]
    if name.startswith(PYTHON_MODEL):
        if not isinstance(space, _cartan.Chart) or space.dim != len(d["q0"]):
            raise ValueError(f"cartan.load: manifold = {name!r} is a Chart defined in Python, which the file only "
                             f"names: pass it, cartan.load(path, space=chart) (a Chart of dimension {len(d['q0'])}; "
                             f"space = {space!r})")
        return space
    if space is not None:
        raise ValueError(f"cartan.load: space = {space!r} applies to a file of a Chart; this file's manifold is "
                         f"{name!r}, which it describes")
    if name == "sphere":
        return _cartan.Sphere()
    if name == "hyperbolic-plane":
        return _cartan.HyperbolicPlane()
    m = len(d["q0"]) if name == "euclidean" else _GROUPS[name].dim
    alpha = np.asarray(d["alpha"], dtype=float)
    if name == "euclidean":
        if d["connection"] != "coefficients":
            return _cartan.Euclidean(dim=m)
        return _cartan.Euclidean(np.transpose(alpha.reshape(m, m, m), (2, 0, 1)))  # christoffel[k, i, j] = alpha[i, j, k]
    connection = d["connection"]
    if connection == "cartan-schouten":
        return _cartan.GroupManifold(name, connection, lam=d["lambda"])
    if connection == "levi-civita":
        metric = d["metric"] if len(d["metric"]) else d.get("mass", d.get("inertia"))
        return _cartan.GroupManifold(name, connection, metric=_square(metric, m))
    return _cartan.GroupManifold(name, connection, alpha=alpha.reshape(m, m, m))


def manifold_fields(d, space):
    """(fields, problem terms) of a manifold's Result from the library's fields of a file: a manifold
    record, or a group record of a model whose Lagrangian is the particle's under another connection."""
    group_record = d["kind"] == "group"
    m, shape = space.dim, tuple(space.point_shape)  # also for a file without samples
    if group_record:
        if d["model"] not in _KINETIC_MODELS:
            raise ValueError(f"cartan.load: model = {d['model']!r} under connection {d['connection']!r}: only the "
                             f"particle's Lagrangian ({', '.join(_KINETIC_MODELS)}) is posed on a GroupManifold in "
                             "Python (`cartan verify` checks this file)")
        mass, gravity, frame0 = d["inertia"], 0.0, np.eye(m).ravel()
        q0, qT, model = d["g0"], d["gT"], "particle"
    else:
        mass, gravity, frame0, q0, qT, model = d["mass"], d["gravity"], d["frame0"], d["q0"], d["qT"], d["model"]
    rows = len(d["t"])
    point = np.shape(space.tangent_basis(np.reshape(q0, shape)))[0]
    out = {key: d[key] for key in _CORE}
    out.update({"q": d["points"].reshape((rows, *shape)), "Xi": d["aux"].reshape((rows, m, m)),
                "v0": d["v"][0] if rows else np.zeros(m), "Xi0": d["aux"][0].reshape(m, m) if rows else np.zeros((m, m))})
    terms = {"q0": np.reshape(q0, shape), "qT": np.reshape(qT, shape), "inertia": _square(mass, m),
             "gravity": None if gravity == 0 else gravity, "frame0": np.reshape(frame0, (m, point)).T, "model": model}
    return _collocation_fields(d, out), terms


# ---- Dense output --------------------------------------------------------------------------------

class State(NamedTuple):
    """The solution at the times of :meth:`cartan.Result.sol` of a group model's problem: g (``*element_shape``), v, mu,
    xi (dim,) at a scalar time, each with a leading axis of the times' length for an array."""
    g: np.ndarray
    v: np.ndarray
    mu: np.ndarray
    xi: np.ndarray


def dense(r, t):
    """`r.sol(t)`: the library's dense output (include/cartan/kernels/lie_group/dense.hpp) at the time or
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
    """`r.sol(t)` of a manifold's Result: the library's dense output (include/cartan/kernels/manifold/dense.hpp)
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
    points = _rows(r.q)
    three_d = (group.name in ("so3", "se3")) if group is not None else points.shape[1] == 3
    path_axes = fig.add_subplot(1, 3, 1, projection="3d" if three_d else None)
    if group is not None:
        _plot_group_path(path_axes, group, r)
    elif points.shape[1] in (2, 3):
        path_axes.plot(*points.T, label="q")
        if len(points):  # a failed solve may have kept no sample
            path_axes.plot(*points[0], "ko")
            path_axes.plot(*points[-1], "ks")
        path_axes.set_title(f"path on {r.manifold}")
    else:
        for i in range(points.shape[1]):
            path_axes.plot(r.t, points[:, i], label=f"q[{i}]")
        path_axes.set_xlabel("t")
        path_axes.set_title(f"q(t) on {r.manifold}")
    if len(r.t):
        path_axes.legend()
    for column, (name, values) in enumerate((("v", r.v), ("mu", r.mu)), start=2):
        axes = fig.add_subplot(1, 3, column)
        for i in range(values.shape[1]):
            axes.plot(r.t, values[:, i], label=f"{name}[{i}]")
        axes.set_xlabel("t")
        axes.set_title(f"{name}(t)")
        if len(r.t):
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
