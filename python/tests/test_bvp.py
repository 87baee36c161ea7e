"""Collocation from Python: cartan.solve_bvp against scipy.integrate.solve_bvp and closed forms,
its failure statuses and errors, what its extras (linear_solver, max_newton_iterations, fd_step)
do, and cartan.solve(method="collocation") against the CLI and the shooting solvers.

Tolerances (theory; measured values are printed with pytest -s):
* solve_bvp vs a closed form: both cartan and SciPy control the relative RMS residual of the
  collocation cubic per interval (<= tol); the global error is that residual propagated by the
  problem's Green's function, of size tol times an O(1) constant here. We require 10 tol.
* Order 4: on a uniform mesh frozen by max_nodes = m (refinement is refused, Newton still
  converges to the tolerance 1e-12), the nodal error of the three-stage Lobatto IIIA scheme is
  O(h^4); halving h divides it by 16, log2 ratio 4 within 0.3 (the asymptotic constant).
* Mathieu eigenvalue: at tol 1e-6 both cartan and SciPy give the eigenvalue to about tol / 10
  relative (measured: cartan 4.6e-9 from scipy.special.mathieu_a); we require 1e-7 against both,
  and the eigenfunctions (|y| <= 4, |y'| <= 20) within 1e-5.
* Module vs CLI: the same C++ code on the same inputs; the JSON round trip keeps 17 digits: 1e-10
  (measured: 0, bit for bit).
* Collocation vs shooting: collocation at tol 1e-10 is the continuous solution to ~1e-11; the
  order-2 scheme differs from it by C h^2, so the difference shrinks by 4 when N doubles: log2
  ratio 2 within 0.25, as tests/kernels/lie_group/test_collocation_system.cpp.
"""
import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest
import scipy.integrate
import scipy.special

import cartan

ROOT = Path(__file__).resolve().parents[2]
CARTAN_BIN = os.environ.get("CARTAN_BIN", str(ROOT / "build" / "cartan"))


# y'' = 3/2 y^2, y(0) = 4, y(1) = 1 (Ascher, Mattheij & Russell): one solution is 4 / (1 + x)^2.
def ascher_fun(x, y):
    return np.vstack((y[1], 1.5 * y[0] ** 2))


def ascher_bc(ya, yb):
    return np.array([ya[0] - 4, yb[0] - 1])


def ascher_exact(x):
    return np.vstack((4 / (1 + x) ** 2, -8 / (1 + x) ** 3))


def ascher_guess(m):
    x = np.linspace(0, 1, m)
    return x, np.vstack((4 - 3 * x, -3 * np.ones_like(x)))


def test_closed_form_and_scipy_agree():
    x, y = ascher_guess(5)
    tol = 1e-6
    r = cartan.solve_bvp(ascher_fun, ascher_bc, x, y, tol=tol)
    s = scipy.integrate.solve_bvp(ascher_fun, ascher_bc, x, y, tol=tol)
    assert r.success and r.status == 0 and s.success
    grid = np.linspace(0, 1, 101)
    error = np.abs(r.sol(grid) - ascher_exact(grid)).max()
    versus_scipy = np.abs(r.sol(grid) - s.sol(grid)).max()
    print(f"\nAscher: cartan error {error:.2e}, SciPy error {np.abs(s.sol(grid) - ascher_exact(grid)).max():.2e}, "
          f"difference {versus_scipy:.2e}; meshes {r.x.size} / {s.x.size}")
    assert error < 10 * tol and versus_scipy < 20 * tol
    assert r.y.shape == (2, r.x.size) and r.yp.shape == r.y.shape and r.rms_residuals.shape == (r.x.size - 1,)
    assert r.p is None and r.niter >= 1 and r.rms_residuals.max() <= tol
    np.testing.assert_allclose(r.yp, ascher_fun(r.x, r.y), rtol=1e-14)  # yp = f at the nodes
    np.testing.assert_allclose(r.sol(r.x), r.y, atol=1e-14)  # the dense output interpolates the nodes
    np.testing.assert_allclose(r.sol(0.5), r.sol(np.array([0.5]))[:, 0], atol=0)  # scalar -> (n,)
    np.testing.assert_allclose(r.sol(grid, 1), ascher_fun(grid, r.sol(grid)), atol=20 * tol)  # S' ~ f


