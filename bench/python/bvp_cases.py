"""The problems of bench/compare_solve_bvp.py (cartan.solve_bvp against scipy.integrate.solve_bvp,
issue 14): published two-point boundary-value problems in scipy.integrate.solve_bvp's conventions,
each with a vectorised fun (x (m,), y (n, m) -> (n, m)), its bc, a guess, a tolerance and, where
natural, fun_jac and bc_jac. Does not import cartan (test_bvp_cases.py checks the definitions
against SciPy).

Sources: SciPy's own tests (scipy/integrate/tests/test_bvp.py, SciPy 1.10: exp, Sturm-Liouville
with a parameter, Emden with the singular term S, the shock layer, nonlinear (Butler-Volmer)
boundary conditions, the big system, the complex problem) and the contract suite
python/tests/test_solve_bvp_contract.py (Ascher, Mattheij & Russell's y'' = 3/2 y^2, Bratu's two
branches and Bratu with its eigenvalue unknown, the Mathieu eigenvalue). The Jacobians not given
there are written here. One problem is new: Bratu's equation on the unit square, discretised
across the strip by second differences on L lines (the method of lines: a coupled nonlinear system
of 2 L components).

A case is a dict: name, fun, bc, x, y (the guess), p (None or a list), S (None or (n, n)),
fun_jac, bc_jac (None or functions), tol, max_nodes, exact (None or x -> (n, m), the solution
where known), p_exact (None or a list) and exact_atol (how close SciPy's own tests or the
contract suite ask it to be: K tol with their K).
"""
import numpy as np
from scipy.optimize import brentq
from scipy.special import erf, mathieu_a


# --- exp: y'' = y, y(0) = 1, y(1) = 0 (SciPy) ---------------------------------------------------

def exp_fun(x, y):
    return np.vstack((y[1], y[0]))


def exp_fun_jac(x, y):
    df_dy = np.empty((2, 2, x.shape[0]))
    df_dy[0, 0] = 0
    df_dy[0, 1] = 1
    df_dy[1, 0] = 1
    df_dy[1, 1] = 0
    return df_dy


def exp_bc(ya, yb):
    return np.hstack((ya[0] - 1, yb[0]))


def exp_bc_complex(ya, yb):
    return np.hstack((ya[0] - 1 - 1j, yb[0]))


def exp_bc_jac(ya, yb):
    return np.array([[1, 0], [0, 0]]), np.array([[0, 0], [1, 0]])


def exp_exact(x):
    c = 1 - np.exp(-2)
    return np.vstack(((np.exp(-x) - np.exp(x - 2)) / c, (-np.exp(-x) - np.exp(x - 2)) / c))


# --- Ascher, Mattheij & Russell: y'' = 3/2 y^2, y(0) = 4, y(1) = 1 (contract suite) ---------------

def ascher_fun(x, y):
    return np.vstack((y[1], 1.5 * y[0] ** 2))


def ascher_fun_jac(x, y):
    df_dy = np.zeros((2, 2, x.shape[0]))
    df_dy[0, 1] = 1
    df_dy[1, 0] = 3 * y[0]
    return df_dy


def ascher_bc(ya, yb):
    return np.array([ya[0] - 4, yb[0] - 1])


def ascher_bc_jac(ya, yb):
    return np.array([[1.0, 0], [0, 0]]), np.array([[0, 0], [1.0, 0]])


def ascher_exact(x):
    return np.vstack((4 / (1 + x) ** 2, -8 / (1 + x) ** 3))


# --- Bratu: y'' + exp(y) = 0, y(0) = y(1) = 0, two branches (contract suite) -----------------------

def bratu_theta(branch):
    """theta = sqrt(2) cosh(theta / 4): the lower (0) and upper (1) branch at lam = 1."""
    return [brentq(lambda t: t - np.sqrt(2) * np.cosh(t / 4), lo, hi) for lo, hi in ((0, 4), (4, 20))][branch]


def bratu_exact_for(theta):
    def exact(x):
        u = (x - 0.5) * theta / 2
        return np.vstack((-2 * np.log(np.cosh(u) / np.cosh(theta / 4)), -theta * np.tanh(u)))
    return exact


def bratu_fun(x, y):
    return np.vstack((y[1], -np.exp(y[0])))


def bratu_fun_jac(x, y):
    df_dy = np.zeros((2, 2, x.shape[0]))
    df_dy[0, 1] = 1
    df_dy[1, 0] = -np.exp(y[0])
    return df_dy


