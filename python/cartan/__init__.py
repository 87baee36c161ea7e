"""cartan: geometric mechanics on Lie groups with invariant connections.

A thin package over the compiled module ``cartan._cartan`` (C++20, pybind11). Conventions are
those of the C++ library (docs/conventions.md): algebra vectors and covectors are 1-D NumPy
arrays of coordinates in a fixed basis and its dual (paired by ``mu @ v``), linear maps on the
algebra are matrices, left trivialisation is the default. Elements are arrays in each group's
own coordinates: (3, 3) rotations for :class:`SO3`, (a, b, c) for :class:`Heisenberg`, (4, 4)
and (3, 3) homogeneous matrices for :class:`SE3` and :class:`SE2`.

Groups
    ``SO3, Heisenberg, SE3, SE2``: static methods ``identity, compose, inverse, exp, log, hat,
    vee, matrix, Ad, ad, ad_star, bracket, left_translate, left_trivialise, validate``.
Connections (paper §3, §5)
    ``G.cartan_schouten(lam, side="left")`` and ``G.Connection(side, table)``, with ``nabla,
    torsion, curvature, transport, transport_sampled``; ``G.cartan_schouten_transport``.
Models
    Built in: ``RigidBody, SO3Oscillator, SpatialRigidBody, H3Oscillator, SE2FreeBody,
    SE3FreeBody`` and Hamiltonians ``RigidBodyHamiltonian, SO3OscillatorHamiltonian,
    SpatialRigidBodyHamiltonian, H3OscillatorHamiltonian, SE2FreeBodyHamiltonian,
    SE3FreeBodyHamiltonian``. Any Python object with the methods ``value(t, g, v),
    momentum(t, g, v), group_gradient(t, g, v), velocity(t, g, mu)`` (and a ``group``
    attribute, or pass ``group=``) is a Lagrangian; see :func:`solve`.
Checking your own model
    :func:`check_lagrangian` compares a Lagrangian's callbacks with finite differences of each
    other (a :class:`CheckReport`); :mod:`cartan.testing` adds checks of connections and charts.
Integrators
    :func:`euler_poincare` (eq:EP-left, eq:EP-right), :func:`lie_poisson` (eq:LP-left, eq:LP-right).
The transported-velocity boundary-value problem (eq:reduced-system)
    :func:`solve` with ``method`` one of :data:`METHODS` (shooting solvers of the discrete scheme,
    or "collocation" of the continuous problem); returns a :class:`SolveResult`, which
    :func:`verify` checks independently of the solver (a :class:`VerifyReport`); :func:`sweep`
    solves many problems on local threads, processes or a Dask cluster, results in order.
Manifolds with a connection (docs/general-connections.md)
    ``Sphere(), HyperbolicPlane(), Euclidean(christoffel, dim=), GroupManifold(group, connection,
    lam=, metric=, alpha=)`` and your own, ``Chart(christoffel, dim=, metric=)`` (Christoffel symbols
    as a Python function of the coordinates), with ``christoffel, torsion, curvature, frame_bracket, step,
    difference, transport_along_step, tangent_basis, metric, torsion_components,
    curvature_components, has_parallel_torsion_and_curvature, validate``.
The transported-velocity problem on any of them (general/solve.hpp)
    :func:`solve` with a manifold as its first argument and l = 1/2 v.A v - V(q), or
    :func:`solve_general` (which also takes a Python Lagrangian of the manifold); returns a
    :class:`GeneralSolveResult`.
General two-point boundary-value problems
    :func:`solve_bvp`: scipy.integrate.solve_bvp's signature, arguments, result and behaviour
    (python/cartan/_bvp.py) on cartan's fourth-order collocation solver; returns a
    :class:`BvpResult` (a scipy.optimize.OptimizeResult whose ``sol`` is a
    scipy.interpolate.PPoly).

Errors: invalid input raises ValueError with the C++ library's message; an exception raised in
a Python callback during a solve is re-raised unchanged when the solver returns.
"""
from dataclasses import dataclass, field
from types import SimpleNamespace
from typing import Any, Optional

import numpy as np

from . import _bvp, _cartan, _results
from ._arguments import check_types
from ._bvp import solve_bvp  # noqa: F401  (re-exported)
from ._sweep import sweep  # noqa: F401  (re-exported)

#: The version of cartan (the CMake project's VERSION, compiled into the module; as `cartan --version`).
__version__ = _cartan.__version__
from ._cartan import (  # noqa: F401  (re-exported)
    SE2,
    Chart,
    Euclidean,
    GroupManifold,
    HyperbolicPlane,
    SE3,
    SO3,
    H3Oscillator,
    H3OscillatorHamiltonian,
    Heisenberg,
    RigidBody,
    RigidBodyHamiltonian,
    SE2FreeBody,
    SE2FreeBodyHamiltonian,
    SE3FreeBody,
    SE3FreeBodyHamiltonian,
    SO3Oscillator,
    SO3OscillatorHamiltonian,
    SpatialRigidBody,
    SpatialRigidBodyHamiltonian,
    Sphere,
)

GROUPS = (SO3, Heisenberg, SE3, SE2)
#: The transported-velocity solvers (see :func:`solve`).
METHODS = tuple(SO3.methods)
#: Every status word a solver reports (the same as the CLI's JSON).
STATUSES = tuple(_cartan.statuses)
#: The manifold classes :func:`solve` (and :func:`solve_general`) accept.
MANIFOLDS = (Sphere, HyperbolicPlane, Euclidean, GroupManifold, Chart)

