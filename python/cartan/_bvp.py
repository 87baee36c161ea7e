"""cartan.solve_bvp: scipy.integrate.solve_bvp's contract (SciPy 1.10) on cartan's collocation solver.

What is cartan's and what is SciPy's:
* Each mesh's collocation equations (the three-stage Lobatto IIIA scheme, the same as SciPy's) are
  solved by cartan's C++ damped Newton (include/cartan/numerics/collocation.hpp, through the binding
  ``_cartan._solve_bvp`` with ``max_refinements=0``), which also returns the relative RMS residual of
  every interval (SciPy's 5-point Lobatto estimate).
* The outer loop is SciPy's, here in Python: an interval whose residual exceeds tol gets one node
  in its middle (tol < r < 100 tol) or two at its thirds (r >= 100 tol) (the rule and the
  interpolation to the next mesh in C++: ``_cartan._scipy_refinement``); status 1 when that would
  exceed max_nodes (the mesh before refinement is returned), status 3 when the residuals are met
  but |bc| > bc_tol after iteration 10, status 2 on a singular Jacobian or a non-finite f or bc.
  So node counts follow SciPy's rule; they differ from SciPy's only where Newton's iterates
  differ (a different Newton: natural monotonicity test, up to max_newton_iterations steps).
* The singular term S, complex problems, the result (an OptimizeResult with a PPoly ``sol``),
  the tol clamp, messages and verbose reports are SciPy's, done here.

SciPy is imported when solve_bvp is first called (scipy.optimize costs ~0.4 s to import), so
that ``import cartan`` does not need it.
"""
import time
import warnings

import numpy as np

from . import _cartan

EPS = np.finfo(float).eps

#: SciPy's messages, by status.
TERMINATION_MESSAGES = {
    0: "The algorithm converged to the desired accuracy.",
    1: "The maximum number of mesh nodes is exceeded.",
    2: "A singular Jacobian encountered when solving the collocation system.",
    3: "The solver was unable to satisfy boundary conditions tolerance on iteration 10.",
}

# SciPy's outer loop: after this many meshes with no node to add and |bc| > bc_tol, status 3.
_MAX_ITERATION = 10
# What the C++ solve of one mesh is told about the mesh size: it never refines (max_refinements = 0),
# the limit only has to admit the mesh; max_nodes is enforced by the outer loop, as SciPy does.
_ANY_MESH = 2**31 - 1
# A positive bc_tol for the C++ Newton that no nonzero |bc| meets (SciPy's bc_tol <= 0 is never met).
_TINY = np.nextafter(0.0, 1.0)
# A finite stand-in for an infinite tol or bc_tol.
_HUGE = np.finfo(float).max

_result_class = None


def result_class():
    """BvpResult: a subclass of scipy.optimize.OptimizeResult (created on first use, see above)."""
    global _result_class
    if _result_class is None:
        from scipy.optimize import OptimizeResult

        class BvpResult(OptimizeResult):
            """The result of :func:`cartan.solve_bvp`: scipy.integrate.solve_bvp's fields ``sol``
            (scipy.interpolate.PPoly), ``p``, ``x``, ``y``, ``yp``, ``rms_residuals``, ``niter``,
            ``status``, ``message``, ``success``, and cartan's ``newton_iterations``,
            ``jacobian_evaluations``, ``rhs_evaluations``, ``max_rms_residual``,
            ``max_bc_residual``, ``details``, ``solve_time``."""

        BvpResult.__module__ = "cartan"
        _result_class = BvpResult
    return _result_class


def _spline_coefficients(y, yp, h):
    """SciPy's create_spline's coefficients c (4, n, m - 1) of (x - x_i)^3 .. (x - x_i)^0: the C^1
    cubic Hermite interpolant of (x, y, y') (the same cubic as cartan's dense output)."""
    n, m = y.shape
    c = np.empty((4, n, m - 1), dtype=y.dtype)
    slope = (y[:, 1:] - y[:, :-1]) / h
    t = (yp[:, :-1] + yp[:, 1:] - 2 * slope) / h
    c[0] = t / h
    c[1] = (slope - yp[:, :-1]) / h - t
    c[2] = yp[:, :-1]
    c[3] = y[:, :-1]
    return c