def bratu_bc(ya, yb):
    return np.array([ya[0], yb[0]])


def bratu_bc_jac(ya, yb):
    return np.array([[1.0, 0], [0, 0]]), np.array([[0, 0], [1.0, 0]])


# Bratu with lam unknown and y'(0) = theta tanh(theta / 4) given: lam = theta^2 / (2 cosh^2(theta / 4)).
BRATU_THETA = 2.0


def bratu_p_fun(x, y, p):
    return np.vstack((y[1], -p[0] * np.exp(y[0])))


def bratu_p_fun_jac(x, y, p):
    m = x.shape[0]
    df_dy = np.zeros((2, 2, m))
    df_dy[0, 1] = 1
    df_dy[1, 0] = -p[0] * np.exp(y[0])
    df_dp = np.zeros((2, 1, m))
    df_dp[1, 0] = -np.exp(y[0])
    return df_dy, df_dp


def bratu_p_bc(ya, yb, p):
    return np.array([ya[0], yb[0], ya[1] - BRATU_THETA * np.tanh(BRATU_THETA / 4)])


def bratu_p_bc_jac(ya, yb, p):
    dya = np.array([[1.0, 0], [0, 0], [0, 1]])
    dyb = np.array([[0, 0], [1.0, 0], [0, 0]])
    return dya, dyb, np.zeros((3, 1))


# --- Sturm-Liouville: y'' + p^2 y = 0, y(0) = y(pi) = 0, y'(0) = p (SciPy) ---------------------------

def sl_fun(x, y, p):
    return np.vstack((y[1], -p[0] ** 2 * y[0]))


def sl_fun_jac(x, y, p):
    n, m = y.shape
    df_dy = np.empty((n, 2, m))
    df_dy[0, 0] = 0
    df_dy[0, 1] = 1
    df_dy[1, 0] = -p[0] ** 2
    df_dy[1, 1] = 0
    df_dp = np.empty((n, 1, m))
    df_dp[0, 0] = 0
    df_dp[1, 0] = -2 * p[0] * y[0]
    return df_dy, df_dp


def sl_bc(ya, yb, p):
    return np.hstack((ya[0], yb[0], ya[1] - p[0]))


def sl_bc_jac(ya, yb, p):
    dbc_dya = np.zeros((3, 2))
    dbc_dya[0, 0] = 1
    dbc_dya[2, 1] = 1
    dbc_dyb = np.zeros((3, 2))
    dbc_dyb[1, 0] = 1
    dbc_dp = np.zeros((3, 1))
    dbc_dp[2, 0] = -1
    return dbc_dya, dbc_dyb, dbc_dp


def sl_exact(x):
    return np.vstack((np.sin(x), np.cos(x)))


# --- Mathieu: y'' + (k - 2 q cos 2x) y = 0, y'(0) = y'(pi) = 0, y(0) = 1; k = a_4(q) (contract suite)

MATHIEU_Q = 5.0


def mathieu_fun(x, y, p):
    return np.vstack((y[1], -(p[0] - 2 * MATHIEU_Q * np.cos(2 * x)) * y[0]))


def mathieu_fun_jac(x, y, p):
    m = x.shape[0]
    df_dy = np.zeros((2, 2, m))
    df_dy[0, 1] = 1
    df_dy[1, 0] = -(p[0] - 2 * MATHIEU_Q * np.cos(2 * x))
    df_dp = np.zeros((2, 1, m))
    df_dp[1, 0] = -y[0]
    return df_dy, df_dp


def mathieu_bc(ya, yb, p):
    return np.array([ya[0] - 1, ya[1], yb[1]])


def mathieu_bc_jac(ya, yb, p):
    return np.array([[1.0, 0], [0, 1], [0, 0]]), np.array([[0, 0], [0, 0], [0, 1.0]]), np.zeros((3, 1))


# --- Emden: y'' + 2/x y' = -y^5, y'(0) = 0, y(1) = sqrt(3/4), as y' = S y / x + f (SciPy) -----------

EMDEN_S = np.array([[0.0, 0], [0, -2]])


def emden_fun(x, y):
    return np.vstack((y[1], -y[0] ** 5))


def emden_fun_jac(x, y):
    df_dy = np.empty((2, 2, x.shape[0]))
    df_dy[0, 0] = 0
    df_dy[0, 1] = 1
    df_dy[1, 0] = -5 * y[0] ** 4
    df_dy[1, 1] = 0
    return df_dy