__all__ = [
    "SO3", "Heisenberg", "SE3", "SE2", "GROUPS", "METHODS", "STATUSES",
    "RigidBody", "SO3Oscillator", "SpatialRigidBody", "H3Oscillator", "SE2FreeBody", "SE3FreeBody",
    "RigidBodyHamiltonian", "SO3OscillatorHamiltonian", "SpatialRigidBodyHamiltonian", "H3OscillatorHamiltonian",
    "SE2FreeBodyHamiltonian", "SE3FreeBodyHamiltonian",
    "Trajectory", "SolveResult", "euler_poincare", "lie_poisson", "lagrangian_hessian", "solve", "sweep",
    "VerifyReport", "verify", "load", "model_of", "CheckReport", "check_lagrangian",
    "BvpResult", "solve_bvp",
    "Sphere", "HyperbolicPlane", "Euclidean", "GroupManifold", "Chart", "MANIFOLDS", "Result", "GeneralSolveResult",
    "solve_general", "verify_general",
]


def _group_of(model, group, what):
    group = group if group is not None else getattr(model, "group", None)
    if group not in GROUPS:
        raise ValueError(f"cartan.{what}: group = {group!r} is not one of SO3, Heisenberg, SE3, SE2 "
                         "(give the model a `group` attribute or pass group=)")
    return group


@dataclass
class Trajectory:
    """A reduced trajectory at the nodes t_k = k T / steps: g (elements), v (velocities, trivialised
    on the integrator's side) and mu (momenta), stacked along the first axis."""
    t: np.ndarray
    g: np.ndarray
    v: np.ndarray
    mu: np.ndarray


def euler_poincare(lagrangian, g0, v0, T, steps, side="left", group=None):
    """Integrates eq:EP-left (side="left": mu' - ad*_v mu = zeta, g' = g v) or eq:EP-right
    (side="right") with RKMK4 from g(0) = g0, v(0) = v0; the Lagrangian must be reduced on `side`."""
    g = _group_of(lagrangian, group, "euler_poincare")
    return Trajectory(**g._euler_poincare(side, lagrangian, g0, v0, T, steps))


def lie_poisson(hamiltonian, g0, mu0, T, steps, side="left", group=None):
    """Integrates eq:LP-left (side="left": mu' - ad*_v mu = -zeta_h, v = dh/dmu) or eq:LP-right
    with RKMK4 from g(0) = g0, mu(0) = mu0."""
    g = _group_of(hamiltonian, group, "lie_poisson")
    return Trajectory(**g._lie_poisson(side, hamiltonian, g0, mu0, T, steps))


def lagrangian_hessian(lagrangian, t, g, v, group=None):
    """Second derivatives used by the tangent-linear sweeps, as a dict of (n, n) matrices
    momentum_v = d mu/dv, momentum_g = d mu/d gamma, gradient_v = d zeta/dv, gradient_g =
    d zeta/d gamma (g perturbed as g exp(e gamma)). Analytic for built-in models; for Python-defined
    ones the object's own hessian(t, g, v) if it has one, else central differences of momentum and
    group_gradient (step 1e-5)."""
    grp = _group_of(lagrangian, group, "lagrangian_hessian")
    return grp._lagrangian_hessian(lagrangian, t, g, v)