def test_fourth_order_on_frozen_meshes():
    errors = []
    for m in (11, 21, 41):
        x, y = ascher_guess(m)
        r = cartan.solve_bvp(ascher_fun, ascher_bc, x, y, tol=1e-12, max_nodes=m)
        assert r.status in (0, 1) and r.x.size == m, r.message  # the mesh is not refined
        errors.append(np.abs(r.y - ascher_exact(r.x)).max())
    rates = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    print(f"\nnodal errors {errors}, log2 ratios {rates}")
    assert np.all(np.abs(rates - 4) < 0.3)


# The Mathieu equation y'' + (k - 2 q cos 2x) y = 0 on [0, pi], y'(0) = y'(pi) = 0, normalised by
# y(0) = 1; k is the unknown parameter (the eigenvalue a_4(q), from the guess cos 4x).
Q = 5.0


def mathieu_fun(x, y, p):
    return np.vstack((y[1], -(p[0] - 2 * Q * np.cos(2 * x)) * y[0]))


def mathieu_bc(ya, yb, p):
    return np.array([ya[0] - 1, ya[1], yb[1]])


def mathieu_fun_jac(x, y, p):
    df_dy = np.array([[np.zeros_like(x), np.ones_like(x)], [-(p[0] - 2 * Q * np.cos(2 * x)), np.zeros_like(x)]])
    df_dp = np.array([[np.zeros_like(x)], [-y[0]]])
    return df_dy, df_dp


def mathieu_bc_jac(ya, yb, p):
    dya = np.array([[1.0, 0], [0, 1], [0, 0]])
    dyb = np.array([[0.0, 0], [0, 0], [0, 1]])
    return dya, dyb, np.zeros((3, 1))


@pytest.mark.parametrize("jacobians", [False, True])
def test_mathieu_eigenvalue(jacobians):
    x = np.linspace(0, np.pi, 5)
    y = np.vstack((np.cos(4 * x), -4 * np.sin(4 * x)))
    extra = dict(fun_jac=mathieu_fun_jac, bc_jac=mathieu_bc_jac) if jacobians else {}
    r = cartan.solve_bvp(mathieu_fun, mathieu_bc, x, y, p=[15], tol=1e-6, **extra)
    s = scipy.integrate.solve_bvp(mathieu_fun, mathieu_bc, x, y, p=[15], tol=1e-6, **extra)
    exact = scipy.special.mathieu_a(4, Q)
    print(f"\nMathieu a_4({Q}): cartan {r.p[0]:.12f}, SciPy {s.p[0]:.12f}, scipy.special {exact:.12f}; "
          f"fun calls {r.rhs_evaluations}")
    assert r.success, r.message
    assert r.p.shape == (1,)
    assert r.p[0] == pytest.approx(exact, rel=1e-7) and r.p[0] == pytest.approx(s.p[0], rel=1e-7)
    grid = np.linspace(0, np.pi, 50)
    np.testing.assert_allclose(r.sol(grid), s.sol(grid), atol=1e-5)


def test_analytic_jacobians_save_calls_but_not_accuracy():
    x = np.linspace(0, np.pi, 5)
    y = np.vstack((np.cos(4 * x), -4 * np.sin(4 * x)))
    fd = cartan.solve_bvp(mathieu_fun, mathieu_bc, x, y, p=[15], tol=1e-6)
    exact = cartan.solve_bvp(mathieu_fun, mathieu_bc, x, y, p=[15], tol=1e-6, fun_jac=mathieu_fun_jac,
                             bc_jac=mathieu_bc_jac)
    assert fd.success and exact.success
    # Forward differences (error ~1e-8 relative) perturb Newton's path and so possibly the mesh,
    # not the continuous solution: both are within ~tol / 10 of the eigenvalue (see above).
    assert exact.p[0] == pytest.approx(fd.p[0], rel=1e-7)
    print(f"\nfun calls: {fd.rhs_evaluations} with forward differences, {exact.rhs_evaluations} with fun_jac")
    assert exact.rhs_evaluations < fd.rhs_evaluations