def _create_spline(y, yp, x, h):
    """SciPy's create_spline: the interpolant as a PPoly."""
    from scipy.interpolate import PPoly

    return PPoly(np.moveaxis(_spline_coefficients(y, yp, h), 1, 0), x, extrapolate=True, axis=1)


def _print_iteration_header():
    print("{:^15}{:^15}{:^15}{:^15}{:^15}".format(
        "Iteration", "Max residual", "Max BC residual", "Total nodes", "Nodes added"))


def _print_iteration_progress(iteration, residual, bc_residual, total_nodes, nodes_added):
    print("{:^15}{:^15.2e}{:^15.2e}{:^15}{:^15}".format(
        iteration, residual, bc_residual, total_nodes, nodes_added))


def _print_termination(status, iteration, nodes, max_rms_res, max_bc_res):
    head = {
        0: "Solved in {} iterations, number of nodes {}. \n".format(iteration, nodes),
        1: "Number of nodes is exceeded after iteration {}. \n".format(iteration),
        2: "Singular Jacobian encountered when solving the collocation system on iteration {}. \n".format(iteration),
        3: "The solver was unable to satisfy boundary conditions tolerance on iteration {}. \n".format(iteration),
    }[status]
    print(head + "Maximum relative residual: {:.2e} \nMaximum boundary residual: {:.2e}".format(
        max_rms_res, max_bc_res))


class _Problem:
    """The user's functions in SciPy's conventions, with the singular term folded in as SciPy does
    (wrap_functions): f + S y / (x - a) for x > a, and (I - S)^+ f at x = a, where the limit of
    S y / (x - a) is S y'(a), so that y'(a) = f + S y'(a) gives y'(a) = (I - S)^{-1} f(a, y(a)).
    Every method takes p (None without parameters) and returns arrays of the problem's dtype."""

    def __init__(self, fun, bc, fun_jac, bc_jac, k, a, S, D, dtype):
        self.fun, self.bc, self.fun_jac, self.bc_jac = fun, bc, fun_jac, bc_jac
        self.k, self.a, self.S, self.D, self.dtype = k, a, S, D, dtype

    def _args(self, u, v, p):
        return (u, v) if self.k == 0 else (u, v, p)

    def f(self, x, y, p):
        f = np.array(self.fun(*self._args(x, y, p)), dtype=self.dtype)  # a copy: changed below
        if self.S is None:
            return f
        column = f.ndim == 1  # a pointwise function's (n,) for one point
        if column:
            f = f[:, np.newaxis]
        if x[0] == self.a:
            f[:, 0] = self.D @ f[:, 0]
            f[:, 1:] += self.S @ y[:, 1:] / (x[1:] - self.a)
        else:
            f += self.S @ y / (x - self.a)
        return f[:, 0] if column else f

    def boundary(self, ya, yb, p):
        return np.asarray(self.bc(*self._args(ya, yb, p)), dtype=self.dtype)

    def f_jac(self, x, y, p):
        """(df_dy, df_dp); df_dp is None without parameters."""
        if self.k == 0:
            df_dy, df_dp = self.fun_jac(x, y), None
        else:
            df_dy, df_dp = self.fun_jac(x, y, p)
            df_dp = np.asarray(df_dp, dtype=self.dtype)
        df_dy = np.array(df_dy, dtype=self.dtype)
        if self.S is not None:
            if df_dy.ndim == 2:  # a pointwise (n, n)
                df_dy = df_dy[:, :, np.newaxis]
            S = self.S[:, :, np.newaxis]
            if x[0] == self.a:
                df_dy[:, :, 0] = self.D @ df_dy[:, :, 0]
                df_dy[:, :, 1:] += S / (x[1:] - self.a)
            else:
                df_dy += S / (x - self.a)
        return df_dy, df_dp

    def boundary_jac(self, ya, yb, p):
        """(dbc_dya, dbc_dyb, dbc_dp); dbc_dp is None without parameters."""
        if self.k == 0:
            dya, dyb = self.bc_jac(ya, yb)
            dp = None
        else:
            dya, dyb, dp = self.bc_jac(ya, yb, p)
            dp = np.asarray(dp, dtype=self.dtype)
        return np.asarray(dya, dtype=self.dtype), np.asarray(dyb, dtype=self.dtype), dp


