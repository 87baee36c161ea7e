"""Bad input through `cartan solve`, table-driven (issue 5, "hardened input"): every case must
exit with code 2 (never a signal, never exit 1 "internal error"), print nothing on stdout and one
line on stderr naming the problem. Complements BAD_INPUTS in test_cli.py (flags) with problem
files, non-finite numbers in both forms, memory limits and misplaced options.

Run by ctest (the `cli` test) with CARTAN_BIN pointing at the built `cartan` executable."""
from functools import partial

import pytest

from cli_support import assert_rejected, run

DIRECTIONS = ["--a0", "1,0,0", "--aT", "0,1,0"]
SMALL = ["--T", "1", "--N", "10"]


run_solve = partial(run, "solve", timeout=60)  # bad input is refused at once


# (flags, fragment of the message). The so3 directions are added unless the case gives its own.
BAD_FLAGS = [
    (["--lambda", "inf"], "lambda = inf is not finite"),
    (["--lambda", "-inf"], "lambda = -inf is not finite"),
    (["--lambda", "nan"], "lambda = nan is not finite"),
    (["--lambda", "1e400"], "lambda = inf is not finite"),  # CLI11 reads 1e400 as inf
    (["--lambda", "half"], "Could not convert: --lambda = half"),
    (["--T", "inf"], "T = inf must be positive and finite"),
    (["--tol", "nan"], "tol = nan must be positive and finite"),
    (["--N", "-5"], "N = -5 must be at least 1"),
    (["--N", "2.5"], "Could not convert: --N = 2.5"),
    (["--N", "ten"], "Could not convert: --N = ten"),
    (["--N", "99999999999"], "Could not convert: --N = 99999999999"),
    (["--N", "5000000"], "N = 5000000 needs an estimated 4.77 GiB"),
    (["--N", "4194305"], "N = 4194305 needs an estimated 4 GiB"),  # one above 4 GiB / 1 KiB
    (["--model", "pendulum"], "model = \"pendulum\" is not one of"),
    (["--group", "heisenberg", "--model", "free-rigid-body", "--gT", "1,2,3"], "model = \"free-rigid-body\""),
    (["--inertia", "0,1,1"], "inertia = 0,1,1 is not positive definite"),
    (["--inertia", "1,nan,1"], "inertia = 1,nan,1 contains a non-finite number"),
    (["--g0", "1,0,0,0,1,0,0,0,inf", "--gT", "1,0,0,0,1,0,0,0,1"], "g0 = 1,0,0,0,1,0,0,0,inf"),
    (["--g0", "1,1,0,0,1,0,0,0,1", "--gT", "1,0,0,0,1,0,0,0,1"], "g0 = "),
    (["--a0", "1,0,0", "--aT", "-2,0,0"], "antiparallel"),
    (["--a0", "1e200,0,0", "--aT", "-1e-200,0,0"], "antiparallel"),
    (["--a0", "1,0,0", "--aT", "0,1,0", "--gT", "1,0,0,0,1,0,0,0,1"], "gT = 1,0,0,0,1,0,0,0,1 conflicts with a0/aT"),
    (["--samples", "5"], "samples = 5 is an option of --method collocation only"),
    (["--segments", "3"], "segments = 3 is an option of --method multiple-shooting only"),
    (["--method", "multiple-shooting", "--N", "4000000", "--segments", "1000"],
     "segments = 1000 needs an estimated 4.29 GiB"),
    (["--group", "heisenberg", "--model", "oscillator", "--gT", "1,2,3", "--method", "collocation",
      "--samples", "5000000"], "samples = 5000000 needs an estimated"),
    (["--unknown-flag"], "not expected: --unknown-flag"),
    (["--N"], "--N: 1 required INT missing"),
    (["--problem", "/nonexistent/p.json"], "--problem = /nonexistent/p.json cannot be opened"),
    (["--problem", "/"], "--problem = / is a directory"),
    (["--output", "/nonexistent/dir/r.json"], "--output = /nonexistent/dir/r.json cannot be written"),
    (["--time-limit", "-1"], "time_limit = -1 must be a non-negative number of seconds"),
    (["--time-limit", "inf"], "time_limit = inf must be a non-negative number of seconds"),
    (["--tol", "1e-18"], "tol = 1e-18 is below 100 machine epsilons"),
]


