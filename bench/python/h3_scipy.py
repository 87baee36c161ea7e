"""The paper's H3 oscillator BVP (appendix sec-app-H3, g0 = e, unit inertia) solved with SciPy's
solve_bvp, as in the paper: the reference for cartan's collocation solver (tests/cli) and the
baseline of bench/compare_collocation.py."""
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


def solve(lam, gT, tol, T=1.0, nodes=11):
    """solve_bvp from the geodesic guess (g = t gT / T, v = gT / T; exact geodesic of H3 from e
    up to the c-coordinate) on `nodes` uniform nodes."""
    gT = np.asarray(gT, dtype=float)
    x = np.linspace(0, T, nodes)
    guess = np.vstack([np.outer(gT, x / T), np.repeat(gT[:, None] / T, x.size, axis=1)])
    bc = lambda ya, yb: np.concatenate([ya[:3], yb[:3] - gT])
    return solve_bvp(printed_system(lam), bc, x, guess, tol=tol, max_nodes=100000)
