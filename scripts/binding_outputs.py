#!/usr/bin/env python3
"""Bit-for-bit safety net for a refactor of cartan's Python bindings (python/src/*.hpp, *.cpp).

    PYTHONPATH=<module dir> /usr/bin/python3 binding_outputs.py --write out.json
    PYTHONPATH=<module dir> /usr/bin/python3 binding_outputs.py --compare ref.json

--write records, for every case below, a digest of everything the bindings return: the SHA-256 of
every array (np.ascontiguousarray(a).tobytes(), with its dtype and shape), every scalar (exact: its
type and repr), every string, and for every exception its type and message. --compare recomputes
and prints every difference (exit 1 if any). Each case, and each part of a case, is in its own
try/except, so that a changed exception (type or message) is a recorded outcome like any other.

Excluded as nondeterministic (each is also marked where it is excluded):
* Result.solve_time (wall clock): only its type is recorded; it is masked in repr(r) and removed
  from the to_json text before hashing.
* The result stopped by time_limit: only its status (and success) is recorded, not its arrays or
  message (how far it got depends on the machine's load).
* Memory addresses ("0x7f..."), should any message or repr contain one, are masked as "0x?" (the
  messages naming a Python object, e.g. "object = <object object at 0x...> has no method value").
* The machine's physical memory in the message of an N too large ("more than this machine's
  23.5 GiB"): deterministic on one machine, masked so that a reference compares across machines.
"""
import argparse
import dataclasses
import hashlib
import json
import math
import os
import pickle
import re
import sys
import tempfile
import time
import traceback
import warnings

import numpy as np

import cartan
from cartan import _cartan

# The test suite's Python models (python/tests/python_models.py), the same objects the tests solve.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "python", "tests"))
from python_models import PyH3Oscillator, PyRigidBody, PySO3Oscillator, PySO3OscillatorWithHessian, SphereKinetic, vee_skew  # noqa: E402

SO3, SE2, SE3, H3 = cartan.SO3, cartan.SE2, cartan.SE3, cartan.Heisenberg

# ---- digests --------------------------------------------------------------------------------------

_ADDRESS = re.compile(r"0x[0-9a-fA-F]{6,}")
_SOLVE_TIME_REPR = re.compile(r"solve_time=[^,)]*")


_MACHINE_MEMORY = re.compile(r"this machine's [0-9.e+]+ GiB")


def clean(text):
    """A string with memory addresses masked (nondeterministic), and the machine's physical memory
    (N too large: "more than this machine's 23.5 GiB") masked so that the file compares across machines."""
    return _MACHINE_MEMORY.sub("this machine's ? GiB", _ADDRESS.sub("0x?", text))


def array_digest(a):
    a = np.asarray(a)
    if a.dtype == object:  # pointers: digest the elements instead
        return {"object_array": [D(x) for x in a.ravel().tolist()], "shape": list(a.shape)}
    c = np.ascontiguousarray(a)
    return {"sha256": hashlib.sha256(c.tobytes()).hexdigest(), "dtype": str(c.dtype), "shape": list(c.shape),
            "type": type(a).__name__}


def D(x):
    """A JSON-able, exact digest of x."""
    if x is None:
        return None
    if isinstance(x, np.ndarray):
        return array_digest(x)
    if isinstance(x, (bool, np.bool_)):
        return f"{type(x).__name__}:{bool(x)}"
    if isinstance(x, (int, np.integer)):
        return f"{type(x).__name__}:{int(x)}"
    if isinstance(x, (float, np.floating)):
        return f"{type(x).__name__}:{float(x)!r}"
    if isinstance(x, complex):
        return f"complex:{x!r}"
    if isinstance(x, str):
        return clean(x)
    if isinstance(x, bytes):
        return {"bytes_sha256": hashlib.sha256(x).hexdigest()}
    if isinstance(x, type):
        return f"type:{x.__module__}.{x.__qualname__}"
    if isinstance(x, tuple) and hasattr(x, "_fields"):  # NamedTuple (State, GeneralState)
        return {"namedtuple": type(x).__name__, **{k: D(getattr(x, k)) for k in x._fields}}
    if isinstance(x, dict):
        return {"dict": {str(k): D(v) for k, v in x.items()}, "keys": [str(k) for k in x.keys()]}
    if isinstance(x, (list, tuple)):
        return {type(x).__name__: [D(v) for v in x]}
    if dataclasses.is_dataclass(x) and not isinstance(x, type):
        return {"dataclass": type(x).__name__, **{f.name: D(getattr(x, f.name)) for f in dataclasses.fields(x)}}
    return {"other": type(x).__qualname__, "repr": clean(repr(x))}


def exc_record(e):
    return {"exception": f"{type(e).__module__}.{type(e).__qualname__}", "message": clean(str(e))}


def attempt(out, key, thunk):
    """out[key] = D(thunk()), or the exception's type and message."""
    try:
        out[key] = D(thunk())
    except Exception as e:  # noqa: BLE001 (every outcome is recorded)
        out[key] = exc_record(e)


# ---- a Result and everything that can be done with it -------------------------------------------

def result_fields(r):
    """Every field of a Result; solve_time (wall clock, nondeterministic) by its type only."""
    out = {}
    for f in dataclasses.fields(r):
        if f.name == "problem":
            continue
        value = getattr(r, f.name)
        out[f.name] = f"type:{type(value).__name__}" if f.name == "solve_time" else D(value)
    p = r.problem
    out["problem"] = {"kind": D(p.kind), "space": D(p.space) if isinstance(p.space, type) else
                      (None if p.space is None else f"instance:{type(p.space).__name__}"),
                      "lagrangian": None if p.lagrangian is None else f"instance:{type(p.lagrangian).__name__}",
                      "lam": D(p.lam), "q0": D(p.q0), "qT": D(p.qT), "inertia": D(p.inertia),
                      "potential": None if p.potential is None else "callable",
                      "potential_gradient": None if p.potential_gradient is None else "callable",
                      "gravity": D(p.gravity), "frame0": D(p.frame0), "model": D(p.model)}
    for name in ("converged", "iterations", "g0", "gT", "lam", "group", "manifold", "connection", "side", "model"):
        attempt(out, "." + name, lambda name=name: getattr(r, name))
    out[".g_is_q"] = r.g is r.q
    out[".P_is_frame"] = r.P is r.frame
    # repr: solve_time masked (nondeterministic)
    attempt(out, "repr", lambda: _SOLVE_TIME_REPR.sub("solve_time=?", repr(r)))
    return out


def dense_times(r):
    T = float(r.T)
    t = np.asarray(r.t)
    times = [0.0, T / 3, T / 2, T]
    if len(t) > 4:
        times.append(0.5 * (t[3] + t[4]))
    return times


def full_record(r, verify_args=(), verify_kwargs=None, group_along=None, json_load=True, load_space=None):
    """The result's fields, verify, along, dense output, pickling, to_json/load and model_of."""
    out = {"fields": result_fields(r)}
    attempt(out, "verify", lambda: cartan.verify(r, *verify_args, **(verify_kwargs or {})))
    if verify_args or verify_kwargs:
        attempt(out, "verify_self", lambda: cartan.verify(r))
    if group_along is not None:  # the library's quantities along a group model's result, called directly
        grp, model = group_along
        attempt(out, "_along", lambda: grp._along(model, r, r.lam))
    times = dense_times(r)
    for i, t in enumerate(times):
        attempt(out, f"sol[{i}]={t!r}", lambda t=t: r.sol(t))
    attempt(out, "sol(array)", lambda: r.sol(np.array(times)))
    attempt(out, "sol(nodes)", lambda: r.sol(np.asarray(r.t)[[0, 1, -1]]))
    attempt(out, "sol(T*(1+1e-16))", lambda: r.sol(float(r.T) * (1 + 1e-16)))
    attempt(out, "sol(beyond T)", lambda: r.sol(float(r.T) * 1.5))
    attempt(out, "sol(-1)", lambda: r.sol(-1.0))

    def pickled():
        back = pickle.loads(pickle.dumps(r))
        rec = {"fields": result_fields(back), "solve_time_kept": back.solve_time == r.solve_time}
        attempt(rec, "verify", lambda: cartan.verify(back, *verify_args, **(verify_kwargs or {})))
        attempt(rec, "sol(T/3)", lambda: back.sol(float(back.T) / 3))
        return rec
    try:
        out["pickle"] = pickled()
    except Exception as e:  # noqa: BLE001
        out["pickle"] = exc_record(e)
    attempt(out, "model_of", lambda: type(cartan.model_of(r)))
    if json_load:
        try:
            out["json"] = json_record(r, load_space, verify_args, verify_kwargs)
        except Exception as e:  # noqa: BLE001
            out["json"] = exc_record(e)
    return out


