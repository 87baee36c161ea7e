"""Every built-in Hamiltonian of the module against things it does not compute itself.

For each Hamiltonian class cartan exposes (CASES; test_every_exposed_hamiltonian_is_tested keeps
the list complete) and its Lagrangian model with the same inertia and potential:

- the reduced Legendre transform (mechanics/natural_system.hpp, right_reduced.hpp): at mu =
  l.momentum(t, g, v), h(g, mu) = mu.v - l(g, v), dh/dmu = v and dh/dg = -dl/dg (for
  l = 1/2 v.I v - V and h = 1/2 mu.I^-1 mu + V the group gradients are -dV and +dV; for the
  right-reduced rigid body zeta_l+ = ad*_v mu and zeta_h+ = -ad*_v mu, right_reduced.hpp);
- plain NumPy formulas: h = 1/2 mu.I^-1 mu + V(g) with V written here, dh/dmu = I^-1 mu, and the
  group gradient against central differences of h.value along g exp(e E_i) (left-reduced) or
  exp(e E_i) g (right-reduced, the spatial rigid body);
- the spatial (right-reduced) rigid body against its definition h+(g, mu) = h-(g, Ad_g^T mu) with
  the left-reduced RigidBodyHamiltonian, and against the physics of a rotating body (spatial
  angular momentum m, h = 1/2 (R^T m).I^-1 (R^T m), angular velocity w = R I^-1 R^T m, right
  gradient w x m);
- cartan.lie_poisson from mu0 = l.momentum(v0) against cartan.euler_poincare from v0, and the
  conservation of h along it.

The inertias are full (non-diagonal) symmetric positive-definite matrices, so that a transpose, a
diagonal-only or an inverted inertia shows. test_checks_fail_for_wrong_hamiltonians runs the same
checks on deliberately wrong Hamiltonians (another inertia, a flipped gradient, a dropped
potential) and requires each to fail by far more than its tolerance.
"""
import numpy as np
import pytest

import cartan

SEED = 20300430
RNG_SAMPLES = 4


def spd(n, seed):
    """A full symmetric positive-definite matrix, condition number ~ 10."""
    a = np.random.default_rng(seed).normal(size=(n, n))
    return 0.5 * (a @ a.T) / n + np.eye(n)


def zero_potential(g):
    return 0.0


def so3_trace_potential(g):
    return 0.5 * (3.0 - np.trace(g))  # the SO(3) oscillator's V (rigid_body.hpp)


def h3_quadratic_potential(g):
    return 0.5 * float(g @ g)  # the H3 oscillator's V in coordinates (a, b, c) (heisenberg_oscillator.hpp)


# (Hamiltonian class, Lagrangian class with the same inertia and potential, group, side, V(g)).
CASES = [
    (cartan.RigidBodyHamiltonian, cartan.RigidBody, cartan.SO3, "left", zero_potential),
    (cartan.SO3OscillatorHamiltonian, cartan.SO3Oscillator, cartan.SO3, "left", so3_trace_potential),
    (cartan.SpatialRigidBodyHamiltonian, cartan.SpatialRigidBody, cartan.SO3, "right", zero_potential),
    (cartan.H3OscillatorHamiltonian, cartan.H3Oscillator, cartan.Heisenberg, "left", h3_quadratic_potential),
    (cartan.SE2FreeBodyHamiltonian, cartan.SE2FreeBody, cartan.SE2, "left", zero_potential),
    (cartan.SE3FreeBodyHamiltonian, cartan.SE3FreeBody, cartan.SE3, "left", zero_potential),
]
IDS = [case[0].__name__ for case in CASES]


def build(case):
    """The Hamiltonian and Lagrangian of `case` with a full inertia (its own for each case), and the
    case's data."""
    hamiltonian_class, lagrangian_class, group, side, potential = case
    inertia = spd(group.dim, SEED + CASES.index(case))
    return hamiltonian_class(inertia), lagrangian_class(inertia), group, side, potential, inertia