@pytest.mark.parametrize("args,needle", BAD_FLAGS)
def test_bad_flags(args, needle):
    flags = {a for a in args if a.startswith("--")}
    base = [w for i in range(0, len(SMALL), 2) if SMALL[i] not in flags for w in SMALL[i:i + 2]]
    if not flags & {"--a0", "--aT", "--gT", "--group"}:
        base += DIRECTIONS
    assert_rejected(run_solve(*base, *args), needle)


# (problem-file text, fragment of the message); the file alone is the problem.
BAD_FILES = [
    ("", "is not valid JSON"),
    ("   \n", "is not valid JSON"),
    ('{"N": 10,', "is not valid JSON"),
    ('{"lambda": NaN}', "is not valid JSON"),
    ('{"lambda": 1e400}', "has a number out of range"),
    ('{"lambda": "nan"}', 'lambda = "nan" must be a number'),
    ('{"lambda": "inf"}', 'lambda = "inf" must be a number'),
    ('{"N": "10"}', 'N = "10" must be an integer'),
    ('{"N": -3, "a0": [1, 0, 0], "aT": [0, 1, 0]}', "N = -3 must be at least 1"),
    ('{"N": 0, "a0": [1, 0, 0], "aT": [0, 1, 0]}', "N = 0 must be at least 1"),
    ('{"N": 1e12}', "N = 1e+12 is out of range"),
    ('{"N": 100000000, "a0": [1, 0, 0], "aT": [0, 1, 0]}', "N = 100000000 needs an estimated"),
    ('{"T": 0, "a0": [1, 0, 0], "aT": [0, 1, 0]}', "T = 0 must be positive"),
    ('{"tol": 0, "a0": [1, 0, 0], "aT": [0, 1, 0]}', "tol = 0 must be positive"),
    ('{"N": 10, "N": 20}', 'repeats the key "N"'),
    ('{"inertia": {"x": 1}}', "inertia"),
    ('{"inertia": [1, 2, -3], "a0": [1, 0, 0], "aT": [0, 1, 0]}', "inertia = 1,2,-3 is not positive definite"),
    ('{"gT": [[1, 0, 0], [0, 1, 0], [0, 0, -1]]}', "gT"),
    ('{"gT": [1, 0, 0, 0, 2, 0, 0, 0, 1]}', "not orthogonal"),
    ('{"a0": [1, 1, 1], "aT": [-1, -1, -1]}', "antiparallel"),
    ('{"a0": [0, 0, 0], "aT": [1, 0, 0]}', "a0 = 0,0,0 has zero length"),
    ('{"method": "magic", "a0": [1, 0, 0], "aT": [0, 1, 0]}', 'method = "magic" is not one of'),
    ('{"group": "se9"}', 'group = "se9" is not one of'),
    ('{"samples": 3, "a0": [1, 0, 0], "aT": [0, 1, 0]}', "samples = 3 is an option of --method collocation only"),
    ('{"output": 7}', "output = 7 must be a string"),
    ('"a string"', "must be a JSON object"),
    ("null", "must be a JSON object"),
]


@pytest.mark.parametrize("content,needle", BAD_FILES)
def test_bad_problem_files(tmp_path, content, needle):
    problem = tmp_path / "p.json"
    problem.write_text(content)
    assert_rejected(run_solve("--problem", str(problem)), needle)



@pytest.mark.parametrize("word", ["bogus", "solv", ""])
def test_an_unknown_command_is_named_with_the_commands(word):
    """Issue 29: `cartan bogus` said only "A subcommand is required"."""
    result = run(word, "--T", "1", timeout=60)
    assert_rejected(result, f'cartan: "{word}" is not a command (commands: solve, sweep, merge, verify')