def json_record(r, load_space, verify_args, verify_kwargs):
    rec = {}
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "r.json")
        try:
            r.to_json(path)
        except Exception as e:  # noqa: BLE001
            rec["to_json"] = exc_record(e)
            return rec
        with open(path, encoding="utf-8") as f:
            text = f.read()
        # solve_time (wall clock) removed before hashing: nondeterministic
        parsed = json.loads(text)
        rec["keys"] = list(parsed.keys())
        rec["solve_time_type"] = type(parsed.get("solve_time_s")).__name__
        # "solve_time_s" (wall clock) masked before hashing: nondeterministic
        masked = re.sub(r'"(solve_time[a-z_]*)":\s*[^,}\]]*', r'"\1":?', text)
        rec["text_sha256"] = hashlib.sha256(masked.encode()).hexdigest()
        rec["text_length"] = len(masked)
        for key in ("status", "message", "method", "branch", "model", "manifold", "group", "connection"):
            if key in parsed:
                rec[key] = D(parsed[key])
        try:
            back = cartan.load(path) if load_space is None else cartan.load(path, space=load_space)
        except Exception as e:  # noqa: BLE001
            rec["load"] = exc_record(e)
            if load_space is None:
                return rec
            return rec
        rec["load"] = result_fields(back)
        attempt(rec, "load_verify", lambda: cartan.verify(back))
        if verify_args or verify_kwargs:
            attempt(rec, "load_verify_given", lambda: cartan.verify(back, *verify_args, **(verify_kwargs or {})))
        attempt(rec, "load_sol", lambda: back.sol(np.array(dense_times(back))))
    return rec


# ---- models written in Python (as in python/tests) ----------------------------------------------

class VectorizedOscillator:
    group = SO3
    vectorized = True

    def __init__(self, inertia):
        self.inertia = np.diag(inertia).astype(float)
        self.inverse_inertia = np.diag(1.0 / np.asarray(inertia, dtype=float))
        self.batches = []

    def value(self, t, g, v):
        self.batches.append(("value", len(t)))
        return 0.5 * np.sum((v @ self.inertia) * v, axis=1) - 0.5 * (3.0 - np.trace(g, axis1=1, axis2=2))

    def momentum(self, t, g, v):
        self.batches.append(("momentum", len(t)))
        return v @ self.inertia

    def group_gradient(self, t, g, v):
        self.batches.append(("group_gradient", len(t)))
        return -0.5 * (g[:, (2, 0, 1), (1, 2, 0)] - g[:, (1, 2, 0), (2, 0, 1)])

    def velocity(self, t, g, mu):
        self.batches.append(("velocity", len(t)))
        return mu @ self.inverse_inertia


class WrongRows(VectorizedOscillator):
    def momentum(self, t, g, v):
        return super().momentum(t, g, v)[0]


class GroupKinetic:
    """l = 1/2 v.A v - 1/2 (3 - tr q) on a GroupManifold of SO(3) (a manifold's Lagrangian object)."""

    def __init__(self, A):
        self.A = np.diag(A).astype(float)

    def value(self, t, q, v):
        return 0.5 * v @ self.A @ v - 0.5 * (3.0 - np.trace(q))

    def momentum(self, t, q, v):
        return self.A @ v

    def velocity(self, t, q, mu):
        return np.linalg.solve(self.A, mu)

    def point_gradient(self, t, q, v):
        return -vee_skew(q)


class PyHamiltonian:
    group = SO3

    def __init__(self, inertia):
        self.inverse = np.diag(1.0 / np.asarray(inertia, float))

    def value(self, t, g, mu):
        return 0.5 * mu @ self.inverse @ mu

    def velocity(self, t, g, mu):
        return self.inverse @ mu

    def group_gradient(self, t, g, mu):
        return np.zeros(3)


class UserError(Exception):
    pass


class RaisingLagrangian(PyRigidBody):
    instance = None

    def group_gradient(self, t, g, v):
        RaisingLagrangian.instance = UserError(f"user bug at t = {t!r}")
        raise RaisingLagrangian.instance


class WrongShape(PyRigidBody):
    def momentum(self, t, g, v):
        return np.zeros(2)


class NaNForce(PyRigidBody):
    def group_gradient(self, t, g, v):
        return np.array([np.nan, 0, 0]) if t > 0.5 else np.zeros(3)


class WrongInverse(PyRigidBody):
    def velocity(self, t, g, mu):
        return super().velocity(t, g, mu) * 1.001


class BadHessian(PySO3OscillatorWithHessian):
    def hessian(self, t, g, v):
        h = super().hessian(t, g, v)
        del h["momentum_g"]
        return h


class BadMomentumOnSphere(SphereKinetic):
    def momentum(self, t, q, v):
        return np.zeros(3)


def half_plane_christoffel(q):
    g = np.zeros((2, 2, 2))
    g[0, 0, 1] = g[0, 1, 0] = g[1, 1, 1] = -1 / q[1]
    g[1, 0, 0] = 1 / q[1]
    return g


def half_plane_metric(q):
    return np.eye(2) / q[1] ** 2


def torsion_christoffel(q):
    """A non-constant field with torsion on R^2 (no metric)."""
    g = np.zeros((2, 2, 2))
    g[0, 0, 1] = 0.3 + 0.1 * q[0]
    g[0, 1, 0] = -0.3
    g[1, 0, 0] = 0.2 * q[1]
    return g


def nan_below_axis(q):
    """The half-plane's symbols, NaN for y <= 0 (outside the chart)."""
    return half_plane_christoffel([q[0], q[1] if q[1] > 0 else np.nan])


def raises_below_axis(q):
    if q[1] <= 0:
        raise ValueError(f"{q[1]!r} is outside the half-plane")
    return half_plane_christoffel(q)


def hyperbolic(x, y):
    return np.array([x, y, np.sqrt(1 + x * x + y * y)])


GT = SO3.minimal_rotation([-1.0, -1, -1], [0.9, 1.0, 1.0])
GT_LONG = SO3.minimal_rotation([-0.7, -1, -0.7], [0.8, 0.8, 1])
INERTIA = [2.0, 3.0, 4.0]
S2_Q0, S2_QT = cartan.Sphere.point([1, 0, -0.3]), cartan.Sphere.point([0, 1, -0.5])
SPHERE_ARGS = dict(T=1.0, N=20, q0=[0, 0, 1.0], qT=cartan.Sphere.point([1, 0, 1]))
GROUP_ARGS = dict(lam=0.5, T=1.0, N=10, gT=GT)

# ---- the cases ------------------------------------------------------------------------------------

CASES = []


def case(name):
    def register(f):
        CASES.append((name, f))
        return f
    return register


def sub(thunk):
    """A part of a case that may raise: its record or the exception."""
    try:
        return thunk()
    except Exception as e:  # noqa: BLE001
        return exc_record(e)


def group_case(model, grp=None, verify_args=(), **kwargs):
    r = cartan.solve(model, **kwargs)
    grp = grp or getattr(model, "group", None)
    return full_record(r, verify_args=verify_args, group_along=(grp, model) if grp is not None else None)


# -- group models (the Lie-group kernel), every group, every method

@case("so3-rigidbody-shooting-order2")
def _():
    return group_case(cartan.RigidBody(INERTIA), lam=0.5, T=3.0, N=100, gT=GT, method="shooting", order=2, tol=1e-10)


@case("so3-oscillator-auto")
def _():
    return group_case(cartan.SO3Oscillator(INERTIA), lam=0.5, T=3.0, N=150, gT=GT)