def emden_bc(ya, yb):
    return np.array([ya[1], yb[0] - (3 / 4) ** 0.5])


def emden_bc_jac(ya, yb):
    return np.array([[0, 1.0], [0, 0]]), np.array([[0, 0], [1.0, 0]])


def emden_exact(x):
    return np.vstack(((1 + x ** 2 / 3) ** -0.5, -x / 3 * (1 + x ** 2 / 3) ** -1.5))


def emden_guess():
    x = np.linspace(0, 1, 10)
    y = np.empty((2, 10))
    y[0] = (3 / 4) ** 0.5
    y[1] = 1e-4
    return x, y


# --- The shock layer: eps y'' + x y' = -eps pi^2 cos(pi x) - pi x sin(pi x), y(-1) = -2, y(1) = 0 (SciPy)

SHOCK_EPS = 1e-3


def shock_fun(x, y):
    return np.vstack((y[1], -(x * y[1] + SHOCK_EPS * np.pi ** 2 * np.cos(np.pi * x) +
                              np.pi * x * np.sin(np.pi * x)) / SHOCK_EPS))


def shock_fun_jac(x, y):
    df_dy = np.zeros((2, 2, x.shape[0]))
    df_dy[0, 1] = 1
    df_dy[1, 1] = -x / SHOCK_EPS
    return df_dy


def shock_bc(ya, yb):
    return np.array([ya[0] + 2, yb[0]])


def shock_bc_jac(ya, yb):
    return np.array([[1.0, 0], [0, 0]]), np.array([[0, 0], [1.0, 0]])


def shock_exact(x):
    k = np.sqrt(2 * SHOCK_EPS)
    return np.vstack((np.cos(np.pi * x) + erf(x / k) / erf(1 / k),
                      -np.pi * np.sin(np.pi * x) + 2 / (k * np.sqrt(np.pi)) * np.exp(-(x / k) ** 2) / erf(1 / k)))


# --- Nonlinear boundary conditions: Laplace's equation with Butler-Volmer kinetics at both ends (SciPy)

BV_KAPPA, BV_IOA, BV_IOC, BV_V, BV_F = 1.64, 0.01, 1.0e-4, 0.5, 38.9


def nonlin_bc_fun(x, y):
    return np.stack([y[1], np.zeros_like(x)])


def nonlin_bc_fun_jac(x, y):
    df_dy = np.zeros((2, 2, x.shape[0]))
    df_dy[0, 1] = 1
    return df_dy


def nonlin_bc_bc(ya, yb):
    phiA, phipA = ya
    phiC, phipC = yb
    hA = 0.0 - phiA - 0.0  # at the anode
    iA = BV_IOA * (np.exp(BV_F * hA) - np.exp(-BV_F * hA))
    hC = BV_V - phiC - 1.0  # at the cathode
    iC = BV_IOC * (np.exp(BV_F * hC) - np.exp(-BV_F * hC))
    return np.array([iA + BV_KAPPA * phipA, iC - BV_KAPPA * phipC])


def nonlin_bc_bc_jac(ya, yb):
    hA = -ya[0]
    hC = BV_V - yb[0] - 1.0
    diA = -BV_IOA * BV_F * (np.exp(BV_F * hA) + np.exp(-BV_F * hA))  # d iA / d phiA
    diC = -BV_IOC * BV_F * (np.exp(BV_F * hC) + np.exp(-BV_F * hC))  # d iC / d phiC
    return np.array([[diA, BV_KAPPA], [0, 0]]), np.array([[0, 0], [diC, -BV_KAPPA]])


def nonlin_bc_exact(x):
    return np.vstack((-0.13426436116763119 - 1.1308709 * x, np.full_like(x, -1.1308709)))


# --- SciPy's big problem: 2 N components, y_{2i}'' = 0, y_{2i}(0) = 0, y_{2i}(1) = 1 (SciPy, N = 30)

BIG_N = 30


def big_fun(x, y):
    f = np.zeros_like(y)
    f[::2] = y[1::2]
    return f


def big_fun_jac(x, y):
    n, m = y.shape
    df_dy = np.zeros((n, n, m))
    df_dy[range(0, n, 2), range(1, n, 2)] = 1
    return df_dy


def big_bc(ya, yb):
    return np.hstack((ya[::2], yb[::2] - 1))


