"""Checks a user can run on their own objects, each returning a :class:`cartan.CheckReport` (``ok``,
``checks``, ``str(report)`` naming each failing callback and the size of its discrepancy), as the
C++ headers ``cartan/testing/*.hpp`` do for GoogleTest users (docs/user-guide.md, "Checking your own
model").

:func:`check_lagrangian`
    a Lagrangian's callbacks against finite differences of each other (re-exported from cartan).
:func:`check_connection`
    an invariant connection on a group (``G.Connection(side, table)``, ``G.cartan_schouten(lam)``,
    or any object with ``nabla(u, w)``, ``torsion(v, w)``, ``curvature(u, v, w)`` and ``side``):
    torsion and curvature against their definitions from nabla and the bracket (cur-tor-left;
    the right side flips the bracket terms), their antisymmetry and the first Bianchi identity with
    torsion.
:func:`check_chart`
    a connection in coordinates (``cartan.Chart(christoffel, dim=)``, ``cartan.Euclidean``, or any
    object with ``christoffel(q, x, y)``, ``torsion(q, x, y)``, ``curvature(q, x, y, z)``): torsion
    and curvature against the Christoffel symbols (the curvature's derivative by central
    differences), their antisymmetry and the first Bianchi identity with torsion.

Relative discrepancies ``|a - b| / max(|a|, |b|, floor)``, with floor the largest term that enters
the identity (so that cancelling terms are measured against their own size, and the scale of the
object does not matter). Exact identities fail above 1e-10 (rounding of a few dozen flops on the
terms is ~1e-15); identities with central differences (step ``1e-5 (1 + |q|)``: error ~1e-10) above
max(1e-6, 10 x the differences' estimated error), as in the C++ check_lagrangian.
"""
import numpy as np

from .. import GROUPS, CheckReport, _cartan, check_lagrangian

__all__ = ["check_lagrangian", "check_connection", "check_chart", "IDENTITY_THRESHOLD", "DIFFERENCE_THRESHOLD"]

#: Relative discrepancy above which an exact identity fails.
IDENTITY_THRESHOLD = 1e-10
#: Relative discrepancy above which an identity with central differences fails (or 10 x their error).
DIFFERENCE_THRESHOLD = 1e-6
_STEP = 1e-5
_ROUNDING = 1e-14
_SAFETY = 10.0


def _inf(x):
    return float(np.max(np.abs(x))) if np.size(x) else 0.0


class _Check:
    """One check accumulated over the samples; the sample whose discrepancy is largest relative to
    its threshold is reported (as CheckAccumulator in check_lagrangian.hpp)."""

    def __init__(self, callback, reference):
        self.entry = dict(callback=callback, reference=reference, checked=True, ok=True, discrepancy=0.0,
                          reference_error=0.0, threshold=0.0, sample=-1, at="", note="")
        self.worst = 0.0

    def add(self, k, at, a, b, floor, base, error=0.0):
        a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
        note = ""
        if not (np.all(np.isfinite(a)) and np.all(np.isfinite(b))):
            discrepancy, relative_error, note = np.inf, 0.0, "a non-finite value"
        else:
            size = max(_inf(a), _inf(b), floor, error)
            discrepancy = _inf(a - b) / size if size > 0 else 0.0
            relative_error = error / size if size > 0 else 0.0
        threshold = max(base, _SAFETY * relative_error)
        ratio = discrepancy / threshold
        if self.entry["sample"] < 0 or ratio > self.worst:
            self.worst = ratio
            self.entry.update(discrepancy=float(discrepancy), reference_error=float(relative_error),
                              threshold=float(threshold), sample=k, at=at, note=note)
        self.entry["ok"] = bool(self.entry["ok"] and discrepancy <= threshold)


def _report(title, checks, samples):
    return CheckReport(**_cartan._check_report(title, [c.entry for c in checks], samples))


def _difference(f, h):
    """Central difference of f(e) at 0 and its estimated error (check_lagrangian.hpp's comment)."""
    plus, minus, plus2, minus2 = (np.asarray(f(e), dtype=float) for e in (h, -h, 2 * h, -2 * h))
    d1, d2 = (plus - minus) / (2 * h), (plus2 - minus2) / (4 * h)
    return d1, _inf(d1 - d2) + _ROUNDING * max(_inf(plus), _inf(minus), _inf(plus2), _inf(minus2)) / h


