"""The contract of scipy.integrate.solve_bvp (SciPy 1.10, Debian's), item by item, run on both
scipy.integrate.solve_bvp and cartan.solve_bvp (issue 14): every test takes the fixture `backend`
("scipy", "cartan"), so that a divergence shows at once as a test failing on one backend only.

Items (one section each below): the signature and positional order; the result (an
OptimizeResult with SciPy's fields, shapes and dtypes); `sol` a scipy.interpolate.PPoly; the
published test problems (SciPy's own tests: exp, Sturm-Liouville with a parameter, Emden with the
singular term S, shock layer, nonlinear boundary conditions, big systems, complex; Ascher,
Mattheij & Russell's y'' = 3/2 y^2; the Mathieu eigenvalue; Bratu's two branches and Bratu with
its eigenvalue unknown) against closed forms; the meaning of rms_residuals; statuses 0-3 and
their messages, NaN included; tol below 100 eps (warning and clamp); bc_tol; max_nodes and
SciPy's refinement rule (node counts within 10 %); verbose 0/1/2 reports; the singular term's
conventions at x = a; complex problems; how the callbacks are called; validation errors;
exceptions raised in callbacks.

Strict xfails mark what one backend does not do: on SciPy, a SciPy 1.10 bug with complex problems
whose Newton needs damping. A strict xfail that starts passing fails,
so the marks go when the cause is fixed.

Tolerances. Both backends solve the same collocation equations (three-stage Lobatto IIIA) with
the same error control: the RMS over each interval of the residual y' - f relative to 1 + |f| is
at most tol. The error of the solution is that residual propagated by the problem's Green's
function, so |y - y_exact| <= K tol with K of order 1 for the well-conditioned problems here;
fourth-order collocation is usually far more accurate at the nodes. Where SciPy's own tests
assert a bound we keep theirs (e.g. 1e-5 at tol 1e-3, 1e-4 for the parameter problems); the other
bounds are 10 tol (K <= 10), with the measured errors in a comment. The two backends' Newton
iterations stop at slightly different points (each within a fraction 0.05 of tol h (1 + |f|) of
the collocation equations), so they agree with each other within those bounds, not bit for bit.
"""
import inspect
import io
import re
import sys
from pathlib import Path
import warnings

import numpy as np
import pytest
import scipy
import scipy.integrate
import scipy.special
from numpy.linalg import pinv
from scipy.interpolate import PPoly
from scipy.optimize import OptimizeResult, brentq
from scipy.special import erf

import cartan

# The published problems, defined once for this suite and the benchmark (bench/python/bvp_cases.py,
# SciPy only; checked against SciPy by bench/python/test_bvp_cases.py).
sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "bench" / "python"))
from bvp_cases import (  # noqa: E402
    ascher_bc,
    ascher_fun,
    big_bc,
    big_fun,
    bratu_bc,
    bratu_fun,
    bratu_p_bc,
    bratu_p_fun,
    emden_bc,
    emden_fun,
    emden_fun_jac,
    emden_guess,
    exp_bc,
    exp_bc_complex,
    exp_bc_jac,
    exp_fun,
    exp_fun_jac,
    mathieu_bc,
    mathieu_fun,
    nonlin_bc_fun,
    shock_bc,
    shock_fun,
    sl_bc,
    sl_bc_jac,
    sl_fun,
    sl_fun_jac,
)

SOLVERS = {"scipy": scipy.integrate.solve_bvp, "cartan": cartan.solve_bvp}

SCIPY_COMPLEX_NEWTON = ("SciPy 1.10 bug: solve_newton's criterion cost = np.dot(step, step) is not a norm for a "
                        "complex step (no conjugate), so its line search fails on complex problems that need "
                        "damping; cartan solves the real system of real and imaginary parts")


@pytest.fixture(params=["scipy", "cartan"])
def backend(request):
    return request.param


def backends(scipy_xfail=None, cartan_xfail=None):
    """Explicit backend parameters, with a strict xfail on a backend where a reason is given."""
    return [pytest.param(name, marks=[pytest.mark.xfail(strict=True, reason=reason)] if reason else [])
            for name, reason in (("scipy", scipy_xfail), ("cartan", cartan_xfail))]