@case("so3-oscillator-collocation")
def _():
    return group_case(cartan.SO3Oscillator(INERTIA), lam=0.5, T=3.0, N=40, gT=GT, method="collocation", tol=1e-8,
                      samples=60)


@case("so3-oscillator-variational")
def _():
    return group_case(cartan.SO3Oscillator(INERTIA), lam=0.3, T=3.0, N=60, gT=GT, method="variational", tol=1e-11)


@case("so3-oscillator-multiple-shooting")
def _():
    return group_case(cartan.SO3Oscillator(INERTIA), lam=0.5, T=3.0, N=90, gT=GT, method="multiple-shooting",
                      segments=3, tol=1e-11)


@case("so3-rigidbody-two-level")
def _():
    return group_case(cartan.RigidBody(INERTIA), lam=0.5, T=3.0, N=100, gT=GT, method="two-level", tol=1e-10)


@case("so3-oscillator-continuation-lambda-and-T")
def _():
    m = cartan.SO3Oscillator(INERTIA)
    out = {"lambda": group_case(m, lam=0.7, T=3.0, N=80, gT=GT, method="shooting", continuation="lambda",
                                lambda_start=0.0, tol=1e-11)}
    out["T"] = group_case(m, lam=0.5, T=3.0, N=80, gT=GT, method="shooting", continuation="T", tol=1e-11)
    return out


@case("so3-guesses-and-progress")
def _():
    m = cartan.SO3Oscillator(INERTIA)
    ref = cartan.solve(m, lam=0.5, T=3.0, N=60, gT=GT, method="shooting", tol=1e-12)
    out = {"ref": result_fields(ref)}
    seen = []
    r = cartan.solve(m, lam=0.5, T=3.0, N=60, gT=GT, method="shooting", v0=ref.v0 + 0.01, xi0=ref.xi0, tol=1e-12,
                     progress=lambda stage, it, res: seen.append((stage, it, res)))
    out["v0xi0"] = result_fields(r)
    out["progress"] = D(seen)
    out["trajectory_guess"] = result_fields(cartan.solve(m, lam=0.5, T=3.0, N=60, gT=GT, method="shooting",
                                                         guess=ref, tol=1e-12))
    out["collocation_guess"] = result_fields(cartan.solve(m, lam=0.5, T=3.0, N=60, gT=GT, method="collocation",
                                                          guess=ref, tol=1e-8))
    out["g0"] = result_fields(cartan.solve(m, lam=0.5, T=2.0, N=50, g0=SO3.exp([0.1, 0.2, -0.1]), gT=GT,
                                           method="shooting", tol=1e-12))
    return out


@case("heisenberg-oscillator")
def _():
    return group_case(cartan.H3Oscillator(), lam=0.3, T=1.0, N=120, gT=np.array([0.5, -0.3, 0.2]), order=2,
                      tol=1e-10)


@case("se2-free-body")
def _():
    return group_case(cartan.SE2FreeBody([3.0, 3.0, 0.7]), lam=0.5, T=1.0, N=120, gT=SE2.exp([0.3, -0.2, 0.4]),
                      order=2, tol=1e-10)


@case("se3-free-body")
def _():
    return group_case(cartan.SE3FreeBody([1.0, 2.0, 3.0, 4.0, 4.0, 4.0]), lam=0.5, T=1.0, N=100,
                      gT=SE3.exp([0.2, -0.1, 0.3, 0.4, 0.1, -0.2]), tol=1e-10)


@case("python-lagrangian-on-group")
def _():
    out = {"so3": group_case(PySO3Oscillator(INERTIA), lam=0.5, T=3.0, N=60, gT=GT, method="shooting", order=2,
                             tol=1e-11)}
    out["so3-hessian"] = group_case(PySO3OscillatorWithHessian(INERTIA), lam=0.5, T=3.0, N=60, gT=GT,
                                    method="two-level", tol=1e-10)
    out["heisenberg"] = group_case(PyH3Oscillator(), lam=0.3, T=1.0, N=50, gT=np.array([0.5, -0.3, 0.2]),
                                   method="shooting", tol=1e-10)
    out["se2-group-kwarg"] = result_fields(cartan.solve(PyRigidBody([1.0, 2.0, 0.5], group=SE2), lam=0.5, T=2, N=60,
                                                        gT=SE2.exp([0.3, -0.2, 0.4]), tol=1e-10))
    return out


@case("vectorized-lagrangian")
def _():
    m = VectorizedOscillator(INERTIA)
    out = group_case(m, lam=0.5, T=3.0, N=60, gT=GT, method="shooting", order=2, tol=1e-12)
    out["batches_sha"] = hashlib.sha256(repr(m.batches).encode()).hexdigest()
    out["batches_len"] = len(m.batches)
    return out


# -- manifolds (the general kernel) and GroupManifold

def manifold_case(manifold, lagrangian=None, verify_args=(), verify_kwargs=None, load_space=None, **kwargs):
    r = cartan.solve(lagrangian, space=manifold, **kwargs) if lagrangian is not None else cartan.solve(manifold, **kwargs)
    return full_record(r, verify_args=verify_args, verify_kwargs=verify_kwargs, load_space=load_space)


@case("sphere-gravity-inertia")
def _():
    out = manifold_case(cartan.Sphere(), T=1.0, N=120, q0=S2_Q0, qT=S2_QT, inertia=[1.0, 2.0], gravity=3.0, order=2,
                        tol=1e-10)
    out["collocation"] = manifold_case(cartan.Sphere(), T=1.0, N=30, q0=S2_Q0, qT=S2_QT, gravity=3.0,
                                       method="collocation", tol=1e-8, samples=40)
    frame0 = cartan.Sphere().tangent_basis(S2_Q0) @ np.array([[0.0, 2.0], [1.0, 0.0]])
    out["frame0-v0"] = result_fields(cartan.solve(cartan.Sphere(), T=1.0, N=60, q0=S2_Q0, qT=S2_QT, gravity=3.0,
                                                  frame0=frame0, inertia=[1.0, 4.0], v0=[0.5, -0.5], tol=1e-10))
    return out


@case("hyperbolic-plane")
def _():
    return manifold_case(cartan.HyperbolicPlane(), T=1.0, N=100, q0=hyperbolic(0.1, 0.2), qT=hyperbolic(-0.4, 0.5),
                         gravity=0.5, tol=1e-11)


@case("euclidean")
def _():
    out = {"torsion": manifold_case(cartan.Euclidean(np.array([[[0, 0.3], [-0.3, 0]], [[0, 0], [0, 0]]])), T=2.0,
                                    N=100, q0=[0.5, 0.0], qT=[-0.3, 0.4], inertia=[1.0, 2.0], order=2, tol=1e-11)}
    out["flat3-gravity-collocation"] = manifold_case(cartan.Euclidean(dim=3), T=1.0, N=20, q0=[0.0, 0, 0],
                                                     qT=[1.0, 0, 0], gravity=9.81, method="collocation", tol=1e-8)
    return out


@case("group-manifold-cartan-schouten")
def _():
    gm = cartan.GroupManifold("so3", "cartan-schouten", lam=0.3)
    out = {"auto": manifold_case(gm, T=3.0, N=100, q0=np.eye(3), qT=GT, inertia=INERTIA, tol=1e-10)}
    out["two-level"] = manifold_case(gm, T=3.0, N=60, q0=np.eye(3), qT=GT, inertia=INERTIA, method="two-level",
                                     tol=1e-10)
    out["se2-multiple-shooting"] = sub(lambda: manifold_case(
        cartan.GroupManifold("se2", "cartan-schouten", lam=0.5), T=1.0, N=60, q0=np.eye(3),
        qT=SE2.exp([0.3, -0.2, 0.4]), inertia=[3.0, 3.0, 0.7], method="multiple-shooting", segments=2, tol=1e-10))
    # A Connection object: the general kernel (not the Lie-group one), so multiple shooting is refused.
    out["se2-connection-object"] = sub(lambda: manifold_case(
        cartan.GroupManifold(SE2, SE2.cartan_schouten(0.5)), T=1.0, N=60, q0=np.eye(3),
        qT=SE2.exp([0.3, -0.2, 0.4]), inertia=[3.0, 3.0, 0.7], tol=1e-10))
    out["se2-connection-object-multiple-shooting"] = sub(lambda: manifold_case(
        cartan.GroupManifold(SE2, SE2.cartan_schouten(0.5)), T=1.0, N=60, q0=np.eye(3),
        qT=SE2.exp([0.3, -0.2, 0.4]), inertia=[3.0, 3.0, 0.7], method="multiple-shooting", segments=2))
    return out