def test_functions_returning_lists_work_too():
    r = cartan.solve_bvp(lambda x, y: [y[1], 1.5 * y[0] ** 2], lambda ya, yb: [ya[0] - 4, yb[0] - 1],
                         *ascher_guess(5), tol=1e-6)
    assert r.success and np.abs(r.sol(0.25) - ascher_exact(np.array([0.25]))[:, 0]).max() < 1e-5


def test_max_nodes_exceeded_is_a_status():
    r = cartan.solve_bvp(ascher_fun, ascher_bc, *ascher_guess(5), tol=1e-10, max_nodes=8)
    assert not r.success and r.status == 1 and r.message == "The maximum number of mesh nodes is exceeded."
    assert r.x.size <= 8


def test_singular_jacobian_is_a_status():
    # y' = 0 with an unknown parameter p that neither f nor bc depends on: the collocation
    # Jacobian has a zero column for p (and y(0) = 1, y(1) = 0 are inconsistent anyway).
    r = cartan.solve_bvp(lambda x, y, p: np.zeros_like(y), lambda ya, yb, p: np.array([ya[0] - 1, yb[0]]),
                         np.linspace(0, 1, 4), np.zeros((1, 4)), p=[1.0])
    assert not r.success and r.status == 2, r.message
    assert r.message == "A singular Jacobian encountered when solving the collocation system."
    assert "singular" in r.details  # the C++ solver's own report


class CallbackError(Exception):
    pass


@pytest.mark.parametrize("where", ["fun", "bc", "fun_jac"])
def test_callback_exception_propagates(where):
    calls = {"n": 0}

    def fail_later(f):
        def wrapped(*args):
            calls["n"] += 1
            if calls["n"] > 3:
                raise CallbackError(f"raised in {where}")
            return f(*args)
        return wrapped

    fun = fail_later(ascher_fun) if where == "fun" else ascher_fun
    bc = fail_later(ascher_bc) if where == "bc" else ascher_bc
    jac = (lambda x, y: np.array([[np.zeros_like(x), np.ones_like(x)], [3 * y[0], np.zeros_like(x)]]))
    fun_jac = fail_later(jac) if where == "fun_jac" else jac
    with pytest.raises(CallbackError, match=f"raised in {where}"):
        cartan.solve_bvp(fun, bc, *ascher_guess(5), fun_jac=fun_jac)


def wrong_after_first_call(n_good):
    calls = {"n": 0}

    def fun(x, y):
        calls["n"] += 1
        return ascher_fun(x, y) if calls["n"] <= n_good else np.zeros(3)
    return fun


