"""Every group of the CLI's model table (include/cartan/models/catalogue.hpp) through `cartan solve`,
`cartan sweep` and `cartan verify`: se2 and se3 results converge, reach the endpoint and pass
verify; a full symmetric inertia on so3 is checked against an independent symmetry (conjugating
the problem by a rotation Q conjugates the solution); hostile input exits 2 with one short line.

Run by ctest (the `cli` test) with CARTAN_BIN pointing at the built `cartan` executable."""
import json
from functools import partial

import numpy as np
import pytest
from scipy.linalg import expm

import cli_support

MAX_MESSAGE = 400  # characters of the one stderr line for hostile input
TIMEOUT = 180  # a hang guard; this file's commands get more time than cli_support.run's default
run = partial(cli_support.run, timeout=TIMEOUT)


def flat(m):
    return ",".join(repr(float(x)) for x in np.asarray(m).reshape(-1))


def se2_exp(x, y, theta):
    return expm(np.array([[0, -theta, x], [theta, 0, y], [0, 0, 0]]))


def hat3(w):
    return np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])


def se3_exp(rho, omega):
    m = np.zeros((4, 4))
    m[:3, :3] = hat3(omega)
    m[:3, 3] = rho
    return expm(m)


SE2_GT = se2_exp(1.0, -0.5, 0.8)
SE3_GT = se3_exp([0.6, -0.3, 0.5], [0.4, -0.7, 0.3])
SE3_INERTIA = np.diag([1.0, 1.5, 2.0, 2.0, 3.0, 4.0]) + 0.1 * (np.eye(6, k=1) + np.eye(6, k=-1))


def solve_to(tmp_path, *args, name="r.json"):
    path = tmp_path / name
    return path, cli_support.solve_to(path, *args, timeout=TIMEOUT)


def assert_verified(path):
    result = run("verify", str(path))
    assert result.returncode == 0, result.stdout + result.stderr
    assert "VERDICT: PASS" in result.stdout, result.stdout


@pytest.mark.parametrize("lam", ["0", "0.5", "1"])
def test_se2_converges_reaches_the_endpoint_and_verifies(tmp_path, lam):
    path, d = solve_to(tmp_path, "--group", "se2", "--lambda", lam, "--T", "1", "--N", "100", "--gT", flat(SE2_GT),
                       "--order", "2")
    assert d["status"] == "converged" and d["group"] == "se2" and d["model"] == "free-body"  # the default model
    assert d["inertia"] == [1, 1, 0.5]  # the model's default
    assert len(d["g"][0]) == 9 and len(d["v"][0]) == 3
    assert np.abs(np.array(d["g"][-1]).reshape(3, 3) - SE2_GT).max() < 1e-8
    assert np.abs(np.array(d["g"][0]).reshape(3, 3) - np.eye(3)).max() < 1e-14
    assert_verified(path)


@pytest.mark.parametrize("lam", ["0", "0.5"])
def test_se3_with_a_full_inertia_from_a_problem_file(tmp_path, lam):
    problem = tmp_path / "p.json"
    problem.write_text(json.dumps({"group": "se3", "inertia": SE3_INERTIA.tolist(), "lambda": float(lam), "T": 1,
                                   "N": 100, "gT": SE3_GT.tolist(), "order": 2, "tol": 1e-10}))  # matrices as rows
    # (verify measures xi_N in the unit shooting stops on, max(1, xi_scale), xi_scale ~ 3 here)
    path, d = solve_to(tmp_path, "--problem", str(problem))
    assert d["status"] == "converged" and d["model"] == "free-body"
    assert np.allclose(np.array(d["inertia"]), SE3_INERTIA, rtol=0, atol=1e-15)  # echoed as rows
    assert len(d["g"][0]) == 16 and len(d["v"][0]) == 6
    assert np.abs(np.array(d["g"][-1]).reshape(4, 4) - SE3_GT).max() < 1e-8
    assert d["terminal_error"] < 1e-8
    assert_verified(path)
    # verify reads the echoed problem: a different lambda no longer solves it
    data = json.loads(path.read_text())
    data["lambda"] = data["lambda"] + 0.5
    path.write_text(json.dumps(data))
    assert run("verify", str(path)).returncode == 1


def test_se3_inertia_on_the_command_line_as_36_numbers_equals_the_file_form(tmp_path):
    _, from_flags = solve_to(tmp_path, "--group", "se3", "--inertia", flat(SE3_INERTIA), "--T", "1", "--N", "50",
                             "--gT", flat(SE3_GT), name="a.json")
    problem = tmp_path / "p.json"
    problem.write_text(json.dumps({"group": "se3", "inertia": SE3_INERTIA.tolist(), "T": 1, "N": 50,
                                   "gT": SE3_GT.tolist()}))
    _, from_file = solve_to(tmp_path, "--problem", str(problem), name="b.json")
    assert from_flags["v"] == from_file["v"]