@case("group-manifold-levi-civita-and-coefficients")
def _():
    out = {"so3-lc": manifold_case(cartan.GroupManifold("so3", "levi-civita", metric=INERTIA), T=3.0, N=100,
                                   q0=np.eye(3), qT=GT, inertia=INERTIA, order=2, tol=1e-10)}
    alpha = 0.2 * np.array([[SO3.bracket(a, b) for b in np.eye(3)] for a in np.eye(3)])
    alpha[0, 1, 2] += 0.05
    out["heisenberg-coefficients"] = manifold_case(cartan.GroupManifold("heisenberg", "coefficients", alpha=alpha),
                                                   T=1.0, N=60, q0=np.zeros(3), qT=np.array([0.4, -0.2, 0.1]),
                                                   tol=1e-10)
    return out


@case("chart-with-metric")
def _():
    chart = cartan.Chart(half_plane_christoffel, dim=2, metric=half_plane_metric, name="half-plane", parallel=True)
    out = manifold_case(chart, T=1.0, N=40, q0=[-0.5, 0.8], qT=[0.6, 1.2], tol=1e-10, load_space=chart)
    out["repr"] = D(repr(chart))
    return out


@case("chart-without-metric")
def _():
    chart = cartan.Chart(torsion_christoffel, dim=2)
    out = manifold_case(chart, T=1.0, N=40, q0=[0.0, 0.2], qT=[1.0, 0.5], inertia=[1.0, 2.0], method="shooting",
                        tol=1e-10, load_space=chart)
    out["repr"] = D(repr(chart))
    return out


@case("python-lagrangian-on-manifold")
def _():
    sk = SphereKinetic(np.diag([1.0, 2.5]), 3.0)
    out = {"sphere": manifold_case(cartan.Sphere(), lagrangian=sk, verify_args=(sk,),
                                   verify_kwargs=dict(space=cartan.Sphere()), T=1.2, N=80,
                                   q0=cartan.Sphere.point([1, 0.2, 0.1]), qT=cartan.Sphere.point([-0.2, 1, -0.4]),
                                   tol=1e-11)}
    gk = GroupKinetic(INERTIA)
    gm = cartan.GroupManifold("so3", "levi-civita", metric=INERTIA)
    out["group-manifold"] = manifold_case(gm, lagrangian=gk, T=2.0, N=60, q0=np.eye(3), qT=GT, tol=1e-10)
    return out


@case("python-potential")
def _():
    k = 2.0
    out = {"euclidean": manifold_case(cartan.Euclidean(dim=2), T=1.3, N=100, q0=[0.4, -0.2], qT=[-0.3, 0.5],
                                      potential=lambda q: 0.5 * k * q @ q, potential_gradient=lambda q: k * q,
                                      order=2, tol=1e-12)}
    out["sphere"] = manifold_case(cartan.Sphere(), T=1.2, N=80, q0=cartan.Sphere.point([1, 0.2, 0.1]),
                                  qT=cartan.Sphere.point([-0.2, 1, -0.4]), inertia=[1.0, 2.5],
                                  potential=lambda q: 3.0 * q[2], potential_gradient=lambda q: np.array([0, 0, 3.0]),
                                  tol=1e-12)
    return out


@case("time-limit")
def _():
    # Nondeterministic (how far a stopped solve got depends on the machine): status and success only.
    out = {}
    for method in ("variational", "shooting"):
        try:
            r = cartan.solve(cartan.SO3Oscillator(INERTIA), lam=0.5, T=12, N=200, gT=GT_LONG, method=method,
                             tol=1e-13, max_iterations=100000, time_limit=1e-9)
            out[method] = {"status": r.status, "success": r.success}
        except Exception as e:  # noqa: BLE001
            out[method] = exc_record(e)
    try:
        r = cartan.solve(cartan.Sphere(), T=1.0, N=200, q0=S2_Q0, qT=S2_QT, gravity=9.81, tol=2.3e-14,
                         method="shooting", max_iterations=100000, time_limit=1e-9)
        out["sphere"] = {"status": r.status, "success": r.success}
    except Exception as e:  # noqa: BLE001
        out["sphere"] = exc_record(e)
    return out


@case("failed-results")
def _():
    out = {"group": group_case(cartan.SO3Oscillator(INERTIA), lam=0.0, T=12, N=200, gT=GT_LONG, method="shooting",
                               max_iterations=3)}
    out["sphere"] = manifold_case(cartan.Sphere(), T=1.0, N=100, q0=S2_Q0, qT=S2_QT, gravity=9.81, tol=1e-12,
                                  method="shooting", max_iterations=1)
    return out


@case("deprecated-doors-and-cancel")
def _():
    out = {}
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = cartan.solve_general(cartan.Sphere(), T=1.0, N=40, q0=S2_Q0, qT=S2_QT, gravity=3.0, tol=1e-11)
        out["solve_general"] = result_fields(r)
        general = r
        attempt(out, "verify_general", lambda: cartan.verify_general(r, cartan.Sphere(), gravity=3.0))
        out["warnings"] = [f"{w.category.__name__}: {w.message}" for w in caught]
    # A cancel token cancelled before the solve: it stops at its first iteration (status only, like time-limit).
    token = _cartan._CancelToken()
    token.cancel()
    out["token_cancelled"] = D(token.cancelled)
    try:
        with token:
            r = cartan.solve(cartan.SO3Oscillator(INERTIA), lam=0.5, T=3.0, N=60, gT=GT, method="shooting")
        out["cancelled_solve"] = {"status": r.status, "success": r.success}
    except BaseException as e:  # noqa: BLE001 (KeyboardInterrupt is a possible outcome)
        out["cancelled_solve"] = exc_record(e)
    attempt(out, "replace", lambda: result_fields(general.replace(q0=S2_QT, status="edited")))
    return out


@case("sweep")
def _():
    problems = [dict(lagrangian=cartan.Sphere(), T=1.0, N=50, q0=S2_Q0, qT=S2_QT, gravity=g) for g in (0.0, 3.0)]
    problems.append(dict(lagrangian=cartan.RigidBody(INERTIA), lam=0.5, T=2.0, N=50, gT=GT))
    return {"results": [result_fields(r) for r in cartan.sweep(problems)]}


# -- the other tools of the bindings