def solve(backend, *args, **kwargs):
    """The backend's solve_bvp, with warnings raised as errors (a warning is part of the contract
    only where a test expects it)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return SOLVERS[backend](*args, **kwargs)


# --- Problems (SciPy's scipy/integrate/tests/test_bvp.py unless said otherwise) -------------------

def exp_sol(x):
    return (np.exp(-x) - np.exp(x - 2)) / (1 - np.exp(-2))


# Emden's equation y'' + 2/x y' = -y^5 as y' = S y / x + f with S = [[0, 0], [0, -2]].
EMDEN_S = np.array([[0, 0], [0, -2]])


def emden_bc_jac(ya, yb):
    return np.array([[0, 1], [0, 0]]), np.array([[0, 0], [1, 0]])


def emden_sol(x):
    return (1 + x ** 2 / 3) ** -0.5


def undefined_fun(x, y):
    return np.zeros_like(y)


def undefined_bc(ya, yb):
    return np.array([ya[0], yb[0] - 1])


def big_fun_with_parameters(x, y, p):
    f = np.zeros_like(y)
    f[::2] = y[1::2]
    f[1::4] = -p[0] ** 2 * y[::4]
    f[3::4] = -p[1] ** 2 * y[2::4]
    return f


def big_fun_with_parameters_jac(x, y, p):
    n, m = y.shape
    df_dy = np.zeros((n, n, m))
    df_dy[range(0, n, 2), range(1, n, 2)] = 1
    df_dy[range(1, n, 4), range(0, n, 4)] = -p[0] ** 2
    df_dy[range(3, n, 4), range(2, n, 4)] = -p[1] ** 2
    df_dp = np.zeros((n, 2, m))
    df_dp[range(1, n, 4), 0] = -2 * p[0] * y[range(0, n, 4)]
    df_dp[range(3, n, 4), 1] = -2 * p[1] * y[range(2, n, 4)]
    return df_dy, df_dp


def big_bc_with_parameters(ya, yb, p):
    return np.hstack((ya[::2], yb[::2], ya[1] - p[0], ya[3] - p[1]))


def big_bc_with_parameters_jac(ya, yb, p):
    n = ya.shape[0]
    dbc_dya = np.zeros((n + 2, n))
    dbc_dyb = np.zeros((n + 2, n))
    dbc_dya[range(n // 2), range(0, n, 2)] = 1
    dbc_dyb[range(n // 2, n), range(0, n, 2)] = 1
    dbc_dp = np.zeros((n + 2, 2))
    dbc_dp[n, 0] = -1
    dbc_dya[n, 1] = 1
    dbc_dp[n + 1, 1] = -1
    dbc_dya[n + 1, 3] = 1
    return dbc_dya, dbc_dyb, dbc_dp


SHOCK_EPS = 1e-3


def shock_sol(x):
    k = np.sqrt(2 * SHOCK_EPS)
    return np.cos(np.pi * x) + erf(x / k) / erf(1 / k)


def nonlin_bc_bc(ya, yb):
    phiA, phipA = ya
    phiC, phipC = yb
    kappa, ioA, ioC, V, f = 1.64, 0.01, 1.0e-4, 0.5, 38.9
    hA = 0.0 - phiA - 0.0  # Butler-Volmer kinetics at the anode
    iA = ioA * (np.exp(f * hA) - np.exp(-f * hA))
    hC = V - phiC - 1.0  # and at the cathode
    iC = ioC * (np.exp(f * hC) - np.exp(-f * hC))
    return np.array([iA + kappa * phipA, iC - kappa * phipC])


def nonlin_bc_sol(x):
    return -0.13426436116763119 - 1.1308709 * x


# Ascher, Mattheij & Russell: y'' = 3/2 y^2, y(0) = 4, y(1) = 1; one solution is 4 / (1 + x)^2.
def ascher_sol(x):
    return np.vstack((4 / (1 + x) ** 2, -8 / (1 + x) ** 3))


# The Mathieu equation y'' + (k - 2 q cos 2x) y = 0 on [0, pi], y'(0) = y'(pi) = 0, y(0) = 1:
# the eigenvalue k = a_4(q) is the unknown parameter.
MATHIEU_Q = 5.0


# Bratu's problem y'' + lam exp(y) = 0, y(0) = y(1) = 0 (SciPy's documentation example): the
# solutions are y = -2 log(cosh((x - 1/2) theta / 2) / cosh(theta / 4)) with
# theta = sqrt(2 lam) cosh(theta / 4); for lam = 1 two of them.
def bratu_sol(x, theta):
    return -2 * np.log(np.cosh((x - 0.5) * theta / 2) / np.cosh(theta / 4))


# Bratu with lam unknown and y'(0) = theta tanh(theta / 4) given (theta = 2):
# lam = theta^2 / (2 cosh^2(theta / 4)).
BRATU_THETA = 2.0


def relative_residual_norms(sol, fun, x_test, extra=None):
    """|sol'(x) - f(x, sol(x))| / (1 + |f|) at the test points (SciPy's tests' pointwise check)."""
    y = sol(x_test)
    f = fun(x_test, y) if extra is None else fun(x_test, y) + extra(x_test, y)
    r = (sol(x_test, 1) - f) / (1 + np.abs(f))
    return np.sum(np.real(r * np.conj(r)), axis=0) ** 0.5


def assert_interpolates(res):
    """sol passes through the nodes with slopes yp (SciPy's tests: 1e-10)."""
    np.testing.assert_allclose(res.sol(res.x), res.y, rtol=1e-10, atol=1e-10)
    np.testing.assert_allclose(res.sol(res.x, 1), res.yp, rtol=1e-10, atol=1e-10)


JACOBIAN_CHOICES = [(False, False), (True, False), (False, True), (True, True)]


# --- The signature ---------------------------------------------------------------------------------

SIGNATURE = [("fun", inspect.Parameter.empty), ("bc", inspect.Parameter.empty), ("x", inspect.Parameter.empty),
             ("y", inspect.Parameter.empty), ("p", None), ("S", None), ("fun_jac", None), ("bc_jac", None),
             ("tol", 0.001), ("max_nodes", 1000), ("verbose", 0), ("bc_tol", None)]


def test_signature_names_order_and_defaults(backend):
    parameters = list(inspect.signature(SOLVERS[backend]).parameters.values())
    positional = [q for q in parameters if q.kind is inspect.Parameter.POSITIONAL_OR_KEYWORD]
    assert [(q.name, q.default) for q in positional] == SIGNATURE
    # Anything more (cartan's Newton and linear-algebra options) is keyword-only, after bc_tol.
    assert all(q.kind is inspect.Parameter.KEYWORD_ONLY for q in parameters[len(SIGNATURE):])


def test_every_argument_can_be_given_by_position(backend):
    x = np.linspace(0, 1, 5)
    res = solve(backend, exp_fun, exp_bc, x, np.zeros((2, 5)), None, None, exp_fun_jac, exp_bc_jac, 1e-4, 50, 0,
                1e-6)
    assert res.status == 0
    assert np.abs(res.sol(x)[0] - exp_sol(x)).max() < 1e-4  # K = 1 (see the module's docstring)


# --- The result --------------------------------------------------------------------------------------

FIELDS = ("sol", "p", "x", "y", "yp", "rms_residuals", "niter", "status", "message", "success")


def test_result_is_an_optimize_result_with_scipys_fields(backend):
    x = np.linspace(0, 1, 5)
    res = solve(backend, exp_fun, exp_bc, x, np.zeros((2, 5)), tol=1e-6)
    assert isinstance(res, OptimizeResult)
    assert set(FIELDS) <= set(res.keys())
    for key in FIELDS:
        assert res[key] is getattr(res, key)
    m = res.x.size
    assert res.x.shape == (m,) and res.x[0] == 0 and res.x[-1] == 1 and np.all(np.diff(res.x) > 0)
    assert res.y.shape == (2, m) and res.yp.shape == (2, m) and res.rms_residuals.shape == (m - 1,)
    assert res.y.dtype == res.yp.dtype == np.float64
    assert res.p is None  # no parameters
    assert isinstance(res.niter, int) and res.niter >= 1
    assert res.status == 0 and res.success is True
    assert res.message == "The algorithm converged to the desired accuracy."
    np.testing.assert_allclose(res.yp, exp_fun(res.x, res.y), rtol=1e-14)  # yp = f at the nodes
    assert np.all(res.rms_residuals <= 1e-6)
    assert "x" in repr(res)  # OptimizeResult's table


