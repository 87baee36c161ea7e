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
    Built in: ``RigidBody, SO3Oscillator, SpatialRigidBody, H3Oscillator`` and Hamiltonians
    ``RigidBodyHamiltonian, SO3OscillatorHamiltonian, SpatialRigidBodyHamiltonian,
    H3OscillatorHamiltonian``. Any Python object with the methods ``value(t, g, v),
    momentum(t, g, v), group_gradient(t, g, v), velocity(t, g, mu)`` (and a ``group``
    attribute, or pass ``group=``) is a Lagrangian; see :func:`solve`.
Integrators
    :func:`euler_poincare` (eq:EP-left, eq:EP-right), :func:`lie_poisson` (eq:LP-left, eq:LP-right).
The transported-velocity boundary-value problem (eq:reduced-system)
    :func:`solve` with ``method`` one of :data:`METHODS`; returns a :class:`SolveResult`.

Errors: invalid input raises ValueError with the C++ library's message; an exception raised in
a Python callback during a solve is re-raised unchanged when the solver returns.
"""
from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from ._cartan import (  # noqa: F401  (re-exported)
    SE2,
    SE3,
    SO3,
    H3Oscillator,
    H3OscillatorHamiltonian,
    Heisenberg,
    RigidBody,
    RigidBodyHamiltonian,
    SO3Oscillator,
    SO3OscillatorHamiltonian,
    SpatialRigidBody,
    SpatialRigidBodyHamiltonian,
)

GROUPS = (SO3, Heisenberg, SE3, SE2)
#: The transported-velocity solvers (see :func:`solve`).
METHODS = tuple(SO3.methods)

__all__ = [
    "SO3", "Heisenberg", "SE3", "SE2", "GROUPS", "METHODS",
    "RigidBody", "SO3Oscillator", "SpatialRigidBody", "H3Oscillator",
    "RigidBodyHamiltonian", "SO3OscillatorHamiltonian", "SpatialRigidBodyHamiltonian", "H3OscillatorHamiltonian",
    "Trajectory", "SolveResult", "euler_poincare", "lie_poisson", "lagrangian_hessian", "solve",
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
class SolveResult:
    """The result of :func:`solve`, in the spirit of scipy.integrate.solve_bvp's.

    status: "converged" or a failure word (max-iterations, stalled, non-finite,
    inner-not-converged, outer-not-converged, continuation-failed, inconsistent, ...);
    success: status == "converged"; message: diagnostics (iterations, residual history);
    t (N+1,), g (N+1, *element_shape), v, mu, xi (N+1, dim): the discrete solution at every node,
    v the transported velocity left-trivialised at g0; v0, xi0 the initial values;
    outer_iterations, inner_iterations, sweeps: work done; terminal_error = |log(gT^-1 g_N)|,
    xi_terminal = |xi_N|; branch: how the solution was reached (e.g. "continued in T from
    T = 3 (6 stages)"); solve_time: seconds in the solver.
    """
    status: str
    message: str
    success: bool
    method: str
    order: int
    branch: str
    group: str
    lam: float
    T: float
    N: int
    t: np.ndarray
    g: np.ndarray
    v: np.ndarray
    mu: np.ndarray
    xi: np.ndarray
    v0: np.ndarray
    xi0: np.ndarray
    terminal_error: float
    xi_terminal: float
    outer_iterations: int
    inner_iterations: int
    sweeps: int
    residual_history: np.ndarray = field(repr=False)
    solve_time: float

    def __repr__(self):
        return (f"SolveResult(status={self.status!r}, success={self.success}, method={self.method!r}, "
                f"group={self.group!r}, lam={self.lam:g}, T={self.T:g}, N={self.N}, "
                f"terminal_error={self.terminal_error:.3e}, iterations=(outer={self.outer_iterations}, "
                f"inner={self.inner_iterations}, sweeps={self.sweeps}), branch={self.branch!r}, "
                f"solve_time={self.solve_time:.4f})")


def solve(lagrangian, *, lam, T, N, gT, g0=None, method="shooting", order=1, tol=1e-10, max_iterations=200,
          segments: Optional[int] = None, lambda_start: Optional[float] = None, v0=None, xi0=None, group=None):
    """Solves the transported-velocity boundary-value problem of the Cartan-Schouten connection
    of parameter `lam` (eq:reduced-system; paper §6-7) on [0, T] with N steps, g(0) = g0
    (default: the identity), g(T) = gT, with the discrete scheme of order 1 (the paper's) or 2.

    `lagrangian` is a built-in left-reduced model (RigidBody, SO3Oscillator, H3Oscillator) or any
    object with methods value(t, g, v), momentum(t, g, v) (= dl/dv), group_gradient(t, g, v)
    (left-trivialised dl/dg) and velocity(t, g, mu) (the inverse Legendre map) taking and
    returning NumPy arrays; its group is `group` or its `group` attribute. The tangent-linear
    sweeps need second derivatives: from the object's optional method hessian(t, g, v) returning
    a dict like :func:`lagrangian_hessian`'s, else by central differences of momentum and
    group_gradient (24 extra callbacks per node on a 3-dimensional group).

    method (options as `cartan solve`: order, tol, max_iterations):
      "two-level"           the paper's scheme (inner LM shooting on v0, outer fixed point on xi);
                            tol is the outer tolerance; accepts v0.
      "shooting"            (default, as the CLI) augmented shooting on (v0, xi0) with an analytic
                            Jacobian, continued in T when it does not converge from the geodesic guess.
      "single-shooting"     augmented shooting from the guess (v0, xi0) only.
      "multiple-shooting"   lifted Levenberg-Marquardt over `segments` segments; accepts v0, xi0.
      "continuation-lambda" shooting continued in lambda from `lambda_start` (default 0).
    v0, xi0: initial guesses where accepted (default: the geodesic guess log(g0^-1 gT)/T and 0).
    """
    if getattr(lagrangian, "side", "left") != "left":
        raise ValueError(f"cartan.solve: lagrangian = {type(lagrangian).__name__} is right-reduced; "
                         "the transported-velocity problem needs a left-reduced Lagrangian")
    grp = _group_of(lagrangian, group, "solve")
    d = grp._solve(lagrangian, lam, T, N, g0, gT, method, order, tol, max_iterations, segments, lambda_start,
                   v0, xi0)
    return SolveResult(**d)