@dataclass
class Result:
    """What every solve returns, whichever the problem: :func:`solve` gives a :class:`SolveResult`
    for a group model and a :class:`GeneralSolveResult` on a manifold, both of this type, with these
    fields in common (each kind adds the fields its problem has: the group's g and xi, or the
    manifold's q, frame and Xi).

    status: one of :data:`STATUSES`; success (also `converged`): status == "converged"; message:
    diagnostics; method: the method that produced the result (one of :data:`METHODS`, never "auto");
    order: the scheme's (1, 2) or 4 for collocation; branch: how it was reached. T, N, tol: the
    problem's horizon and steps and the requested tolerance. t (N+1,): the times; v, mu (N+1, dim):
    the transported velocity and the momentum (a failed result: its best iterate of the requested
    problem, or no rows at all). v0: the initial velocity; terminal_error: how far the end point is
    from the requested one; xi_terminal: the size of the auxiliary at T; sweeps: runs of the scheme
    (collocation: Jacobian evaluations); residual_history; solve_time: seconds in the solver.
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
    v: np.ndarray
    mu: np.ndarray
    v0: np.ndarray
    terminal_error: float
    xi_terminal: float
    sweeps: int
    residual_history: np.ndarray = field(repr=False)
    solve_time: float

    @property
    def converged(self):
        """The same as `success` (the C++ result's converged())."""
        return self.success


@dataclass
class SolveResult(Result):
    """The result of :func:`solve`, in the spirit of scipy.integrate.solve_bvp's.

    status: one of :data:`STATUSES` ("converged", or what failed: "max-iterations", "stalled",
    "non-finite", "no-progress", "continuation-failed", "strategy-failed", ...; the same words as
    the CLI's JSON); success: status == "converged"; message: diagnostics (every attempt, iterations,
    residual history); method: the method that produced the result (one of :data:`METHODS`, never
    "auto"); branch: how it was reached (e.g. "continuation in T (continued in T from T = 3 (6
    stages)), after shooting failed").
    t (N+1,), g (N+1, ``*element_shape``), v, mu, xi (N+1, dim): the discrete solution at every node, v
    the transported velocity left-trivialised at g0 (collocation: at the final mesh or `samples`
    times). A failed result carries the best iterate *of the requested problem* (never a stage of a
    continuation at another T or lambda), or no rows at all.
    g0, gT, tol: the problem's boundary elements and the requested tolerance (what :func:`verify` checks
    against).
    v0, xi0: the initial values; terminal_error = ``|log(gT^-1 g_N)|``, xi_terminal = ``|xi_N|``;
    action: the discrete transported action S_h of the trajectory (tells branches apart);
    outer_iterations, inner_iterations, sweeps: work done (collocation: mesh refinements, Newton
    iterations, Jacobians); mesh_size, max_residual, group_defect: collocation only (else None;
    group_defect = max ``|g^T g - I|`` over the mesh of g and the transport element on SO(3), NaN elsewhere);
    solve_time: seconds in the solver.

    Self-description (what :meth:`to_json` writes and :func:`load` reads, the CLI's vocabulary):
    model: the CLI's model name of a built-in model ("free-rigid-body" or "oscillator" on SO3,
    "oscillator" on Heisenberg, "free-body" on SE2 and SE3; the CLI's group is ``group.lower()``)
    or "python:<type name>" for a Lagrangian defined in Python, which a file
    cannot rebuild; inertia: the built-in model's (n, n) inertia (a Python Lagrangian's `inertia`
    attribute, else None); connection "cartan-schouten" with parameter `lam` and side "left" (v is
    left-trivialised; the transport P acts on it from the left, eq:reduced-system).
    :func:`model_of` rebuilds the built-in model.

    Along the solution (one row per node, computed by the library, include/cartan/transported/along.hpp):
    P (N+1, dim, dim): the transport operator P_k = Ad(h_k) of eq:reduced-system, h_0 = e and
    h_k+1 = exp(-lam log(g_k^-1 g_k+1)) h_k (disc-exp; exact for the shooting schemes and the
    variational integrator, second order in the spacing for collocation); u (N+1, dim): the body
    velocity u_k = P_k v_k = g^-1 g' (disc-body-v); energy (N+1,): E_k = mu_k.v_k - l(t_k, g_k, v_k),
    what `cartan verify` checks; cumulative_action (N+1,): the discrete transported action S_h over
    the first k steps (0 at k = 0; its last entry is `action`). energy and cumulative_action are None
    for a loaded file of a Python-defined model. (They are computed once after the solve: for a
    Lagrangian defined in Python, N+1 more calls of value and momentum.) A result stopped on request
    (status "interrupted" or "time-limit") carries its best iterate's samples only: action is NaN and
    P, u, energy, cumulative_action are None, since over a long trajectory they cost what the stop
    was there to save (:func:`load` of its :meth:`to_json` file computes them).
    Dense output :meth:`sol`, the CLI's JSON :meth:`to_json` and :func:`load`, a figure :meth:`plot`.
    """
    group: str
    lam: float
    g0: np.ndarray = field(repr=False)
    gT: np.ndarray = field(repr=False)
    g: np.ndarray
    xi: np.ndarray
    xi0: np.ndarray
    action: float
    outer_iterations: int
    inner_iterations: int
    mesh_size: Optional[int] = None
    max_residual: Optional[float] = None
    group_defect: Optional[float] = None
    model: str = ""
    inertia: Optional[np.ndarray] = field(default=None, repr=False)
    connection: str = "cartan-schouten"
    side: str = "left"
    u: Optional[np.ndarray] = field(default=None, repr=False)
    P: Optional[np.ndarray] = field(default=None, repr=False)
    energy: Optional[np.ndarray] = field(default=None, repr=False)
    cumulative_action: Optional[np.ndarray] = field(default=None, repr=False)

    def sol(self, t):
        """Dense output: the solution at the time or times `t` in [t_0, t_N] = [0, T] (outside:
        ValueError), as a :class:`cartan._results.State` (g, v, mu, xi; a leading axis for an array
        `t`). At a node it returns the sample itself. The interpolants are the library's
        (include/cartan/transported/dense.hpp), as follows.

        Discrete schemes (shooting, two-level, multiple-shooting, variational): on step k, g(t) =
        g_k exp(s log(g_k^-1 g_k+1)), s = (t - t_k)/h, the translated one-parameter subgroup through
        both nodes:
        the Lie–Euler and RKMK steps of the scheme (disc-grp) move g along exactly such a curve, it
        stays on the group (a linear blend of matrices would leave SO(3)), and its error against the
        smooth solution is O(h^2), no larger than the nodes' own error at order 1 or 2; v, mu, xi are
        linear in s (O(h^2)). Collocation: g by the cubic Hermite interpolant in the chart g_k exp(X),
        with X' from the body velocities u at both ends; xi by cubic Hermite with xi' = -ad*_v mu
        (disc-aux); v and mu by not-a-knot cubic splines through the nodes (their derivatives need the
        model). The measured orders are in python/tests/test_results.py."""
        return _results.dense(self, t)

    def to_json(self, path):
        """Writes the result to `path` as the JSON of `cartan solve --output` (the same keys; NaN and
        infinities as null), which `cartan verify path` checks and :func:`load` reads back. A
        Lagrangian defined in Python is written as model "python:<type name>", which `cartan verify`
        rejects (it cannot rebuild the model) and :func:`load` accepts."""
        _results.to_json(self, path)

    def plot(self, path=None):
        """A matplotlib Figure (matplotlib is imported on first use): the path in the group (SO(3):
        the body axes g e1, g e2, g e3 on the unit sphere; Heisenberg: a, b, c against t; SE(2), SE(3):
        the translation), then v and mu against t, one line per component. With `path`, also saved
        there (the format from its extension)."""
        return _results.plot(self, path)

    def __repr__(self):
        return (f"SolveResult(status={self.status!r}, success={self.success}, method={self.method!r}, "
                f"group={self.group!r}, lam={self.lam:g}, T={self.T:g}, N={self.N}, "
                f"terminal_error={self.terminal_error:.3e}, action={self.action:.6g}, "
                f"iterations=(outer={self.outer_iterations}, inner={self.inner_iterations}, sweeps={self.sweeps}), "
                f"branch={self.branch!r}, solve_time={self.solve_time:.4f})")


def solve(lagrangian, *, lam=None, T, N, gT=None, g0=None, method="auto", continuation="none", order=1,
          tol=_cartan.defaults["tol"], max_iterations=_cartan.defaults["max_iterations"],
          segments: Optional[int] = None, lambda_start: Optional[float] = None, v0=None, xi0=None, guess=None,
          group=None, samples: Optional[int] = None, max_nodes: Optional[int] = None,
          time_limit: Optional[float] = None, progress=None, q0=None, qT=None, inertia=None, potential=None,
          potential_gradient=None, gravity=None, frame0=None, Xi0=None):
    """Solves the transported-velocity boundary-value problem. One entry point for both kinds of
    problem, decided by the first argument:

    * a group model (below): the Cartan-Schouten connection of parameter `lam` (eq:reduced-system;
      paper §6-7) on [0, T] with N steps, g(0) = g0 (default: the identity), g(T) = gT (`lam` and
      `gT` required), returning a :class:`SolveResult`;
    * a manifold (any of :data:`MANIFOLDS`, its connection included): the problem of
      :func:`solve_general` with q0, qT and the Lagrangian given by `inertia`, `potential`,
      `potential_gradient`, `gravity` (and `frame0`, `Xi0`), returning a :class:`GeneralSolveResult`.
      A :class:`GroupManifold` with connection "cartan-schouten" reaches the Lie-group kernel by
      itself. A Lagrangian object of the manifold goes through ``solve_general(manifold,
      lagrangian=...)``.

    The keywords of the other kind raise ValueError naming them. With the discrete scheme of order 1
    (the paper's) or 2. The library's solve (include/cartan/transported/compiled.hpp) does the work;
    methods, options and behaviour are those of `cartan solve`. What follows is the group model's
    problem; the manifold's is :func:`solve_general`'s.

    `lagrangian` is a built-in left-reduced model (RigidBody, SO3Oscillator, H3Oscillator) or any
    object with methods value(t, g, v), momentum(t, g, v) (= dl/dv), group_gradient(t, g, v)
    (left-trivialised dl/dg) and velocity(t, g, mu) (the inverse Legendre map) taking and
    returning NumPy arrays; its group is `group` or its `group` attribute. The tangent-linear
    sweeps need second derivatives: from the object's optional method hessian(t, g, v) returning
    a dict like :func:`lagrangian_hessian`'s, else by central differences of momentum and
    group_gradient (24 extra callbacks per node on a 3-dimensional group).

    method (one of :data:`METHODS`):

    "auto"
        (default) a strategy: shooting from the guess, continuation in T (not for purely kinetic
        Lagrangians), continuation in lambda from 0 and from 1, collocation then shooting from its
        solution, multiple shooting; it stops at the first success and `branch` names the path.
    "shooting"
        augmented shooting on (v0, xi0) with an analytic Jacobian; `continuation` "T" or "lambda"
        (from `lambda_start`, default 0) when it fails from the guess.
    "multiple-shooting"
        lifted Levenberg-Marquardt over `segments` segments.
    "two-level"
        the paper's scheme (inner LM shooting on v0, outer fixed point on xi).
    "collocation"
        the continuous problem by fourth-order adaptive collocation from the geodesic guess (or
        `guess`) on a uniform mesh of N intervals; tol bounds the relative RMS residual per
        interval; `samples` (0: the final mesh, else >= 2 uniform times) and `max_nodes` (default
        20000); `continuation` "T"/"lambda": where to start when Newton fails (from that order-2
        shooting solution). Built-in natural models only.
    "variational"
        Newton on the discrete Euler-Lagrange equations of the discrete action S_h for the interior
        nodes (second order; dense, for N up to a few hundred); from the geodesic path or `guess`
        (its g); tol bounds the last Newton correction (radians); no v0/xi0, order 1 only.

    tol: shooting methods, on ``|(log(gT^-1 g_N), xi_N / xi_scale)|`` (radians and a relative xi, so that
    it means the same at every horizon); two-level, the outer change of xi relative to xi_scale.
    v0, xi0: guesses (default: the geodesic velocity log(g0^-1 gT)/T and 0); guess: a whole trajectory
    (any object with t, g, v, xi, e.g. a previous SolveResult), as scipy.integrate.solve_bvp takes y.
    progress: a callable (stage, iteration, residual) called once per iteration.
    time_limit: seconds the whole call may take, every method and attempt (default None: no limit);
    past it the running method stops at its next iteration and the result has status "time-limit"
    (its samples only: no action, P, u, energy or cumulative_action; see :class:`SolveResult`).
    Ctrl-C raises KeyboardInterrupt within one iteration; invalid arguments raise ValueError before
    any work. Solves of built-in models run without the GIL (so that threads solve in parallel).
    Many problems at once, on threads, processes or a cluster: :func:`sweep`.
    """
    arguments = locals()
    if isinstance(lagrangian, MANIFOLDS):
        return _solve_on_manifold(lagrangian, arguments)
    result = _transported("_solve", arguments)
    grp = _group_of(lagrangian, group, "solve")
    result["model"], result["inertia"] = _results.describe_model(lagrangian, grp)
    return SolveResult(**result)


def load(path):
    """Reads a :class:`SolveResult` from the JSON `cartan solve --output` writes (or
    :meth:`SolveResult.to_json`): every key is checked, and a bad or missing one raises ValueError
    naming it; null (the CLI's NaN or infinity) becomes NaN. What the file does not hold is rebuilt:
    v0 and xi0 are the first rows of v and xi, residual_history is empty, and u, P, energy and
    cumulative_action come from the library as after a solve (for a built-in model, with the model
    :func:`model_of` rebuilds; for "python:<name>" models energy and cumulative_action are None).
    ``cartan.verify(r, cartan.model_of(r))`` then checks the file as `cartan verify` does."""
    fields = _results.load_dict(path)
    grp = _results._group_class(fields["group"], "cartan.load")
    model = None if fields["model"].startswith(_results.PYTHON_MODEL) else _results.model_of(SimpleNamespace(**fields))
    return SolveResult(**fields, **grp._along(model, fields, fields["lam"]))


def model_of(result):
    """The built-in model of a :class:`SolveResult` (e.g. one from :func:`load`), rebuilt from its
    group, model name and inertia: ``cartan.verify(r, cartan.model_of(r))``. Raises ValueError for a
    Lagrangian defined in Python (model "python:<type name>"), which a result cannot rebuild."""
    return _results.model_of(result)


#: cartan.solve's keywords of each kind of problem (a group model's, a manifold's).
_GROUP_KEYWORDS = ("lam", "gT", "g0", "xi0", "group")
_MANIFOLD_KEYWORDS = ("q0", "qT", "inertia", "potential", "potential_gradient", "gravity", "frame0", "Xi0")


def _refuse_other_kind(where, arguments, keywords, why):
    """ValueError "<where>: <key> = <value> <why>" for the first of `keywords` given (not None) in
    `arguments`: cartan.solve's and cartan.verify's refusal of the other kind of problem's keywords."""
    for name in keywords:
        value = arguments.get(name)
        if value is not None:
            shown = " ".join(repr(value).split())  # an array on one line
            raise ValueError(f"{where}: {name} = {shown[:80]}{'...' if len(shown) > 80 else ''} {why}")


def _solve_on_manifold(manifold, arguments):
    """cartan.solve on a manifold: :func:`solve_general` with the manifold's keywords."""
    _refuse_other_kind("cartan.solve", arguments, _GROUP_KEYWORDS,
                       f"applies to a group model's problem, not on the manifold {type(manifold).__name__} (its "
                       "connection is the manifold's)")
    names = ("T", "N", "method", "continuation", "order", "tol", "max_iterations", "segments", "lambda_start", "v0",
             "guess", "max_nodes", "time_limit", "progress") + _MANIFOLD_KEYWORDS
    samples = arguments["samples"]
    return solve_general(manifold, samples=0 if samples is None else samples, **{k: arguments[k] for k in names})



#: The solve's options (the library's OptionWords, principle/options.hpp).
_OPTIONS = ("method", "continuation", "order", "tol", "max_iterations", "segments", "lambda_start", "samples",
            "max_nodes", "time_limit")


def _set_options(request, arguments):
    """The options given (not None) on a request; the library's defaults stand for the others."""
    for name in _OPTIONS:
        if arguments[name] is not None:
            setattr(request, name, arguments[name])


def _transported(entry, arguments):
    """`<Group>.<entry>` ("_solve", or "_validate": every input error of _solve, no solve) on the
    keyword arguments of :func:`solve` given as a dict."""
    lagrangian = arguments["lagrangian"]
    _refuse_other_kind("cartan.solve", arguments, _MANIFOLD_KEYWORDS,
                       "applies to a problem on a manifold (pass the manifold as the first argument); lagrangian = "
                       f"{type(lagrangian).__name__} is a group model")
    for name in ("lam", "gT"):
        if arguments[name] is None:
            raise TypeError(f"cartan.solve: missing a required argument: {name!r} (a group model's problem)")
    check_types("cartan.solve", arguments)
    if getattr(lagrangian, "side", "left") != "left":
        raise ValueError(f"cartan.solve: lagrangian = {type(lagrangian).__name__} is right-reduced; "
                         "the transported-velocity problem needs a left-reduced Lagrangian")
    grp = _group_of(lagrangian, arguments["group"], "solve")
    request = _cartan._SolveRequest()
    _set_options(request, arguments)
    a = arguments
    return getattr(grp, entry)(lagrangian, a["lam"], a["T"], a["N"], a["g0"], a["gT"], request, a["v0"], a["xi0"],
                               a["guess"], a["progress"])


@dataclass
class GeneralSolveResult(Result):
    """The result of :func:`solve` on a manifold (and of :func:`solve_general`), with the vocabulary of
    :class:`SolveResult`.

    status: one of :data:`STATUSES`; success (also `converged`): status == "converged"; message,
    method ("shooting" or "collocation"; on the Lie-group kernel also "multiple-shooting" and
    "two-level"), order, branch: as in SolveResult; manifold: the manifold's
    name; T, N, q0, qT, tol: the problem and the requested tolerance.
    t (N+1,), q (N+1, ``*point_shape``): the nodes and points (collocation: the final mesh or the
    `samples` times); frame (N+1, d, m): the parallel frame
    e_i(t_k) (frame[0] = frame0); v, mu (N+1, m): the transported velocity and the momentum in
    components of frame0 (q' = frame @ v); Xi (N+1, m, m): the auxiliary Xi^k_n = int_t^T v^k mu_n.
    A failed result carries the best iterate of the requested problem, or no rows at all.
    v0, Xi0: the initial values; terminal_error: how far q_N is from qT, ``|difference(qT, q_N)|`` where
    that is a logarithm and the distance of the stored points at the cut locus (never 0 there);
    xi_terminal = ``|Xi_N|``;
    iterations (Levenberg-Marquardt's, summed over the stages of a continuation in T and the
    attempts of the default strategy; or collocation's Newton), sweeps (runs of the scheme;
    collocation: Jacobian evaluations); residual_history; solve_time: seconds in the solver; mesh_size,
    max_residual: collocation only (else None; order is then 4).
    """
    manifold: str
    q0: np.ndarray = field(repr=False)
    qT: np.ndarray = field(repr=False)
    q: np.ndarray
    frame: np.ndarray
    Xi: np.ndarray
    Xi0: np.ndarray
    iterations: int
    mesh_size: Optional[int] = None
    max_residual: Optional[float] = None
    space: Any = field(default=None, repr=False, compare=False)

    def __getstate__(self):
        """Pickling keeps every array and word but not `space` (a manifold with Python callbacks,
        a Chart, cannot be pickled): a result that travelled has `space` None; set it to the
        manifold again for :meth:`sol`."""
        state = dict(self.__dict__)
        state["space"] = None
        return state

    def sol(self, t):
        """Dense output: the solution at the time or times `t` in [t_0, t_N] = [0, T] (outside:
        ValueError) on the manifold it was solved on (`space`), as a :class:`cartan._results.GeneralState`
        (q, frame, v, mu, Xi; a leading axis for an array `t`). At a node it returns the sample itself.
        On a step, q(t) = step(q_k, s difference(q_k, q_k+1)) and the frame transported along that
        piece (the one the schemes move along; O(h^2)); v, mu, Xi linear in s for the discrete
        schemes, and for collocation v, mu by not-a-knot cubic splines and Xi by cubic Hermite with
        Xi' = -v mu^T. The library's (include/cartan/general/dense.hpp)."""
        return _results.general_dense(self, t)

    def __repr__(self):
        return (f"GeneralSolveResult(status={self.status!r}, success={self.success}, manifold={self.manifold!r}, "
                f"T={self.T:g}, N={self.N}, order={self.order}, terminal_error={self.terminal_error:.3e}, "
                f"iterations={self.iterations}, sweeps={self.sweeps}, branch={self.branch!r}, "
                f"solve_time={self.solve_time:.4f})")


def solve_general(manifold, *, T, N, q0, qT, inertia=None, potential=None, potential_gradient=None, gravity=None,
                  lagrangian=None, frame0=None, method="auto", continuation="none", order=1,
                  tol=_cartan.defaults["tol"], max_iterations=_cartan.defaults["max_iterations"], v0=None,
                  Xi0=None, guess=None, samples=0, max_nodes=None, time_limit=None, progress=None,
                  segments: Optional[int] = None, lambda_start: Optional[float] = None):
    """Solves the transported-velocity boundary-value problem on a manifold with any linear connection
    (docs/general-connections.md; the library's general::solve): on [0, T] with N steps, q(0) = q0,
    q(T) = qT, for l(q, v) with v the components of the transported velocity in the frame `frame0`
    of T_{q0}Q ((d, m); default manifold.tangent_basis(q0)), with the scheme of order 1 or 2.

    manifold: a :class:`Sphere`, :class:`HyperbolicPlane`, :class:`Euclidean`, :class:`GroupManifold` or
    :class:`Chart`
    (any of :data:`MANIFOLDS`). Points q0, qT have the manifold's `point_shape` and must be valid
    points (on the sphere, on the upper sheet of the hyperboloid, group elements).

    The Lagrangian, either

    l = 1/2 v.A v - V(q)
        inertia A, a symmetric positive-definite (m, m) matrix or its (m,) diagonal (default
        identity); potential V(q) -> float with potential_gradient(q) -> an ambient (d,) covector
        zeta with zeta . x = d/de V(step(q, e x)) for tangent x (both or neither; on a group, the
        left-trivialised gradient); or gravity G, on the Sphere only: V = G q[2];
    or lagrangian
        an object with methods value(t, q, v), momentum(t, q, v) (= dl/dv, (m,)), velocity(t, q, mu)
        (the inverse Legendre map) and point_gradient(t, q, v) (an ambient (d,) covector with
        zeta . x = d/de l(t, step(q, e x), v)), taking and returning NumPy arrays.

    method: "auto" (the default strategy, as :func:`solve`'s: shooting from the guess, continuation in
    T, collocation polished by shooting; on the Lie-group kernel also continuation in lambda and
    multiple shooting), "shooting"
    (with continuation "none" or "T") or "collocation" of the continuous system (fourth order,
    adaptive mesh; from `guess` or the geodesic guess, and with continuation "T" from the order-2
    shooting solution when Newton fails from the geodesic guess). On a GroupManifold with connection
    "cartan-schouten" (lam given) and the default frame0, shooting and continuation in T run on the
    Lie-group kernel, the scheme of cartan.solve with 2 dim unknowns instead of dim + dim^2, and the
    result is converted to this scheme's (the same discrete equations: frame = P, Xi rebuilt;
    docs/general-connections.md, "The Lie-group kernel"); its message starts "Lie-group kernel".
    There the kernel's own methods are available too, as :func:`solve` runs them: "multiple-shooting"
    (`segments`), "two-level", and "shooting" with continuation "lambda" (from `lambda_start`,
    default 0); anywhere else they are refused by name. "variational" is :func:`solve`'s only. tol: shooting, on the
    dimensionless terminal residual ``|(difference(qT, q_N), Xi_N / s)|`` (on the Lie-group kernel
    ``|(log(qT^-1 q_N), xi_N / s)|``, xi = C(Xi)); collocation, on the relative RMS residual per interval.
    max_iterations: Levenberg-Marquardt (Newton) iterations per stage (per mesh). v0 (m,), Xi0 (m, m):
    guesses (default: the geodesic guess and 0); guess: a whole trajectory instead, any object with
    t (from 0 to T), q, frame, v, mu, Xi such as an earlier GeneralSolveResult. samples (collocation):
    output at this many uniform times (0: the final mesh); max_nodes (collocation, default 20000).
    time_limit: seconds the whole call may take (default None: no limit); past it the running method
    stops at its next iteration with status "time-limit". solve_time: the whole call, every attempt.
    progress: a callable (stage, iteration, residual) called once per iteration.

    Solves without Python callbacks run without the GIL. Ctrl-C raises KeyboardInterrupt within one
    iteration; invalid arguments raise ValueError naming the value; an exception raised in a Python
    callback is re-raised unchanged. Returns a :class:`GeneralSolveResult`.
    """
    check_types("cartan.solve_general", dict(T=T, N=N, method=method, continuation=continuation,
                                             order=order, tol=tol, max_iterations=max_iterations, samples=samples,
                                             max_nodes=max_nodes, time_limit=time_limit, segments=segments,
                                             lambda_start=lambda_start))
    request = _cartan._GeneralRequest()
    request.T, request.N, request.q0, request.qT = T, N, q0, qT
    request.inertia, request.potential, request.potential_gradient = inertia, potential, potential_gradient
    request.gravity, request.lagrangian, request.frame0 = gravity, lagrangian, frame0
    request.v0, request.Xi0, request.progress, request.guess = v0, Xi0, progress, guess
    _set_options(request, dict(method=method, continuation=continuation, order=order, tol=tol,
                               max_iterations=max_iterations, samples=samples, max_nodes=max_nodes,
                               time_limit=time_limit, segments=segments, lambda_start=lambda_start))
    return GeneralSolveResult(**_cartan._solve_general(manifold, request), space=manifold)


class _Printed:
    """A report whose ``str`` is its ``text``."""

    def __str__(self):
        return self.text


@dataclass
class VerifyReport(_Printed):
    """The verdict of :func:`verify` (the same checks and thresholds as `cartan verify`;
    docs/verify.md): passed (every check passes), verdict ("PASS" or "FAIL"), resolution
    rho = h omega, order p of the thresholds, amplification a (the lambda factor), checks (a list of
    dicts name, figure, threshold, result ("PASS", "FAIL", "N/A"), note) and text (the report as
    `cartan verify` prints it; also ``str(report)``)."""
    passed: bool
    verdict: str
    resolution: float
    order: int
    amplification: float
    checks: list
    text: str = field(repr=False)


def verify_general(result, manifold, *, inertia=None, potential=None, potential_gradient=None, gravity=None,
                   lagrangian=None):
    """Checks a :class:`GeneralSolveResult` on `manifold` independently of the solver, as
    `cartan verify` does for --manifold and --connection results (docs/general-connections.md,
    "Verification"): boundary conditions against result.tol, the Legendre relation, conservation of
    E = mu.v - l, the residual of the local form by finite differences (the parallel frame rebuilt
    from the samples) and the stationarity of the discrete transported action. The Lagrangian is given
    as for :func:`solve_general`. `result` may be any object with the fields T, q0, qT, tol, order,
    status, t, q, frame (frame[0] is the frame at q0), v, mu, Xi. Returns a :class:`VerifyReport`."""
    request = _cartan._GeneralRequest()
    request.inertia, request.potential, request.potential_gradient = inertia, potential, potential_gradient
    request.gravity, request.lagrangian = gravity, lagrangian
    return VerifyReport(**_cartan._verify_general(manifold, request, result))


def verify(result, lagrangian, *, group=None, inertia=None, potential=None, potential_gradient=None, gravity=None):
    """Checks a result independently of the solver, as `cartan verify` does, and returns a
    :class:`VerifyReport`. One entry point for both kinds of result:

    * a :class:`SolveResult` of the Lagrangian `lagrangian` (docs/verify.md): boundary conditions
      against result.tol, the Legendre relation, conservation of E = mu.v - l (for a Lagrangian that
      does not depend on t), the residual of eq:reduced-system by finite differences and the
      stationarity of the discrete transported action, with thresholds from the order and the
      resolution h omega. A result that did not converge always fails (check "converged"). `result`
      may be any object with the fields lam, T, g0, gT, order, tol, status, t, g, v, mu, xi (e.g. a
      SolveResult with a changed field); `lagrangian` is a built-in model or a Python-defined
      Lagrangian as for :func:`solve`.
    * a :class:`GeneralSolveResult`, with `lagrangian` its manifold (any of :data:`MANIFOLDS`): the
      checks of :func:`verify_general`, the Lagrangian given by `inertia`, `potential`,
      `potential_gradient`, `gravity` as for :func:`solve_general`. A Lagrangian object of the
      manifold goes through ``verify_general(result, manifold, lagrangian=...)``.

    Which one is decided by `lagrangian`: a manifold means the second, anything else the first; the
    keywords of the other kind raise ValueError naming them."""
    terms = dict(inertia=inertia, potential=potential, potential_gradient=potential_gradient, gravity=gravity)
    if isinstance(lagrangian, MANIFOLDS):
        _refuse_other_kind("cartan.verify", dict(group=group), ("group",), "applies to a group model's SolveResult, "
                           f"not on the manifold {type(lagrangian).__name__}")
        return verify_general(result, lagrangian, **terms)
    if isinstance(result, GeneralSolveResult):
        raise ValueError(f"cartan.verify: lagrangian = {type(lagrangian).__name__} is not a manifold; a "
                         "GeneralSolveResult is checked on its manifold: cartan.verify(result, manifold, ...)")
    _refuse_other_kind("cartan.verify", terms, terms, "applies to a manifold's GeneralSolveResult (pass the "
                       "manifold as the second argument); a group model carries its own Lagrangian")
    grp = _group_of(lagrangian, group, "verify")
    d = grp._verify(lagrangian, result, result.lam, result.T, result.g0, result.gT, result.order, result.tol,
                    result.status)
    return VerifyReport(**d)


@dataclass
class CheckReport(_Printed):
    """The report of :func:`check_lagrangian` and of the checks in :mod:`cartan.testing`: ok (every
    check passed), samples (how many sample points), checks (one dict per check: callback (the
    callback checked, e.g. "group_gradient" or "hessian.gradient_g"), reference (what it is
    compared with), checked (False when there is nothing to check), ok, discrepancy (the largest
    relative discrepancy over the samples), reference_error (the relative error of the reference
    itself there, e.g. of the finite differences), threshold, sample (its index, -1 for none), at
    (that sample), note (a non-finite value or an exception)), and text (also ``str(report)``),
    which names each failing callback and the size of its discrepancy."""
    ok: bool
    samples: int
    checks: list
    text: str = field(repr=False)

    @property
    def failing(self):
        """The callbacks whose check failed, in order."""
        return [c["callback"] for c in self.checks if not c["ok"]]


def check_lagrangian(model, group=None, *, samples=8, seed=20261122, scale=1.0, side=None):
    """Checks a Lagrangian's callbacks against each other (the C++ mechanics::check_lagrangian,
    include/cartan/mechanics/check_lagrangian.hpp) and returns a :class:`CheckReport`:

    - momentum against central differences of value along v + e E_i,
    - group_gradient against central differences of value along g exp(e E_i) (``side="right"``:
      exp(e E_i) g),
    - velocity against the inverse of momentum (velocity(momentum(v)) = v, momentum(velocity(mu)) = mu),
    - the model's own hessian, if it has one, block by block against central differences of momentum
      and group_gradient (the solvers otherwise difference them; :func:`lagrangian_hessian`).

    Discrepancies are relative, with the differences' own error estimate as floor, so that the
    scale of the model does not matter; a derivative fails above a relative 1e-6 (or ten times the
    differences' error where that is larger; they are accurate to about 1e-10), the inverse above
    1e-8. A sign error or a wrong factor gives a discrepancy of order 1.

    model: a built-in Lagrangian or a Python object as for :func:`solve` (value, momentum,
    group_gradient, velocity and optionally hessian); its group is `group` or its ``group``
    attribute. samples: a count of seeded pseudo-random points (t in [0, scale], g = exp(w) and v
    with coordinates in [-scale, scale]; `seed`), or a sequence of (t, g, v) triples. side: how
    group_gradient is trivialised, "left" or "right" (default: the model's ``side`` attribute, else
    "left"). A non-finite value is reported (note) rather than raised; an exception raised in a
    Python callback is re-raised."""
    grp = _group_of(model, group, "check_lagrangian")
    side = side if side is not None else getattr(model, "side", "left")
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or not 0 <= seed < 2**32:
        raise ValueError(f"cartan.check_lagrangian: seed = {seed!r} is not an integer in [0, 2**32)")
    return CheckReport(**grp._check_lagrangian(model, samples, int(seed), scale, side))


def __getattr__(name):
    # BvpResult subclasses scipy.optimize.OptimizeResult: SciPy is imported on first use only.
    if name == "BvpResult":
        return _bvp.result_class()
    raise AttributeError(f"module 'cartan' has no attribute {name!r}")