def _split(z):
    """A complex array (n, ...) as the real one (2n, ...): real parts, then imaginary parts."""
    return np.concatenate((z.real, z.imag))


def _join(r):
    """The inverse of _split."""
    half = r.shape[0] // 2
    return r[:half] + 1j * r[half:]


def _split_jacobian(J):
    """d(Re g, Im g)/d(Re z, Im z) of a complex-differentiable g with dg/dz = J ((r, c, ...) ->
    (2r, 2c, ...)): [[Re J, -Im J], [Im J, Re J]] (the Cauchy-Riemann equations)."""
    return np.concatenate((np.concatenate((J.real, -J.imag), axis=1), np.concatenate((J.imag, J.real), axis=1)))


def _binding_functions(problem, wrapped, complex_problem):
    """fun, bc, fun_jac, bc_jac in the binding's conventions (p as a last argument only with
    parameters; fun_jac returns df_dy alone without them), real-valued: a complex problem becomes
    the real system of size 2n with 2k parameters. Unwrapped user functions are passed as they are."""
    k = problem.k
    if not complex_problem:
        if not wrapped:
            return problem.fun, problem.bc, problem.fun_jac, problem.bc_jac
        fun_jac = None
        if problem.fun_jac is not None:
            fun_jac = (lambda x, y: problem.f_jac(x, y, None)[0]) if k == 0 else problem.f_jac
        return ((lambda x, y: problem.f(x, y, None)) if k == 0 else problem.f), problem.bc, fun_jac, problem.bc_jac

    def params(P):
        return None if k == 0 else _join(np.asarray(P))

    def fun(x, Y, P=None):
        return _split(problem.f(x, _join(np.asarray(Y)), params(P)))

    def bc(Ya, Yb, P=None):
        return _split(problem.boundary(_join(Ya), _join(Yb), params(P)))

    def fun_jac(x, Y, P=None):
        df_dy, df_dp = problem.f_jac(x, _join(np.asarray(Y)), params(P))
        return _split_jacobian(df_dy) if k == 0 else (_split_jacobian(df_dy), _split_jacobian(df_dp))

    def bc_jac(Ya, Yb, P=None):
        dya, dyb, dp = problem.boundary_jac(_join(Ya), _join(Yb), params(P))
        out = (_split_jacobian(dya), _split_jacobian(dyb))
        return out if k == 0 else out + (_split_jacobian(dp),)

    return (fun, bc, fun_jac if problem.fun_jac is not None else None,
            bc_jac if problem.bc_jac is not None else None)


def _mesh_f(problem, x, y, p):
    """f at the columns of y, in one vectorised call, as SciPy and the C++ solver call it."""
    return np.reshape(problem.f(x, y, p), y.shape)


def _rms_residuals(problem, sol, x, h, p):
    """SciPy's estimate_rms_residuals from the spline: the RMS over each interval of
    |S' - f(x, S)| / (1 + |f|) (complex moduli) by 5-point Lobatto quadrature (zero at the nodes).
    Used for complex problems, where the C++ solver sees real and imaginary parts separately."""
    middle = x[:-1] + 0.5 * h
    s = 0.5 * h * (3 / 7) ** 0.5
    squares = []
    for t in (middle, middle + s, middle - s):
        f = _mesh_f(problem, t, sol(t), p)
        r = (sol(t, 1) - f) / (1 + np.abs(f))
        squares.append(np.sum(np.real(r * np.conj(r)), axis=0))
    return (0.5 * (32 / 45 * squares[0] + 49 / 90 * (squares[1] + squares[2]))) ** 0.5