def test_result_p_is_an_array_with_parameters(backend):
    x = np.linspace(0, np.pi, 5)
    res = solve(backend, sl_fun, sl_bc, x, np.ones((2, 5)), p=[0.5])
    assert res.success and isinstance(res.p, np.ndarray) and res.p.shape == (1,) and res.p.dtype == np.float64


def test_rms_residuals_mean_what_scipy_says(backend):
    # rms_residuals[i]: the RMS over interval i of |sol' - f(x, sol)| / (1 + |f|), by 5-point
    # Lobatto quadrature (the residual vanishes at the nodes): recomputed here from sol and fun.
    # Both sides evaluate the same cubic (PPoly vs cartan's Hermite form), so they agree to rounding
    # of the residual (~1e-16 |f| / 1e-5): rtol 1e-6.
    x = np.linspace(0, 1, 5)
    res = solve(backend, ascher_fun, ascher_bc, x, np.vstack((4 - 3 * x, -3 * np.ones(5))), tol=1e-5)
    h = np.diff(res.x)
    middle = res.x[:-1] + h / 2
    s = h / 2 * (3 / 7) ** 0.5
    squares = []
    for t in (middle, middle - s, middle + s):
        f = ascher_fun(t, res.sol(t))
        squares.append(np.sum(((res.sol(t, 1) - f) / (1 + np.abs(f))) ** 2, axis=0))
    rms = np.sqrt(16 / 45 * squares[0] + 49 / 180 * (squares[1] + squares[2]))
    np.testing.assert_allclose(res.rms_residuals, rms, rtol=1e-6, atol=1e-14)
    assert res.success and rms.max() <= 1e-5


# --- sol is a PPoly ------------------------------------------------------------------------------------

def test_sol_is_a_ppoly(backend):
    x = np.linspace(0, 1, 5)
    res = solve(backend, ascher_fun, ascher_bc, x, np.vstack((4 - 3 * x, -3 * np.ones(5))), tol=1e-6)
    sol = res.sol
    assert isinstance(sol, PPoly)
    assert np.array_equal(sol.x, res.x) and sol.c.shape == (4, res.x.size - 1, 2) and sol.axis == 1
    assert sol.extrapolate
    assert sol(0.5).shape == (2,)  # a number -> (n,)
    grid = np.linspace(0, 1, 7)
    assert sol(grid).shape == (2, 7)
    assert sol(grid.reshape(7, 1)).shape == (2, 7, 1) and sol(np.zeros((3, 4))).shape == (2, 3, 4)  # n-D x
    np.testing.assert_allclose(sol.derivative()(grid), sol(grid, 1), rtol=1e-13, atol=1e-13)
    # A C^1 cubic spline: y'' piecewise linear (nu = 2), y''' piecewise constant, y'''' = 0.
    exact = ascher_sol(grid)
    np.testing.assert_allclose(sol(grid), exact, atol=10 * 1e-6)  # K <= 10; measured 1.3e-8
    # y'' = 3/2 y^2: the cubic's second derivative is O(h^2) accurate, h ~ 0.02 here (40 intervals).
    np.testing.assert_allclose(sol(grid, 2)[0], 1.5 * exact[0] ** 2, rtol=1e-2)
    assert np.all(sol(grid, 4) == 0)
    np.testing.assert_allclose(sol.antiderivative()(1.0)[0], 2.0, atol=1e-5)  # int_0^1 4/(1+x)^2 = 2
    assert np.all(np.isfinite(sol(1.5)))  # extrapolates


# --- Published problems ---------------------------------------------------------------------------------

@pytest.mark.parametrize("jacobians", JACOBIAN_CHOICES)
def test_exp_problem(backend, jacobians):
    x = np.linspace(0, 1, 5)
    x_test = np.linspace(0, 1, 100)
    res = solve(backend, exp_fun, exp_bc, x, np.zeros((2, 5)), fun_jac=exp_fun_jac if jacobians[0] else None,
                bc_jac=exp_bc_jac if jacobians[1] else None)
    assert res.status == 0 and res.success
    assert res.x.size == 5  # SciPy's test: no refinement needed at tol 1e-3
    np.testing.assert_allclose(res.sol(x_test)[0], exp_sol(x_test), atol=1e-5)  # SciPy's bound
    assert np.all(relative_residual_norms(res.sol, exp_fun, x_test) < 1e-3)
    assert np.all(res.rms_residuals < 1e-3)
    assert_interpolates(res)


@pytest.mark.parametrize("jacobians", JACOBIAN_CHOICES)
def test_sturm_liouville_with_a_parameter(backend, jacobians):
    x = np.linspace(0, np.pi, 5)
    x_test = np.linspace(0, np.pi, 100)
    res = solve(backend, sl_fun, sl_bc, x, np.ones((2, 5)), p=[0.5], fun_jac=sl_fun_jac if jacobians[0] else None,
                bc_jac=sl_bc_jac if jacobians[1] else None)
    assert res.status == 0 and res.success
    assert res.x.size < 10
    np.testing.assert_allclose(res.p, [1], rtol=1e-4)  # SciPy's bounds
    np.testing.assert_allclose(res.sol(x_test)[0], np.sin(x_test), rtol=1e-4, atol=1e-4)
    assert np.all(relative_residual_norms(res.sol, lambda t, y: sl_fun(t, y, [1]), x_test) < 1e-3)
    assert_interpolates(res)


