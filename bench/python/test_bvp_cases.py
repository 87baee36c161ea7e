"""Checks of bench/python/bvp_cases.py, the problems of bench/compare_solve_bvp.py (about 2 s;
SciPy only, no cartan):
  * fun is vectorised: on a whole mesh it returns what it returns column by column;
  * fun_jac and bc_jac, where given, agree with central differences of fun and bc;
  * scipy.integrate.solve_bvp solves every case (status 0) to the known solution where there is
    one (within exact_atol: SciPy's own tests' bounds, or 10 tol), and the benchmark's cases with
    meshes of 100 nodes or more have them.
"""
import os
import sys

import numpy as np
import pytest
from scipy.integrate import solve_bvp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bvp_cases  # noqa: E402

CASES = bvp_cases.cases()
NAMES = [case["name"] for case in CASES]


def by_name(name):
    return next(case for case in CASES if case["name"] == name)


def sample_point(case, seed=1):
    """A mesh of 7 interior points and states near the guess's scale, with the case's dtype."""
    rng = np.random.default_rng(seed)
    a, b = case["x"][0], case["x"][-1]
    x = np.sort(rng.uniform(a, b, 7))
    n = case["y"].shape[0]
    y = rng.uniform(-1, 1, (n, 7)).astype(case["y"].dtype)
    p = None if case["p"] is None else np.asarray(case["p"], dtype=float) * (1 + 0.1 * rng.uniform(-1, 1))
    return x, y, p


def call(f, p, *args):
    return f(*args) if p is None else f(*args, p)


def test_names_are_unique():
    assert len(set(NAMES)) == len(NAMES)


@pytest.mark.parametrize("name", NAMES)
def test_fun_is_vectorised(name):
    case = by_name(name)
    x, y, p = sample_point(case)
    whole = call(case["fun"], p, x, y)
    assert whole.shape == y.shape
    for j in range(x.size):
        column = call(case["fun"], p, x[j:j + 1], y[:, j:j + 1])
        np.testing.assert_allclose(whole[:, j], np.reshape(column, -1), rtol=1e-14, atol=1e-14)


@pytest.mark.parametrize("name", [case["name"] for case in CASES if case["fun_jac"] is not None])
def test_fun_jac_agrees_with_differences(name):
    case = by_name(name)
    x, y, p = sample_point(case)
    jac = call(case["fun_jac"], p, x, y)
    df_dy, df_dp = (jac, None) if p is None else jac
    n, m = y.shape
    assert np.shape(df_dy) == (n, n, m)
    step = 1e-6
    for i in range(n):
        e = np.zeros((n, 1))
        e[i] = step
        column = (call(case["fun"], p, x, y + e) - call(case["fun"], p, x, y - e)) / (2 * step)
        np.testing.assert_allclose(df_dy[:, i, :], column, rtol=1e-6, atol=1e-6)
    if p is not None:
        assert np.shape(df_dp) == (n, p.size, m)
        for j in range(p.size):
            e = np.zeros(p.size)
            e[j] = step
            column = (case["fun"](x, y, p + e) - case["fun"](x, y, p - e)) / (2 * step)
            np.testing.assert_allclose(df_dp[:, j, :], column, rtol=1e-6, atol=1e-6)


@pytest.mark.parametrize("name", [case["name"] for case in CASES if case["bc_jac"] is not None])
def test_bc_jac_agrees_with_differences(name):
    case = by_name(name)
    x, y, p = sample_point(case, seed=2)
    y = 0.1 * y  # Butler-Volmer's exponentials: stay where differences are accurate
    ya, yb = y[:, 0], y[:, -1]
    jac = call(case["bc_jac"], p, ya, yb)
    n = ya.size
    step = 1e-7
    for which, derivative in enumerate(jac[:2]):
        for i in range(n):
            e = np.zeros(n)
            e[i] = step
            plus = (ya + e, yb) if which == 0 else (ya, yb + e)
            minus = (ya - e, yb) if which == 0 else (ya, yb - e)
            column = (call(case["bc"], p, *plus) - call(case["bc"], p, *minus)) / (2 * step)
            np.testing.assert_allclose(np.asarray(derivative)[:, i], column, rtol=1e-6, atol=1e-6)
    if p is not None:
        for j in range(p.size):
            e = np.zeros(p.size)
            e[j] = step
            column = (case["bc"](ya, yb, p + e) - case["bc"](ya, yb, p - e)) / (2 * step)
            np.testing.assert_allclose(np.asarray(jac[2])[:, j], column, rtol=1e-6, atol=1e-6)


@pytest.fixture(scope="module")
def scipy_results():
    results = {}
    for case in CASES:
        args, kwargs = bvp_cases.arguments(case)
        results[case["name"]] = solve_bvp(*args, **kwargs)
    return results


@pytest.mark.parametrize("name", NAMES)
def test_scipy_solves_the_case(scipy_results, name):
    case = by_name(name)
    res = scipy_results[name]
    assert res.status == 0, res.message
    if case["exact"] is not None:
        grid = np.linspace(case["x"][0], case["x"][-1], 101)
        assert np.abs(res.sol(grid) - case["exact"](grid)).max() < case["exact_atol"]
    if case["p_exact"] is not None:
        np.testing.assert_allclose(res.p, case["p_exact"], rtol=0, atol=max(10 * case["tol"], 1e-4))


def test_the_set_has_meshes_of_100_nodes_and_more(scipy_results):
    # Issue 14's goal distinguishes these: the shock layer at every tolerance, among others.
    big = [name for name, res in scipy_results.items() if res.x.size >= 100]
    assert len(big) >= 6 and all(name in big for name in NAMES if name.startswith("shock layer"))


def test_arguments_are_fresh_copies():
    # SciPy writes into y when S is given: each solve must get its own arrays.
    case = by_name("Emden, singular term S, tol 1e-6")
    (_, _, x1, y1), _ = bvp_cases.arguments(case)
    (_, _, x2, y2), _ = bvp_cases.arguments(case)
    assert x1 is not x2 and y1 is not y2 and not np.shares_memory(y1, case["y"])