def samples(group, seed):
    """(t, g, v) with g = exp of a random algebra vector (|.| ~ 1, away from the identity so that
    the potentials' gradients and Ad_g are far from trivial) and v random."""
    rng = np.random.default_rng(seed)
    return [(float(rng.uniform(0, 2)), group.exp(rng.normal(size=group.dim)), rng.normal(size=group.dim))
            for _ in range(RNG_SAMPLES)]


def translated(group, side, g, w):
    """g exp(w) (left-trivialised) or exp(w) g (right-trivialised)."""
    return group.compose(g, group.exp(w)) if side == "left" else group.compose(group.exp(w), g)


# Rounding tolerance of the Legendre relations: every quantity is a few products and sums of
# O(1) numbers with I or I^-1 (condition ~ 10), so each side carries errors of a few eps x cond
# relative to the size of the terms; 1e-12 of that size leaves a factor ~ 500 of margin and is
# still ~ 1e10 below what a wrong sign, factor or inertia gives (O(1) relative).
LEGENDRE_RTOL = 1e-12


def legendre_discrepancies(h, l, group, t, g, v):
    """Relative discrepancies of h from the Legendre transform of l at (t, g, v)."""
    mu = l.momentum(t, g, v)
    value_scale = abs(mu @ v) + abs(l.value(t, g, v))
    zeta_l = l.group_gradient(t, g, v)
    # The group gradients' terms: the potential's gradient and (right-reduced) ad*_v mu, of size
    # at most ~ |v| |mu| on these groups.
    gradient_scale = np.linalg.norm(zeta_l) + np.linalg.norm(v) * np.linalg.norm(mu)
    return dict(
        value=abs(h.value(t, g, mu) - (mu @ v - l.value(t, g, v))) / value_scale,
        velocity=np.linalg.norm(h.velocity(t, g, mu) - v) / np.linalg.norm(v),
        group_gradient=np.linalg.norm(h.group_gradient(t, g, mu) + zeta_l) / gradient_scale,
    )


# Central differences with step 1e-5: truncation ~ e^2 |h'''| ~ 1e-10 and cancellation ~ eps |h| / e
# ~ 1e-11, relative to O(1) gradients; 1e-8 leaves a factor ~ 100 and is far below a wrong sign
# or factor (O(1)). dh/dmu of a quadratic in mu has no truncation error at all.
DIFFERENCE_STEP = 1e-5
DIFFERENCE_RTOL = 1e-8


def formula_discrepancies(h, group, side, potential, inertia, t, g, mu):
    """Relative discrepancies of h from 1/2 mu.I^-1 mu + V(g) (left-reduced; the right-reduced
    one is checked against its definition separately) and of its derivatives from central
    differences of h.value."""
    n, e = group.dim, DIFFERENCE_STEP
    basis = np.eye(n)
    velocity = h.velocity(t, g, mu)
    gradient = h.group_gradient(t, g, mu)
    dh_dmu = np.array([(h.value(t, g, mu + e * b) - h.value(t, g, mu - e * b)) / (2 * e) for b in basis])
    dh_dg = np.array([(h.value(t, translated(group, side, g, e * b), mu) -
                       h.value(t, translated(group, side, g, -e * b), mu)) / (2 * e) for b in basis])
    scale = np.linalg.norm(mu) * np.linalg.norm(velocity) + abs(h.value(t, g, mu)) + 1.0
    out = dict(
        velocity_vs_differences=np.linalg.norm(velocity - dh_dmu) / np.linalg.norm(velocity),
        group_gradient_vs_differences=np.linalg.norm(gradient - dh_dg) / scale,
    )
    if side == "left":
        exact = 0.5 * mu @ np.linalg.solve(inertia, mu) + potential(g)
        out["value_vs_formula"] = abs(h.value(t, g, mu) - exact) / (abs(exact) + 1.0)
        out["velocity_vs_formula"] = (np.linalg.norm(velocity - np.linalg.solve(inertia, mu)) /
                                      np.linalg.norm(velocity))
    return out