def test_sweep_on_se2_and_se3(tmp_path):
    other = se2_exp(-0.5, 0.7, -1.2)
    result = run("sweep", "--group", "se2", "--T", "1", "--N", "60", "--lambdas", "0,1", "--gT-list",
                 flat(SE2_GT) + ";" + flat(other), "--quiet", "--jobs", "2")
    assert result.returncode == 0, result.stderr
    table = json.loads(result.stdout)
    assert table["points"] == 4 and table["converged"] == 4
    assert all(len(row["v0"]) == 3 for row in table["rows"])
    result = run("sweep", "--group", "se3", "--model", "free-body", "--T", "1", "--N", "60", "--gT", flat(SE3_GT),
                 "--lambda-range", "0:1:3", "--quiet", "--format", "csv")
    assert result.returncode == 0, result.stderr
    lines = result.stdout.strip().splitlines()
    assert len(lines) == 4 and all(",converged," in line for line in lines[1:])


def rotation(axis, angle):
    return expm(hat3(np.asarray(axis, float) / np.linalg.norm(axis) * angle))


@pytest.mark.parametrize("model", ["free-rigid-body", "oscillator"])
def test_so3_rotated_inertia_gives_the_rotated_solution(tmp_path, model):
    """l(v) = 1/2 v.I v and the Cartan-Schouten connections are invariant under conjugation by a
    rotation Q (Ad_Q = Q on so(3), V = (3 - tr g)/2 too), so the problem (Q I Q^T, Q g0 Q^T, Q gT Q^T)
    is solved by Q g(t) Q^T with velocity Q v(t): a check of the full-matrix inertia that does not
    use the solver's own equations."""
    q = rotation([1, 2, -0.5], 0.9)
    g0 = rotation([0, 1, 0], 0.3)
    gT = rotation([1, 1, 1], 1.7)
    common = ["--model", model, "--lambda", "0.5", "--T", "2", "--N", "200", "--tol", "1e-12", "--method", "shooting"]
    _, plain = solve_to(tmp_path, *common, "--inertia", "2,3,4", "--g0", flat(g0), "--gT", flat(gT), name="plain.json")
    inertia = q @ np.diag([2.0, 3.0, 4.0]) @ q.T
    inertia = (inertia + inertia.T) / 2  # symmetric to rounding
    _, turned = solve_to(tmp_path, *common, "--inertia", flat(inertia), "--g0", flat(q @ g0 @ q.T), "--gT",
                         flat(q @ gT @ q.T), name="turned.json")
    assert plain["status"] == turned["status"] == "converged"
    for g, h in zip(plain["g"], turned["g"]):
        assert np.abs(q @ np.reshape(g, (3, 3)) @ q.T - np.reshape(h, (3, 3))).max() < 1e-9
    for v, w in zip(plain["v"], turned["v"]):
        assert np.abs(q @ np.array(v) - np.array(w)).max() < 1e-9
    assert abs(plain["action"] - turned["action"]) < 1e-9 * max(1, abs(plain["action"]))


def test_default_model_is_the_groups_first():
    for group, gT, model in [("heisenberg", "1,0.5,0.8", "oscillator"), ("so3", flat(rotation([0, 0, 1], 1)),
                                                                         "free-rigid-body")]:
        result = run("solve", "--group", group, "--T", "1", "--N", "20", "--gT", gT)
        assert result.returncode == 0, result.stderr
        assert json.loads(result.stdout)["model"] == model


def assert_rejected(result, needle):
    cli_support.assert_rejected(result, needle, max_length=MAX_MESSAGE)


HUGE = "x" * 100000  # one command-line word may have at most 128 KiB
BAD_FLAGS = [
    (["--group", "se4", "--gT", "1,2,3"], 'group = "se4" is not one of: so3, heisenberg, se2, se3'),
    (["--group", "se2", "--model", "oscillator", "--gT", flat(SE2_GT)],
     'model = "oscillator" is not one of: free-body (the models of group se2)'),
    (["--group", "se3", "--gT", flat(SE2_GT)], "must have 16 numbers"),
    (["--group", "se2", "--gT", flat(SE3_GT)], "must have 9 numbers"),
    (["--group", "se2", "--gT", "1,0,0,0,1,0,0,0.5,1"], "has bottom row 0,0.5,1, not 0,0,1"),
    (["--group", "se2", "--gT", "1,0,3,0,2,1,0,0,1"], "rotation block R that is not orthogonal"),
    (["--group", "se3", "--g0", flat(np.eye(4)[:, ::-1]), "--gT", flat(SE3_GT)], "g0 = "),
    (["--group", "se2", "--gT", "1,0,0,0,1,0,0,0,nan"], "contains a non-finite number"),
    (["--group", "se3", "--gT", flat(SE3_GT), "--v0", "1,2,3"], "v0 = 1,2,3 must have 6 numbers"),
    (["--group", "se3", "--gT", flat(SE3_GT), "--inertia", "1,2,3"], "must have 6 numbers (the diagonal) or 36"),
    (["--inertia", "2,1,0,0,3,0,0,0,4"], "inertia = 2,1,0,0,3,0,0,0,4 is not symmetric"),
    (["--inertia", "1,2,2,2,1,2,2,2,1"], "is not positive definite"),
    (["--inertia", "2,0,0,0,nan,0,0,0,4"], "contains a non-finite number"),
    (["--inertia", "1,2,3,4"], "inertia = 1,2,3,4 must have 3 numbers (the diagonal) or 9"),
    (["--inertia", ",".join(["1"] * 5000)], "(5000 numbers) must have 3 numbers"),
    (["--group", HUGE], 'group = "xxxxxxxx'),
    (["--model", HUGE], 'model = "xxxxxxxx'),
    (["--inertia", HUGE], "is not a comma-separated list of numbers"),
]


