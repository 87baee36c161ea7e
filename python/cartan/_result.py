"""The one result of every solve (:class:`Result`) and the problem it carries (:class:`Problem`).

A group model's solve (the Lie-group kernel) and a manifold's (the general kernel) return the same
type in the same vocabulary: points q with their parallel frame, the transported velocity v and the
momentum mu in the components of the frame at q0, the quantities along the solution, the
diagnostics. Each kernel's auxiliary keeps its own form: xi in the dual of the algebra on the
Lie-group kernel (eq:reduced-system), the matrix Xi^k_n = int_t^T v^k mu_n elsewhere
(eq:int-diff-EL's local form); the other is None.
"""
import dataclasses
import math
import pickle
from dataclasses import dataclass, field
from typing import Any, Optional

import numpy as np

from . import _results


@dataclass(frozen=True, eq=False)
class Problem:
    """The problem a :class:`Result` solves, as :func:`cartan.solve` was given it, so that
    :func:`cartan.verify`, dense output, plots and files need nothing else.

    kind: "group" (a group model's problem: the Cartan-Schouten connection of parameter `lam`) or
    "manifold" (the connection is the manifold's). space: the group class (cartan.SO3, ...) or the
    manifold (any of cartan.MANIFOLDS). lagrangian: the group model (built in or defined in Python),
    a manifold's Lagrangian object, or None where l = 1/2 v.A v - V(q) is given by the terms
    `inertia`, `potential`, `potential_gradient`, `gravity`. q0, qT: the boundary points (a group's
    elements). frame0: the frame of T_q0 Q the components are taken in (None: space.default_frame(q0, qT)).
    model: how a result file names the Lagrangian ("free-rigid-body", ... for a built-in model,
    "python:<type name>" for one defined in Python; on a manifold "" for the particle given by its
    terms, "python:<type name>" for a Lagrangian object and "python:potential" for a potential
    defined in Python, which a result file names and verify then asks for).

    A problem that travelled (pickling, processes) keeps the objects that pickle; one that does
    not (a Chart or Lagrangian built from lambdas) is None, and what needs it asks for it by name.
    """
    kind: str
    space: Any
    lagrangian: Any = None
    lam: Optional[float] = None
    q0: Any = None
    qT: Any = None
    inertia: Any = None
    potential: Any = None
    potential_gradient: Any = None
    gravity: Optional[float] = None
    frame0: Any = None
    model: str = ""

    #: The objects of a problem that may hold Python code (dropped when they do not pickle).
    LIVE = ("space", "lagrangian", "potential", "potential_gradient")

    def terms(self):
        """The Lagrangian of a manifold's problem as cartan.solve takes it: its object or its terms."""
        return dict(lagrangian=self.lagrangian, inertia=self.inertia, potential=self.potential,
                    potential_gradient=self.potential_gradient, gravity=self.gravity)

    def portable(self):
        """The problem with every live object that does not pickle replaced by None."""
        changes = {}
        for name in self.LIVE:
            value = getattr(self, name)
            if value is None:
                continue
            try:
                pickle.dumps(value)
            except Exception:  # any object pickle refuses (TypeError, PicklingError, AttributeError)
                changes[name] = None
        return dataclasses.replace(self, **changes) if changes else self


#: The names a group model's result is read by (its elements g, the transport P = Ad(h), ...), each
#: the general name it presents its solution in (docs/architecture.md, "One core, two kernels").
_ALIASES = {"g": "q", "P": "frame"}
_PROBLEM_ALIASES = {"g0": "q0", "gT": "qT", "q0": "q0", "qT": "qT", "lam": "lam", "inertia": "inertia"}