# SciPy's messages for what SciPy checks (python/tests/test_solve_bvp_contract.py runs them on both);
# the C++ solver's for the rest: options that SciPy does not have, and a callback's return checked
# during the solve.
@pytest.mark.parametrize("kwargs, message", [
    (dict(x=[0, 1, 1, 2]), r"^`x` must be strictly increasing\.$"),
    (dict(x=np.zeros((4, 1))), r"^`x` must be 1 dimensional\.$"),
    (dict(y=np.zeros((2, 3))), r"^`y` is expected to have 4 columns, but actually has 3\.$"),
    (dict(y=np.zeros(4)), r"^`y` must be 2 dimensional\.$"),
    (dict(p=[[1.0]]), r"^`p` must be 1 dimensional\.$"),
    (dict(verbose=3), r"^`verbose` must be in \[0, 1, 2\]\.$"),
    (dict(S=np.zeros((1, 2))), r"^`S` is expected to have shape \(2, 2\), but actually has \(1, 2\)$"),
    (dict(fun=lambda x, y: np.zeros(3)),
     r"^`fun` return is expected to have shape \(2, 1\), but actually has \(3,\)\.$"),
    (dict(bc=lambda ya, yb: np.zeros(1)), r"^`bc` return is expected to have shape \(2,\), but actually has \(1,\)\.$"),
    (dict(fun=wrong_after_first_call(1)),
     r"solve_bvp: fun: return value = array of shape \(3,\) must have shape \(2, \d+\)"),
    (dict(bc_jac=lambda ya, yb: np.eye(3)), r"bc_jac: return value = .* must be a sequence of 2 arrays"),
    (dict(x=[0, 0.5, 1, np.inf]), r"^`x` must be finite\.$"),  # SciPy: status 2 (solves towards inf)
    (dict(linear_solver="qr"), r"linear_solver = \"qr\" is not one of"),
    (dict(fd_step=0.0), r"fd_step = 0 must be positive"),
    (dict(max_newton_iterations=0), r"max_newton_iterations = 0 must be at least 1"),
])
def test_bad_arguments_raise_value_error(kwargs, message):
    x, y = ascher_guess(4)
    args = dict(fun=ascher_fun, bc=ascher_bc, x=x, y=y)
    args.update(kwargs)
    with pytest.raises(ValueError, match=message):
        cartan.solve_bvp(**args)


def test_sol_is_the_cpp_dense_output():
    # The PPoly is built from the final mesh's x, y and yp = f(x, y) (SciPy's create_spline); the
    # C++ solver's dense output (the binding's CubicHermite) is the same C^1 cubic: both agree to
    # rounding (the PPoly's monomial coefficients cost a few ulps of |y| + h |y'|).
    d = cartan._cartan._solve_bvp(ascher_fun, ascher_bc, *ascher_guess(5), None, None, None, 1e-6, 1000, None, 20,
                                  40, 2.0 ** -26, "block-lu")
    r = cartan.solve_bvp(ascher_fun, ascher_bc, d["x"], d["y"], tol=1e-6)
    assert r.success and r.niter == 1 and np.array_equal(r.x, d["x"])  # already converged on that mesh
    grid = np.linspace(0, 1, 1001)
    np.testing.assert_allclose(r.sol(grid), d["sol"](grid), rtol=0, atol=1e-13)
    np.testing.assert_allclose(r.sol(grid, 1), d["sol"](grid, 1), rtol=0, atol=1e-11)


def test_cartan_counters_are_kept():
    r = cartan.solve_bvp(ascher_fun, ascher_bc, *ascher_guess(5), tol=1e-6)
    assert isinstance(r, cartan.BvpResult)
    for key in ("newton_iterations", "jacobian_evaluations", "rhs_evaluations"):
        assert isinstance(r[key], int) and r[key] > 0, key
    assert r.max_rms_residual == r.rms_residuals.max() <= 1e-6 and r.max_bc_residual <= 1e-6
    assert r.solve_time > 0 and isinstance(r.details, str) and r.details.startswith("converged")


def test_the_callers_guess_is_not_modified():
    # SciPy's S projection (y[:, 0] = B y[:, 0]) writes into a float guess passed to it; cartan copies.
    x = np.linspace(0, 1, 10)
    y = np.vstack((np.full(10, 0.9), np.full(10, 0.5)))  # y2(0) = 0.5 violates S y(a) = 0
    before = y.copy()
    r = cartan.solve_bvp(lambda x, y: np.vstack((y[1], -y[0] ** 5)),
                         lambda ya, yb: np.array([ya[1], yb[0] - 0.75 ** 0.5]), x, y, S=np.array([[0, 0], [0, -2]]))
    assert r.success and np.array_equal(y, before)


