#!/usr/bin/python3
"""The paper's two-level scheme on SO(3), written the way a NumPy/SciPy user would write it.

This is the *speed baseline* and an *independent cross-check* for cartan's C++ solver. It does not
import cartan. It implements, for the rigid body on SO(3) with the Cartan--Schouten connection of
parameter lambda, the first-order discretisation of the paper (section "Discretizations":
(disc-grp), (disc-body-v), (disc-exp), (disc-Legendre), (disc-aux), (disc-mmt), (disc-mmt-eqn);
appendix "Non-nilpotent case: the rigid-body") and the two-level solver of section "A two-level
scheme" with the pseudocode of the appendix "More about the two-level scheme".

Conventions (docs/paper-notes.md):
  * g0 = I, so the transported velocity v is the paper's v (no left translation by g0 is needed).
  * hat(v) w = v x w;  ad_v = hat(v);  ad*_v mu = -v x mu  (appendix so(3)).
  * Oscillator: l = 1/2 v.Iv - V(g), V(g) = 1/2 (3 - tr g).  The left-trivialised dl/dg is
    zeta = -vee(Skew g) (docs/paper-notes.md#erratum-1: the paper prints +vee(Skew g), the
    gradient of V).
  * eta_k = P_k^T zeta_k  (the dual P_k^* of (disc-mmt); equal to P_k^{-1} on SO(3)).
  * The momentum step (disc-mmt-eqn) is explicit (docs/paper-notes.md#erratum-2): every term at
    step k.
  * Shooting residual r(v0) = vee(log(gT^{-1} g_N)) in R^3 (3 equations for 3 unknowns).
  * gT is the minimal rotation taking a0 to aT (axis a0 x aT / |a0 x aT|, angle = angle(a0, aT)).

Forward sweep, for k = 0..N-1 (h = T/N, P_0 = I, mu_k = I v_k):
    u_k     = P_k v_k                                        (disc-body-v)
    eta_k   = P_k^T zeta(g_k)                                (disc-mmt)
    g_{k+1} = g_k exp(h hat(u_k))                            (disc-grp)
    P_{k+1} = exp(-lambda h hat(u_k)) P_k                    (disc-exp)
    mu_{k+1} = mu_k + h (eta_k + (2 lambda - 1) v_k x mu_k
                          + lambda (1 - lambda) v_k x xi_k)  (disc-mmt-eqn with ad*_v = -v x)
    v_{k+1} = I^{-1} mu_{k+1}                                (disc-Legendre inverted)
Backward recursion (disc-aux): xi_N = 0, xi_k = xi_{k+1} - h v_k x mu_k  (vectorised: a reversed
cumulative sum).

Two-level solver: the outer loop is the plain fixed point (Picard) iteration on {xi_k}; the inner
loop solves r(v0) = 0 with scipy.optimize.least_squares(method='lm') (MINPACK lmdif with its own
forward-difference Jacobian) with tight tolerances; v0 starts at log(gT)/T (the geodesic guess) and
is warm-started from the previous inner solution. The outer loop stops when
max_k |xi_new_k - xi_old_k| < tol. Counted: outer iterations; inner = the sum of least_squares'
nfev (for the default MINPACK differences this is MINPACK's count, which includes its difference
evaluations; 'lm' reports no njev); sweeps = every call of forward_sweep. sweeps > inner + outer:
least_squares evaluates the residual at x0 before MINPACK starts and, after MINPACK returns,
7 more times for the `jac` attribute of its result (scipy's 3-point differences), and we sweep once
per outer iteration to rebuild the trajectory at the accepted v0 (measured: a 29-nfev solve costs
38 sweeps). solve_time_s is wall time
(time.perf_counter) of solve() only; cpu_time_s is time.process_time of the same span.

Implementation choices: the forward sweep is a plain Python loop over k (it is sequential) with
3x3 NumPy arithmetic; exp is our own Rodrigues formula (one axis/skew matrix per step, reused for
both exp(h hat u) and exp(-lambda h hat u)); the two cross products of the momentum step are one
matrix-vector product hat(v_k) ((2 lambda - 1) mu_k + lambda (1 - lambda) xi_k). log, needed once
per sweep for the residual, is scipy.spatial.transform.Rotation.as_rotvec (robust at angle pi).

Run with Debian's interpreter, /usr/bin/python3 (NumPy, SciPy). `--help` lists the options; the
result is JSON on stdout or in --output FILE. Exit status: 0 converged, 1 not converged, 2 usage.
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import time

import numpy as np
from scipy.optimize import least_squares
from scipy.spatial.transform import Rotation

MODELS = ("free-rigid-body", "oscillator")

# Paper cases (section "Numerical examples").
PAPER_FREE_BODY = dict(model="free-rigid-body", T=50.0, N=1000, tol=1e-8,
                       a0=(-1.0, -1.0, -1.0), aT=(0.9, 1.0, 1.0))
PAPER_OSCILLATOR = dict(model="oscillator", T=12.0, N=800, tol=1e-6,
                        a0=(-0.7, -1.0, -0.7), aT=(0.8, 0.8, 1.0))


# --------------------------------------------------------------------------------------------
# so(3) / SO(3) helpers
# --------------------------------------------------------------------------------------------
def hat(w):
    """hat: R^3 -> so(3), hat(w) x = w x x."""
    return np.array([[0.0, -w[2], w[1]],
                     [w[2], 0.0, -w[0]],
                     [-w[1], w[0], 0.0]])


def vee(W):
    """Inverse of hat (reads the skew part of W)."""
    return np.array([W[2, 1], W[0, 2], W[1, 0]])


def vee_skew(g):
    """vee(Skew g), Skew g = (g - g^T)/2."""
    return 0.5 * np.array([g[2, 1] - g[1, 2], g[0, 2] - g[2, 0], g[1, 0] - g[0, 1]])


def expm_so3(w):
    """exp(hat(w)) by Rodrigues' formula (Taylor series below |w| = 1e-8)."""
    theta = math.sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2])
    K = hat(w)
    if theta < 1e-8:
        return np.eye(3) + K + 0.5 * (K @ K)
    return (np.eye(3) + (math.sin(theta) / theta) * K
            + ((1.0 - math.cos(theta)) / (theta * theta)) * (K @ K))


