"""`cartan solve`'s default method (the library's strategy, include/cartan/methods/lie_group/solve.hpp):
the failure cases the redesign issue lists, honest failures, guesses and the action (SIGINT:
test_interrupt.py).

Run by ctest with CARTAN_BIN pointing at the built `cartan` executable."""
import json
from functools import partial

import pytest

from cli_support import run, solve_json

FREE_BODY_ENDS = ["--a0=-1,-1,-1", "--aT", "0.9,1,1"]
OSCILLATOR_ENDS = ["--a0", "-0.7,-1,-0.7", "--aT", "0.8,0.8,1"]
TIMEOUT = 300  # a hang guard; the strategy's continuations get more time than cli_support.run's default
run_solve = partial(run, "solve", timeout=TIMEOUT)


def solved(*args):
    d = solve_json(*args, timeout=TIMEOUT)
    assert d["status"] == "converged"
    return d


def test_tiny_horizon_converges_at_the_default_tolerance():
    # T = 1e-4: v0 ~ 1e4, xi ~ 1e8 in absolute terms; the dimensionless residual makes this the
    # same problem as at T = 1, so direct shooting converges at tol 1e-10 (it did not before).
    d = solved("--model", "free-rigid-body", "--lambda", "0.5", "--T", "1e-4", "--N", "100", *FREE_BODY_ENDS)
    assert d["method"] == "shooting" and d["branch"].startswith("shooting")
    assert d["terminal_error"] < 1e-10


def test_long_purely_kinetic_problem():
    d = solved("--model", "free-rigid-body", "--inertia", "1,5,9", "--lambda", "0.5", "--T", "100", "--N", "5000",
               "--tol", "1e-8", *FREE_BODY_ENDS)
    # the trajectory is the requested problem's: N + 1 nodes ending at T
    assert len(d["t"]) == 5001 and d["t"][-1] == pytest.approx(100, rel=1e-12)
    assert "continuation in T" not in d["branch"]  # never tried for a purely kinetic Lagrangian


def test_paper_oscillator_names_the_whole_path():
    d = solved("--model", "oscillator", "--lambda", "0.5", "--T", "12", "--N", "800", "--tol", "1e-6",
               *OSCILLATOR_ENDS)
    assert d["branch"].startswith("continuation in T") and d["branch"].endswith("after shooting failed")


def test_heisenberg_beyond_the_fold_fails_honestly():
    # H3 oscillator, gT = (1, 0.5, 0.8): the branch from short horizons folds between T = 1.5 and
    # 2, and from the straight-line guess neither collocation nor any shooting method finds a
    # solution at T = 3 (a known gap). The result must say so: exit 1, every attempt named, and
    # the data of the requested horizon.
    result = run_solve("--group", "heisenberg", "--model", "oscillator", "--lambda", "0.7", "--T", "3",
                       "--N", "300", "--gT", "1,0.5,0.8", "--tol", "1e-8")
    assert result.returncode == 1
    d = json.loads(result.stdout)
    assert d["status"] == "strategy-failed" and d["branch"].startswith("failed: shooting: ")
    for attempt in ["continuation in T", "continuation in lambda from 0", "collocation", "multiple shooting"]:
        assert attempt in d["message"]
    assert d["t"][-1] == pytest.approx(3, rel=1e-12)


def test_a_failed_continuation_carries_the_requested_problem_only():
    # Two iterations per solve cannot reach T = 12: the result must still be of T = 12, N = 800.
    result = run_solve("--model", "oscillator", "--lambda", "0.5", "--T", "12", "--N", "800", "--tol", "1e-6",
                       "--method", "shooting", "--continuation", "T", "--max-iterations", "2", *OSCILLATOR_ENDS)
    assert result.returncode == 1
    d = json.loads(result.stdout)
    assert d["status"] == "continuation-failed" and d["branch"].startswith("failed")
    assert len(d["t"]) in (0, 801)
    if d["t"]:
        assert d["t"][-1] == pytest.approx(12, rel=1e-12)
        assert d["terminal_error"] > 1e-6


def test_guesses_select_the_start_and_every_result_has_an_action():
    base = ["--model", "oscillator", "--lambda", "0.5", "--T", "3", "--N", "300", "--tol", "1e-10", *OSCILLATOR_ENDS]
    a = solved(*base)
    b = solved(*base, "--method", "shooting", "--v0=" + ",".join(map(repr, a["v"][0])),
               "--xi0=" + ",".join(map(repr, a["xi"][0])))
    assert b["branch"] == "direct from the given guess" and b["iterations"]["inner"] <= 2
    assert a["action"] == pytest.approx(b["action"], rel=1e-9)


@pytest.mark.parametrize("method", ["auto", "shooting", "multiple-shooting"])
def test_a_xi0_guess_alone_starts_from_the_geodesic_velocity(method):
    # Only xi0 given: v0 falls back to the geodesic guess (this used to dereference an empty guess).
    d = solved("--model", "oscillator", "--lambda", "0.5", "--T", "1", "--N", "10", "--a0", "1,0,0", "--aT", "0,1,0",
               "--method", method, "--xi0", "0,0,0")
    assert d["terminal_error"] < 1e-10


@pytest.mark.parametrize("args, words", [
    (["--v0", "1,2"], ["v0", "3 numbers"]),
    (["--xi0", "1,nan,2"], ["xi0"]),
    (["--method", "collocation", "--v0", "1,2,3"], ["v0", "collocation"]),
    (["--method", "two-level", "--xi0", "1,2,3"], ["xi0", "two-level"]),
    (["--continuation", "T"], ["continuation", "shooting and collocation"]),
    (["--method", "newton"], ["method", "auto, shooting, multiple-shooting, two-level, collocation, variational"]),
    (["--method", "variational", "--v0", "1,2,3"], ["v0", "variational"]),
    (["--method", "variational", "--order", "2"], ["order", "variational"]),
    (["--method", "shooting", "--continuation", "lambda", "--v0", "1,2,3"], ["continuation lambda", "no guess"]),
])
def test_bad_guesses_and_options_exit_2(args, words):
    result = run_solve("--model", "free-rigid-body", "--T", "1", "--N", "10", *FREE_BODY_ENDS, *args)
    assert result.returncode == 2 and result.stdout == ""
    for w in words:
        assert w in result.stderr, result.stderr


def test_progress_reports_on_stderr():
    result = run_solve("--model", "oscillator", "--lambda", "0.5", "--T", "3", "--N", "100", "--progress",
                       *OSCILLATOR_ENDS)
    assert result.returncode == 0
    assert "cartan solve: shooting, iteration 0, residual" in result.stderr