def test_complex_problem_needs_no_complex_derivative_with_differences():
    # y' = conj(y) is not complex differentiable: SciPy's complex differences assume it is; cartan's
    # real system of (Re y, Im y) = (u, v), u' = u, v' = -v, is differentiated as it is.
    x = np.linspace(0, 1, 5)
    r = cartan.solve_bvp(lambda x, y: np.conj(y), lambda ya, yb: np.array([ya[0] - (1 + 1j)]), x,
                         np.ones((1, 5), dtype=complex), tol=1e-6)
    grid = np.linspace(0, 1, 11)
    assert r.success and np.abs(r.sol(grid)[0] - (np.exp(grid) + 1j * np.exp(-grid))).max() < 1e-5


# --- The keyword-only extras: linear_solver, max_newton_iterations, fd_step ---------------------

# y''' = y + sin x, periodic on [0, 2 pi]: y = (cos x - sin x) / 2 is the only periodic solution
# (the roots of r^3 = 1 give no 2 pi-periodic homogeneous one). Boundary conditions coupling both
# ends, and n = 3, a state size the solver does not fix at compile time.
def periodic_fun(x, y):
    return np.vstack((y[1], y[2], y[0] + np.sin(x)))


def periodic_bc(ya, yb):
    return ya - yb


def periodic_exact(x):
    c, s = np.cos(x), np.sin(x)
    return np.vstack((c - s, -s - c, s - c)) / 2


def solve_with_each_linear_solver(*args, **kwargs):
    return [cartan.solve_bvp(*args, linear_solver=name, **kwargs) for name in ("block-lu", "sparse-lu")]


def assert_same_solve(a, b):
    # Both factorisations solve the same Newton systems, so the iterations, the meshes they refine
    # and the solution agree up to rounding (measured: 4.4e-16 at most).
    assert a.success and b.success, (a.message, b.message)
    assert (a.niter, a.newton_iterations, a.jacobian_evaluations) == (b.niter, b.newton_iterations,
                                                                       b.jacobian_evaluations)
    assert np.array_equal(a.x, b.x)
    np.testing.assert_allclose(a.y, b.y, rtol=0, atol=1e-12)
    if a.p is not None:
        np.testing.assert_allclose(a.p, b.p, rtol=1e-12)


def test_linear_solvers_give_the_same_solution_with_coupled_ends():
    x, tol = np.linspace(0, 2 * np.pi, 7), 1e-6
    block, sparse = solve_with_each_linear_solver(periodic_fun, periodic_bc, x, np.zeros((3, 7)), tol=tol)
    assert_same_solve(block, sparse)
    s = scipy.integrate.solve_bvp(periodic_fun, periodic_bc, x, np.zeros((3, 7)), tol=tol)
    grid = np.linspace(0, 2 * np.pi, 201)
    # Bounds of the module docstring: 10 tol from the closed form, so 20 tol from SciPy.
    assert np.abs(block.sol(grid) - periodic_exact(grid)).max() < 10 * tol
    assert np.abs(block.sol(grid) - s.sol(grid)).max() < 20 * tol


def test_linear_solvers_give_the_same_solution_nonlinear_and_with_a_parameter():
    tol = 1e-6
    block, sparse = solve_with_each_linear_solver(ascher_fun, ascher_bc, *ascher_guess(5), tol=tol)
    assert_same_solve(block, sparse)
    grid = np.linspace(0, 1, 101)
    assert np.abs(block.sol(grid) - ascher_exact(grid)).max() < 10 * tol
    x = np.linspace(0, np.pi, 5)
    y = np.vstack((np.cos(4 * x), -4 * np.sin(4 * x)))
    block, sparse = solve_with_each_linear_solver(mathieu_fun, mathieu_bc, x, y, p=[15], tol=tol)
    assert_same_solve(block, sparse)  # the parameter's row and column are eliminated too
    assert block.p[0] == pytest.approx(scipy.special.mathieu_a(4, Q), rel=1e-7)  # the docstring's bound