def logm_so3(R):
    """vee(log R) with angle in [0, pi] (SciPy's quaternion route: robust near 0 and pi)."""
    return Rotation.from_matrix(R).as_rotvec()


def minimal_rotation(a0, aT):
    """The rotation of least angle taking direction a0 to direction aT (inputs need not be unit)."""
    a0 = np.asarray(a0, float) / np.linalg.norm(a0)
    aT = np.asarray(aT, float) / np.linalg.norm(aT)
    c = np.cross(a0, aT)
    s = np.linalg.norm(c)
    angle = math.atan2(s, float(a0 @ aT))
    if s < 1e-12:
        if a0 @ aT > 0:
            return np.eye(3)
        raise ValueError("a0 = -aT: the minimal rotation is not unique; choose other endpoints")
    return expm_so3(angle * c / s)


# --------------------------------------------------------------------------------------------
# The discrete system
# --------------------------------------------------------------------------------------------
class Problem:
    """Data of one boundary value problem and the discrete maps of the paper."""

    def __init__(self, model="free-rigid-body", inertia=(2.0, 3.0, 4.0), lam=0.0, T=50.0,
                 N=1000, a0=(1.0, 0.0, 0.0), aT=(0.0, 1.0, 0.0), gT=None):
        if model not in MODELS:
            raise ValueError(f"unknown model {model!r}; expected one of {MODELS}")
        if N < 1 or not T > 0:
            raise ValueError("need N >= 1 and T > 0")
        self.model = model
        self.inertia = np.asarray(inertia, float)
        if self.inertia.shape != (3,) or np.any(self.inertia <= 0):
            raise ValueError("inertia must be three positive numbers")
        self.lam = float(lam)
        self.T = float(T)
        self.N = int(N)
        self.h = self.T / self.N
        self.a0 = np.asarray(a0, float)
        self.aT = np.asarray(aT, float)
        self.g0 = np.eye(3)
        self.gT = minimal_rotation(a0, aT) if gT is None else np.asarray(gT, float)
        self.sweeps = 0  # every call of forward_sweep

    # l(g, v) = 1/2 v.Iv - V(g); dl/dg left-trivialised
    def zeta(self, g):
        if self.model == "oscillator":
            return -vee_skew(g)          # docs/paper-notes.md#erratum-1 (restoring force)
        return np.zeros(3)

    def potential(self, g):
        return 0.5 * (3.0 - np.trace(g)) if self.model == "oscillator" else 0.0

    def forward_sweep(self, v0, xi):
        """One forward sweep (Step 2 of the scheme). xi: (N+1, 3). Returns g (N+1,3,3), v, mu."""
        self.sweeps += 1
        N, h, lam = self.N, self.h, self.lam
        Iv = self.inertia
        c_mu = 2.0 * lam - 1.0
        c_xi = lam * (1.0 - lam)
        oscillator = self.model == "oscillator"

        g = np.empty((N + 1, 3, 3))
        v = np.empty((N + 1, 3))
        mu = np.empty((N + 1, 3))
        g[0] = self.g0
        v[0] = v0
        mu[0] = Iv * v[0]
        P = np.eye(3)
        eye = np.eye(3)
        zero3 = np.zeros(3)
        for k in range(N):
            vk = v[k]
            u = P @ vk                                                # (disc-body-v)
            force = zero3
            if oscillator:
                force = P.T @ -vee_skew(g[k])                         # (disc-mmt), eta_k
            # Rodrigues; hat(axis) shared by exp(h u^) and exp(-lam h u^)  (disc-grp, disc-exp)
            theta = math.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2])
            if theta * h > 1e-8:
                K = hat(u / theta)
                K2 = K @ K
                a = h * theta
                E = eye + math.sin(a) * K + (1.0 - math.cos(a)) * K2
                if lam != 0.0:
                    b = lam * a
                    P = (eye - math.sin(b) * K + (1.0 - math.cos(b)) * K2) @ P
            else:
                E = expm_so3(h * u)
                if lam != 0.0:
                    P = expm_so3(-lam * h * u) @ P
            g[k + 1] = g[k] @ E
            # (disc-mmt-eqn), explicit: mu_{k+1} = mu_k + h(eta_k + (2l-1) v x mu + l(1-l) v x xi)
            mu[k + 1] = mu[k] + h * (force + hat(vk) @ (c_mu * mu[k] + c_xi * xi[k]))
            v[k + 1] = mu[k + 1] / Iv                                 # (disc-Legendre)
        return g, v, mu

    def backward_xi(self, v, mu):
        """(disc-aux): xi_N = 0, xi_k = xi_{k+1} + h ad*_{v_k} mu_k = xi_{k+1} - h v_k x mu_k."""
        incr = -self.h * np.cross(v[:-1], mu[:-1])
        xi = np.zeros_like(v)
        xi[:-1] = np.cumsum(incr[::-1], axis=0)[::-1]
        return xi

    def residual_of(self, gN):
        """r = vee(log(gT^{-1} g_N))."""
        return logm_so3(self.gT.T @ gN)

    def shooting_residual(self, v0, xi):
        g, _, _ = self.forward_sweep(v0, xi)
        return self.residual_of(g[-1])

    def energy(self, g, v):
        """E_k = 1/2 v_k.I v_k + V(g_k) (conserved along exact solutions for every lambda)."""
        kin = 0.5 * np.einsum("ki,i,ki->k", v, self.inertia, v)
        if self.model == "oscillator":
            kin = kin + 0.5 * (3.0 - np.trace(g, axis1=1, axis2=2))
        return kin