@case("groups-and-connections")
def _():
    out = {}
    rng = np.random.default_rng(7)
    for grp in cartan.GROUPS:
        n = grp.dim
        u, v, w = rng.normal(size=n) * 0.4, rng.normal(size=n) * 0.4, rng.normal(size=n) * 0.4
        g, h = grp.exp(u), grp.exp(v)
        rec = {"name": D(grp.name), "dim": D(grp.dim), "element_shape": D(grp.element_shape), "methods": D(grp.methods)}
        calls = {
            "identity": lambda: grp.identity(), "compose": lambda: grp.compose(g, h), "inverse": lambda: grp.inverse(g),
            "exp": lambda: grp.exp(u), "log": lambda: grp.log(g), "hat": lambda: grp.hat(u),
            "vee": lambda: grp.vee(grp.hat(u)), "matrix": lambda: grp.matrix(g), "Ad": lambda: grp.Ad(g),
            "ad": lambda: grp.ad(u), "ad_star": lambda: grp.ad_star(u, v), "ad_star_matrix": lambda: grp.ad_star(u),
            "bracket": lambda: grp.bracket(u, v), "left_translate": lambda: grp.left_translate(g, u),
            "left_trivialise": lambda: grp.left_trivialise(g, grp.left_translate(g, u)),
            "validate": lambda: grp.validate(g), "validate_bad": lambda: grp.validate(np.full(grp.element_shape, 7.0)),
            "constructor": lambda: grp(),
        }
        for key, f in calls.items():
            attempt(rec, key, f)
        cs = grp.cartan_schouten(0.3)
        table = np.ascontiguousarray(rng.normal(size=(n, n * n)))
        attempt(rec, "cs", lambda: {"side": cs.side, "coefficients": cs.coefficients, "nabla": cs.nabla(u, v),
                                    "torsion": cs.torsion(u, v), "curvature": cs.curvature(u, v, w),
                                    "is_cartan": cs.is_cartan()})
        attempt(rec, "cs_right", lambda: grp.cartan_schouten(0.3, side="right").coefficients)
        attempt(rec, "connection_table", lambda: (lambda c: {"side": c.side, "coefficients": c.coefficients,
                                                             "is_cartan": c.is_cartan(),
                                                             "curvature": c.curvature(u, v, w)})(
            grp.Connection("left", table)))
        for method in ("lie-euler", "magnus2", "magnus4"):
            attempt(rec, f"transport-{method}", lambda method=method: cs.transport(
                lambda r: u + r * v, 0.0, 1.0, steps=8, method=method))
            attempt(rec, f"cs_transport-{method}", lambda method=method: grp.cartan_schouten_transport(
                0.3, lambda r: u + r * v, 0.0, 1.0, steps=8, method=method))
        nodes = np.array([u + k / 4 * v for k in range(5)])
        attempt(rec, "transport_sampled", lambda: cs.transport_sampled(nodes, 0.0, 1.0, method="magnus2"))
        attempt(rec, "transport_nodes", lambda: cs.transport(lambda r: u + r * v, 0.0, 1.0, steps=4, nodes=True))
        attempt(rec, "transport_bad_method", lambda: cs.transport(lambda r: u, 0.0, 1.0, method="euler"))
        attempt(rec, "connection_bad_table", lambda: grp.Connection("left", np.zeros((n, n))))
        out[grp.__name__] = rec
    attempt(out, "SO3.minimal_rotation", lambda: SO3.minimal_rotation([1.0, 0, 0], [0, 1.0, 0.2]))
    attempt(out, "SO3.from_matrix", lambda: SO3.from_matrix(np.round(GT, 7)))
    attempt(out, "SO3.from_matrix_tolerance", lambda: SO3.from_matrix(np.round(GT, 7), tolerance=1e-6))
    attempt(out, "SO3.from_matrix_bad", lambda: SO3.from_matrix(np.diag([2.0, 1, 1])))
    return out


@case("models-mechanics-and-checks")
def _():
    out = {}
    rng = np.random.default_rng(11)
    builtins = [(cartan.RigidBody, SO3, INERTIA), (cartan.SO3Oscillator, SO3, INERTIA),
                (cartan.SpatialRigidBody, SO3, INERTIA), (cartan.H3Oscillator, H3, [1.0, 2.0, 3.0]),
                (cartan.SE2FreeBody, SE2, [3.0, 3.0, 0.7]), (cartan.SE3FreeBody, SE3, [1.0, 2, 3, 4, 4, 4]),
                (cartan.RigidBodyHamiltonian, SO3, INERTIA), (cartan.SO3OscillatorHamiltonian, SO3, INERTIA),
                (cartan.SpatialRigidBodyHamiltonian, SO3, INERTIA), (cartan.H3OscillatorHamiltonian, H3, [1.0, 2, 3]),
                (cartan.SE2FreeBodyHamiltonian, SE2, [3.0, 3.0, 0.7]),
                (cartan.SE3FreeBodyHamiltonian, SE3, [1.0, 2, 3, 4, 4, 4])]
    for cls, grp, inertia in builtins:
        m = cls(inertia)
        g, v = grp.exp(rng.normal(size=grp.dim) * 0.3), rng.normal(size=grp.dim)
        rec = {"group": D(m.group), "side": D(m.side), "inertia": D(m.inertia), "state": D(m.__getstate__())}
        names = ("value", "velocity", "group_gradient") + (() if "Hamiltonian" in cls.__name__ else ("momentum",))
        for name in names:
            attempt(rec, name, lambda name=name: getattr(m, name)(0.3, g, v))
        attempt(rec, "pickle", lambda: pickle.loads(pickle.dumps(m)).inertia)
        attempt(rec, "full_inertia", lambda: cls(np.diag(inertia) + 0.0).inertia)
        if "Hamiltonian" not in cls.__name__:
            attempt(rec, "lagrangian_hessian", lambda: cartan.lagrangian_hessian(m, 0.3, g, v))
            attempt(rec, "check_lagrangian", lambda: cartan.check_lagrangian(m, samples=3))
        out[cls.__name__] = rec
    attempt(out, "H3Oscillator()", lambda: cartan.H3Oscillator().inertia)
    attempt(out, "models", lambda: _cartan.models)
    attempt(out, "spaces", lambda: _cartan.spaces)
    attempt(out, "defaults", lambda: _cartan.defaults)
    attempt(out, "statuses", lambda: _cartan.statuses)
    attempt(out, "METHODS", lambda: cartan.METHODS)
    attempt(out, "SPACES", lambda: cartan.SPACES)
    attempt(out, "version", lambda: cartan.__version__)
    g0, v0 = SO3.exp([0.1, 0.2, 0.3]), np.array([0.5, -0.2, 0.3])
    attempt(out, "euler_poincare", lambda: cartan.euler_poincare(cartan.RigidBody(INERTIA), g0, v0, T=2.0, steps=50))
    attempt(out, "euler_poincare_right", lambda: cartan.euler_poincare(cartan.SpatialRigidBody(INERTIA), g0, v0, T=2.0,
                                                                       steps=50, side="right"))
    attempt(out, "euler_poincare_python", lambda: cartan.euler_poincare(PySO3Oscillator(INERTIA), g0, v0, T=2.0,
                                                                        steps=50))
    attempt(out, "lie_poisson", lambda: cartan.lie_poisson(cartan.SO3OscillatorHamiltonian(INERTIA), g0,
                                                           np.array(INERTIA) * v0, T=2.0, steps=50))
    attempt(out, "lie_poisson_python", lambda: cartan.lie_poisson(PyHamiltonian(INERTIA), g0, np.array(INERTIA) * v0,
                                                                  T=2.0, steps=50))
    attempt(out, "lie_poisson_se3", lambda: cartan.lie_poisson(cartan.SE3FreeBodyHamiltonian([1.0, 2, 3, 4, 4, 4]),
                                                               np.eye(4), np.arange(1.0, 7.0) * 0.1, T=1.0, steps=20))
    attempt(out, "hessian_python", lambda: cartan.lagrangian_hessian(PySO3Oscillator(INERTIA), 0.1, g0, v0))
    attempt(out, "hessian_python_own", lambda: cartan.lagrangian_hessian(PySO3OscillatorWithHessian(INERTIA), 0.1, g0,
                                                                         v0))
    attempt(out, "check_python", lambda: cartan.check_lagrangian(PySO3OscillatorWithHessian(INERTIA), samples=3))
    attempt(out, "check_python_bad", lambda: cartan.check_lagrangian(WrongInverse(INERTIA), samples=3))
    attempt(out, "check_triples", lambda: cartan.check_lagrangian(cartan.SO3Oscillator(INERTIA),
                                                                  samples=[(0.0, g0, v0), (0.5, GT, -v0)]))
    attempt(out, "check_manifold_terms", lambda: cartan.check_lagrangian(None, cartan.Sphere(), samples=3,
                                                                         inertia=[1.0, 2.0], gravity=2.0))
    attempt(out, "check_manifold_object", lambda: cartan.check_lagrangian(SphereKinetic(np.diag([1.0, 2.0]), 3.0),
                                                                          cartan.Sphere(), samples=3))
    attempt(out, "check_chart", lambda: cartan.check_lagrangian(None, cartan.Chart(half_plane_christoffel, dim=2,
                                                                                   metric=half_plane_metric),
                                                                samples=3, q=[0.0, 1.0], inertia=[1.0, 2.0]))
    attempt(out, "check_report", lambda: _cartan._check_report("title", [], 0))
    return out