@pytest.mark.parametrize("jacobians", JACOBIAN_CHOICES)
def test_emden_with_the_singular_term(backend, jacobians):
    x, y = emden_guess()
    x_test = np.linspace(0.05, 1, 100)
    res = solve(backend, emden_fun, emden_bc, x, y, S=EMDEN_S, fun_jac=emden_fun_jac if jacobians[0] else None,
                bc_jac=emden_bc_jac if jacobians[1] else None)
    assert res.status == 0 and res.success
    assert res.x.size == 10
    np.testing.assert_allclose(res.sol(x_test)[0], emden_sol(x_test), atol=1e-5)  # SciPy's bound
    singular = lambda t, y: EMDEN_S @ y / t  # noqa: E731
    assert np.all(relative_residual_norms(res.sol, emden_fun, x_test, singular) < 1e-3)
    assert_interpolates(res)


def test_shock_layer(backend):
    x = np.linspace(-1, 1, 5)
    x_test = np.linspace(-1, 1, 100)
    res = solve(backend, shock_fun, shock_bc, x, np.zeros((2, 5)))
    assert res.status == 0 and res.success
    assert res.x.size < 110
    np.testing.assert_allclose(res.sol(x_test)[0], shock_sol(x_test), rtol=1e-5, atol=1e-5)  # SciPy's
    assert np.all(relative_residual_norms(res.sol, shock_fun, x_test) < 1e-3)
    assert_interpolates(res)


def test_nonlinear_boundary_conditions(backend):
    x = np.linspace(0, 0.1, 5)
    res = solve(backend, nonlin_bc_fun, nonlin_bc_bc, x, np.zeros((2, 5)))
    assert res.status == 0 and res.success
    assert res.x.size < 8
    np.testing.assert_allclose(res.sol(x)[0], nonlin_bc_sol(x), rtol=1e-5, atol=1e-5)  # SciPy's
    assert np.all(relative_residual_norms(res.sol, nonlin_bc_fun, x) < 1e-3)
    assert np.abs(nonlin_bc_bc(res.y[:, 0], res.y[:, -1])).max() <= 1e-3  # bc_tol = tol
    assert_interpolates(res)


def test_big_problem(backend):
    n = 30
    x = np.linspace(0, 1, 5)
    res = solve(backend, big_fun, big_bc, x, np.zeros((2 * n, 5)))
    assert res.status == 0 and res.success
    exact = np.ones((2 * n, 5))
    exact[::2] = x  # y_{2i} = x, y_{2i+1} = 1: a cubic, so collocation is exact
    np.testing.assert_allclose(res.sol(x), exact, atol=1e-10)
    assert np.all(res.rms_residuals < 1e-3)
    assert_interpolates(res)


@pytest.mark.parametrize("jacobians", JACOBIAN_CHOICES)
def test_big_problem_with_parameters(backend, jacobians):
    n = 30
    x = np.linspace(0, np.pi, 5)
    x_test = np.linspace(0, np.pi, 100)
    res = solve(backend, big_fun_with_parameters, big_bc_with_parameters, x, np.ones((2 * n, 5)), p=[0.5, 0.5],
                fun_jac=big_fun_with_parameters_jac if jacobians[0] else None,
                bc_jac=big_bc_with_parameters_jac if jacobians[1] else None)
    assert res.status == 0 and res.success
    np.testing.assert_allclose(res.p, [1, 1], rtol=1e-4)  # SciPy's bounds
    sol_test = res.sol(x_test)
    for i in range(0, n, 4):
        np.testing.assert_allclose(sol_test[i], np.sin(x_test), rtol=1e-4, atol=1e-4)
        np.testing.assert_allclose(sol_test[i + 2], np.sin(x_test), rtol=1e-4, atol=1e-4)
    assert np.all(res.rms_residuals < 1e-3)
    assert_interpolates(res)


@pytest.mark.parametrize("tol", [1e-3, 1e-6])
def test_ascher_mattheij_russell(backend, tol):
    x = np.linspace(0, 1, 5)
    res = solve(backend, ascher_fun, ascher_bc, x, np.vstack((4 - 3 * x, -3 * np.ones(5))), tol=tol)
    assert res.status == 0 and res.success
    grid = np.linspace(0, 1, 101)
    # K <= 10 (measured: 1.1e-5 at tol 1e-3 on 5 nodes, 1.3e-8 at 1e-6, on both backends).
    assert np.abs(res.sol(grid) - ascher_sol(grid)).max() < 10 * tol * 8  # y' = -8/(1+x)^3 scales to 8
    assert np.abs(res.sol(grid)[0] - ascher_sol(grid)[0]).max() < 10 * tol


def test_mathieu_eigenvalue(backend):
    x = np.linspace(0, np.pi, 5)
    res = solve(backend, mathieu_fun, mathieu_bc, x, np.vstack((np.cos(4 * x), -4 * np.sin(4 * x))), p=[15],
                tol=1e-6)
    assert res.status == 0 and res.success
    # The eigenvalue (~17.1) at tol 1e-6: measured within 5e-9 relative on both; 1e-7 relative
    # (the residual bound tol times |k| / 10: an eigenvalue is a smooth functional of y).
    assert res.p[0] == pytest.approx(scipy.special.mathieu_a(4, MATHIEU_Q), rel=1e-7)


@pytest.mark.parametrize("y0, branch", [(0.0, 0), (3.0, 1)])
def test_bratu_two_branches(backend, y0, branch):
    theta = [brentq(lambda t: t - np.sqrt(2) * np.cosh(t / 4), lo, hi) for lo, hi in ((0, 4), (4, 20))][branch]
    x = np.linspace(0, 1, 5)
    y = np.zeros((2, 5))
    y[0] = y0
    res = solve(backend, bratu_fun, bratu_bc, x, y, tol=1e-6)
    assert res.status == 0 and res.success
    grid = np.linspace(0, 1, 101)
    # K <= 10 (measured 1.2e-8 and 1.0e-8, both backends; the upper branch has |y| up to 4.2).
    assert np.abs(res.sol(grid)[0] - bratu_sol(grid, theta)).max() < 10 * 1e-6