# On 101 nodes, frozen by max_nodes, the Ascher problem is solved without refinement (residuals
# below 1e-6), after several Newton iterations from the straight-line guess (the problem is
# nonlinear): a setting where the Newton iterations are all on one mesh.
FROZEN = dict(tol=1e-6, max_nodes=101)


def test_max_newton_iterations_caps_newton_on_one_mesh():
    full = cartan.solve_bvp(ascher_fun, ascher_bc, *ascher_guess(101), **FROZEN)
    needed = full.newton_iterations
    assert full.success and full.niter == 1 and needed >= 3, (full.message, needed)
    enough = cartan.solve_bvp(ascher_fun, ascher_bc, *ascher_guess(101), max_newton_iterations=needed, **FROZEN)
    assert enough.success and enough.newton_iterations == needed and np.array_equal(enough.y, full.y)
    for cap in range(1, needed):  # Newton had not converged before `needed`, so each cap is reached
        r = cartan.solve_bvp(ascher_fun, ascher_bc, *ascher_guess(101), max_newton_iterations=cap, **FROZEN)
        assert r.newton_iterations == cap, (cap, r.details)
    # One step from the straight line leaves residuals far above tol (measured 0.13): the mesh would
    # need refining, which max_nodes refuses (status 1); the C++ solver's report names the cap.
    one = cartan.solve_bvp(ascher_fun, ascher_bc, *ascher_guess(101), max_newton_iterations=1, **FROZEN)
    assert not one.success and one.status == 1 and one.max_rms_residual > 100 * FROZEN["tol"]
    assert "Newton did not converge in 1 iterations on 101 nodes" in one.details, one.details


def test_max_newton_iterations_counts_per_mesh():
    # With refinement, each mesh gets its own max_newton_iterations steps (SciPy's outer loop warm-
    # starts the next mesh), so the total may exceed the cap but not cap times the meshes.
    r = cartan.solve_bvp(ascher_fun, ascher_bc, *ascher_guess(5), tol=1e-6, max_newton_iterations=2)
    assert r.success and r.niter > 1 and r.newton_iterations <= 2 * r.niter, (r.niter, r.newton_iterations)
    assert r.newton_iterations > 2


def difference_steps(calls):
    """(j, how far row j of y moved, max(1, |y[j]|)) for each recorded call of fun that repeats an
    earlier call's x with only row j of y changed: a forward difference, which moves one component
    at every point at once (solve_bvp's docstring)."""
    found = []
    for i, (x, y) in enumerate(calls):
        for x0, y0 in calls[:i]:
            if x0.shape != x.shape or not np.array_equal(x0, x):
                continue
            rows = np.flatnonzero(np.any(y != y0, axis=1))
            if rows.size == 1:
                j = rows[0]
                found.append((j, y[j] - y0[j], np.maximum(1, np.abs(y0[j]))))
    return found


@pytest.mark.parametrize("fd_step", [2.0**-26, 2.0**-10])
def test_fd_step_is_the_relative_step_of_the_differences(fd_step):
    calls = []

    def recorded(x, y):
        calls.append((np.array(x), np.array(y)))
        return ascher_fun(x, y)

    r = cartan.solve_bvp(recorded, ascher_bc, *ascher_guess(5), tol=1e-6, fd_step=fd_step)
    assert r.success, r.message
    steps = difference_steps(calls)
    assert {j for j, _, _ in steps} == {0, 1} and len(steps) >= 2 * r.jacobian_evaluations
    for j, move, scale in steps:
        # y + step rounds by half an ulp of |y| + step <= eps/2 (1 + fd_step) max(1, |y|): relative to
        # the step, at most eps / fd_step.
        np.testing.assert_allclose(move, fd_step * scale, rtol=np.finfo(float).eps / fd_step, atol=0)


