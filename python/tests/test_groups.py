"""Group operations of every bound group against independent references: SciPy's matrix
exponential, matrix products and inverses of the faithful representation, and the defining
identities of Ad, ad and ad* (Sophus-style axioms). Points: the identity, near it (1e-8) and
seeded random ones.

Tolerances: every quantity is O(1) and computed in a few dozen flops by both sides; expm
(Pade, scaling and squaring) is accurate to a few ulps for these small norms, so 1e-12 leaves
two orders of margin over rounding while any formula error would be O(1)."""
import numpy as np
import pytest
import scipy.linalg

import cartan

RNG_SEED = 20240611
TOL = 1e-12


def points(group, count=5):
    rng = np.random.default_rng(RNG_SEED)
    pts = [np.zeros(group.dim), np.full(group.dim, 1e-8)]
    # Random algebra vectors with |v| < 2.5 (inside the injectivity radius of exp for rotations).
    pts += [2.5 * x / np.sqrt(group.dim) for x in rng.uniform(-1, 1, size=(count, group.dim))]
    return pts


@pytest.mark.parametrize("group", cartan.GROUPS, ids=lambda g: g.name)
def test_exp_matches_scipy_expm_and_log_inverts_it(group):
    for v in points(group):
        g = group.exp(v)
        assert g.shape == group.element_shape
        np.testing.assert_allclose(group.matrix(g), scipy.linalg.expm(group.hat(v)), atol=TOL)
        np.testing.assert_allclose(group.log(g), v, atol=1e-10)  # log loses ~2 digits near |v| = 2.5
        np.testing.assert_allclose(group.vee(group.hat(v)), v, atol=TOL)


@pytest.mark.parametrize("group", cartan.GROUPS, ids=lambda g: g.name)
def test_compose_inverse_identity_match_matrices(group):
    pts = points(group)
    for u, v in zip(pts, pts[1:]):
        g, h = group.exp(u), group.exp(v)
        np.testing.assert_allclose(group.matrix(group.compose(g, h)), group.matrix(g) @ group.matrix(h), atol=TOL)
        np.testing.assert_allclose(group.matrix(group.inverse(g)), np.linalg.inv(group.matrix(g)), atol=TOL)
    np.testing.assert_allclose(group.matrix(group.identity()), np.eye(group.matrix(group.identity()).shape[0]))


@pytest.mark.parametrize("group", cartan.GROUPS, ids=lambda g: g.name)
def test_adjoint_representations(group):
    pts = points(group)
    for u, v in zip(pts, pts[1:]):
        g = group.exp(u)
        m = group.matrix(g)
        # Ad_g v = vee(g hat(v) g^-1)
        np.testing.assert_allclose(group.hat(group.Ad(g) @ v), m @ group.hat(v) @ np.linalg.inv(m), atol=TOL)
        # ad_u v = [hat u, hat v] (matrix commutator), and bracket = ad
        hu, hv = group.hat(u), group.hat(v)
        np.testing.assert_allclose(group.hat(group.ad(u) @ v), hu @ hv - hv @ hu, atol=TOL)
        np.testing.assert_allclose(group.bracket(u, v), group.ad(u) @ v, atol=TOL)
        # <ad*_u mu, w> = <mu, ad_u w>
        mu, w = v[::-1].copy(), u + v
        assert group.ad_star(u, mu) @ w == pytest.approx(mu @ (group.ad(u) @ w), abs=TOL)
        np.testing.assert_allclose(group.ad_star(u), group.ad(u).T, atol=0)
        # Ad_{exp u} = expm(ad_u)
        np.testing.assert_allclose(group.Ad(g), scipy.linalg.expm(group.ad(u)), atol=1e-11)
        # left translation and its inverse
        x = group.left_translate(g, v)
        np.testing.assert_allclose(group.left_trivialise(g, x), v, atol=TOL)


def test_so3_specifics():
    a, b = np.array([-1.0, -1, -1]), np.array([0.9, 1, 1])
    r = cartan.SO3.minimal_rotation(a, b)
    np.testing.assert_allclose(r @ a / np.linalg.norm(a), b / np.linalg.norm(b), atol=TOL)
    axis = cartan.SO3.log(r)
    assert abs(axis @ a) < TOL and abs(axis @ b) < TOL  # rotation axis along a x b
    np.testing.assert_allclose(cartan.SO3.from_matrix(np.round(r, 8), 1e-6), r, atol=1e-8)
    np.testing.assert_allclose(cartan.SO3.hat([1, 2, 3]) @ [4, 5, 6], np.cross([1, 2, 3], [4, 5, 6]), atol=0)


def test_heisenberg_coordinates():
    # g(a,b,c) g(a',b',c') = g(a+a', b+b', c+c'+ab') and exp(v) = (v1, v2, v3 + v1 v2 / 2).
    g, h = np.array([1.0, 0.5, 0.8]), np.array([-0.3, 2.0, 0.1])
    np.testing.assert_allclose(cartan.Heisenberg.compose(g, h), [0.7, 2.5, 0.9 + 1.0 * 2.0], atol=TOL)
    np.testing.assert_allclose(cartan.Heisenberg.exp([1.0, 2.0, 3.0]), [1.0, 2.0, 4.0], atol=TOL)


def test_bad_input_raises_value_error_with_the_cpp_message():
    with pytest.raises(ValueError, match=r"^SO3\.exp: v = array of shape \(2,\) must have shape \(3,\)$"):
        cartan.SO3.exp([1.0, 2.0])
    with pytest.raises(ValueError, match=r"^SE3\.log: g = array of shape \(3, 3\) must have shape \(4, 4\)$"):
        cartan.SE3.log(np.eye(3))
    with pytest.raises(ValueError, match=r"SO3\.compose: g = 'abc' is not an array of numbers"):
        cartan.SO3.compose("abc", np.eye(3))
    bad = np.eye(3)
    bad[0, 0] = 1.01
    with pytest.raises(ValueError, match=r"^SO3: g = \[1\.01, 0, 0; .* is not orthogonal"):
        cartan.SO3.validate(bad)
    with pytest.raises(ValueError, match=r"^SO3::minimal_rotation: \(a, b\) = .*antiparallel"):
        cartan.SO3.minimal_rotation([1, 0, 0], [-2, 0, 0])
    with pytest.raises(ValueError, match=r"^Heisenberg: g = \[nan; 0; 0\] contains a non-finite number$"):
        cartan.Heisenberg.validate([np.nan, 0, 0])