def test_bratu_with_the_eigenvalue_unknown(backend):
    x = np.linspace(0, 1, 5)
    res = solve(backend, bratu_p_fun, bratu_p_bc, x, np.zeros((2, 5)), p=[1.0], tol=1e-6)
    assert res.status == 0 and res.success
    lam = BRATU_THETA ** 2 / (2 * np.cosh(BRATU_THETA / 4) ** 2)
    grid = np.linspace(0, 1, 101)
    # K <= 10 for lam and y (measured 1.4e-9 and 2.7e-9 on both backends).
    assert abs(res.p[0] - lam) < 10 * 1e-6
    assert np.abs(res.sol(grid)[0] - bratu_sol(grid, BRATU_THETA)).max() < 10 * 1e-6


# --- Statuses and messages ------------------------------------------------------------------------------

MESSAGES = {
    0: "The algorithm converged to the desired accuracy.",
    1: "The maximum number of mesh nodes is exceeded.",
    2: "A singular Jacobian encountered when solving the collocation system.",
    3: "The solver was unable to satisfy boundary conditions tolerance on iteration 10.",
}


def test_status_1_max_nodes_exceeded(backend):
    x = np.linspace(0, 1, 2)
    res = solve(backend, exp_fun, exp_bc, x, np.zeros((2, 2)), tol=1e-5, max_nodes=5)
    assert res.status == 1 and not res.success and res.message == MESSAGES[1]
    # The mesh is the one before the refinement that would exceed max_nodes, solved.
    assert res.x.size <= 5 and res.y.shape == (2, res.x.size) and res.rms_residuals.max() > 1e-5


def test_status_1_when_the_initial_mesh_exceeds_max_nodes(backend):
    # SciPy solves the given mesh once, then stops: m + nodes added > max_nodes.
    x = np.linspace(0, 1, 20)
    res = solve(backend, exp_fun, exp_bc, x, np.zeros((2, 20)), max_nodes=10)
    assert res.status == 1 and res.message == MESSAGES[1] and res.niter == 1
    assert res.x.size == 20 and np.abs(res.y[0] - exp_sol(x)).max() < 1e-5  # solved on that mesh


def test_status_2_singular_jacobian(backend):
    x = np.linspace(0, 1, 5)
    res = solve(backend, undefined_fun, undefined_bc, x, np.zeros((2, 5)))
    assert res.status == 2 and not res.success and res.message == MESSAGES[2]


@pytest.mark.parametrize("where", ["fun", "bc"])
def test_status_2_when_fun_or_bc_is_nan(backend, where):
    # SciPy: the Jacobian of a NaN f or bc cannot be factorised (splu fails): status 2.
    x = np.linspace(0, 1, 5)
    fun = (lambda x, y: np.full_like(y, np.nan)) if where == "fun" else exp_fun
    bc = (lambda ya, yb: np.full(2, np.nan)) if where == "bc" else exp_bc
    with np.errstate(invalid="ignore"):
        res = solve(backend, fun, bc, x, np.zeros((2, 5)))
    assert res.status == 2 and not res.success and res.message == MESSAGES[2] and res.niter == 1
    assert res.x.size == 5 and res.rms_residuals.shape == (4,)


def test_status_3_bc_tol_not_met(backend):
    # |bc| cannot go below ~1e-15 (rounding in the exponentials): the residuals are met, bc_tol is
    # not, and SciPy tries the same mesh again until iteration 10.
    x = np.linspace(0, 0.1, 5)
    res = solve(backend, nonlin_bc_fun, nonlin_bc_bc, x, np.zeros((2, 5)), bc_tol=1e-20)
    assert res.status == 3 and not res.success and res.message == MESSAGES[3]
    assert res.niter == 10 and res.x.size == 5
    assert np.all(res.rms_residuals <= 1e-3)
    np.testing.assert_allclose(res.sol(x)[0], nonlin_bc_sol(x), rtol=1e-5, atol=1e-5)


@pytest.mark.parametrize("where", ["y", "p"])
@pytest.mark.parametrize("value", [np.nan, np.inf])
def test_status_2_when_the_guess_is_not_finite(backend, where, value):
    x = np.linspace(0, np.pi, 5)
    y = np.ones((2, 5))
    p = [0.5]
    if where == "y":
        y[0, 2] = value
    else:
        p = [value]
    with np.errstate(invalid="ignore"):
        res = solve(backend, sl_fun, sl_bc, x, y, p=p)
    assert res.status == 2 and res.message == MESSAGES[2] and res.niter == 1 and res.x.size == 5


@pytest.mark.parametrize("tol, bc_tol, status, niter", [
    (np.inf, None, 0, 1),  # every residual is below inf
    (np.nan, None, 3, 10),  # no comparison with NaN holds: no node added, bc_tol = NaN never met
    (1e-3, np.nan, 3, 10),
    (1e-3, 0.0, 3, 10),  # |bc| < 0 never holds
    (1e-3, -1.0, 3, 10),
    (1e-3, np.inf, 0, 1),
])
def test_unusual_tolerances_are_compared_as_scipy_compares_them(backend, tol, bc_tol, status, niter):
    x = np.linspace(0, 0.1, 5)
    res = solve(backend, nonlin_bc_fun, nonlin_bc_bc, x, np.zeros((2, 5)), tol=tol, bc_tol=bc_tol)
    assert (res.status, res.niter, res.x.size) == (status, niter, 5)


@pytest.mark.parametrize("bc_tol", [1e-10, 1e-14])
def test_bc_tol_is_met_on_success(backend, bc_tol):
    x = np.linspace(0, 0.1, 5)
    res = solve(backend, nonlin_bc_fun, nonlin_bc_bc, x, np.zeros((2, 5)), bc_tol=bc_tol)
    assert res.status == 0 and np.abs(nonlin_bc_bc(res.y[:, 0], res.y[:, -1])).max() <= bc_tol


def test_tol_below_100_eps_warns_and_is_clamped(backend):
    # A linear solution is a cubic: the collocation is exact, so the clamped tol 100 eps is met.
    line = lambda x, y: np.vstack((y[1], np.zeros_like(x)))  # noqa: E731
    bc = lambda ya, yb: np.array([ya[0], yb[0] - 1])  # noqa: E731
    x = np.linspace(0, 1, 4)
    for tol in (1e-20, 0.0, -1.0):
        with pytest.warns(UserWarning, match=r"^`tol` is too low, setting to 2\.22e-14$"):
            res = SOLVERS[backend](line, bc, x, np.zeros((2, 4)), tol=tol)
        assert res.status == 0 and np.all(res.rms_residuals <= 100 * np.finfo(float).eps)
        np.testing.assert_allclose(res.y[0], x, atol=1e-14)