TOLERANCES = dict(value=LEGENDRE_RTOL, velocity=LEGENDRE_RTOL, group_gradient=LEGENDRE_RTOL,
                  value_vs_formula=LEGENDRE_RTOL, velocity_vs_formula=LEGENDRE_RTOL,
                  velocity_vs_differences=DIFFERENCE_RTOL, group_gradient_vs_differences=DIFFERENCE_RTOL)


def test_every_exposed_hamiltonian_is_tested():
    exposed = {name for name in cartan.__all__ if name.endswith("Hamiltonian")}
    exposed |= {name for name in dir(cartan._cartan) if name.endswith("Hamiltonian")}
    assert exposed == set(IDS)


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_class_attributes_and_inertia(case):
    h, l, group, side, _, inertia = build(case)
    assert h.group is group and l.group is group
    assert h.side == side and l.side == side
    np.testing.assert_allclose(h.inertia, inertia, rtol=1e-15, atol=0)
    np.testing.assert_array_equal(h.inertia, l.inertia)


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_hamiltonian_is_the_legendre_transform_of_its_lagrangian(case):
    h, l, group, _, _, _ = build(case)
    for k, (t, g, v) in enumerate(samples(group, SEED)):
        for name, d in legendre_discrepancies(h, l, group, t, g, v).items():
            assert d <= LEGENDRE_RTOL, f"sample {k}: {name} discrepancy {d:.3g}"


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_hamiltonian_matches_its_formula_and_its_own_differences(case):
    h, _, group, side, potential, inertia = build(case)
    for k, (t, g, v) in enumerate(samples(group, SEED + 1)):
        mu = inertia @ v  # a momentum built here, not by the Lagrangian
        for name, d in formula_discrepancies(h, group, side, potential, inertia, t, g, mu).items():
            assert d <= TOLERANCES[name], f"sample {k}: {name} discrepancy {d:.3g}"


def test_potentials_have_nonzero_gradients_at_the_samples():
    """The oscillators' group-gradient checks are not vacuous: zeta is O(1) at the samples."""
    for case in CASES:
        h, _, group, side, potential, inertia = build(case)
        if potential is zero_potential and side == "left":
            continue
        for t, g, v in samples(group, SEED):
            assert np.linalg.norm(h.group_gradient(t, g, inertia @ v)) > 1e-2


def test_spatial_rigid_body_hamiltonian_is_its_definition():
    """right_reduced.hpp: h+(t, g, mu) = h-(t, g, Ad_g^T mu), v+ = Ad_g dh-/dmu(Ad_g^T mu),
    zeta_h+ = Ad_{g^-1}^T zeta_h- - ad*_{v+} mu with zeta_h- = 0 for the free body; and the same
    in the physics of a rotating body: for spatial angular momentum m and R = g, the body momentum
    is R^T m, the spatial angular velocity w = R I^-1 R^T m, and d/de h(exp(e W) R, m) = (w x m).W.
    Tolerance: rounding of a few 3 x 3 products with I^-1 (condition ~ 10), as LEGENDRE_RTOL."""
    inertia = spd(3, SEED + 7)
    spatial = cartan.SpatialRigidBodyHamiltonian(inertia)
    body = cartan.RigidBodyHamiltonian(inertia)
    for k, (t, g, m) in enumerate(samples(cartan.SO3, SEED + 2)):
        ad = cartan.SO3.Ad(g)
        np.testing.assert_allclose(ad, g, rtol=0, atol=1e-15)  # Ad_R = R on (R^3, x)
        mu_body = ad.T @ m
        w = spatial.velocity(t, g, m)
        scale = np.linalg.norm(m) * np.linalg.norm(w)
        assert spatial.value(t, g, m) == pytest.approx(body.value(t, g, mu_body), rel=LEGENDRE_RTOL)
        np.testing.assert_allclose(w, ad @ body.velocity(t, g, mu_body), rtol=0, atol=LEGENDRE_RTOL * np.linalg.norm(w))
        np.testing.assert_allclose(spatial.group_gradient(t, g, m), -cartan.SO3.ad_star(w, m), rtol=0,
                                   atol=LEGENDRE_RTOL * scale)
        # The physics, in NumPy only:
        body_m = g.T @ m
        assert spatial.value(t, g, m) == pytest.approx(0.5 * body_m @ np.linalg.solve(inertia, body_m),
                                                       rel=LEGENDRE_RTOL)
        np.testing.assert_allclose(w, g @ np.linalg.solve(inertia, body_m), rtol=0,
                                   atol=LEGENDRE_RTOL * np.linalg.norm(w))
        np.testing.assert_allclose(spatial.group_gradient(t, g, m), np.cross(w, m), rtol=0, atol=LEGENDRE_RTOL * scale)
        assert np.linalg.norm(np.cross(w, m)) > 1e-2 * scale, f"sample {k}: w nearly parallel to m"
        # The spatial momentum of a body velocity: Ad_{g^-1}^T (I v_body); its spatial energy is the
        # body energy.
        v_body = np.random.default_rng(SEED + k).normal(size=3)
        m_of_v = np.linalg.inv(ad).T @ (inertia @ v_body)
        assert spatial.value(t, g, m_of_v) == pytest.approx(0.5 * v_body @ inertia @ v_body, rel=LEGENDRE_RTOL)
        np.testing.assert_allclose(spatial.velocity(t, g, m_of_v), ad @ v_body, rtol=0,
                                   atol=LEGENDRE_RTOL * np.linalg.norm(v_body))