@pytest.mark.parametrize("args,needle", BAD_FLAGS)
def test_hostile_flags(args, needle):
    base = ["--T", "1", "--N", "10"]
    if not any(a in ("--gT", "--group") for a in args):
        base += ["--a0", "1,0,0", "--aT", "0,1,0"]
    assert_rejected(run("solve", *base, *args), needle)


def deep(levels):
    return "[" * levels + "1" + "]" * levels


BAD_FILES = [
    ({"group": HUGE, "gT": [1, 2, 3]}, 'group = "xxxx'),
    ({HUGE: 1}, 'key "xxxx'),
    ({"inertia": list(range(100000)), "a0": [1, 0, 0], "aT": [0, 1, 0]}, "(100000 numbers)"),
    ({"inertia": [[2, 0, 0], [0.5, 3, 0], [0, 0, 4]], "a0": [1, 0, 0], "aT": [0, 1, 0]}, "is not symmetric"),
    ({"inertia": [[2, 0, 0], [0, 3, 0]], "a0": [1, 0, 0], "aT": [0, 1, 0]}, "must have 3 numbers"),
    ({"inertia": [[2, 0, 0], [0, 3], [0, 0, 4]]}, "inertia[1] = (an array of 2 entries) must be a row of 3 numbers"),
    ({"inertia": [2, [3], 4]}, "inertia[1] = (an array of 1 entries) must be a number"),
    ({"group": "se3", "gT": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]}, "gT = 1,0,0,0,0,1,0,0,0,0,1,0 must have 16"),
    ({"group": "se3", "gT": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, HUGE]]}, 'gT[3][3] = "xxxx'),
    ({"group": "se2", "g0": {"rows": 3}, "gT": [1, 0, 0, 0, 1, 0, 0, 0, 1]}, "g0 = (an object with 1 keys)"),
    ({"group": "se2", "gT": "1,0,0,0,1,0"}, "gT = 1,0,0,0,1,0 must have 9 numbers"),
]


@pytest.mark.parametrize("content,needle", BAD_FILES)
def test_hostile_problem_files(tmp_path, content, needle):
    problem = tmp_path / "p.json"
    problem.write_text(json.dumps(content))
    assert_rejected(run("solve", "--problem", str(problem)), needle)


def test_deeply_nested_values_are_described_not_dumped(tmp_path):
    problem = tmp_path / "p.json"
    problem.write_text('{"g0": ' + deep(5000) + ', "gT": [1]}')
    result = run("solve", "--problem", str(problem))
    assert result.returncode == 2 and len(result.stderr) < MAX_MESSAGE, result.stderr[:MAX_MESSAGE]


def test_hostile_result_files(tmp_path):
    path, _ = solve_to(tmp_path, "--group", "se2", "--T", "1", "--N", "20", "--gT", flat(SE2_GT))
    for change, needle in [
        (lambda d: d.__setitem__("inertia", [[1, 0.5, 0], [0, 1, 0], [0, 0, 0.5]]), "is not symmetric"),
        (lambda d: d.__setitem__("inertia", [1, 1, -0.5]), "inertia = 1,1,-0.5 is not positive definite"),
        (lambda d: d["g"].__setitem__(3, [1, 0, 0, 0, 1, 0, 0, 0, 2]), "g[3] = "),
        (lambda d: d.__setitem__("model", HUGE), 'model = "xxxx'),
        (lambda d: d.__setitem__("group", "se3"), "must be a list of 16 numbers"),  # se2's g0 read as se3's
    ]:
        data = json.loads(path.read_text())
        change(data)
        bad = tmp_path / "bad.json"
        bad.write_text(json.dumps(data))
        result = run("verify", str(bad))
        assert result.returncode == 2, (needle, result.returncode, result.stdout, result.stderr)
        assert needle in result.stderr and len(result.stderr) < MAX_MESSAGE, result.stderr