# --- max_nodes and the refinement rule --------------------------------------------------------------------

NODE_COUNT_PROBLEMS = {
    "exp, tol 1e-6": (exp_fun, exp_bc, np.linspace(0, 1, 5), np.zeros((2, 5)), dict(tol=1e-6)),
    "shock, tol 1e-3": (shock_fun, shock_bc, np.linspace(-1, 1, 5), np.zeros((2, 5)), {}),
    "shock, tol 1e-5": (shock_fun, shock_bc, np.linspace(-1, 1, 5), np.zeros((2, 5)), dict(tol=1e-5)),
    "Ascher, tol 1e-8": (ascher_fun, ascher_bc, np.linspace(0, 1, 5),
                         np.vstack((4 - 3 * np.linspace(0, 1, 5), -3 * np.ones(5))), dict(tol=1e-8)),
    "Bratu upper branch, tol 1e-6": (bratu_fun, bratu_bc, np.linspace(0, 1, 5),
                                     np.vstack((3 * np.ones(5), np.zeros(5))), dict(tol=1e-6)),
    "Emden, tol 1e-6": (emden_fun, emden_bc, *emden_guess(), dict(S=EMDEN_S, tol=1e-6)),
    "Mathieu, tol 1e-6": (mathieu_fun, mathieu_bc, np.linspace(0, np.pi, 5),
                          np.vstack((np.cos(4 * np.linspace(0, np.pi, 5)), -4 * np.sin(4 * np.linspace(0, np.pi, 5)))),
                          dict(p=[15], tol=1e-6)),
}


@pytest.mark.parametrize("name", list(NODE_COUNT_PROBLEMS))
def test_node_counts_follow_scipys_refinement_rule(backend, name):
    # SciPy's rule: an interval with tol < r < 100 tol gets one node, r >= 100 tol two; so the
    # final mesh depends only on the residuals, which depend on Newton's stopping point only
    # slightly. Within 10 % of SciPy's count (measured: equal on every problem here).
    fun, bc, x, y, kwargs = NODE_COUNT_PROBLEMS[name]
    reference = solve("scipy", fun, bc, x, y.copy(), **kwargs)
    res = solve(backend, fun, bc, x, y.copy(), **kwargs)
    assert reference.status == res.status == 0
    assert abs(res.x.size - reference.x.size) <= 0.1 * reference.x.size, (res.x.size, reference.x.size)


@pytest.mark.parametrize("name", ["shock, tol 1e-3", "Ascher, tol 1e-8"])
def test_max_nodes_stops_where_scipy_stops(backend, name):
    fun, bc, x, y, kwargs = NODE_COUNT_PROBLEMS[name]
    full = solve("scipy", fun, bc, x, y.copy(), **kwargs).x.size
    reference = solve("scipy", fun, bc, x, y.copy(), max_nodes=full - 1, **kwargs)
    res = solve(backend, fun, bc, x, y.copy(), max_nodes=full - 1, **kwargs)
    assert reference.status == res.status == 1 and res.x.size <= full - 1
    assert abs(res.x.size - reference.x.size) <= 0.1 * reference.x.size and abs(res.niter - reference.niter) <= 1


# --- verbose ---------------------------------------------------------------------------------------------

def run_printing(backend, *args, **kwargs):
    out = io.StringIO()
    old, sys.stdout = sys.stdout, out
    try:
        res = solve(backend, *args, **kwargs)
    finally:
        sys.stdout = old
    return res, out.getvalue()


def max_bc(res, bc):
    return np.max(np.abs(bc(res.y[:, 0], res.y[:, -1])))


def test_verbose_0_prints_nothing(backend):
    res, text = run_printing(backend, exp_fun, exp_bc, np.linspace(0, 1, 5), np.zeros((2, 5)), verbose=0)
    assert res.success and text == ""


def test_verbose_1_prints_scipys_termination_report(backend):
    res, text = run_printing(backend, ascher_fun, ascher_bc, np.linspace(0, 1, 5),
                             np.vstack((4 - 3 * np.linspace(0, 1, 5), -3 * np.ones(5))), tol=1e-6, verbose=1)
    assert res.success
    assert text == ("Solved in {} iterations, number of nodes {}. \nMaximum relative residual: {:.2e} \n"
                    "Maximum boundary residual: {:.2e}\n").format(res.niter, res.x.size, res.rms_residuals.max(),
                                                                  max_bc(res, ascher_bc))


def test_verbose_2_prints_a_line_per_iteration(backend):
    res, text = run_printing(backend, ascher_fun, ascher_bc, np.linspace(0, 1, 5),
                             np.vstack((4 - 3 * np.linspace(0, 1, 5), -3 * np.ones(5))), tol=1e-6, verbose=2)
    lines = text.splitlines()
    header = "{:^15}{:^15}{:^15}{:^15}{:^15}".format("Iteration", "Max residual", "Max BC residual", "Total nodes",
                                                     "Nodes added")
    assert lines[0] == header
    assert len(lines) == 1 + res.niter + 3 and lines[-3].startswith("Solved in")
    progress = [line.split() for line in lines[1:1 + res.niter]]
    assert [int(p[0]) for p in progress] == list(range(1, res.niter + 1))
    assert progress[-1] == ["{}".format(res.niter), "{:.2e}".format(res.rms_residuals.max()),
                            "{:.2e}".format(max_bc(res, ascher_bc)), str(res.x.size), "0"]
    # Total nodes grows by the nodes added at each iteration.
    for this, following in zip(progress, progress[1:]):
        assert int(this[3]) + int(this[4]) == int(following[3])