def test_fd_step_changes_newtons_path_not_the_solution():
    # d/dy0 of 3/2 y0^2 by a forward difference of step max(1, |y0|) (fd_step = 1) is 3 y0 + 3/2 |y0|
    # for |y0| >= 1: half again too large, so Newton contracts more slowly than with the default
    # (difference error ~1e-8) and needs more iterations to the same solution of the collocation
    # equations. Both stop at collocation residuals <= tol / 20 h (1 + |f|) per interval, which the
    # problem's O(1) Green's function turns into nodal differences below tol (measured 1.5e-8).
    default = cartan.solve_bvp(ascher_fun, ascher_bc, *ascher_guess(101), **FROZEN)
    coarse = cartan.solve_bvp(ascher_fun, ascher_bc, *ascher_guess(101), fd_step=1.0, **FROZEN)
    assert default.success and coarse.success and np.array_equal(default.x, coarse.x)
    print(f"\nNewton iterations: {default.newton_iterations} with the default fd_step, "
          f"{coarse.newton_iterations} with 1")
    assert coarse.newton_iterations > default.newton_iterations
    assert np.abs(coarse.y - default.y).max() < FROZEN["tol"]


def test_fd_step_is_unused_with_both_jacobians():
    def fun_jac(x, y):
        return np.array([[np.zeros_like(x), np.ones_like(x)], [3 * y[0], np.zeros_like(x)]])

    def bc_jac(ya, yb):
        return np.array([[1.0, 0], [0, 0]]), np.array([[0.0, 0], [1, 0]])

    a, b = (cartan.solve_bvp(ascher_fun, ascher_bc, *ascher_guess(5), tol=1e-6, fun_jac=fun_jac, bc_jac=bc_jac,
                             fd_step=step) for step in (2.0**-26, 1.0))
    assert a.success and np.array_equal(a.x, b.x) and np.array_equal(a.y, b.y)
    assert (a.newton_iterations, a.rhs_evaluations) == (b.newton_iterations, b.rhs_evaluations)


# --- The transported problem by collocation (cartan.solve(method="collocation")) ---------------

H3 = dict(lam=0.5, T=1.0, g0=[0.3, -0.2, 0.5], gT=[1.0, 0.5, 0.8])


def cli(*args):
    out = subprocess.run([CARTAN_BIN, "solve", *args], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout)


@pytest.mark.parametrize("samples", [0, 11])
def test_h3_collocation_matches_cli(samples):
    d = cli("--group", "heisenberg", "--model", "oscillator", "--method", "collocation", "--lambda", "0.5", "--T",
            "1", "--N", "20", "--g0", "0.3,-0.2,0.5", "--gT", "1,0.5,0.8", "--samples", str(samples))
    r = cartan.solve(cartan.H3Oscillator(), N=20, method="collocation", samples=samples, **H3)
    assert r.success and r.status == d["status"] == "converged"
    assert (r.method, r.order, r.branch) == (d["method"], d["order"], d["branch"]) == (r.method, 4, r.branch)
    assert (r.outer_iterations, r.inner_iterations, r.sweeps) == tuple(d["iterations"][k] for k in ("outer", "inner", "sweeps"))
    assert r.t.size == (d["mesh_size"] if samples == 0 else samples)
    worst = max(np.abs(getattr(r, key) - np.array(d[key])).max() for key in ("t", "g", "v", "mu", "xi"))
    print(f"\nH3 module vs CLI (samples={samples}): {worst:.1e}")
    assert worst <= 1e-10
    assert r.terminal_error == pytest.approx(d["terminal_error"], abs=1e-12)
    assert r.xi_terminal == pytest.approx(d["xi_terminal"], abs=1e-12)


def transported_difference(c, s):
    return max(np.abs(c.g - s.g).max(), np.abs(c.v - s.v).max(), np.abs(c.xi - s.xi).max())