@case("manifold-geometry")
def _():
    out = {}
    rng = np.random.default_rng(5)
    spaces = {
        "sphere": (cartan.Sphere(), cartan.Sphere.point([0.3, -0.4, 0.8]), cartan.Sphere.point([0.1, 0.5, 0.7])),
        "hyperbolic": (cartan.HyperbolicPlane(), cartan.HyperbolicPlane.point(0.3, -0.5),
                       cartan.HyperbolicPlane.point(-0.2, 0.4)),
        "euclidean3": (cartan.Euclidean(rng.normal(scale=0.5, size=(3, 3, 3))), np.array([0.1, 0.2, 0.3]),
                       np.array([0.5, -0.2, 0.0])),
        "gm-so3-cs": (cartan.GroupManifold("so3", "cartan-schouten", lam=0.3), SO3.exp([0.2, -0.4, 0.5]), GT),
        "gm-so3-lc": (cartan.GroupManifold("so3", "levi-civita", metric=np.diag(INERTIA)), SO3.exp([0.2, -0.4, 0.5]),
                      GT),
        "gm-se3-coeff": (cartan.GroupManifold("se3", "coefficients", alpha=rng.normal(scale=0.2, size=(6, 6, 6))),
                         SE3.exp([0.1, 0.2, 0.3, 0.1, 0.0, -0.1]), SE3.exp([0.3, 0.0, 0.1, -0.2, 0.1, 0.0])),
        "chart": (cartan.Chart(half_plane_christoffel, dim=2, metric=half_plane_metric, name="hp", parallel=True),
                  np.array([0.2, 0.9]), np.array([-0.3, 1.4])),
        "chart-nometric": (cartan.Chart(torsion_christoffel, dim=2), np.array([0.2, 0.9]), np.array([-0.3, 1.4])),
    }
    for key, (m, q, p) in spaces.items():
        rec = {}
        for attr in ("name", "dim", "ambient_dim", "point_shape", "lam", "alpha", "christoffel_symbols"):
            if hasattr(type(m), attr):
                attempt(rec, attr, lambda attr=attr: getattr(m, attr))
        attempt(rec, "repr", lambda: repr(m))
        try:
            e = m.tangent_basis(q)
            x, y, z = e @ rng.normal(size=m.dim) * 0.3, e @ rng.normal(size=m.dim), e @ rng.normal(size=m.dim)
        except Exception as exc:  # noqa: BLE001
            rec["tangent_basis"] = exc_record(exc)
            out[key] = rec
            continue
        rec["tangent_basis"] = D(e)
        calls = {
            "christoffel": lambda: m.christoffel(q, x, y), "frame_bracket": lambda: m.frame_bracket(x, y),
            "torsion": lambda: m.torsion(q, x, y), "curvature": lambda: m.curvature(q, x, y, z),
            "step": lambda: m.step(q, x), "difference": lambda: m.difference(q, p),
            "transport_along_step": lambda: m.transport_along_step(q, x),
            "default_frame": lambda: m.default_frame(q, p), "metric": lambda: m.metric(q),
            "torsion_components": lambda: m.torsion_components(q), "curvature_components": lambda: m.curvature_components(q),
            "parallel": lambda: m.has_parallel_torsion_and_curvature(), "validate": lambda: m.validate(q),
            "validate_bad": lambda: m.validate(np.full(m.point_shape, -3.0)),
            "step_nan": lambda: m.step(q, np.full(np.shape(x), np.nan)),
        }
        for k, f in calls.items():
            attempt(rec, k, f)
        if hasattr(type(m), "connection"):
            attempt(rec, "connection", lambda: m.connection.coefficients)
        if hasattr(type(m), "__getstate__"):
            attempt(rec, "pickle", lambda: repr(pickle.loads(pickle.dumps(m))))
        out[key] = rec
    return out


def timeless(result):
    """A solve_bvp result (a dict) without its dense output object; solve_time (wall clock,
    nondeterministic) by its type only."""
    out = {}
    for k in sorted(result.keys()):
        v = result[k]
        if k.startswith("solve_time"):
            out[k] = f"type:{type(v).__name__}"
        elif k == "sol" or isinstance(v, _cartan.BvpSolution):
            out[k] = f"type:{type(v).__name__}"
        else:
            out[k] = D(v)
    return out


@case("solve_bvp")
def _():
    def fun(x, y):
        return np.vstack((y[1], 1.5 * y[0] ** 2))

    def bc(ya, yb):
        return np.array([ya[0] - 4, yb[0] - 1])

    x = np.linspace(0, 1, 5)
    y = np.vstack((4 - 3 * x, -3 * np.ones_like(x)))
    r = cartan.solve_bvp(fun, bc, x, y, tol=1e-6)
    out = timeless(r)
    attempt(out, "sol(x)", lambda: r.sol(np.linspace(0, 1, 7)))
    # the compiled dense output directly
    attempt(out, "_solve_bvp", lambda: timeless(_cartan._solve_bvp(
        fun, bc, x, y, np.zeros(0), None, None, 1e-6, 1000, None, 20, 10, 2.0 ** -26, "block-lu")))

    def fun_p(x, y, p):  # Mathieu-like eigenvalue problem with a parameter
        return np.vstack((y[1], -(p[0] - 2 * 5 * np.cos(2 * x)) * y[0]))

    def bc_p(ya, yb, p):
        return np.array([ya[1], yb[1], ya[0] - 1])

    xm = np.linspace(0, np.pi, 11)
    ym = np.vstack((np.cos(4 * xm), -4 * np.sin(4 * xm)))
    rp = cartan.solve_bvp(fun_p, bc_p, xm, ym, p=[15.0], tol=1e-5)
    out["param"] = timeless(rp)
    attempt(out, "bad_shape", lambda: cartan.solve_bvp(fun, bc, x, y[:, :3]))
    return out


# -- bad inputs: the exact exception (type and message)

def _raising_lagrangian():
    try:
        cartan.solve(RaisingLagrangian(INERTIA), **GROUP_ARGS)
    except UserError as e:
        return {"same_instance": e is RaisingLagrangian.instance, **exc_record(e)}
    return "no exception"


def _raising_potential():
    raised = []

    def gradient(q):
        raised.append(UserError("from the gradient"))
        raise raised[-1]
    try:
        cartan.solve(cartan.Sphere(), potential=lambda q: q[2], potential_gradient=gradient, **SPHERE_ARGS)
    except UserError as e:
        return {"same_instance": e is raised[-1], **exc_record(e)}
    return "no exception"


def _progress_raises(stage, iteration, residual):
    raise RuntimeError("stop here")