def big_bc_jac(ya, yb):
    n = ya.shape[0]
    dya, dyb = np.zeros((n, n)), np.zeros((n, n))
    dya[range(n // 2), range(0, n, 2)] = 1
    dyb[range(n // 2, n), range(0, n, 2)] = 1
    return dya, dyb


def big_exact(x):
    y = np.ones((2 * BIG_N, x.size))
    y[::2] = x
    return y


# --- Bratu on the unit square, across the strip by the method of lines ----------------------------------
# u_xx + u_zz + lam exp(u) = 0 on (0, 1)^2, u = 0 on the boundary; u_zz by second differences on L
# interior lines z_j = j / (L + 1): y = (u_1..u_L, u_1'..u_L'), a coupled system of 2 L components,
# y' = (u', -D u - lam exp(u)) with D the second-difference matrix, u(0) = u(1) = 0.

STRIP_LINES = 16
STRIP_LAMBDA = 5.0  # below the square's turning point lam* ~ 6.81: the lower branch from u = 0


def _second_differences(lines):
    h = 1.0 / (lines + 1)
    return (np.diag(np.full(lines, -2.0)) + np.diag(np.ones(lines - 1), 1) + np.diag(np.ones(lines - 1), -1)) / h ** 2


STRIP_D = _second_differences(STRIP_LINES)


def strip_fun(x, y):
    L = STRIP_LINES
    u = y[:L]
    return np.vstack((y[L:], -STRIP_D @ u - STRIP_LAMBDA * np.exp(u)))


def strip_fun_jac(x, y):
    L = STRIP_LINES
    m = x.shape[0]
    df_dy = np.zeros((2 * L, 2 * L, m))
    df_dy[range(L), range(L, 2 * L)] = 1
    df_dy[L:, :L] = -STRIP_D[:, :, np.newaxis]
    df_dy[range(L, 2 * L), range(L)] -= STRIP_LAMBDA * np.exp(y[:L])
    return df_dy


def strip_bc(ya, yb):
    L = STRIP_LINES
    return np.hstack((ya[:L], yb[:L]))


def strip_bc_jac(ya, yb):
    L = STRIP_LINES
    dya, dyb = np.zeros((2 * L, 2 * L)), np.zeros((2 * L, 2 * L))
    dya[range(L), range(L)] = 1
    dyb[range(L, 2 * L), range(L)] = 1
    return dya, dyb


# --- The cases -----------------------------------------------------------------------------------------

def _case(name, fun, bc, x, y, tol, p=None, S=None, fun_jac=None, bc_jac=None, max_nodes=1000, exact=None,
          p_exact=None, exact_atol=None):
    return dict(name=name, fun=fun, bc=bc, x=np.asarray(x, dtype=float), y=np.asarray(y), p=p, S=S,
                fun_jac=fun_jac, bc_jac=bc_jac, tol=tol, max_nodes=max_nodes, exact=exact, p_exact=p_exact,
                exact_atol=exact_atol if exact_atol is not None else 10 * tol)


def cases():
    """The benchmark's problems, in the order of its table."""
    out = []
    x5 = np.linspace(0, 1, 5)
    out.append(_case("exp, tol 1e-3 (SciPy's test)", exp_fun, exp_bc, x5, np.zeros((2, 5)), 1e-3,
                     fun_jac=exp_fun_jac, bc_jac=exp_bc_jac, exact=exp_exact, exact_atol=1e-5))
    out.append(_case("exp, tol 1e-6, no Jacobians", exp_fun, exp_bc, x5, np.zeros((2, 5)), 1e-6, exact=exp_exact))
    out.append(_case("Ascher y'' = 3/2 y^2, tol 1e-6", ascher_fun, ascher_bc, x5,
                     np.vstack((4 - 3 * x5, -3 * np.ones(5))), 1e-6, fun_jac=ascher_fun_jac, bc_jac=ascher_bc_jac,
                     exact=ascher_exact, exact_atol=80e-6))
    out.append(_case("Ascher y'' = 3/2 y^2, tol 1e-8, no Jacobians", ascher_fun, ascher_bc, x5,
                     np.vstack((4 - 3 * x5, -3 * np.ones(5))), 1e-8, exact=ascher_exact, exact_atol=80e-8))
    y_upper = np.zeros((2, 5))
    y_upper[0] = 3.0
    out.append(_case("Bratu, upper branch, tol 1e-6", bratu_fun, bratu_bc, x5, y_upper, 1e-6,
                     fun_jac=bratu_fun_jac, bc_jac=bratu_bc_jac, exact=bratu_exact_for(bratu_theta(1)),
                     exact_atol=1e-4))
    out.append(_case("Bratu, eigenvalue unknown (p), tol 1e-6", bratu_p_fun, bratu_p_bc, x5, np.zeros((2, 5)), 1e-6,
                     p=[1.0], fun_jac=bratu_p_fun_jac, bc_jac=bratu_p_bc_jac, exact=bratu_exact_for(BRATU_THETA),
                     p_exact=[BRATU_THETA ** 2 / (2 * np.cosh(BRATU_THETA / 4) ** 2)]))
    xpi = np.linspace(0, np.pi, 5)
    out.append(_case("Sturm-Liouville eigenvalue (p), tol 1e-6", sl_fun, sl_bc, xpi, np.ones((2, 5)), 1e-6, p=[0.5],
                     fun_jac=sl_fun_jac, bc_jac=sl_bc_jac, exact=sl_exact, p_exact=[1.0], exact_atol=1e-4))
    out.append(_case("Mathieu a_4(5) (p), tol 1e-6", mathieu_fun, mathieu_bc, xpi,
                     np.vstack((np.cos(4 * xpi), -4 * np.sin(4 * xpi))), 1e-6, p=[15.0], fun_jac=mathieu_fun_jac,
                     bc_jac=mathieu_bc_jac, p_exact=[float(mathieu_a(4, MATHIEU_Q))]))
    out.append(_case("Emden, singular term S, tol 1e-6", emden_fun, emden_bc, *emden_guess(), 1e-6, S=EMDEN_S,
                     fun_jac=emden_fun_jac, bc_jac=emden_bc_jac, exact=emden_exact))
    x_shock = np.linspace(-1, 1, 5)
    for tol in (1e-3, 1e-4, 1e-5, 1e-6):
        out.append(_case(f"shock layer, tol {tol:.0e}", shock_fun, shock_bc, x_shock, np.zeros((2, 5)), tol,
                         fun_jac=shock_fun_jac, bc_jac=shock_bc_jac, max_nodes=10000, exact=shock_exact,
                         exact_atol=max(1e-5, 10 * tol) * 40))  # y' reaches ~36 in the layer
    out.append(_case("shock layer, tol 1e-5, no Jacobians", shock_fun, shock_bc, x_shock, np.zeros((2, 5)), 1e-5,
                     max_nodes=10000, exact=shock_exact, exact_atol=1e-4 * 40))
    x_bv = np.linspace(0, 0.1, 5)
    out.append(_case("nonlinear bc (Butler-Volmer), tol 1e-6", nonlin_bc_fun, nonlin_bc_bc, x_bv, np.zeros((2, 5)),
                     1e-6, fun_jac=nonlin_bc_fun_jac, bc_jac=nonlin_bc_bc_jac, exact=nonlin_bc_exact,
                     exact_atol=1e-5))
    out.append(_case(f"big system, {2 * BIG_N} components (SciPy's)", big_fun, big_bc, x5, np.zeros((2 * BIG_N, 5)),
                     1e-3, fun_jac=big_fun_jac, bc_jac=big_bc_jac, exact=big_exact, exact_atol=1e-8))
    x_strip = np.linspace(0, 1, 11)
    for tol in (1e-3, 1e-6):
        out.append(_case(f"Bratu on a square, {2 * STRIP_LINES} components (lines), tol {tol:.0e}", strip_fun,
                         strip_bc, x_strip, np.zeros((2 * STRIP_LINES, 11)), tol, fun_jac=strip_fun_jac,
                         bc_jac=strip_bc_jac))
    out.append(_case("complex exp, y(0) = 1 + i, tol 1e-6", exp_fun, exp_bc_complex, x5,
                     np.zeros((2, 5), dtype=complex), 1e-6, fun_jac=exp_fun_jac, bc_jac=exp_bc_jac,
                     exact=lambda x: (1 + 1j) * exp_exact(x)))
    return out


def arguments(case):
    """solve_bvp's arguments for a case, fresh copies of the arrays (SciPy writes into y when S is
    given): (fun, bc, x, y), keywords."""
    kwargs = dict(tol=case["tol"], max_nodes=case["max_nodes"])
    for key in ("p", "S", "fun_jac", "bc_jac"):
        if case[key] is not None:
            kwargs[key] = np.array(case[key]) if key in ("p", "S") else case[key]
    return (case["fun"], case["bc"], case["x"].copy(), case["y"].copy()), kwargs