# --------------------------------------------------------------------------------------------
# The two-level solver
# --------------------------------------------------------------------------------------------
def _forward_difference_pair(p, xi):
    """Residual and a forward-difference Jacobian with an *absolute* step sqrt(eps) max(1, |x_j|).

    MINPACK's own difference step is relative, sqrt(eps)|x_j| (sqrt(eps) only if x_j == 0 exactly),
    so a component that is tiny but nonzero (v0_1 ~ 1e-11 on the symmetric lambda = 1/2 free-body
    solution) gets a step ~1e-19 and a garbage Jacobian column. The residual at the last x is
    cached so the Jacobian costs 3 sweeps, not 4.
    """
    cache = {}

    def fun(x):
        r = p.shooting_residual(x, xi)
        cache["x"], cache["r"] = x.copy(), r
        return r

    def jac(x):
        r0 = cache["r"] if ("x" in cache and np.array_equal(cache["x"], x)) else fun(x)
        J = np.empty((3, 3))
        for j in range(3):
            xp = x.copy()
            xp[j] += _SQRT_EPS * max(1.0, abs(x[j]))
            J[:, j] = (p.shooting_residual(xp, xi) - r0) / (xp[j] - x[j])
        return J

    return fun, jac


_SQRT_EPS = math.sqrt(np.finfo(float).eps)
JACOBIANS = ("minpack", "forward")