# Lie-Poisson against Euler-Poincare: both are RKMK4 with the same step (T = 4, 400 steps) on
# mu' = +-ad*_v mu + zeta, with v = dh/dmu = l's inverse Legendre map and -zeta_h = zeta_l, so
# for a correct Legendre pair the two trajectories are the same computation up to rounding
# (observed: bitwise equal for the natural systems, <= 5e-15 for the right-reduced one). 1e-11
# allows rounding to grow over 400 steps and is far below what a wrong inertia or sign does to the
# trajectory (O(1e-2) and more, test_checks_fail_for_wrong_hamiltonians).
T, STEPS = 4.0, 400
TRAJECTORY_ATOL = 1e-11
# h is a first integral of the exact flow; RKMK4 is not symplectic, so h drifts by its global error,
# O(h^4) at h = T / STEPS = 0.01: observed <= 3e-10 relative to h (H3 and SE(3)), and 16 times
# that with 200 steps, as fourth order predicts. 1e-8 leaves a factor ~ 30; a flipped group
# gradient with a potential makes dh/dt = 2 dV.v (drift O(1), test_checks_fail_for_wrong_hamiltonians).
ENERGY_RTOL = 1e-8


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_lie_poisson_conserves_h_and_agrees_with_euler_poincare(case):
    h, l, group, side, _, _ = build(case)
    rng = np.random.default_rng(SEED + 3)
    g0, v0 = group.exp(0.8 * rng.normal(size=group.dim)), rng.normal(size=group.dim)
    mu0 = l.momentum(0.0, g0, v0)
    lp = cartan.lie_poisson(h, g0, mu0, T=T, steps=STEPS, side=side)
    ep = cartan.euler_poincare(l, g0, v0, T=T, steps=STEPS, side=side)
    np.testing.assert_allclose(lp.g, ep.g, rtol=0, atol=TRAJECTORY_ATOL)
    np.testing.assert_allclose(lp.mu, ep.mu, rtol=0, atol=TRAJECTORY_ATOL)
    np.testing.assert_allclose(lp.v, ep.v, rtol=0, atol=TRAJECTORY_ATOL)
    energy = np.array([h.value(t, g, mu) for t, g, mu in zip(lp.t, lp.g, lp.mu)])
    assert energy[0] == pytest.approx(mu0 @ v0 - l.value(0.0, g0, v0), rel=LEGENDRE_RTOL)
    assert np.ptp(energy) <= ENERGY_RTOL * abs(energy[0])
    # The motion is not trivial: g and mu move by O(1).
    assert np.abs(lp.g[-1] - lp.g[0]).max() > 0.1
    if side == "left":
        assert np.linalg.norm(lp.mu[-1] - lp.mu[0]) > 1e-2
    else:  # the right-reduced free body: eq:LP-right gives mu' = 0, the spatial angular momentum
        np.testing.assert_allclose(lp.mu, np.broadcast_to(mu0, lp.mu.shape), rtol=0, atol=TRAJECTORY_ATOL)