@pytest.mark.parametrize("status, case", [
    (1, "Number of nodes is exceeded after iteration 1. \n"),
    (2, "Singular Jacobian encountered when solving the collocation system on iteration 1. \n"),
    (3, "The solver was unable to satisfy boundary conditions tolerance on iteration 10. \n"),
])
def test_verbose_reports_each_failure(backend, status, case):
    if status == 1:
        args, kwargs = (exp_fun, exp_bc, np.linspace(0, 1, 2), np.zeros((2, 2))), dict(tol=1e-5, max_nodes=2)
    elif status == 2:
        args, kwargs = (undefined_fun, undefined_bc, np.linspace(0, 1, 5), np.zeros((2, 5))), {}
    else:
        args, kwargs = (nonlin_bc_fun, nonlin_bc_bc, np.linspace(0, 0.1, 5), np.zeros((2, 5))), dict(bc_tol=1e-20)
    res, text = run_printing(backend, *args, verbose=2, **kwargs)
    assert res.status == status
    assert text.endswith(case + "Maximum relative residual: {:.2e} \nMaximum boundary residual: {:.2e}\n".format(
        res.rms_residuals.max(), max_bc(res, args[1])))
    if status == 1:  # the progress line gives the nodes that would have been added in parentheses
        assert re.fullmatch(r"\(\d+\)", text.splitlines()[1].split()[-1])


def test_verbose_must_be_0_1_or_2(backend):
    with pytest.raises(ValueError, match=r"^`verbose` must be in \[0, 1, 2\]\.$"):
        solve(backend, exp_fun, exp_bc, np.linspace(0, 1, 5), np.zeros((2, 5)), verbose=3)


# --- The singular term S ------------------------------------------------------------------------------