@dataclass(eq=False)
class Result:
    """The result of :func:`cartan.solve`, whichever the problem (a group model, any manifold, any
    connection), in the spirit of scipy.integrate.solve_bvp's; it carries its problem (`problem`, a
    :class:`Problem`), so that ``cartan.verify(r)``, ``r.sol(t)``, ``r.plot()``, ``r.to_json(path)``
    need nothing else.

    status: one of cartan.STATUSES ("converged", or what failed: "max-iterations", "stalled",
    "non-finite", "no-progress", "continuation-failed", "strategy-failed", "interrupted", "time-limit",
    ...; the CLI's words); success (also `converged`): status == "converged"; message: diagnostics
    (every attempt, iterations, residual history); method: the method that produced the result (one
    of cartan.METHODS, never "auto"); order: the scheme's (1, 2), or 4 for collocation; branch: how it
    was reached (e.g. "continuation in T (continued in T from T = 3 (6 stages)), after shooting
    failed"). T, N, tol: the problem's horizon and steps and the requested tolerance.

    The solution at every sample (the nodes; collocation: its final mesh or `samples` times): t
    (N+1,); q ``(N+1, *point_shape)``: the points (a group's elements, also `g`); frame (N+1, d, m): the
    parallel frame e_i(t_k) along the path (frame[0] the frame at q0; on a group the transport
    operator P_k = Ad(h_k) of eq:reduced-system, also `P`, acting on the algebra); v, mu (N+1, m): the
    transported velocity and the momentum in components of the frame at q0 (q' = frame @ v); the
    auxiliary of the curvature integral: xi (N+1, m) in the dual of the algebra on a group model's
    problem (disc-aux), or Xi (N+1, m, m), Xi^k_n = int_t^T v^k mu_n, on a manifold (the other None).
    A failed result carries the best iterate of the requested problem (never a stage of a
    continuation at another T or lambda), or no rows at all.

    v0 and xi0 or Xi0: the initial values; terminal_error: how far q_N is from qT (``|log(gT^-1 g_N)|`` on
    a group, ``|difference(qT, q_N)|`` where that is a logarithm on a manifold, never 0 at a cut locus);
    xi_terminal: the size of the auxiliary at T; outer_iterations, inner_iterations (also
    `iterations`), sweeps: work done (collocation: mesh refinements, Newton iterations, Jacobians);
    residual_history; solve_time: seconds in the solver, every attempt; mesh_size, max_residual,
    group_defect: collocation only (else None).

    Along the solution (computed by the library after the solve, from the samples:
    include/cartan/kernels/lie_group/along.hpp, include/cartan/kernels/manifold/along.hpp): u (N+1, d): q' = frame @ v
    (on a group the body velocity u_k = P_k v_k, disc-body-v); energy (N+1,): E_k = mu(v_k).v_k - l(t_k,
    q_k, v_k), conserved for every connection when l does not depend on t; cumulative_action (N+1,):
    the discrete transported action over the first k steps (0 first), whose last entry is `action`
    (tells branches apart). A result stopped on request ("interrupted", "time-limit") carries its
    samples only: action NaN and u, energy, cumulative_action None (a loaded file computes them).

    The problem's words: lam, group (a group model's problem: the group class's name, e.g. "SO3"),
    manifold (a manifold's name), model, inertia, connection ("cartan-schouten" with `lam` on a group
    model's problem), side ("left": v is left-trivialised), g0, gT (also q0, qT), space.
    Dense output :meth:`sol`, a figure :meth:`plot`, the CLI's JSON :meth:`to_json` and
    :func:`cartan.load`, :meth:`replace` for a changed copy, pickling (the problem's objects that do
    not pickle stay behind: see :class:`Problem`).
    """
    status: str
    message: str
    success: bool
    method: str
    order: int
    branch: str
    T: float
    N: int
    tol: float
    t: np.ndarray
    q: np.ndarray
    v: np.ndarray
    mu: np.ndarray
    v0: np.ndarray
    terminal_error: float
    xi_terminal: float
    sweeps: int
    residual_history: np.ndarray = field(repr=False)
    solve_time: float
    problem: Problem = field(repr=False)
    frame: Optional[np.ndarray] = field(default=None, repr=False)
    xi: Optional[np.ndarray] = field(default=None, repr=False)
    xi0: Optional[np.ndarray] = field(default=None, repr=False)
    Xi: Optional[np.ndarray] = field(default=None, repr=False)
    Xi0: Optional[np.ndarray] = field(default=None, repr=False)
    action: float = math.nan
    u: Optional[np.ndarray] = field(default=None, repr=False)
    energy: Optional[np.ndarray] = field(default=None, repr=False)
    cumulative_action: Optional[np.ndarray] = field(default=None, repr=False)
    outer_iterations: int = 0
    inner_iterations: int = 0
    mesh_size: Optional[int] = None
    max_residual: Optional[float] = None
    group_defect: Optional[float] = None

    # ---- the problem's words, and the group model's names of the general fields ----------------

    @property
    def converged(self):
        """The same as `success` (the C++ result's converged())."""
        return self.success

    @property
    def iterations(self):
        """The same as `inner_iterations` (Levenberg-Marquardt's, or collocation's Newton's)."""
        return self.inner_iterations

    @property
    def g(self):
        """The points q of a group model's problem (its elements)."""
        return self.q

    @property
    def P(self):
        """The frame of a group model's problem: the transport operator P_k = Ad(h_k)."""
        return self.frame

    @property
    def g0(self):
        return self.problem.q0

    @property
    def gT(self):
        return self.problem.qT

    @property
    def q0(self):
        return self.problem.q0

    @property
    def qT(self):
        return self.problem.qT

    @property
    def lam(self):
        """The Cartan-Schouten parameter: a group model's problem's, or a GroupManifold's (None for
        another connection)."""
        if self.problem.kind == "group":
            return self.problem.lam
        return getattr(self.problem.space, "lam", None)

    @property
    def group(self):
        """The group class's name ("SO3", ...) of a group model's problem or a GroupManifold's, else None."""
        space = self.problem.space
        if self.problem.kind == "group":
            return space.__name__ if space is not None else self.problem.model.split("/")[0]
        group = getattr(space, "group", None)
        return None if group is None else group.__name__

    @property
    def manifold(self):
        """The manifold's name on a manifold's problem, else None."""
        if self.problem.kind == "group" or self.problem.space is None:
            return None
        return self.problem.space.name

    @property
    def space(self):
        """The group class or the manifold the problem is posed on (None after travelling, when it
        did not pickle: set it again, ``r.space = manifold``)."""
        return self.problem.space

    @space.setter
    def space(self, value):
        self.problem = dataclasses.replace(self.problem, space=value)

    @property
    def model(self):
        return self.problem.model

    @property
    def inertia(self):
        return self.problem.inertia

    @property
    def connection(self):
        """The connection's word: "cartan-schouten" on a group model's problem; on a GroupManifold its
        kind ("cartan-schouten", "levi-civita", "coefficients"); the Levi-Civita connection of the
        sphere and the hyperbolic plane; "christoffel" for a Euclidean space or a Chart (their
        Christoffel symbols); None where the manifold did not travel with the result."""
        space = self.problem.space
        if self.problem.kind == "group":
            return "cartan-schouten"
        if space is None:
            return None
        if hasattr(space, "group"):  # a GroupManifold
            if space.lam is not None:
                return "cartan-schouten"
            return "levi-civita" if space.metric(space.group.identity()) is not None else "coefficients"
        return "levi-civita" if space.name in ("sphere", "hyperbolic-plane") else "christoffel"

    @property
    def side(self):
        return "left"

    # ---- tools -------------------------------------------------------------------------------------

    def replace(self, **changes):
        """A copy with some fields changed (dataclasses.replace), by their names or the group model's
        (g, P; and the problem's g0, gT, q0, qT, lam, inertia)."""
        fields = {_ALIASES.get(name, name): value for name, value in changes.items() if name not in _PROBLEM_ALIASES}
        problem = {_PROBLEM_ALIASES[name]: value for name, value in changes.items() if name in _PROBLEM_ALIASES}
        if problem:
            fields["problem"] = dataclasses.replace(self.problem, **problem)
        return dataclasses.replace(self, **fields)

    def __getstate__(self):
        state = dict(self.__dict__)
        state["problem"] = self.problem.portable()
        return state

    def sol(self, t):
        """Dense output: the solution at the time or times `t` in [t_0, t_N] = [0, T] (a time past an
        end by a few roundings, 16 machine epsilons relative, is that end; further: ValueError), a leading axis for an array `t`; at a node the sample itself. The interpolants
        are the library's.

        A group model's problem (include/cartan/kernels/lie_group/dense.hpp), a State (g, v, mu, xi): on
        step k of a discrete scheme g(t) = g_k exp(s log(g_k^-1 g_k+1)), s = (t - t_k)/h, the translated
        one-parameter subgroup through both nodes (the curve the Lie-Euler and RKMK steps move along,
        O(h^2), on the group), v, mu, xi linear in s; collocation: g by the cubic Hermite interpolant
        in the chart g_k exp(X) with X' from the body velocities, xi by cubic Hermite with
        xi' = -ad*_v mu, v and mu by not-a-knot cubic splines.

        A manifold's (include/cartan/kernels/manifold/dense.hpp), a GeneralState (q, frame, v, mu, Xi): on a
        step q(t) = step(q_k, s difference(q_k, q_k+1)) with the frame transported along that piece,
        v, mu, Xi linear in s for the discrete schemes; collocation: v, mu by not-a-knot cubic splines
        and Xi by cubic Hermite with Xi' = -v mu^T. The measured orders: python/tests/test_results.py."""
        if self.problem.kind == "group":
            return _results.dense(self, t)
        return _results.general_dense(self, t)

    def to_json(self, path):
        """Writes the result to `path` as the JSON of `cartan solve --output` (the same keys; NaN and
        infinities as null), which `cartan verify path` checks and :func:`cartan.load` reads back: a
        group model's problem, or the particle on any space of :data:`cartan.SPACES` with its
        connection, mass, gravity and frame0. A Lagrangian or potential defined in Python is written
        as model "python:<type name>", which `cartan verify` rejects (it cannot rebuild it) and
        :func:`cartan.load` accepts; so is a Chart (manifold "python:<name>": pass it again,
        ``cartan.load(path, space=chart)``)."""
        _results.to_json(self, path)

    def plot(self, path=None):
        """A matplotlib Figure (matplotlib is imported on first use): the path (SO(3): the body axes
        g e1, g e2, g e3 on the unit sphere; Heisenberg: a, b, c against t; SE(2), SE(3): the
        translation; the sphere and the hyperbolic plane: the path in R^3; a 2-dimensional space: the
        path in its coordinates; else each coordinate against t), then v and mu against t, one line
        per component. With `path`, also saved there (the format from its extension)."""
        return _results.plot(self, path)

    def __repr__(self):
        where = (f"group={self.group!r}, lam={self.lam:g}" if self.problem.kind == "group"
                 else f"manifold={self.manifold!r}")
        return (f"Result(status={self.status!r}, success={self.success}, method={self.method!r}, {where}, "
                f"T={self.T:g}, N={self.N}, order={self.order}, terminal_error={self.terminal_error:.3e}, "
                f"action={self.action:.6g}, iterations=(outer={self.outer_iterations}, inner={self.inner_iterations}, "
                f"sweeps={self.sweeps}), branch={self.branch!r}, solve_time={self.solve_time:.4f})")


def from_group_fields(d, problem):
    """The Result of a group model's solve (or file) from the library's fields (g, P, g0, gT, lam, ...)."""
    d = dict(d)
    for old, new in _ALIASES.items():
        if old in d:
            d[new] = d.pop(old)
    for name in ("g0", "gT", "lam", "group", "model", "inertia", "connection", "side"):
        d.pop(name, None)
    return Result(**d, problem=problem)


def from_manifold_fields(d, problem):
    """The Result of a manifold's solve from the library's fields (q0, qT, manifold, iterations, ...)."""
    d = dict(d)
    d["inner_iterations"] = d.pop("iterations")
    for name in ("q0", "qT", "manifold"):
        d.pop(name, None)
    return Result(**d, problem=problem)