def _triples(rng, count, dim, scale):
    return [tuple(scale * rng.uniform(-1.0, 1.0, dim) for _ in range(3)) for _ in range(count)]


def _identity_checks(torsion, curvature, bianchi_note):
    """The five checks of a connection at (u, v, w): torsion and curvature against the given
    references, their antisymmetry, and the first Bianchi identity with torsion."""
    return [_Check("torsion", torsion), _Check("torsion antisymmetry", "-torsion(w, v)"),
            _Check("curvature", curvature), _Check("curvature antisymmetry", "-curvature(v, u, w)"),
            _Check("Bianchi identity", "cyc T(T(u, v), w) + (nabla_u T)(v, w)" + bianchi_note)]


def _group_of_connection(connection, group):
    if group is not None:
        return group
    group = getattr(connection, "group", None)
    if group is not None:
        return group
    for g in GROUPS:
        if isinstance(connection, g.Connection):
            return g
    raise ValueError(f"cartan.testing.check_connection: connection = {type(connection).__name__} has no group "
                     "(pass group=, e.g. cartan.SO3, or give it a `group` attribute)")


def check_connection(connection, group=None, *, samples=10, seed=20261122, scale=1.0):
    """Checks an invariant connection at `samples` seeded random triples (u, v, w) of algebra vectors
    with coordinates in [-scale, scale] and returns a :class:`cartan.CheckReport` with the checks
    torsion, torsion antisymmetry, curvature, curvature antisymmetry, Bianchi identity. The group
    is `group`, the connection's ``group`` attribute, or the group whose ``Connection`` class it is;
    ``side`` ("left" or "right") decides the sign of the bracket terms."""
    grp = _group_of_connection(connection, group)
    side = getattr(connection, "side", "left")
    if side not in ("left", "right"):
        raise ValueError(f"cartan.testing.check_connection: connection.side = {side!r} is not one of: left, right")
    sign = 1.0 if side == "left" else -1.0
    c = connection
    checks = _identity_checks("nabla_v w - nabla_w v - [v, w] (cur-tor-left)",
                              "nabla_u nabla_v w - nabla_v nabla_u w - nabla_[u,v] w (cur-tor-left)", "")
    rng = np.random.default_rng(seed)
    for k, (u, v, w) in enumerate(_triples(rng, samples, grp.dim, scale)):
        at = f"u = {u}, v = {v}, w = {w}"
        t_vw, bracket = c.torsion(v, w), grp.bracket(v, w)
        terms = (c.nabla(v, w), c.nabla(w, v), bracket)
        size = max(map(_inf, terms))  # the floor of both torsion checks
        checks[0].add(k, at, t_vw, terms[0] - terms[1] - sign * bracket, size, IDENTITY_THRESHOLD)
        checks[1].add(k, at, t_vw, -np.asarray(c.torsion(w, v)), size, IDENTITY_THRESHOLD)
        r = c.curvature(u, v, w)
        terms = (c.nabla(u, c.nabla(v, w)), c.nabla(v, c.nabla(u, w)), c.nabla(grp.bracket(u, v), w))
        size = max(map(_inf, terms))
        checks[2].add(k, at, r, terms[0] - terms[1] - sign * terms[2], size, IDENTITY_THRESHOLD)
        checks[3].add(k, at, r, -np.asarray(c.curvature(v, u, w)), size, IDENTITY_THRESHOLD)
        left, right, size = _bianchi_sides(
            lambda x, y, z: c.curvature(x, y, z), lambda x, y: c.torsion(x, y),
            lambda x, y, z: c.nabla(x, c.torsion(y, z)) - c.torsion(c.nabla(x, y), z) - c.torsion(y, c.nabla(x, z)),
            u, v, w)
        checks[4].add(k, at, left, right, size, IDENTITY_THRESHOLD)
    return _report("check_connection", checks, samples)