BAD = {
    "group-negative-T": lambda: cartan.solve(cartan.RigidBody(INERTIA), lam=0.5, T=-1, N=10, gT=GT),
    "group-N-zero": lambda: cartan.solve(cartan.RigidBody(INERTIA), lam=0.5, T=1, N=0, gT=GT),
    "group-N-2**31": lambda: cartan.solve(cartan.RigidBody(INERTIA), lam=0.5, T=1, N=2**31, gT=GT),
    "group-N-too-large": lambda: cartan.solve(cartan.RigidBody(INERTIA), lam=0.5, T=1, N=2**31 - 1, gT=GT),
    "manifold-N-too-large": lambda: cartan.solve(cartan.Sphere(), **{**SPHERE_ARGS, "N": 2**31 - 1}),
    "group-N-float": lambda: cartan.solve(cartan.RigidBody(INERTIA), lam=0.5, T=1, N=2.5, gT=GT),
    "group-gT-shape": lambda: cartan.solve(cartan.RigidBody(INERTIA), lam=0.5, T=1, N=10, gT=np.eye(2)),
    "group-gT-not-orthogonal": lambda: cartan.solve(cartan.RigidBody(INERTIA), lam=0.5, T=1, N=10,
                                                    gT=np.diag([2.0, 1, 1])),
    "group-g0-shape": lambda: cartan.solve(cartan.RigidBody(INERTIA), g0=np.zeros(3), **GROUP_ARGS),
    "heisenberg-gT-shape": lambda: cartan.solve(cartan.H3Oscillator(), lam=0.5, T=1, N=10, gT=np.eye(3)),
    "group-unknown-method": lambda: cartan.solve(cartan.RigidBody(INERTIA), method="newton", **GROUP_ARGS),
    "group-unknown-continuation": lambda: cartan.solve(cartan.RigidBody(INERTIA), continuation="N", **GROUP_ARGS),
    "group-method-int": lambda: cartan.solve(cartan.RigidBody(INERTIA), method=3, **GROUP_ARGS),
    "group-order-3": lambda: cartan.solve(cartan.RigidBody(INERTIA), order=3, **GROUP_ARGS),
    "group-tol-negative": lambda: cartan.solve(cartan.RigidBody(INERTIA), tol=-1, **GROUP_ARGS),
    "group-tol-tiny": lambda: cartan.solve(cartan.RigidBody(INERTIA), tol=1e-18, **GROUP_ARGS),
    "group-tol-str": lambda: cartan.solve(cartan.RigidBody(INERTIA), tol="1e-8", **GROUP_ARGS),
    "group-time-limit-negative": lambda: cartan.solve(cartan.RigidBody(INERTIA), time_limit=-1, **GROUP_ARGS),
    "group-max-iterations-huge": lambda: cartan.solve(cartan.RigidBody(INERTIA), max_iterations=-2**31 - 1,
                                                      **GROUP_ARGS),
    "group-missing-gT": lambda: cartan.solve(cartan.RigidBody(INERTIA), lam=0.5, T=1, N=10),
    "group-gravity-keyword": lambda: cartan.solve(cartan.RigidBody(INERTIA), gravity=1.0, **GROUP_ARGS),
    "group-right-reduced": lambda: cartan.solve(cartan.SpatialRigidBody(INERTIA), **GROUP_ARGS),
    "group-collocation-v0": lambda: cartan.solve(cartan.RigidBody(INERTIA), method="collocation", v0=np.zeros(3),
                                                 **GROUP_ARGS),
    "group-v0-shape": lambda: cartan.solve(cartan.RigidBody(INERTIA), method="shooting", v0=np.zeros(4), **GROUP_ARGS),
    "group-variational-order2": lambda: cartan.solve(cartan.RigidBody(INERTIA), method="variational", order=2,
                                                     **GROUP_ARGS),
    "solve-nothing": lambda: cartan.solve(T=1.0, N=10),
    "python-lagrangian-raises": _raising_lagrangian,
    "python-lagrangian-wrong-shape": lambda: cartan.solve(WrongShape(INERTIA), method="two-level", **GROUP_ARGS),
    "python-lagrangian-nan": lambda: cartan.solve(NaNForce(INERTIA), **GROUP_ARGS),
    "python-lagrangian-wrong-inverse": lambda: cartan.solve(WrongInverse(INERTIA), **GROUP_ARGS),
    "python-lagrangian-bad-hessian": lambda: cartan.solve(BadHessian(INERTIA), method="shooting", **GROUP_ARGS),
    "python-lagrangian-no-group": lambda: cartan.solve(object(), **GROUP_ARGS),
    "python-lagrangian-missing-method": lambda: cartan.solve(type("Incomplete", (), {"group": SO3})(), **GROUP_ARGS),
    "vectorized-wrong-rows": lambda: cartan.solve(WrongRows(INERTIA), method="shooting", **GROUP_ARGS),
    "progress-raises": lambda: cartan.solve(cartan.SO3Oscillator(INERTIA), progress=_progress_raises, **GROUP_ARGS),
    "model-negative-inertia": lambda: cartan.RigidBody([1.0, -2.0, 3.0]),
    "model-inertia-shape": lambda: cartan.SE3FreeBody([1.0, 2.0, 3.0]),
    "model-inertia-not-symmetric": lambda: cartan.RigidBody(np.array([[1.0, 0.5, 0], [0, 1, 0], [0, 0, 1]])),
    "manifold-negative-T": lambda: cartan.solve(cartan.Sphere(), **{**SPHERE_ARGS, "T": -1.0}),
    "manifold-q0-not-on-sphere": lambda: cartan.solve(cartan.Sphere(), **{**SPHERE_ARGS, "q0": [1.0, 1, 1]}),
    "manifold-q0-shape": lambda: cartan.solve(cartan.Sphere(), **{**SPHERE_ARGS, "q0": [1.0, 0]}),
    "manifold-qT-shape-group": lambda: cartan.solve(cartan.GroupManifold("so3", lam=0.5), T=1.0, N=10, q0=np.eye(3),
                                                    qT=np.eye(4)),
    "manifold-q0-not-orthogonal": lambda: cartan.solve(cartan.GroupManifold("so3", lam=0.5), T=1.0, N=10,
                                                       q0=np.ones((3, 3)), qT=np.eye(3)),
    "manifold-unknown-method": lambda: cartan.solve(cartan.Sphere(), method="nope", **SPHERE_ARGS),
    "manifold-two-level": lambda: cartan.solve(cartan.Sphere(), method="two-level", **SPHERE_ARGS),
    "manifold-variational": lambda: cartan.solve(cartan.Sphere(), method="variational", **SPHERE_ARGS),
    "manifold-continuation-lambda": lambda: cartan.solve(cartan.Sphere(), continuation="lambda", **SPHERE_ARGS),
    "manifold-lam-keyword": lambda: cartan.solve(cartan.Sphere(), lam=0.3, **SPHERE_ARGS),
    "manifold-missing-qT": lambda: cartan.solve(cartan.Sphere(), T=1.0, N=10, q0=[0, 0, 1.0]),
    "manifold-potential-without-gradient": lambda: cartan.solve(cartan.Sphere(), potential=lambda q: q[2],
                                                                **SPHERE_ARGS),
    "manifold-potential-not-callable": lambda: cartan.solve(cartan.Sphere(), potential=1.0,
                                                            potential_gradient=lambda q: q, **SPHERE_ARGS),
    "manifold-potential-raises": _raising_potential,
    "manifold-inertia-shape": lambda: cartan.solve(cartan.Sphere(), inertia=[1.0, 2, 3], **SPHERE_ARGS),
    "manifold-inertia-negative": lambda: cartan.solve(cartan.Sphere(), inertia=[1.0, -1], **SPHERE_ARGS),
    "manifold-gravity-str": lambda: cartan.solve(cartan.Sphere(), gravity="strong", **SPHERE_ARGS),
    "manifold-gravity-inf": lambda: cartan.solve(cartan.Sphere(), gravity=np.inf, **SPHERE_ARGS),
    "manifold-gravity-on-group": lambda: cartan.solve(cartan.GroupManifold("so3", lam=0.5), gravity=1.0, T=1.0, N=10,
                                                      q0=np.eye(3), qT=np.eye(3)),
    "manifold-v0-shape": lambda: cartan.solve(cartan.Sphere(), v0=[0.0, 0, 0], **SPHERE_ARGS),
    "manifold-Xi0-nan": lambda: cartan.solve(cartan.Sphere(), Xi0=np.full((2, 2), np.nan), **SPHERE_ARGS),
    "manifold-frame0-not-tangent": lambda: cartan.solve(cartan.Sphere(), frame0=[[1.0, 0], [0, 0], [0, 1]],
                                                        **SPHERE_ARGS),
    "manifold-antipodal": lambda: cartan.solve(cartan.Sphere(), T=1.0, N=10, q0=[0, 0, 1.0], qT=[0, 0, -1.0],
                                               inertia=[1.0, 2.0]),
    "manifold-lagrangian-no-value": lambda: cartan.solve(object(), space=cartan.Sphere(), **SPHERE_ARGS),
    "manifold-lagrangian-and-gravity": lambda: cartan.solve(SphereKinetic(np.eye(2), 1.0), space=cartan.Sphere(),
                                                            gravity=1.0, **SPHERE_ARGS),
    "manifold-lagrangian-bad-momentum": lambda: cartan.solve(BadMomentumOnSphere(np.eye(2), 1.0),
                                                             space=cartan.Sphere(), **SPHERE_ARGS),
    "manifold-space-not-manifold": lambda: cartan.solve(space="sphere", **SPHERE_ARGS),
    "manifold-twice": lambda: cartan.solve(cartan.Sphere(), space=cartan.Sphere(), **SPHERE_ARGS),
    "manifold-progress-raises": lambda: cartan.solve(cartan.Sphere(), gravity=1.0, progress=_progress_raises,
                                                     **SPHERE_ARGS),
    "manifold-samples-huge": lambda: cartan.solve(cartan.Sphere(), samples=2**40, **SPHERE_ARGS),
    "groupmanifold-affine": lambda: cartan.GroupManifold("so3", "affine"),
    "groupmanifold-so4": lambda: cartan.GroupManifold("so4", lam=0.5),
    "groupmanifold-no-lam": lambda: cartan.GroupManifold("so3"),
    "groupmanifold-lam-str": lambda: cartan.GroupManifold("so3", lam="a\nb"),
    "groupmanifold-lam-long": lambda: cartan.GroupManifold("so3", lam="y" * 100),
    "groupmanifold-metric-cs": lambda: cartan.GroupManifold("so3", lam=0.5, metric=[1, 1, 1]),
    "groupmanifold-metric-negative": lambda: cartan.GroupManifold("so3", "levi-civita", metric=[1.0, -1, 1]),
    "groupmanifold-alpha-shape": lambda: cartan.GroupManifold("so3", "coefficients", alpha=np.zeros((3, 3))),
    "groupmanifold-right-connection": lambda: cartan.GroupManifold("so3", SO3.cartan_schouten(0.5, side="right")),
    "groupmanifold-pickled-state": lambda: cartan.GroupManifold.__new__(cartan.GroupManifold).__setstate__(
        ("so3", "levi-civita")),
    "euclidean-shape": lambda: cartan.Euclidean(np.zeros((4, 4, 4))),
    "euclidean-no-dim": lambda: cartan.Euclidean(),
    "euclidean-dim-float": lambda: cartan.Euclidean(dim=2.5),
    "euclidean-dim-mismatch": lambda: cartan.Euclidean(np.zeros((2, 2, 2)), dim=3),
    "chart-dim-4": lambda: cartan.Chart(half_plane_christoffel, dim=4),
    "chart-not-callable": lambda: cartan.Chart(np.zeros((2, 2, 2)), dim=2),
    "chart-wrong-shape": lambda: cartan.Chart(lambda q: np.zeros((3, 3, 3)), dim=2).christoffel([0, 1.0], [1, 0],
                                                                                               [0, 1]),
    "chart-outside-nan": lambda: cartan.Chart(nan_below_axis, dim=2).validate([0.0, -1.0]),
    "chart-outside-raises": lambda: cartan.Chart(raises_below_axis, dim=2).validate([0.0, -1.0]),
    "chart-outside-raises-christoffel": lambda: cartan.Chart(raises_below_axis, dim=2).christoffel(
        [0.0, -1.0], [1.0, 0.0], [0.0, 1.0]),
    "chart-q0-outside": lambda: cartan.solve(cartan.Chart(nan_below_axis, dim=2), T=1.0, N=10, q0=[0.0, -1.0],
                                             qT=[0.0, 1.0]),
    "chart-to_json-no-error": lambda: cartan.solve(cartan.Chart(lambda q: np.zeros((2, 2, 2)), dim=2), T=1.0, N=10,
                                          q0=[0.0, 0.0], qT=[1.0, 0.5]).to_json(os.devnull),
    "sphere-torsion-off-sphere": lambda: cartan.Sphere().torsion([1.0, 1, 0], [0, 0, 1], [0, 1, 0]),
    "euler-poincare-negative-T": lambda: cartan.euler_poincare(cartan.RigidBody(INERTIA), np.eye(3), np.ones(3),
                                                               T=-1.0, steps=10),
    "euler-poincare-bad-side": lambda: cartan.euler_poincare(cartan.RigidBody(INERTIA), np.eye(3), np.ones(3), T=1.0,
                                                             steps=10, side="up"),
    "lie-poisson-bad-mu": lambda: cartan.lie_poisson(cartan.RigidBodyHamiltonian(INERTIA), np.eye(3), np.ones(2),
                                                     T=1.0, steps=10),
    "check-lagrangian-bad-seed": lambda: cartan.check_lagrangian(cartan.RigidBody(INERTIA), seed=-1),
    "verify-no-lagrangian": lambda: _verify_travelled(),
    "verify-terms-on-group": lambda: cartan.verify(cartan.solve(cartan.RigidBody(INERTIA), **GROUP_ARGS),
                                                   gravity=1.0),
    "load-bad-json": lambda: _load_text('{"kind": "group"}'),
    "load-not-json": lambda: _load_text("not json"),
    "read-result-bad": lambda: _cartan._read_result("{}", "here"),
    "solve_bvp-bad-x": lambda: cartan.solve_bvp(lambda x, y: y, lambda a, b: a, np.array([0.0, 0.0, 1.0]),
                                                np.zeros((2, 3))),
    "so3-exp-shape": lambda: SO3.exp(np.zeros(4)),
    "se3-log-shape": lambda: SE3.log(np.eye(3)),
}


