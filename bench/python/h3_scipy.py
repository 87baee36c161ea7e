"""The paper's H3 oscillator BVP (appendix sec-app-H3, g0 = e, unit inertia) solved with SciPy's
solve_bvp, as in the paper: the reference for cartan's collocation solver (tests/cli) and the
baseline of bench/compare_collocation.py and bench/compare_collocation_warm.py."""
import numpy as np
from scipy.integrate import solve_bvp


def printed_system(lam):
    """The six ODEs printed in the appendix, vectorised over the mesh."""
    def f(t, y):
        a, b, c, v1, v2, v3 = y
        return np.vstack([v1, v2, v3 + (1 - lam) * a * v2 + lam * b * v1,
                          -a - lam * c * b + (2 * lam - 1) * v2 * v3,
                          -b - (1 - lam) * c * a - (2 * lam - 1) * v1 * v3,
                          -c])
    return f


def straight_guess(gT, T, x):
    """g = t gT / T, v = gT / T: the exact geodesic of H3 from e up to the c-coordinate."""
    gT = np.asarray(gT, dtype=float)
    return np.vstack([np.outer(gT, x / T), np.repeat(gT[:, None] / T, x.size, axis=1)])


def geodesic_guess(gT, T, x):
    """cartan's guess (kernels/lie_group/heisenberg_collocation.hpp, heisenberg_geodesic_guess):
    g(t) = exp(t w / T), v = w / T with w = log(gT) = (a, b, c - a b / 2) and
    exp(w) = (w1, w2, w3 + w1 w2 / 2) (groups/heisenberg.hpp)."""
    a, b, c = np.asarray(gT, dtype=float)
    w = np.array([a, b, c - a * b / 2])
    s = x / T
    g = np.vstack([s * w[0], s * w[1], s * w[2] + s * s * w[0] * w[1] / 2])
    return np.vstack([g, np.repeat(w[:, None] / T, x.size, axis=1)])


def solve(lam, gT, tol, T=1.0, nodes=11, guess=straight_guess):
    """solve_bvp from `guess` (straight_guess or geodesic_guess) on `nodes` uniform nodes."""
    gT = np.asarray(gT, dtype=float)
    x = np.linspace(0, T, nodes)
    bc = lambda ya, yb: np.concatenate([ya[:3], yb[:3] - gT])
    return solve_bvp(printed_system(lam), bc, x, guess(gT, T, x), tol=tol, max_nodes=100000)