def solve(problem, tol=1e-8, max_outer=50, inner_xtol=1e-14, inner_ftol=1e-14,
          inner_gtol=1e-14, max_nfev=None, v0_guess=None, xi_guess=None, jacobian="minpack"):
    """Two-level scheme: outer Picard iteration on {xi_k}, inner LM shooting on v0.

    jacobian: 'minpack' (least_squares' default for 'lm': MINPACK lmdif differences, the paper's
    "finite differences") or 'forward' (our forward differences with an absolute step, lmder).
    Returns a dict (see to_json). Status: 'converged', 'outer-not-converged' (max_outer reached),
    'inner-not-converged' (LM stopped with |r| >= tol), 'diverged' (non-finite numbers).
    """
    if jacobian not in JACOBIANS:
        raise ValueError(f"jacobian must be one of {JACOBIANS}")
    p = problem
    p.sweeps = 0
    N = p.N
    t0 = time.perf_counter()
    c0 = time.process_time()

    v0 = (logm_so3(p.g0.T @ p.gT) / p.T) if v0_guess is None else np.asarray(v0_guess, float)
    v0_initial = v0.copy()
    xi = np.zeros((N + 1, 3)) if xi_guess is None else np.array(xi_guess, float)

    outer = 0
    inner = 0
    jacobians = 0
    history = []
    status, message = "outer-not-converged", ""
    g = v = mu = None
    xi_new = xi
    r = np.full(3, np.nan)
    while outer < max_outer:
        outer += 1
        # Steps 2-3: inner shooting for v0 with the current xi (least_squares 'lm' = MINPACK lmdif,
        # forward-difference Jacobian computed by MINPACK itself).
        if jacobian == "minpack":
            sol = least_squares(p.shooting_residual, v0, args=(xi,), method="lm",
                                xtol=inner_xtol, ftol=inner_ftol, gtol=inner_gtol,
                                max_nfev=max_nfev)
        else:
            fun, jac = _forward_difference_pair(p, xi)
            sol = least_squares(fun, v0, jac=jac, method="lm", xtol=inner_xtol,
                                ftol=inner_ftol, gtol=inner_gtol, max_nfev=max_nfev)
            jacobians += sol.njev
        inner += sol.nfev
        v0 = sol.x
        g, v, mu = p.forward_sweep(v0, xi)          # the trajectory at the accepted v0
        r = p.residual_of(g[-1])
        err = float(np.linalg.norm(r))
        # Step 4: backward recursion for xi
        xi_new = p.backward_xi(v, mu)
        change = float(np.max(np.linalg.norm(xi_new - xi, axis=1)))
        history.append(dict(outer=outer, nfev=int(sol.nfev), lm_status=int(sol.status),
                            terminal_error=err, xi_change=change, v0=v0.tolist()))
        if not (np.all(np.isfinite(v)) and np.all(np.isfinite(xi_new)) and math.isfinite(err)):
            status, message = "diverged", f"non-finite values at outer iteration {outer}"
            break
        if not err < tol:
            status = "inner-not-converged"
            message = (f"outer iteration {outer}: Levenberg-Marquardt stopped (status "
                       f"{sol.status}: {sol.message}) with terminal error {err:.3e} >= tol {tol:g}")
            break
        # Step 5: convergence test of the fixed point
        if change < tol:
            status = "converged"
            message = (f"max_k |xi_new - xi_old| = {change:.3e} < {tol:g} after {outer} outer "
                       f"iterations")
            break
        xi = xi_new
    else:
        message = (f"no convergence in {max_outer} outer iterations; last max_k |xi_new - xi_old|"
                   f" = {history[-1]['xi_change']:.3e}")
    solve_time = time.perf_counter() - t0
    cpu_time = time.process_time() - c0

    return dict(problem=p, status=status, message=message, g=g, v=v, mu=mu, xi=xi_new,
                terminal_error=float(np.linalg.norm(r)), outer=outer, inner=inner,
                jacobian=jacobian, jacobians=jacobians,
                sweeps=p.sweeps, solve_time_s=solve_time, cpu_time_s=cpu_time, history=history,
                v0_initial=v0_initial, tol=tol)


def to_json(res):
    """The JSON document of a result (all nodes k = 0..N)."""
    p = res["problem"]
    t = np.linspace(0.0, p.T, p.N + 1)
    g = res["g"]
    E = p.energy(g, res["v"]) if g is not None else None
    return dict(
        status=res["status"], message=res["message"],
        group="so3", model=p.model, inertia=p.inertia.tolist(), **{"lambda": p.lam},
        T=p.T, N=p.N, method="two-level", order=1, tol=res["tol"],
        a0=(p.a0 / np.linalg.norm(p.a0)).tolist(), aT=(p.aT / np.linalg.norm(p.aT)).tolist(),
        gT=p.gT.reshape(-1).tolist(), v0_initial_guess=res["v0_initial"].tolist(),
        t=t.tolist(),
        g=g.reshape(p.N + 1, 9).tolist(),
        v=res["v"].tolist(), mu=res["mu"].tolist(), xi=res["xi"].tolist(),
        terminal_error=res["terminal_error"],
        energy_drift=float(E[-1] - E[0]),
        jacobian=res["jacobian"],
        iterations=dict(outer=res["outer"], inner=res["inner"], sweeps=res["sweeps"],
                        jacobians=res["jacobians"]),
        outer_history=res["history"],
        solve_time_s=res["solve_time_s"],
        cpu_time_s=res["cpu_time_s"],
    )