def _bianchi_sides(curvature, torsion, torsion_derivative, u, v, w):
    """The sides of cyc R(u, v) w = cyc [T(T(u, v), w) + (nabla_u T)(v, w)] and the largest term."""
    left, right, size = 0.0, 0.0, 0.0
    for x, y, z in ((u, v, w), (v, w, u), (w, u, v)):
        terms = (np.asarray(curvature(x, y, z)), np.asarray(torsion(torsion(x, y), z)), np.asarray(torsion_derivative(x, y, z)))
        left, right = left + terms[0], right + terms[1] + terms[2]
        size = max(size, *map(_inf, terms))
    return left, right, size


def check_chart(manifold, points, *, samples=4, seed=20261122, scale=1.0):
    """Checks a connection in coordinates at each of `points` (coordinate vectors inside the chart)
    with `samples` seeded random triples (x, y, z) of vectors with coordinates in [-scale, scale]
    each, and returns a :class:`cartan.CheckReport` with the checks torsion (against
    Gamma(x, y) - Gamma(y, x)), torsion antisymmetry, curvature (against D_x Gamma(y, z) -
    D_y Gamma(x, z) + Gamma(x, Gamma(y, z)) - Gamma(y, Gamma(x, z)), D by central differences of
    christoffel), curvature antisymmetry, Bianchi identity (nabla T by central differences of
    torsion). Coordinate vector fields commute and nabla_x y = Gamma_q(x, y) for constant y
    (``christoffel``'s convention)."""
    m = manifold
    dim = int(getattr(m, "dim"))
    if tuple(getattr(m, "point_shape", (dim,))) != (dim,):
        raise ValueError(f"cartan.testing.check_chart: manifold = {m!r} is not given in coordinates "
                         f"(point_shape {m.point_shape} is not ({dim},)); use a Chart or Euclidean")
    checks = _identity_checks("christoffel(v, w) - christoffel(w, v)", "differences of christoffel and its products",
                              ", nabla T by differences")
    rng = np.random.default_rng(seed)
    k = 0
    for q in points:
        q = np.asarray(q, dtype=float)
        h = _STEP * (1.0 + _inf(q))
        for x, y, z in _triples(rng, samples, dim, scale):
            at = f"q = {q}, x = {x}, y = {y}, z = {z}"
            gamma = lambda a, b, p=q: np.asarray(m.christoffel(p, a, b), dtype=float)  # noqa: E731
            terms = (gamma(x, y), gamma(y, x))
            size = max(map(_inf, terms))  # the floor of both torsion checks
            checks[0].add(k, at, m.torsion(q, x, y), terms[0] - terms[1], size, IDENTITY_THRESHOLD)
            checks[1].add(k, at, m.torsion(q, x, y), -np.asarray(m.torsion(q, y, x)), size, IDENTITY_THRESHOLD)
            r = m.curvature(q, x, y, z)
            dx, ex = _difference(lambda e: m.christoffel(q + e * x, y, z), h)
            dy, ey = _difference(lambda e: m.christoffel(q + e * y, x, z), h)
            terms = (dx, dy, gamma(x, gamma(y, z)), gamma(y, gamma(x, z)))
            size = max(map(_inf, terms))
            checks[2].add(k, at, r, terms[0] - terms[1] + terms[2] - terms[3], size, DIFFERENCE_THRESHOLD, ex + ey)
            checks[3].add(k, at, r, -np.asarray(m.curvature(q, y, x, z)), size, IDENTITY_THRESHOLD)
            errors = []

            def torsion_derivative(a, b, c):
                d, e = _difference(lambda s: m.torsion(q + s * a, b, c), h)
                errors.append(e)
                t = np.asarray(m.torsion(q, b, c))
                return d + gamma(a, t) - m.torsion(q, gamma(a, b), c) - m.torsion(q, b, gamma(a, c))

            left, right, size = _bianchi_sides(lambda a, b, c: m.curvature(q, a, b, c), lambda a, b: m.torsion(q, a, b),
                                               torsion_derivative, x, y, z)
            checks[4].add(k, at, left, right, size, DIFFERENCE_THRESHOLD, sum(errors))
            k += 1
    return _report("check_chart", checks, k)