def solve_bvp(fun, bc, x, y, p=None, S=None, fun_jac=None, bc_jac=None, tol=0.001, max_nodes=1000, verbose=0,
              bc_tol=None, *, max_newton_iterations=20, fd_step=2.0 ** -26, linear_solver="block-lu"):
    """Solves dy/dx = f(x, y, p) + S y / (x - a) on [a, b] with bc(y(a), y(b), p) = 0 (n + k
    conditions): scipy.integrate.solve_bvp's signature, arguments, result and behaviour (SciPy
    1.10), on cartan's collocation solver (fourth-order Lobatto IIIA collocation, SciPy's scheme).
    A SciPy script ports by changing the import.

    fun(x, y[, p]) -> (n, m); bc(ya, yb[, p]) -> (n + k,); fun_jac(x, y[, p]) -> df_dy (n, n, m)
    or, with parameters, (df_dy, df_dp (n, k, m)); bc_jac(ya, yb[, p]) -> (dbc_dya, dbc_dyb[,
    dbc_dp]); without them, forward differences. x (m,) strictly increasing, y (n, m) the guess
    (complex for a complex problem), p (k,) or None, S (n, n) or None: the singular term, with
    S y(a) = 0 imposed on the guess; tol: each interval's RMS residual relative to ``1 + |f|`` (below
    100 eps: a warning, and 100 eps); max_nodes; verbose 0, 1 (a termination report) or 2 (a line
    per iteration too); bc_tol: ``max |bc|`` (default tol).

    Returns a scipy.optimize.OptimizeResult (:class:`cartan.BvpResult`) with SciPy's fields: sol
    (scipy.interpolate.PPoly, the C^1 cubic spline: sol(x), sol(x, 1), sol.derivative(), ...), p
    (None without parameters), x, y, yp, rms_residuals, niter, status (0 converged, 1 max_nodes
    exceeded, 2 singular Jacobian, or f or bc not finite, 3 bc_tol not met), message (SciPy's),
    success; and cartan's newton_iterations, jacobian_evaluations, rhs_evaluations (points at
    which fun was evaluated, differences included), max_rms_residual, max_bc_residual, details
    (the C++ solver's report on the last mesh) and solve_time (seconds).

    Where cartan differs from SciPy:

    * fun and fun_jac are called on whole sweeps of the mesh as SciPy calls them (x (m,),
      y (n, m)), but not always on the same sweeps (nodes, midpoints, quadrature points); without
      fun_jac, the differences move one component at every point at once (n + k calls of fun).
    * Newton on each mesh is cartan's (damped, natural monotonicity test, up to
      max_newton_iterations steps, Jacobian reuse), not SciPy's (at most 8 steps and 4
      Jacobians), so iterates, residuals and now and then the mesh differ slightly.
    * The singular term's S y(a) = 0 is imposed on the guess, not re-imposed after every Newton
      step as SciPy does: the boundary conditions must imply it (SciPy: must agree with it).
    * A complex problem is solved as the real system of its real and imaginary parts (size 2n,
      2k parameters); y, yp, p and sol are complex. Forward differences then need no complex
      differentiability; fun_jac and bc_jac, if given, must be complex derivatives, as in SciPy.
    * The caller's y is never modified (SciPy's S projection writes into a float array).
    * x with fewer than 2 nodes or a non-finite node, and a bad max_newton_iterations, fd_step or
      linear_solver ("block-lu" or "sparse-lu") raise ValueError.

    Invalid arguments raise ValueError with SciPy's messages (cartan's for the C++ solver's checks);
    an exception raised by a callback stops the solve and is re-raised unchanged.
    """
    started = time.perf_counter()
    x = np.asarray(x, dtype=float)
    if x.ndim != 1:
        raise ValueError("`x` must be 1 dimensional.")
    # SciPy fails on these too, later (PPoly: "at least 2 breakpoints are needed", NaN), or
    # solves towards an infinite end (status 2).
    if not np.all(np.isfinite(x)):
        raise ValueError("`x` must be finite.")
    h = np.diff(x)
    if np.any(h <= 0):
        raise ValueError("`x` must be strictly increasing.")
    if x.size < 2:
        raise ValueError("`x` must have at least 2 nodes.")
    a = x[0]

    y = np.asarray(y)
    dtype = complex if np.issubdtype(y.dtype, np.complexfloating) else float
    y = y.astype(dtype)  # a copy: the caller's array is not modified

    if y.ndim != 2:
        raise ValueError("`y` must be 2 dimensional.")
    if y.shape[1] != x.shape[0]:
        raise ValueError("`y` is expected to have {} columns, but actually has {}.".format(x.shape[0], y.shape[1]))

    p = np.array([]) if p is None else np.asarray(p, dtype=dtype)
    if p.ndim != 1:
        raise ValueError("`p` must be 1 dimensional.")

    if tol < 100 * EPS:
        warnings.warn("`tol` is too low, setting to {:.2e}".format(100 * EPS), stacklevel=2)
        tol = 100 * EPS

    if verbose not in [0, 1, 2]:
        raise ValueError("`verbose` must be in [0, 1, 2].")

    n = y.shape[0]
    k = p.shape[0]

    if S is not None:
        S = np.asarray(S, dtype=dtype)
        if S.shape != (n, n):
            raise ValueError("`S` is expected to have shape {}, but actually has {}".format((n, n), S.shape))
        B = np.identity(n) - np.linalg.pinv(S) @ S  # projects onto S y = 0
        y[:, 0] = B @ y[:, 0]
        D = np.linalg.pinv(np.identity(n) - S)
    else:
        D = None

    if bc_tol is None:
        bc_tol = tol

    complex_problem = dtype is complex
    problem = _Problem(fun, bc, fun_jac, bc_jac, k, a, S, D, dtype)
    c_fun, c_bc, c_fun_jac, c_bc_jac = _binding_functions(problem, S is not None, complex_problem)

    # SciPy's checks of what fun and bc return, at the first node (fun as the solver calls it).
    pk = p if k > 0 else None
    f0 = problem.f(x[:1], y[:, :1], pk)
    if f0.shape not in ((n, 1), (n,)):
        raise ValueError("`fun` return is expected to have shape {}, but actually has {}.".format((n, 1), f0.shape))
    bc0 = problem.boundary(y[:, 0], y[:, -1], pk)
    if bc0.shape != (n + k,):
        raise ValueError("`bc` return is expected to have shape {}, but actually has {}.".format((n + k,), bc0.shape))

    # The C++ Newton's tolerances. On |bc| it is componentwise on the real system: for a complex
    # problem |Re|, |Im| <= bc_tol / sqrt(2) gives the modulus <= bc_tol that SciPy's test below
    # asks. Both must be finite and positive (tol >= 100 eps) there, while the outer loop below
    # compares with the user's values as SciPy does: bc_tol <= 0 or NaN is never met, inf always;
    # with tol NaN no node is ever added (and status 3 follows), with tol inf every residual is met.
    newton_tol = tol if np.isfinite(tol) else (_HUGE if tol > 0 else 100 * EPS)
    newton_bc_tol = bc_tol / (2 ** 0.5 if complex_problem else 1)
    newton_bc_tol = newton_bc_tol if np.isfinite(newton_bc_tol) and newton_bc_tol > 0 else (
        _HUGE if newton_bc_tol == np.inf else _TINY)

    def to_real(z):
        return _split(z) if complex_problem else z

    def from_real(r):
        return _join(r) if complex_problem else r

    counters = dict(newton_iterations=0, jacobian_evaluations=0, rhs_evaluations=1)
    status = 0
    iteration = 0
    if verbose == 2:
        _print_iteration_header()

    while True:
        m = x.shape[0]
        if np.all(np.isfinite(y)) and np.all(np.isfinite(p)):
            d = _cartan._solve_bvp(c_fun, c_bc, x, to_real(y), to_real(p) if k > 0 else None, c_fun_jac, c_bc_jac,
                                   newton_tol, _ANY_MESH, newton_bc_tol, max_newton_iterations, 0, fd_step,
                                   linear_solver)
        else:  # the C++ solver refuses a non-finite guess; SciPy's first factorisation fails: status 2
            d = dict(y=to_real(y), yp=to_real(_mesh_f(problem, x, y, p if k > 0 else None)),
                     p=to_real(p), rms_residuals=np.empty(0), max_bc_residual=np.nan, status_name="not-converged",
                     message="the guess is not finite", newton_iterations=0, jacobian_evaluations=0,
                     rhs_evaluations=m)
        iteration += 1
        for key in ("newton_iterations", "jacobian_evaluations", "rhs_evaluations"):
            counters[key] += d[key]
        y, f = from_real(d["y"]), from_real(d["yp"])
        if k > 0:
            p = from_real(d["p"])
        # f, its midpoint values or bc not finite (at this mesh's start: Newton rejects such
        # trials): SciPy's factorisation then fails on the non-finite Jacobian, status 2.
        finite = np.all(np.isfinite(f)) and d["rms_residuals"].shape == (m - 1,) and np.isfinite(d["max_bc_residual"])
        if not finite:
            rms_res = np.full(m - 1, np.nan)
            max_bc_res = np.max(abs(problem.boundary(y[:, 0], y[:, -1], p if k > 0 else None)))
        elif complex_problem:
            rms_res = _rms_residuals(problem, _create_spline(y, f, x, h), x, h, p if k > 0 else None)
            counters["rhs_evaluations"] += 3 * (m - 1)
            max_bc_res = np.max(abs(problem.boundary(y[:, 0], y[:, -1], p if k > 0 else None)))
        else:
            rms_res = d["rms_residuals"]
            max_bc_res = d["max_bc_residual"]
        max_rms_res = np.max(rms_res)

        if d["status_name"] == "singular-jacobian" or not finite:
            status = 2
            break

        # SciPy's rule (one node where tol < r < 100 tol, two where r >= 100 tol) and the
        # interpolant on the next mesh, in C++ (numerics/scipy_refinement.hpp).
        refined, refined_y, nodes_added = _cartan._scipy_refinement(x, to_real(y), to_real(f), rms_res, tol)

        if m + nodes_added > max_nodes:
            status = 1
            if verbose == 2:
                _print_iteration_progress(iteration, max_rms_res, max_bc_res, m, "({})".format(nodes_added))
            break

        if verbose == 2:
            _print_iteration_progress(iteration, max_rms_res, max_bc_res, m, nodes_added)

        if nodes_added > 0:
            y = from_real(refined_y)
            x, h = refined, np.diff(refined)
        elif max_bc_res <= bc_tol:
            status = 0
            break
        elif iteration >= _MAX_ITERATION:
            status = 3
            break

    if verbose > 0:
        _print_termination(status, iteration, x.shape[0], max_rms_res, max_bc_res)

    return result_class()(
        sol=_create_spline(y, f, x, h), p=p if k > 0 else None, x=x, y=y, yp=f, rms_residuals=rms_res,
        niter=iteration, status=status, message=TERMINATION_MESSAGES[status], success=status == 0, max_rms_residual=max_rms_res,
        max_bc_residual=max_bc_res, details=d["message"], solve_time=time.perf_counter() - started, **counters)