def order_against_shooting(model, N_values=(50, 100, 200), **problem):
    differences = []
    for N in N_values:
        c = cartan.solve(model, N=N, method="collocation", tol=1e-10, samples=N + 1, **problem)
        s = cartan.solve(model, N=N, order=2, tol=1e-13, **problem)
        assert c.success and s.success, (c.message, s.message)
        np.testing.assert_allclose(c.t, s.t, atol=1e-14)
        differences.append(transported_difference(c, s))
    rates = np.log2(np.array(differences[:-1]) / np.array(differences[1:]))
    print(f"\n{type(model).__name__} {problem.get('lam')}: differences {differences}, log2 ratios {rates}")
    return rates


def test_h3_collocation_matches_shooting_at_the_schemes_order():
    rates = order_against_shooting(cartan.H3Oscillator(), **H3)
    assert np.all(np.abs(rates - 2) < 0.25)


A0, AT = np.array([-1.0, -1, -1]), np.array([0.9, 1.0, 1.0])


@pytest.mark.parametrize("lam", [0.0, 0.5, 1.0])
def test_so3_free_body_collocation_matches_shooting_at_the_schemes_order(lam):
    gT = cartan.SO3.minimal_rotation(A0, AT)
    rates = order_against_shooting(cartan.RigidBody([2.0, 3.0, 4.0]), lam=lam, T=5.0, gT=gT)
    assert np.all(np.abs(rates - 2) < 0.25)


def test_group_defect_is_reported_as_by_the_cli():
    # SO(3) collocation reports max |g^T g - I| over its mesh (the CLI's "group_defect"): the
    # collocation polynomial of g leaves the group by O(h^4) between renormalisations, so tiny;
    # H3 has no such defect (NaN); shooting does not report one (None).
    gT = cartan.SO3.minimal_rotation(A0, AT)
    c = cartan.solve(cartan.RigidBody([2.0, 3.0, 4.0]), lam=0.5, T=2.0, N=40, gT=gT, method="collocation", tol=1e-10)
    d = cli("--method", "collocation", "--lambda", "0.5", "--T", "2", "--N", "40", "--a0=-1,-1,-1", "--aT", "0.9,1,1",
            "--tol", "1e-10")
    assert c.success and c.group_defect < 1e-9
    assert c.group_defect == pytest.approx(d["group_defect"], rel=1e-6, abs=1e-15)
    assert np.isnan(cartan.solve(cartan.H3Oscillator(), N=20, method="collocation", **H3).group_defect)
    assert cartan.solve(cartan.RigidBody([2.0, 3.0, 4.0]), lam=0.5, T=2.0, N=40, gT=gT).group_defect is None


def test_so3_oscillator_collocation_matches_shooting_at_the_schemes_order():
    gT = cartan.SO3.minimal_rotation(np.array([-0.7, -1.0, -0.7]), np.array([0.8, 0.8, 1.0]))
    rates = order_against_shooting(cartan.SO3Oscillator([2.0, 3.0, 4.0]), lam=0.5, T=3.0, gT=gT)
    assert np.all(np.abs(rates - 2) < 0.25)


def test_collocation_options_and_refusals():
    with pytest.raises(ValueError, match="samples"):
        cartan.solve(cartan.H3Oscillator(), N=10, method="collocation", samples=1, **H3)
    with pytest.raises(ValueError, match="samples"):  # not an option of the shooting methods
        cartan.solve(cartan.H3Oscillator(), N=10, samples=5, **H3)

    class PyModel:  # a Python Lagrangian: collocation needs a built-in natural one
        group = cartan.Heisenberg

        def value(self, t, g, v): return 0.5 * v @ v
        def momentum(self, t, g, v): return v
        def group_gradient(self, t, g, v): return np.zeros(3)
        def velocity(self, t, g, mu): return mu

    with pytest.raises(ValueError, match="collocation"):
        cartan.solve(PyModel(), N=10, method="collocation", **H3)
    r = cartan.solve(cartan.H3Oscillator(), N=4, method="collocation", tol=1e-12, max_nodes=6, **H3)
    assert not r.success and r.status == "max-nodes-exceeded", r.message