# Negative controls: the checks above fail for Hamiltonians that are wrong in each way a
# Legendre pair or an integrator can be.
class Wrapped:
    """A built-in Hamiltonian with one callback changed (a Python-defined Hamiltonian)."""

    def __init__(self, inner, value=None, velocity=None, group_gradient=None):
        self.inner, self.group, self.side = inner, inner.group, inner.side
        self._value, self._velocity, self._gradient = value, velocity, group_gradient

    def value(self, t, g, mu):
        return self._value(self.inner, t, g, mu) if self._value else self.inner.value(t, g, mu)

    def velocity(self, t, g, mu):
        return self._velocity(self.inner, t, g, mu) if self._velocity else self.inner.velocity(t, g, mu)

    def group_gradient(self, t, g, mu):
        return self._gradient(self.inner, t, g, mu) if self._gradient else self.inner.group_gradient(t, g, mu)


def flipped_gradient(h):
    return Wrapped(h, group_gradient=lambda inner, t, g, mu: -inner.group_gradient(t, g, mu))


def without_potential(h, potential):
    return Wrapped(h, value=lambda inner, t, g, mu: inner.value(t, g, mu) - potential(g))


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_checks_fail_for_wrong_hamiltonians(case):
    h, l, group, side, potential, inertia = build(case)
    hamiltonian_class = case[0]
    wrong = {
        # the same inertia transposed is the same matrix; a perturbed or diagonal-only one is not
        "inertia x 1.05": hamiltonian_class(1.05 * inertia),
        "diagonal inertia": hamiltonian_class(np.diag(np.diag(inertia))),
        "inverse inertia": hamiltonian_class(np.linalg.inv(inertia)),
    }
    if potential is not zero_potential or side == "right":
        wrong["flipped group gradient"] = flipped_gradient(h)
    if potential is not zero_potential:
        wrong["no potential in value"] = without_potential(h, potential)
    for label, bad in wrong.items():
        worst = 0.0
        for t, g, v in samples(group, SEED):
            legendre = legendre_discrepancies(bad, l, group, t, g, v)
            worst = max(worst, max(d / TOLERANCES[name] for name, d in legendre.items()))
            formula = formula_discrepancies(bad, group, side, potential, inertia, t, g, inertia @ v)
            worst = max(worst, max(d / TOLERANCES[name] for name, d in formula.items()))
        assert worst > 1e4, f"{label}: the worst discrepancy is only {worst:.3g} x its tolerance"

    # The integrator checks: a wrong inertia or a flipped gradient moves the Lie-Poisson trajectory
    # away from Euler-Poincare's; with a potential, a flipped gradient also breaks the conservation
    # of h (dh/dt = 2 dV.v; for the spatial free body h stays conserved, ad*_v mu . v = 0).
    rng = np.random.default_rng(SEED + 3)
    g0, v0 = group.exp(0.8 * rng.normal(size=group.dim)), rng.normal(size=group.dim)
    mu0 = l.momentum(0.0, g0, v0)
    ep = cartan.euler_poincare(l, g0, v0, T=T, steps=STEPS, side=side)
    for label in ("inertia x 1.05", "flipped group gradient"):
        if label in wrong:
            lp = cartan.lie_poisson(wrong[label], g0, mu0, T=T, steps=STEPS, side=side)
            assert np.abs(lp.g - ep.g).max() > 1e3 * TRAJECTORY_ATOL, label
    if potential is not zero_potential:
        lp = cartan.lie_poisson(wrong["flipped group gradient"], g0, mu0, T=T, steps=STEPS, side=side)
        energy = np.array([h.value(t, g, mu) for t, g, mu in zip(lp.t, lp.g, lp.mu)])
        assert np.ptp(energy) > 1e3 * ENERGY_RTOL * abs(energy[0])
