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
    or "collocation" of the continuous problem); returns a :class:`Result` carrying its problem,
    which ``verify(r)`` checks independently of the solver (a :class:`VerifyReport`); :func:`sweep`
    solves many problems on local threads, processes or a Dask cluster, results in order.
Manifolds with a connection (docs/general-connections.md)
    ``Sphere(), HyperbolicPlane(), Euclidean(christoffel, dim=), GroupManifold(group, connection,
    lam=, metric=, alpha=)`` and your own, ``Chart(christoffel, dim=, metric=)`` (Christoffel symbols
    as a Python function of the coordinates), with ``christoffel, torsion, curvature, frame_bracket, step,
    difference, transport_along_step, tangent_basis, metric, torsion_components,
    curvature_components, has_parallel_torsion_and_curvature, validate``.
The transported-velocity problem on any of them (methods/solve.hpp)
    :func:`solve` with a manifold as its first argument and l = 1/2 v.A v - V(q), or with a
    Lagrangian object of the manifold and ``space=manifold``; returns the same :class:`Result`.
General two-point boundary-value problems
    :func:`solve_bvp`: scipy.integrate.solve_bvp's signature, arguments, result and behaviour
    (python/cartan/_bvp.py) on cartan's fourth-order collocation solver; returns a
    :class:`BvpResult` (a scipy.optimize.OptimizeResult whose ``sol`` is a
    scipy.interpolate.PPoly).