def test_singular_term_conventions_at_a(backend):
    # At x = a the solver uses y'(a) = (I - S)^+ f(a, y(a)) (the limit of S y / (x - a) is S y'(a));
    # elsewhere f + S y / (x - a); and S y(a) = 0.
    x, y = emden_guess()
    res = solve(backend, emden_fun, emden_bc, x, y, S=EMDEN_S, tol=1e-6)
    assert res.success
    f = emden_fun(res.x, res.y)
    np.testing.assert_allclose(res.yp[:, 0], pinv(np.eye(2) - EMDEN_S) @ f[:, 0], rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(res.yp[:, 1:], f[:, 1:] + EMDEN_S @ res.y[:, 1:] / res.x[1:], rtol=1e-12, atol=1e-15)
    assert np.abs(EMDEN_S @ res.y[:, 0]).max() <= 1e-6  # bc_tol = tol
    # Emden's y = (1 + x^2/3)^(-1/2), y' = -x/3 (1 + x^2/3)^(-3/2): K <= 10 (measured 2e-9).
    grid = np.linspace(0, 1, 50)
    assert np.abs(res.sol(grid)[0] - emden_sol(grid)).max() < 10 * 1e-6


def test_singular_term_must_be_n_by_n(backend):
    x, y = emden_guess()
    with pytest.raises(ValueError, match=r"^`S` is expected to have shape \(2, 2\), but actually has \(1, 2\)$"):
        solve(backend, emden_fun, emden_bc, x, y, S=np.zeros((1, 2)))


# --- Complex problems --------------------------------------------------------------------------------------

@pytest.mark.parametrize("jacobians", JACOBIAN_CHOICES)
def test_complex_problem(backend, jacobians):
    x = np.linspace(0, 1, 5)
    x_test = np.linspace(0, 1, 100)
    res = solve(backend, exp_fun, exp_bc_complex, x, np.zeros((2, 5), dtype=complex),
                fun_jac=exp_fun_jac if jacobians[0] else None, bc_jac=exp_bc_jac if jacobians[1] else None)
    assert res.status == 0 and res.success
    assert res.y.dtype == res.yp.dtype == np.complex128 and res.sol(x_test).dtype == np.complex128
    np.testing.assert_allclose(res.sol(x_test)[0].real, exp_sol(x_test), atol=1e-5)  # SciPy's bounds
    np.testing.assert_allclose(res.sol(x_test)[0].imag, exp_sol(x_test), atol=1e-5)
    assert np.all(relative_residual_norms(res.sol, exp_fun, x_test) < 1e-3)
    assert np.all(res.rms_residuals < 1e-3)
    assert_interpolates(res)


def test_complex_problem_is_never_cast_to_real(backend):
    # The guess is complex; the answer has y(0) = 1 + 1j: a real cast would lose the imaginary part.
    x = np.linspace(0, 1, 5)
    res = solve(backend, exp_fun, exp_bc_complex, x, np.zeros((2, 5), dtype=complex), tol=1e-6)
    assert res.success and np.iscomplexobj(res.y) and res.y[0, 0] == pytest.approx(1 + 1j, abs=1e-6)


def complex_rate_fun(x, y, p):
    return p[0] * y


def complex_rate_bc(ya, yb, p):
    return np.array([ya[0] - 1, yb[0] - np.exp(1 + 1j)])


def test_real_guess_with_complex_values_is_cast_with_a_warning(backend):
    # SciPy's documented rule: a complex problem needs a complex guess. With a real one the
    # complex values of bc are cast to real, with NumPy's ComplexWarning (never silently).
    with pytest.warns(np.ComplexWarning):
        res = SOLVERS[backend](exp_fun, exp_bc_complex, np.linspace(0, 1, 5), np.zeros((2, 5)))
    assert res.success and res.y.dtype == np.float64 and res.y[0, 0] == pytest.approx(1)


def complex_rate_fun_jac(x, y, p):
    return np.full((1, 1, x.size), p[0]), y.reshape(1, 1, -1)


def complex_rate_bc_jac(ya, yb, p):
    return np.array([[1], [0]]), np.array([[0], [1]]), np.zeros((2, 1))


@pytest.mark.parametrize("jacobians", JACOBIAN_CHOICES)
@pytest.mark.parametrize("backend", backends(scipy_xfail=SCIPY_COMPLEX_NEWTON))
def test_complex_parameter(backend, jacobians):
    # y' = p y, y(0) = 1, y(1) = e^(1+i): p = 1 + i. Newton from p = (1 + i)/2 needs damping.
    x = np.linspace(0, 1, 5)
    res = solve(backend, complex_rate_fun, complex_rate_bc, x, np.ones((1, 5), dtype=complex), p=[0.5 + 0.5j],
                tol=1e-6, fun_jac=complex_rate_fun_jac if jacobians[0] else None,
                bc_jac=complex_rate_bc_jac if jacobians[1] else None)
    assert res.status == 0 and res.p.dtype == np.complex128
    # K <= 10 (measured 2.4e-8 for p and 8e-8 for y, cartan; SciPy with a conjugated cost alike).
    assert abs(res.p[0] - (1 + 1j)) < 10 * 1e-6
    grid = np.linspace(0, 1, 50)
    assert np.abs(res.sol(grid)[0] - np.exp((1 + 1j) * grid)).max() < 10 * 1e-6 * np.e


def test_complex_callbacks_get_complex_arguments(backend):
    seen = set()

    def fun(x, y):
        seen.add(("fun", x.dtype.name, y.dtype.name))
        return exp_fun(x, y)

    def bc(ya, yb):
        seen.add(("bc", ya.dtype.name, yb.dtype.name))
        return exp_bc_complex(ya, yb)

    res = solve(backend, fun, bc, np.linspace(0, 1, 5), np.zeros((2, 5), dtype=complex))
    assert res.success
    assert seen == {("fun", "float64", "complex128"), ("bc", "complex128", "complex128")}


# --- How the callbacks are called ------------------------------------------------------------------------

def recording(f, calls):
    def wrapped(*args):
        calls.append(tuple(np.shape(a) for a in args))
        return f(*args)
    return wrapped


def test_fun_is_called_on_the_whole_mesh(backend):
    calls = []
    x = np.linspace(0, 1, 5)
    res = solve(backend, recording(exp_fun, calls), exp_bc, x, np.zeros((2, 5)))
    assert res.success
    assert ((5,), (2, 5)) in calls  # the nodes at once
    assert ((4,), (2, 4)) in calls  # the midpoints at once


def test_fun_jac_is_called_on_the_whole_mesh(backend):
    calls = []
    x = np.linspace(0, 1, 5)
    res = solve(backend, exp_fun, exp_bc, x, np.zeros((2, 5)), fun_jac=recording(exp_fun_jac, calls))
    assert res.success
    assert ((5,), (2, 5)) in calls and ((4,), (2, 4)) in calls


def test_fun_gets_x_and_y_with_matching_columns(backend):
    # Whatever the batching, x has shape (m,), y (n, m) and p (k,), and fun_jac likewise.
    calls, jac_calls = [], []
    x = np.linspace(0, np.pi, 5)
    res = solve(backend, recording(sl_fun, calls), sl_bc, x, np.ones((2, 5)), p=[0.5],
                fun_jac=recording(sl_fun_jac, jac_calls))
    assert res.success
    for shapes in calls + jac_calls:
        (m,), (n, m2), (k,) = shapes
        assert n == 2 and m2 == m >= 1 and k == 1


def test_bc_and_bc_jac_get_the_end_values(backend):
    calls, jac_calls = [], []
    x = np.linspace(0, np.pi, 5)
    res = solve(backend, sl_fun, recording(sl_bc, calls), x, np.ones((2, 5)), p=[0.5],
                bc_jac=recording(sl_bc_jac, jac_calls))
    assert res.success
    assert set(calls) == set(jac_calls) == {((2,), (2,), (1,))}


class CallbackError(Exception):
    pass


@pytest.mark.parametrize("where", ["fun", "bc", "fun_jac", "bc_jac"])
def test_an_exception_in_a_callback_propagates(backend, where):
    def fail(*args):
        raise CallbackError(where)

    funcs = dict(fun=exp_fun, bc=exp_bc, fun_jac=exp_fun_jac, bc_jac=exp_bc_jac)
    funcs[where] = fail
    with pytest.raises(CallbackError, match=where):
        solve(backend, funcs["fun"], funcs["bc"], np.linspace(0, 1, 5), np.zeros((2, 5)), fun_jac=funcs["fun_jac"],
              bc_jac=funcs["bc_jac"])


# --- Validation -----------------------------------------------------------------------------------------

@pytest.mark.parametrize("kwargs, message", [
    (dict(x=[0, 1, 0.5]), r"^`x` must be strictly increasing\.$"),
    (dict(x=np.zeros((5, 1))), r"^`x` must be 1 dimensional\.$"),
    (dict(y=np.zeros((2, 4))), r"^`y` is expected to have 5 columns, but actually has 4\.$"),
    (dict(y=np.zeros(5)), r"^`y` must be 2 dimensional\.$"),
    (dict(p=[[1.0]]), r"^`p` must be 1 dimensional\.$"),
    # SciPy fails on these later, in the PPoly: "at least 2 breakpoints", "strictly increasing or decreasing".
    (dict(x=[0.0], y=np.zeros((2, 1))), r"2 (breakpoints|nodes)"),
    (dict(x=[0.0, np.nan, 1.0], y=np.zeros((2, 3))), r"`x` must be"),
    # SciPy calls fun on the whole mesh first (m = 5), cartan at the first node (m = 1).
    (dict(fun=lambda x, y: np.zeros(3)),
     r"^`fun` return is expected to have shape \(2, [15]\), but actually has \(3,\)\.$"),
    (dict(bc=lambda ya, yb: np.zeros(3)), r"^`bc` return is expected to have shape \(2,\), but actually has \(3,\)\.$"),
    # With parameters, bc must return n + k values.
    (dict(fun=lambda x, y, p: exp_fun(x, y), bc=lambda ya, yb, p: exp_bc(ya, yb), p=[1.0]),
     r"^`bc` return is expected to have shape \(3,\), but actually has \(2,\)\.$"),
])
def test_bad_arguments_raise_scipys_value_errors(backend, kwargs, message):
    args = dict(fun=exp_fun, bc=exp_bc, x=np.linspace(0, 1, 5), y=np.zeros((2, 5)))
    args.update(kwargs)
    with pytest.raises(ValueError, match=message):
        solve(backend, **args)


def test_scipy_version_is_the_one_the_contract_was_read_from():
    # The contract above is SciPy 1.10's (Debian's python3-scipy); a newer SciPy may change it.
    assert scipy.__version__.startswith("1.10."), scipy.__version__