# --------------------------------------------------------------------------------------------
# CLI
# --------------------------------------------------------------------------------------------
def _vec3(text):
    try:
        x = [float(s) for s in text.split(",")]
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected x,y,z numbers, got {text!r}")
    if len(x) != 3:
        raise argparse.ArgumentTypeError(f"expected three comma-separated numbers, got {text!r}")
    return tuple(x)


def _is_number_list(text):
    """True for '-1', '-1e-3', '-1,-1,-1': a value, not an option."""
    try:
        [float(s) for s in text.split(",")]
    except ValueError:
        return False
    return True


_VALUE_FLAGS = ("--inertia", "--lambda", "--T", "--N", "--a0", "--aT", "--tol", "--max-outer",
                "--max-nfev", "--v0")


def _join_negative_values(argv):
    """argparse treats '-1,-1,-1' (a negative number *list*) as an option; rewrite
    ['--a0', '-1,-1,-1'] as ['--a0=-1,-1,-1'] so both spellings work."""
    out, i = [], 0
    while i < len(argv):
        a = argv[i]
        nxt = argv[i + 1] if i + 1 < len(argv) else ""
        if a in _VALUE_FLAGS and nxt.startswith("-") and _is_number_list(nxt):
            out.append(f"{a}={argv[i + 1]}")
            i += 2
        else:
            out.append(a)
            i += 1
    return out


def build_parser():
    ap = argparse.ArgumentParser(
        prog="paper_scheme.py",
        description="The paper's two-level scheme (outer fixed point on xi, inner LM shooting "
                    "on v0) for the rigid body on SO(3); first order. Prints JSON.")
    ap.add_argument("--model", choices=MODELS, default="free-rigid-body")
    ap.add_argument("--inertia", type=_vec3, default=(2.0, 3.0, 4.0), help="I1,I2,I3 (2,3,4)")
    ap.add_argument("--lambda", dest="lam", type=float, default=0.0, help="connection parameter")
    ap.add_argument("--T", type=float, default=None, help="horizon (paper: 50 free, 12 osc.)")
    ap.add_argument("--N", type=int, default=None, help="steps (paper: 1000 free, 800 osc.)")
    ap.add_argument("--a0", type=_vec3, default=None, help="start direction (normalised)")
    ap.add_argument("--aT", type=_vec3, default=None, help="end direction (normalised)")
    ap.add_argument("--tol", type=float, default=None, help="outer tolerance (paper: 1e-8/1e-6)")
    ap.add_argument("--max-outer", type=int, default=50)
    ap.add_argument("--max-nfev", type=int, default=None,
                    help="LM function evaluations per inner solve (least_squares' default: "
                         "1200 with MINPACK differences, 300 with --jacobian forward)")
    ap.add_argument("--v0", type=_vec3, default=None,
                    help="initial guess for v0 (default log(gT)/T)")
    ap.add_argument("--jacobian", choices=JACOBIANS, default="minpack",
                    help="LM Jacobian: MINPACK's differences (default) or ours (absolute step)")
    ap.add_argument("--output", default=None, help="write JSON here instead of stdout")
    ap.add_argument("--compact", action="store_true", help="omit the per-node arrays")
    return ap


def main(argv=None):
    argv = sys.argv[1:] if argv is None else list(argv)
    args = build_parser().parse_args(_join_negative_values(argv))
    case = PAPER_OSCILLATOR if args.model == "oscillator" else PAPER_FREE_BODY
    p = Problem(model=args.model, inertia=args.inertia, lam=args.lam,
                T=case["T"] if args.T is None else args.T,
                N=case["N"] if args.N is None else args.N,
                a0=case["a0"] if args.a0 is None else args.a0,
                aT=case["aT"] if args.aT is None else args.aT)
    res = solve(p, tol=case["tol"] if args.tol is None else args.tol, max_outer=args.max_outer,
                max_nfev=args.max_nfev, v0_guess=args.v0, jacobian=args.jacobian)
    doc = to_json(res)
    if args.compact:
        for key in ("t", "g", "v", "mu", "xi"):
            doc.pop(key)
        doc["v0"] = res["v"][0].tolist()
    text = json.dumps(doc, indent=None if not args.compact else 1)
    if args.output:
        with open(args.output, "w") as f:
            f.write(text + "\n")
    else:
        print(text)
    return 0 if res["status"] == "converged" else 1


if __name__ == "__main__":
    sys.exit(main())