Errors: invalid input raises ValueError with the C++ library's message; an exception raised in
a Python callback during a solve is re-raised unchanged when the solver returns.
"""
import warnings
from dataclasses import dataclass, field
from types import SimpleNamespace
from typing import Optional

import numpy as np

from . import _bvp, _cartan, _result, _results
from ._result import Problem, Result
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
    "Trajectory", "Result", "Problem", "euler_poincare", "lie_poisson", "lagrangian_hessian", "solve", "sweep",
    "VerifyReport", "verify", "load", "model_of", "CheckReport", "check_lagrangian",
    "BvpResult", "solve_bvp",
    "Sphere", "HyperbolicPlane", "Euclidean", "GroupManifold", "Chart", "MANIFOLDS", "SPACES",
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


def solve(lagrangian=None, *, space=None, lam=None, T, N, gT=None, g0=None, method="auto", continuation="none",
          order=1, tol=_cartan.defaults["tol"], max_iterations=_cartan.defaults["max_iterations"],
          segments: Optional[int] = None, lambda_start: Optional[float] = None, v0=None, xi0=None, guess=None,
          group=None, samples: Optional[int] = None, max_nodes: Optional[int] = None,
          time_limit: Optional[float] = None, progress=None, q0=None, qT=None, inertia=None, potential=None,
          potential_gradient=None, gravity=None, frame0=None, Xi0=None):
    """Solves the transported-velocity boundary-value problem and returns a :class:`Result`, which
    carries the problem. One entry point for every problem:

    * a group model (below): the Cartan-Schouten connection of parameter `lam` (eq:reduced-system;
      paper §6-7) on [0, T] with N steps, g(0) = g0 (default: the identity), g(T) = gT (`lam` and
      `gT` required);
    * a manifold with its connection (any of :data:`MANIFOLDS`), as the first argument or as `space`:
      q(0) = q0, q(T) = qT, and the Lagrangian given by `inertia`, `potential`,
      `potential_gradient`, `gravity`, or as an object of the manifold, ``solve(my_lagrangian,
      space=manifold, ...)`` (its methods below, "On a manifold"). A :class:`GroupManifold` with
      connection "cartan-schouten" reaches the Lie-group kernel by itself.

    The keywords of the other kind raise ValueError naming them. With the discrete scheme of order 1
    (the paper's) or 2. The library's solves (include/cartan/kernels/lie_group/compiled.hpp,
    include/cartan/kernels/manifold/compiled.hpp) do the work; methods, options and behaviour are those of
    `cartan solve`. What follows is the group model's problem; the manifold's is after it.

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
    (any object with t, g, v, xi, e.g. a previous Result), as scipy.integrate.solve_bvp takes y.
    progress: a callable (stage, iteration, residual) called once per iteration.
    time_limit: seconds the whole call may take, every method and attempt (default None: no limit);
    past it the running method stops at its next iteration and the result has status "time-limit"
    (its samples only: no action, P, u, energy or cumulative_action; see :class:`Result`).
    Ctrl-C raises KeyboardInterrupt within one iteration; invalid arguments raise ValueError before
    any work. Solves of built-in models run without the GIL (so that threads solve in parallel).
    Many problems at once, on threads, processes or a cluster: :func:`sweep`.

    On a manifold (docs/general-connections.md; the library's general::solve): on [0, T] with N steps,
    q(0) = q0, q(T) = qT, for l(q, v) with v the components of the transported velocity in the frame
    `frame0` of T_{q0}Q ((d, m); default manifold.default_frame(q0, qT): on the sphere and the
    hyperbolic plane e1 towards qT along the minimal geodesic, elsewhere tangent_basis(q0),
    orthonormal in a Chart's metric). Points q0, qT have the manifold's `point_shape` and must be valid points. The
    Lagrangian, either l = 1/2 v.A v - V(q): inertia A, a symmetric positive-definite (m, m) matrix or
    its (m,) diagonal (default identity); potential V(q) -> float with potential_gradient(q) -> an
    ambient (d,) covector zeta with zeta . x = d/de V(step(q, e x)) for tangent x (both or neither; on
    a group, the left-trivialised gradient); or gravity G, on the sphere, the hyperbolic plane and Euclidean space: V = G q[last]; or an
    object (the first argument, with `space` the manifold) with methods value(t, q, v), momentum(t, q,
    v) (= dl/dv, (m,)), velocity(t, q, mu) (the inverse Legendre map) and point_gradient(t, q, v) (an
    ambient (d,) covector with zeta . x = d/de l(t, step(q, e x), v)), taking and returning NumPy
    arrays (:func:`check_lagrangian` checks them); `frame_invariant = True` (an attribute or a method)
    says that l does not depend on the orthonormal frame, so that equal endpoints (antipodal ones on
    the sphere) need no frame0. method: "auto" (the default strategy: shooting
    from the guess, continuation in T, collocation polished by shooting), "shooting" (continuation
    "none" or "T") or "collocation"; on a GroupManifold with connection "cartan-schouten" and the
    default frame0 the Lie-group kernel runs, with its "multiple-shooting", "two-level" and
    continuation "lambda" (its message starts "Lie-group kernel"); elsewhere those are refused by
    name, and "variational" is the group model's only. tol: shooting, on the dimensionless terminal
    residual ``|(difference(qT, q_N), Xi_N / s)|``; collocation, on the relative RMS residual per
    interval. v0 (m,), Xi0 (m, m): guesses (default: the geodesic guess and 0); guess: a whole
    trajectory (t, q, frame, v, mu, Xi, e.g. an earlier Result); samples (collocation): output at this
    many uniform times (default: the final mesh).
    """
    arguments = locals()
    manifold = space if space is not None else lagrangian if isinstance(lagrangian, MANIFOLDS) else None
    if manifold is not None:
        if space is not None and isinstance(lagrangian, MANIFOLDS):
            raise ValueError(f"cartan.solve: lagrangian = {type(lagrangian).__name__} is a manifold, and space = "
                             f"{type(space).__name__} another (give the manifold once, with its Lagrangian object "
                             "or its terms)")
        if not isinstance(manifold, MANIFOLDS):
            raise ValueError(f"cartan.solve: space = {manifold!r} is not a manifold (one of: "
                             f"{', '.join(m.__name__ for m in MANIFOLDS)})")
        return _solve_on_manifold(manifold, None if lagrangian is manifold else lagrangian, arguments)
    if lagrangian is None:
        raise TypeError("cartan.solve: missing the problem: a group model as the first argument, or a manifold "
                        "(the first argument or space=)")
    d = _transported("_solve", arguments)
    grp = _group_of(lagrangian, group, "solve")
    model, inertia = _results.describe_model(lagrangian, grp)
    problem = Problem(kind="group", space=grp, lagrangian=lagrangian, lam=d["lam"], q0=d["g0"], qT=d["gT"],
                      inertia=inertia, model=model)
    return _result.from_group_fields(d, problem)


def load(path, *, space=None):
    """Reads a :class:`Result` from the JSON `cartan solve --output` writes (or
    :meth:`Result.to_json`): every key is checked, and a bad or missing one raises ValueError
    naming it; null (the CLI's NaN or infinity) becomes NaN. Every problem a file describes reads
    back: a group model's (Cartan-Schouten), the particle on any space of :data:`SPACES` (the
    sphere, the hyperbolic plane, Euclidean space, a GroupManifold of any connection), and a group
    record of another connection whose model is the particle's (free-rigid-body, free-body: the
    particle on the GroupManifold). What the file does not hold is rebuilt: v0 and xi0 (or Xi0) are
    the first rows, residual_history is empty, and the frame (P on a group), u, energy and
    cumulative_action come from the library as after a solve, with the Lagrangian the file
    describes, which the result's problem then carries, so that ``cartan.verify(r)`` checks the
    file as `cartan verify` does. A Lagrangian defined in Python is only named ("python:<name>"):
    energy and cumulative_action are None, and verify needs it: ``cartan.verify(r, my_lagrangian)``.
    So is a :class:`Chart` (manifold "python:<name>"): pass it, ``cartan.load(path, space=chart)``."""
    d = _results.read_fields(path)
    if d["kind"] == "group" and d["connection"] == "cartan-schouten":
        if space is not None:
            raise ValueError(f"cartan.load: space = {space!r} applies to a file of a Chart; this file's problem is a "
                             f"group model's ({d['group']})")
        fields = _results.group_fields(d)
        grp = _results._group_class(fields["group"], "cartan.load")
        named = fields["model"].startswith(_results.PYTHON_MODEL)
        model = None if named else _results.model_of(SimpleNamespace(**fields))
        problem = Problem(kind="group", space=grp, lagrangian=model, lam=fields["lam"], q0=fields["g0"],
                          qT=fields["gT"], inertia=fields["inertia"], model=fields["model"])
        return _result.from_group_fields({**fields, **grp._along(model, fields, fields["lam"])}, problem)
    space = _results.manifold_of_fields(d, space)
    fields, terms = _results.manifold_fields(d, space)
    named = terms["model"].startswith(_results.PYTHON_MODEL)
    request = _cartan._GeneralRequest()
    request.inertia, request.gravity = terms["inertia"], terms["gravity"]
    along = _cartan._along_general(space, request, {**fields, **terms}, named)
    problem = Problem(kind="manifold", space=space, q0=terms["q0"], qT=terms["qT"], inertia=terms["inertia"],
                      gravity=terms["gravity"], frame0=terms["frame0"], model="" if terms["model"] == "particle" else terms["model"])
    return _result.Result(**{**fields, **along}, problem=problem)


#: The spaces of the library's catalogue (include/cartan/api/spaces.hpp), which a result file and the
#: CLI's ``--manifold`` describe: name -> dict(dims, point, connections, gravity, what).
SPACES = _results.SPACES


def model_of(result):
    """The Lagrangian a :class:`Result` was solved for: the model its problem carries, else the
    built-in model rebuilt from its group, model name and inertia (e.g. of a file). Raises ValueError
    for a Lagrangian defined in Python that the result no longer holds (model "python:<type name>"),
    and for a manifold's problem given by its terms (inertia, potential, gravity: ``r.problem``)."""
    problem = getattr(result, "problem", None)
    if problem is not None and problem.lagrangian is not None:
        return problem.lagrangian
    if problem is not None and problem.kind == "manifold":
        raise ValueError("cartan.model_of: the result's Lagrangian is given by its terms on the manifold "
                         "(result.problem.inertia, potential, potential_gradient, gravity), not by a model")
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


def _solve_on_manifold(manifold, lagrangian, arguments, validate=False):
    """cartan.solve on a manifold: the library's general::solve with the manifold's keywords and a
    Lagrangian object of the manifold or the terms; with `validate`, only every check the solve
    makes before it starts (cartan.sweep's), returning None."""
    _refuse_other_kind("cartan.solve", arguments, _GROUP_KEYWORDS,
                       f"applies to a group model's problem, not on the manifold {type(manifold).__name__} (its "
                       "connection is the manifold's)")
    for name in ("q0", "qT"):
        if arguments[name] is None:
            raise TypeError(f"cartan.solve: missing a required argument: {name!r} (a problem on a manifold)")
    a = arguments
    if validate:
        return _cartan._validate_general(manifold, _manifold_request(lagrangian, a))
    d = _cartan._solve_general(manifold, _manifold_request(lagrangian, a))
    python = (type(lagrangian).__name__ if lagrangian is not None
              else "potential" if a["potential"] is not None else None)
    problem = Problem(kind="manifold", space=manifold, lagrangian=lagrangian, q0=d["q0"], qT=d["qT"],
                      inertia=a["inertia"], potential=a["potential"], potential_gradient=a["potential_gradient"],
                      gravity=a["gravity"], frame0=a["frame0"], model="" if python is None else _results.PYTHON_MODEL + python)
    return _result.from_manifold_fields(d, problem)


def _manifold_request(lagrangian, a):
    """The library's request of a manifold's problem from cartan.solve's arguments `a` (types
    checked here, values by the library)."""
    check_types("cartan.solve", {k: a[k] for k in ("T", "N", "method", "continuation", "order", "tol", "max_iterations",
                                                   "samples", "max_nodes", "time_limit", "segments", "lambda_start")})
    request = _cartan._GeneralRequest()
    request.T, request.N, request.q0, request.qT = a["T"], a["N"], a["q0"], a["qT"]
    request.inertia, request.potential, request.potential_gradient = a["inertia"], a["potential"], a["potential_gradient"]
    request.gravity, request.lagrangian, request.frame0 = a["gravity"], lagrangian, a["frame0"]
    request.v0, request.Xi0, request.progress, request.guess = a["v0"], a["Xi0"], a["progress"], a["guess"]
    _set_options(request, {**a, "samples": 0 if a["samples"] is None else a["samples"]})
    return request


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


def solve_general(manifold, *, T, N, q0, qT, inertia=None, potential=None, potential_gradient=None, gravity=None,
                  lagrangian=None, frame0=None, method="auto", continuation="none", order=1,
                  tol=_cartan.defaults["tol"], max_iterations=_cartan.defaults["max_iterations"], v0=None,
                  Xi0=None, guess=None, samples=0, max_nodes=None, time_limit=None, progress=None,
                  segments: Optional[int] = None, lambda_start: Optional[float] = None):
    """Deprecated (one release): ``cartan.solve(lagrangian, space=manifold, ...)``, or
    ``cartan.solve(manifold, ...)`` with the Lagrangian's terms, which this calls; returns the same
    :class:`Result`."""
    warnings.warn("cartan.solve_general is deprecated: use cartan.solve(manifold, ...) or "
                  "cartan.solve(lagrangian, space=manifold, ...)", DeprecationWarning, stacklevel=2)
    return solve(lagrangian, space=manifold, T=T, N=N, q0=q0, qT=qT, inertia=inertia, potential=potential,
                 potential_gradient=potential_gradient, gravity=gravity, frame0=frame0, method=method,
                 continuation=continuation, order=order, tol=tol, max_iterations=max_iterations, v0=v0, Xi0=Xi0,
                 guess=guess, samples=samples, max_nodes=max_nodes, time_limit=time_limit, progress=progress,
                 segments=segments, lambda_start=lambda_start)


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
    """Deprecated (one release): :func:`verify`, which this calls (``cartan.verify(result)`` for a
    :class:`Result`, which carries its problem)."""
    warnings.warn("cartan.verify_general is deprecated: use cartan.verify(result) (a Result carries its problem), "
                  "or cartan.verify(result, manifold, ...)", DeprecationWarning, stacklevel=2)
    if lagrangian is not None:
        return verify(result, lagrangian, space=manifold, inertia=inertia, potential=potential,
                      potential_gradient=potential_gradient, gravity=gravity)
    return verify(result, manifold, inertia=inertia, potential=potential, potential_gradient=potential_gradient,
                  gravity=gravity)


def verify(result, lagrangian=None, *, space=None, group=None, inertia=None, potential=None, potential_gradient=None,
           gravity=None):
    """Checks a result independently of the solver, as `cartan verify` does, and returns a
    :class:`VerifyReport`. ``cartan.verify(r)`` checks a :class:`Result` against the problem it
    carries; the other arguments check it (or any object with the fields below, e.g. a trajectory
    computed elsewhere) against the problem they give:

    * a group model's problem, `lagrangian` a built-in model or a Python-defined Lagrangian as for
      :func:`solve` (docs/verify.md): boundary conditions against result.tol, the Legendre relation,
      conservation of E = mu.v - l (for a Lagrangian that does not depend on t), the residual of
      eq:reduced-system by finite differences and the stationarity of the discrete transported action,
      with thresholds from the order and the resolution h omega. `result` needs the fields lam, T,
      g0, gT, order, tol, status, t, g, v, mu, xi.
    * a manifold's (docs/general-connections.md, "Verification"), the manifold as `lagrangian` (or
      `space`) with the Lagrangian's terms `inertia`, `potential`, `potential_gradient`, `gravity` as
      :func:`solve` takes them (none given: the result's own problem's), or a Lagrangian object with
      ``space=manifold``: the same checks of the local form, the parallel frame rebuilt from the
      samples. `result` needs T, q0, qT, tol, order, status, t, q, frame (frame[0] the frame at q0), v,
      mu, Xi.

    A result that did not converge always fails (check "converged"); a check that the result's
    resolution cannot decide fails as unresolved (docs/verify.md). The keywords of the other kind
    raise ValueError naming them."""
    problem = getattr(result, "problem", None)
    terms = dict(inertia=inertia, potential=potential, potential_gradient=potential_gradient, gravity=gravity)
    given_terms = any(value is not None for value in terms.values())
    if isinstance(lagrangian, MANIFOLDS) or space is not None:
        manifold, body = (lagrangian, None) if isinstance(lagrangian, MANIFOLDS) else (space, lagrangian)
    elif lagrangian is None and problem is not None and problem.kind == "manifold":
        manifold, body = problem.space, None
        if manifold is None:
            raise ValueError("cartan.verify: the result's manifold did not travel with it (problem.space = None): "
                             "cartan.verify(result, manifold, ...)")
    else:
        manifold = None
    if manifold is not None:
        _refuse_other_kind("cartan.verify", dict(group=group), ("group",), "applies to a group model's problem, "
                           f"not on the manifold {type(manifold).__name__}")
        if body is None and not given_terms and problem is not None and problem.kind == "manifold":
            terms, body = {k: v for k, v in problem.terms().items() if k != "lagrangian"}, problem.lagrangian
            if problem.model.startswith(_results.PYTHON_MODEL) and body is None and terms["potential"] is None:
                raise ValueError(f"cartan.verify: the result's Lagrangian was defined in Python (model = "
                                 f"{problem.model!r}) and did not travel with it: cartan.verify(result, lagrangian, "
                                 "space=manifold) or cartan.verify(result, manifold, potential=..., ...)")
        request = _cartan._GeneralRequest()
        request.inertia, request.potential, request.potential_gradient = (terms["inertia"], terms["potential"],
                                                                          terms["potential_gradient"])
        request.gravity, request.lagrangian = terms["gravity"], body
        return VerifyReport(**_cartan._verify_general(manifold, request, result))
    if problem is not None and problem.kind == "manifold":
        raise ValueError(f"cartan.verify: lagrangian = {type(lagrangian).__name__} is not a manifold; a manifold's "
                         "result is checked on its manifold: cartan.verify(result), or cartan.verify(result, manifold, ...)")
    _refuse_other_kind("cartan.verify", terms, terms, "applies to a manifold's problem (pass the manifold as the "
                       "second argument); a group model carries its own Lagrangian")
    if lagrangian is None:
        lagrangian = problem.lagrangian if problem is not None else None
        if lagrangian is None:
            raise ValueError("cartan.verify: lagrangian = None, and the result does not hold its Lagrangian (a model "
                             "defined in Python that did not travel with it): cartan.verify(result, lagrangian)")
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


def check_lagrangian(model, group=None, *, samples=8, seed=20261122, scale=1.0, side=None, q=None, inertia=None,
                     potential=None, potential_gradient=None, gravity=None):
    """Checks a Lagrangian's callbacks against each other and returns a :class:`CheckReport`: on a
    group (the C++ mechanics::check_lagrangian, include/cartan/mechanics/check_lagrangian.hpp)

    - momentum against central differences of value along v + e E_i,
    - group_gradient against central differences of value along g exp(e E_i) (``side="right"``:
      exp(e E_i) g),
    - velocity against the inverse of momentum (velocity(momentum(v)) = v, momentum(velocity(mu)) = mu),
    - the model's own hessian, if it has one, block by block against central differences of momentum
      and group_gradient (the solvers otherwise difference them; :func:`lagrangian_hessian`);

    on a manifold (`group` any of :data:`MANIFOLDS`; general::check_lagrangian,
    include/cartan/mechanics/manifold_check_lagrangian.hpp) the same with point_gradient in place of
    group_gradient: its components along tangent_basis(q) against central differences of value along
    step(q, e E_i). The manifold's Lagrangian is `model` (an object with value, momentum, velocity,
    point_gradient as :func:`solve` takes it on a manifold) or, with `model` None, the one `inertia`,
    `potential`, `potential_gradient`, `gravity` define.

    Discrepancies are relative, with the differences' own error estimate as floor, so that the
    scale of the model does not matter; a derivative fails above a relative 1e-6 (or ten times the
    differences' error where that is larger; they are accurate to about 1e-10), the inverse above
    1e-8. A sign error or a wrong factor gives a discrepancy of order 1.

    model: a built-in Lagrangian or a Python object as for :func:`solve` (value, momentum,
    group_gradient, velocity and optionally hessian); its group is `group` or its ``group``
    attribute. samples: a count of seeded pseudo-random points (t in [0, scale], g = exp(w) and v
    with coordinates in [-scale, scale]; on a manifold q = step(q0, scale E x) around the point `q`,
    by default the pole (0, 0, 1) of the sphere and the hyperbolic plane, the origin of Euclidean,
    the identity of a GroupManifold; a Chart needs `q`), or a sequence of (t, g, v) (or (t, q, v))
    triples. side: how group_gradient is trivialised, "left" or "right" (default: the model's
    ``side`` attribute, else "left"). A non-finite value is reported (note) rather than raised; an
    exception raised in a Python callback is re-raised."""
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or not 0 <= seed < 2**32:
        raise ValueError(f"cartan.check_lagrangian: seed = {seed!r} is not an integer in [0, 2**32)")
    if isinstance(group, MANIFOLDS):
        _refuse_other_kind("cartan.check_lagrangian", dict(side=side), ("side",),
                           f"applies to a group's Lagrangian, not on the manifold {type(group).__name__}")
        request = _cartan._GeneralRequest()
        request.lagrangian, request.inertia, request.potential = model, inertia, potential
        request.potential_gradient, request.gravity = potential_gradient, gravity
        return CheckReport(**_cartan._check_general_lagrangian(group, request, samples, int(seed), scale, q))
    _refuse_other_kind("cartan.check_lagrangian",
                       dict(q=q, inertia=inertia, potential=potential, potential_gradient=potential_gradient,
                            gravity=gravity), ("q", "inertia", "potential", "potential_gradient", "gravity"),
                       "applies to a Lagrangian on a manifold (pass the manifold as the second argument)")
    grp = _group_of(model, group, "check_lagrangian")
    side = side if side is not None else getattr(model, "side", "left")
    return CheckReport(**grp._check_lagrangian(model, samples, int(seed), scale, side))


def __getattr__(name):
    # BvpResult subclasses scipy.optimize.OptimizeResult: SciPy is imported on first use only.
    if name == "BvpResult":
        return _bvp.result_class()
    # The two result types before there was one (one release): Result itself.
    if name in ("SolveResult", "GeneralSolveResult"):
        warnings.warn(f"cartan.{name} is deprecated: every solve returns a cartan.Result", DeprecationWarning,
                      stacklevel=2)
        return Result
    raise AttributeError(f"module 'cartan' has no attribute {name!r}")