def _verify_travelled():
    """A result of a Lagrangian that does not pickle (a local class) loses it on pickling: verify asks."""
    class Local(PySO3Oscillator):
        pass
    r = cartan.solve(Local(INERTIA), **GROUP_ARGS)
    return cartan.verify(pickle.loads(pickle.dumps(r)))


def _load_text(text):
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "bad.json")
        with open(path, "w") as f:
            f.write(text)
        try:
            return cartan.load(path)
        except Exception as e:  # noqa: BLE001 (the message names the temporary path: mask it)
            raise type(e)(str(e).replace(path, "<path>")) from None


@case("bad-inputs")
def _():
    out = {}
    for name, make in BAD.items():
        try:
            value = make()
            out[name] = {"no exception": D(value) if not isinstance(value, cartan.Result)
                         else result_fields(value)}
        except Exception as e:  # noqa: BLE001
            out[name] = exc_record(e)
    return out


# ---- driver ---------------------------------------------------------------------------------------

def run(only=None):
    warnings.simplefilter("ignore")
    results, timings = {}, {}
    for name, f in CASES:
        if only and name not in only:
            continue
        start = time.perf_counter()
        try:
            results[name] = f()
        except Exception as e:  # noqa: BLE001
            results[name] = {"case_exception": exc_record(e), "where": clean(traceback.format_exc().splitlines()[-3])}
        timings[name] = time.perf_counter() - start
    return results, timings


def differences(a, b, path=""):
    if isinstance(a, dict) and isinstance(b, dict):
        for k in list(a) + [k for k in b if k not in a]:
            if k not in b:
                yield f"{path}/{k}: only in reference"
            elif k not in a:
                yield f"{path}/{k}: only in new"
            else:
                yield from differences(a[k], b[k], f"{path}/{k}")
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            yield f"{path}: length {len(a)} != {len(b)}"
        for i, (x, y) in enumerate(zip(a, b)):
            yield from differences(x, y, f"{path}[{i}]")
    elif a != b:
        def short(x):
            s = json.dumps(x)
            return s if len(s) < 400 else s[:400] + "..."
        yield f"{path}:\n    reference: {short(a)}\n    new:       {short(b)}"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    group = parser.add_mutually_exclusive_group(required=True)
    group.add_argument("--write", metavar="OUT")
    group.add_argument("--compare", metavar="REF")
    parser.add_argument("--only", nargs="*", help="run these cases only")
    args = parser.parse_args()
    start = time.perf_counter()
    results, timings = run(args.only)
    total = time.perf_counter() - start
    for name, t in timings.items():
        print(f"  {t:7.2f} s  {name}", file=sys.stderr)
    print(f"  {total:7.2f} s  total ({len(timings)} cases, cartan {cartan.__version__} from "
          f"{os.path.dirname(cartan.__file__)})", file=sys.stderr)
    document = {"cartan_version": cartan.__version__, "numpy": np.__version__, "cases": results}
    if args.write:
        with open(args.write, "w") as f:
            json.dump(document, f, indent=1, sort_keys=False)
        print(f"wrote {args.write}")
        return 0
    with open(args.compare) as f:
        reference = json.load(f)
    ref_cases = reference["cases"]
    if args.only:
        ref_cases = {k: v for k, v in ref_cases.items() if k in args.only}
    diffs = list(differences(ref_cases, json.loads(json.dumps(results))))
    for d in diffs:
        print(d)
    print(f"{len(diffs)} difference(s) against {args.compare}")
    return 1 if diffs else 0


if __name__ == "__main__":
    sys.exit(main())
