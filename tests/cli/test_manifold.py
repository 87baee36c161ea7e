"""`cartan solve --manifold SPACE` (cartan::api::ManifoldProblem, include/cartan/api/solve.hpp, on
every space of include/cartan/api/spaces.hpp): the general transported-velocity problem on S^2
(and H^2) with its Levi-Civita connection, on R^n and on the groups with their connections, and the
particle l = 1/2 v^T A v - G q[last]. Checked against things the solver does not use: the classical
spherical pendulum integrated by SciPy (a metric connection and an isotropic mass give back
classical mechanics), energy conservation at the scheme's order, the documented frame, and the
bad-input contract (exit 2, one line naming the value).

Run by ctest (the `cli` test) with CARTAN_BIN pointing at the built `cartan` executable."""
import json
from functools import partial

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import cli_support

Q0, QT = "1,0,-0.3", "0,1,-0.5"
TIMEOUT = 180  # a hang guard; this file's commands get more time than cli_support.run's default
run = partial(cli_support.run, timeout=TIMEOUT)


def solve_file(tmp_path, *args, name="r.json"):
    """`cartan solve ARGS --output tmp_path/name`, which must succeed: the result read back."""
    return cli_support.solve_to(tmp_path / name, *args, timeout=TIMEOUT)


def sphere(tmp_path, *args, name="s.json"):
    return solve_file(tmp_path, "--manifold", "sphere", "--q0", Q0, "--qT", QT, *args, name=name)


def unit(x):
    x = np.array([float(c) for c in x.split(",")])
    return x / np.linalg.norm(x)


def energy(r):
    a, g = np.array(r["mass"]), r["gravity"]
    v, q = np.array(r["v"]), np.array(r["q"])
    return 0.5 * (v**2 * a).sum(axis=1) + g * q[:, 2]


def test_result_has_the_documented_keys_shapes_and_frame(tmp_path):
    r = sphere(tmp_path, "--gravity", "2", "--mass", "1,3", "--T", "1.5", "--N", "150")
    assert r["status"] == "converged" and r["manifold"] == "sphere" and r["model"] == "particle"
    n = len(r["t"])
    assert n == 151 and r["t"][0] == 0 and abs(r["t"][-1] - 1.5) < 1e-12
    q, v, mu, xi = (np.array(r[k]) for k in ("q", "v", "mu", "Xi"))
    assert q.shape == (n, 3) and v.shape == (n, 2) and mu.shape == (n, 2) and xi.shape == (n, 4)
    np.testing.assert_allclose(np.linalg.norm(q, axis=1), 1, atol=1e-12)  # points of S^2
    np.testing.assert_allclose(q[0], unit(Q0), atol=1e-15)
    np.testing.assert_allclose(q[-1], unit(QT), atol=1e-9)  # |r| <= tol (1e-10) in radians
    np.testing.assert_allclose(mu, v * np.array([1, 3]), rtol=1e-14, atol=1e-14)  # mu = A v
    np.testing.assert_allclose(xi[-1], 0, atol=1e-9)  # Xi(T) = 0
    e1, e2 = np.array(r["frame0"])
    q0, qT = unit(Q0), unit(QT)
    tangent = qT - q0.dot(qT) * q0  # e1: towards qT along the minimal great circle
    np.testing.assert_allclose(e1, tangent / np.linalg.norm(tangent), atol=1e-15)
    np.testing.assert_allclose(e2, np.cross(q0, e1), atol=1e-15)


def classical_pendulum_endpoint(q0, velocity, g, T):
    """q'' = -g (e_z - z q) - |q'|^2 q on the unit sphere (RK45, tight tolerances)."""
    def f(_, y):
        q, p = y[:3], y[3:]
        return np.concatenate([p, -g * (np.array([0, 0, 1.0]) - q[2] * q) - p.dot(p) * q])
    sol = solve_ivp(f, (0, T), np.concatenate([q0, velocity]), rtol=1e-12, atol=1e-12)
    return sol.y[:3, -1]


def test_isotropic_particle_is_the_classical_spherical_pendulum(tmp_path):
    """The Levi-Civita connection is metric and l sees only |v|: the solution is the classical
    pendulum, so SciPy started from q0 with velocity v0 in the frame reaches qT, up to the order-2
    scheme's error in v0, which falls 4x when N doubles."""
    miss = []
    for n in (200, 400):
        r = sphere(tmp_path, "--gravity", "9.81", "--T", "1", "--N", str(n), "--order", "2")
        e1, e2 = np.array(r["frame0"])
        v0 = np.array(r["v"][0])
        miss.append(np.linalg.norm(classical_pendulum_endpoint(unit(Q0), v0[0] * e1 + v0[1] * e2, 9.81, 1.0) - unit(QT)))
    assert miss[1] < 1e-4
    assert 3.2 < miss[0] / miss[1] < 4.8


def test_energy_is_conserved_at_the_schemes_order(tmp_path):
    """1/2 (a1 v1^2 + a2 v2^2) + G z is conserved for every connection (docs/general-connections.md);
    the discrete drift falls at least at the scheme's order (measured: 2 and 8 for orders 1 and 2)."""
    for order, ratio in (("1", 2), ("2", 4)):
        drift = []
        for n in (200, 400):
            r = sphere(tmp_path, "--gravity", "3", "--mass", "1,2.5", "--T", "1.2", "--N", str(n), "--order", order)
            e = energy(r)
            drift.append(np.abs(e - e[0]).max())
        assert drift[0] / drift[1] > 0.85 * ratio, (order, drift)


def test_collocation_is_the_classical_pendulum_to_its_tolerance(tmp_path):
    """--method collocation solves the continuous system (fourth order, adaptive mesh): SciPy's
    pendulum from (q0, E0 v0) reaches qT to about the tolerance (measured 1e-9 at tol 1e-10), far
    closer than the order-2 scheme at N = 400 (1e-5); output at the --samples times, on S^2 to the
    same accuracy; cartan verify passes it (its checks are second order in the sample spacing).
    Newton fails from the geodesic guess here; --continuation T starts from order-2 shooting."""
    r = sphere(tmp_path, "--gravity", "9.81", "--T", "1", "--N", "40", "--method", "collocation", "--tol", "1e-10",
               "--samples", "201", "--continuation", "T")
    assert r["status"] == "converged" and r["method"] == "collocation" and r["order"] == 4, r["message"]
    assert r["mesh_size"] >= 41 and r["max_residual"] <= 1e-10
    assert len(r["t"]) == 201 and np.array(r["Xi"]).shape == (201, 4)
    e1, e2 = np.array(r["frame0"])
    v0 = np.array(r["v"][0])
    reached = classical_pendulum_endpoint(unit(Q0), v0[0] * e1 + v0[1] * e2, 9.81, 1.0)
    assert np.linalg.norm(reached - unit(QT)) < 1e-8
    np.testing.assert_allclose(np.linalg.norm(r["q"], axis=1), 1, atol=1e-9)
    v = run("verify", str(tmp_path / "s.json"))
    assert v.returncode == 0 and "VERDICT: PASS" in v.stdout, v.stdout + v.stderr


def test_collocation_and_the_order_two_scheme_agree_under_a_general_connection(tmp_path):
    """Under the Levi-Civita connection of another metric (nabla R != 0) the order-2 scheme
    converges to the continuous solution that collocation computes: the gap in v0 falls 4x when N
    doubles."""
    args = (*FREE_BODY[:-1], "3", "--connection", "levi-civita", "--metric", "1,2,3")
    c = solve_file(tmp_path, *args, "--N", "40", "--method", "collocation", "--tol", "1e-10", name="c.json")
    assert c["status"] == "converged" and c["method"] == "collocation", c["message"]
    gap = []
    for n in (100, 200):
        s = solve_file(tmp_path, *args, "--N", str(n), "--order", "2", "--tol", "1e-12", name="s.json")
        gap.append(np.linalg.norm(np.array(s["v"][0]) - np.array(c["v"][0])))
    assert 3.4 < gap[0] / gap[1] < 4.6, gap


def test_anisotropic_mass_changes_the_dynamics(tmp_path):
    """A1 != A2 sees the direction of v: the curve between the same endpoints differs from the
    pendulum's by far more than the discretisation error."""
    iso = sphere(tmp_path, "--gravity", "2", "--T", "1", "--N", "200", "--order", "2", name="a.json")
    aniso = sphere(tmp_path, "--gravity", "2", "--mass", "1,4", "--T", "1", "--N", "200", "--order", "2", name="b.json")
    gap = np.linalg.norm(np.array(iso["q"]) - np.array(aniso["q"]), axis=1).max()
    assert gap > 1e-2


@pytest.mark.parametrize("args, fragment", [
    (["--qT", "-1,0,0.3", "--mass", "1,2"], "are antipodal: the default frame's e1"),
    (["--qT", "2,0,-0.6", "--mass", "1,2"], "are equal: the default frame's e1"),
    (["--qT", "0,0,0"], "qT = 0,0,0 has zero length"),
    (["--qT", "1,2"], "qT = 1,2 must have 3 numbers"),
    (["--lambda", "0.3"], "lambda = 0.3 is an option of --connection cartan-schouten only"),
    (["--connection", "coefficients"], "connection = coefficients is not a connection of sphere"),
    (["--frame0", "0,1,0"], "frame0 = 0,1,0 must have 6 numbers"),
    (["--frame0", "1,0,0,0,1,0"], "must consist of tangent vectors at q0"),
    (["--group", "se2"], "is not an option of --manifold sphere"),
    (["--mass", "1,-2"], "mass = 1,-2 must be symmetric positive definite"),
    (["--mass", "1,2,3"], "must have 2 numbers"),
    (["--method", "two-level"], "is not a method of --manifold sphere"),
    (["--samples", "5"], "samples = 5 is an option of --method collocation only"),
    (["--method", "collocation", "--samples", "1"], "samples = 1"),
    (["--method", "shooting", "--continuation", "lambda"], "continuation = \"lambda\""),
    (["--model", "rigid"], "model = \"rigid\" is not a model of --manifold sphere"),
    (["--gravity", "nan"], "gravity"),
    (["--v0", "1,2,3"], "v0"),
])
def test_bad_sphere_input_exits_2_naming_the_value(args, fragment):
    endpoints = ["--q0", Q0] + ([] if "--qT" in args else ["--qT", QT])
    r = run("solve", "--manifold", "sphere", *endpoints, *args)
    assert r.returncode == 2, r.stderr
    assert fragment in r.stderr and r.stderr.count("\n") == 1, r.stderr


def test_manifold_options_are_refused_on_groups_and_unknown_manifolds():
    r = run("solve", "--group", "so3", "--a0", "1,0,0", "--aT", "0,1,0", "--q0", "1,0,0")
    assert r.returncode == 2 and "q0 = 1,0,0 is not an option of a problem on a group" in r.stderr
    r = run("solve", "--manifold", "torus", "--q0", Q0, "--qT", QT)
    assert r.returncode == 2 and 'manifold = "torus" is not one of: so3, heisenberg, se2, se3, sphere' in r.stderr
    r = run("solve", "--manifold", "sphere", "--qT", QT)
    assert r.returncode == 2 and "q0 = (missing) is required" in r.stderr


def test_verify_passes_sphere_results_and_fails_them_for_another_problem(tmp_path):
    """cartan verify rebuilds the problem from the echoed fields and runs the general checks
    (include/cartan/kernels/manifold/verify.hpp); the same data under another gravity fail them."""
    for order in ("1", "2"):
        sphere(tmp_path, "--gravity", "3", "--mass", "1,2.5", "--T", "1.2", "--N", "300", "--order", order)
        r = run("verify", str(tmp_path / "s.json"))
        assert r.returncode == 0 and "VERDICT: PASS" in r.stdout and "sphere particle" in r.stdout, r.stdout + r.stderr
        data = json.loads((tmp_path / "s.json").read_text())
        data["gravity"] = 3.5
        (tmp_path / "wrong.json").write_text(json.dumps(data))
        r = run("verify", str(tmp_path / "wrong.json"), "--json")
        assert r.returncode == 1 and json.loads(r.stdout)["verdict"] == "FAIL", r.stdout


def test_lambda_is_written_only_under_the_connection_it_parametrises(tmp_path):
    """lambda is a parameter of the Cartan-Schouten connection only: a group model's file under
    Levi-Civita writes "lambda": null (the flag's default 0.5 is no part of that problem; Python's
    result has lam None) and `cartan verify` reads it back; under Cartan-Schouten the number given.
    A file written before, with a number under Levi-Civita, still reads (the number is not used)."""
    lc = solve_file(tmp_path, *FREE_BODY[:-1], "2", "--N", "100", "--connection", "levi-civita", "--metric", "1,2,3",
                    name="lc.json")
    assert lc["status"] == "converged" and lc["connection"] == "levi-civita" and lc["lambda"] is None, lc["message"]
    old = tmp_path / "old.json"
    old.write_text(json.dumps(dict(lc, **{"lambda": 0.5})))
    for path in (tmp_path / "lc.json", old):
        v = run("verify", str(path))
        assert v.returncode == 0 and "VERDICT: PASS" in v.stdout, v.stdout + v.stderr
    cs = solve_file(tmp_path, *FREE_BODY[:-1], "2", "--N", "100", "--lambda", "0.3", name="cs.json")
    assert cs["status"] == "converged" and cs["connection"] == "cartan-schouten" and cs["lambda"] == 0.3, cs["message"]


def test_every_space_of_the_catalogue_solves_and_verifies(tmp_path):
    """Each space the library compiles, through `cartan solve --manifold` and `cartan verify` of its
    file; the projectile in R^3 against its closed form (both schemes integrate a constant force
    exactly: the shooting tolerance remains)."""
    r = solve_file(tmp_path, "--manifold", "euclidean", "--q0", "0,0,0", "--qT", "1,2,-0.5", "--gravity", "9.81",
                   "--mass", "2,1,4", "--T", "1.5", "--N", "60", "--order", "2", name="e.json")
    assert r["status"] == "converged" and r["connection"] == "levi-civita", r["message"]
    t, q = np.array(r["t"]), np.array(r["q"])
    a = np.array([0, 0, 9.81 / 4])
    c = np.array([1, 2, -0.5]) / 1.5 + 0.5 * a * 1.5
    np.testing.assert_allclose(q, np.outer(t, c) - 0.5 * np.outer(t**2, a), atol=1e-9)
    cases = {
        "h.json": ["--manifold", "hyperbolic-plane", "--q0", "0,0,1", "--qT", "0.5,0.2,1.2", "--gravity", "1"],
        "p.json": ["--manifold", "euclidean", "--q0", "0,0", "--qT", "1,0.4", "--connection", "coefficients",
                   "--alpha", str(tmp_path / "alpha.json"), "--order", "2"],
        "so3.json": ["--manifold", "so3", "--qT", "0.36,-0.48,0.8,0.8,0.6,0,-0.48,0.64,0.6", "--connection",
                     "levi-civita", "--metric", "1,2,3", "--mass", "2,3,4"],
        "cs.json": ["--manifold", "se2", "--qT", "0.8,-0.6,1,0.6,0.8,0.5,0,0,1", "--lambda", "0.3"],
        "h3.json": ["--manifold", "heisenberg", "--q0", "0,0,0", "--qT", "1,0.5,0.2", "--connection", "levi-civita"],
        "se3.json": ["--manifold", "se3", "--qT", "1,0,0,0.5,0,1,0,0.2,0,0,1,-0.3,0,0,0,1", "--mass", "1,1,1,2,3,4"],
    }
    (tmp_path / "alpha.json").write_text(json.dumps([[[0, 1.5], [0, 0]], [[0, 0], [0, 0]]]))
    for name, args in cases.items():
        r = solve_file(tmp_path, *args, name=name)
        assert r["status"] == "converged", (name, r["message"])
        out = run("verify", str(tmp_path / name))
        assert out.returncode == 0 and "VERDICT: PASS" in out.stdout, (name, out.stdout + out.stderr)
    r = run("solve", "--manifold", "so3", "--qT", "1,0,0,0,1,0,0,0,1", "--gravity", "1")
    assert r.returncode == 2 and "gravity = 1 does not apply on so3" in r.stderr, r.stderr
    r = run("solve", "--manifold", "euclidean", "--q0", "0,0,0,0", "--qT", "1,0,0,0")
    assert r.returncode == 2 and "q0 = 0,0,0,0 must have 2 or 3 numbers" in r.stderr, r.stderr


def test_gravity_where_it_does_not_apply_is_refused_even_0_and_echoed_null(tmp_path):
    """A group's points are not vectors: no gravity. `--gravity 0` was taken for "not given" and the
    file said "gravity": 0.0 there, where Python's Result has None and cartan.solve refuses
    gravity=0. Now refused as any value, and the echo is null (which `cartan verify` reads); a space
    that takes gravity still echoes its number."""
    cli_support.assert_rejected(run("solve", "--manifold", "so3", "--qT", "0,-1,0,1,0,0,0,0,1", "--gravity", "0"),
                                "cartan solve: gravity = 0 does not apply on so3")
    r = solve_file(tmp_path, "--manifold", "so3", "--qT", "0,-1,0,1,0,0,0,0,1", "--T", "1", "--N", "20")
    assert "gravity" in r and r["gravity"] is None
    out = run("verify", str(tmp_path / "r.json"))
    assert out.returncode == 0 and "VERDICT: PASS" in out.stdout, out.stdout + out.stderr
    assert sphere(tmp_path, "--T", "1", "--N", "20")["gravity"] == 0.0


# ---- --connection on groups: the general solver on a Lie group -----------------------------------

FREE_BODY = ["--model", "free-rigid-body", "--a0", "-1,-1,-1", "--aT", "0.9,1,1", "--T", "5"]


def so3_ad(i):
    """ad(E_i) on so(3): [E_i, E_j] = eps_ijk E_k."""
    m = np.zeros((3, 3))
    j, k = (i + 1) % 3, (i + 2) % 3
    m[k, j], m[j, k] = 1, -1
    return m


def test_cartan_schouten_given_as_coefficients_reproduces_the_lambda_solver(tmp_path):
    """alpha = lambda ad in a file (alpha[i][j][k] = lambda [E_i, E_j]_k) is solved by the general
    solver; it satisfies the same discrete equations as --lambda (docs/general-connections.md),
    so the two agree to the solvers' tolerance."""
    lam = 0.3
    alpha = [[list(lam * so3_ad(i)[:, j]) for j in range(3)] for i in range(3)]
    (tmp_path / "alpha.json").write_text(json.dumps(alpha))
    general = solve_file(tmp_path, *FREE_BODY, "--N", "200", "--connection", "coefficients",
                         "--alpha", str(tmp_path / "alpha.json"), "--tol", "1e-12", name="g.json")
    reference = solve_file(tmp_path, *FREE_BODY, "--N", "200", "--lambda", str(lam), "--method", "shooting",
                           "--tol", "1e-12", name="l.json")
    assert general["connection"] == "coefficients" and np.array(general["alpha"]).shape == (3, 3, 3)
    assert np.array(general["Xi"]).shape == (201, 9) and "xi" not in general
    np.testing.assert_allclose(general["g"], reference["g"], atol=1e-8)
    np.testing.assert_allclose(general["v"], reference["v"], atol=1e-8)


def test_levi_civita_of_the_inertia_is_the_classical_free_rigid_body(tmp_path):
    """Levi-Civita of the metric I with l = 1/2 v.I v: transport is an isometry, the action is the
    classical one, the curve is the lambda = 0 curve; at order 2 the gap falls 4x with h."""
    gap = []
    for n in (100, 200):
        lc = solve_file(tmp_path, *FREE_BODY, "--N", str(n), "--connection", "levi-civita", "--order", "2", name="a.json")
        classical = solve_file(tmp_path, *FREE_BODY, "--N", str(n), "--lambda", "0", "--method", "shooting",
                               "--order", "2", name="b.json")
        assert lc["metric"] == [2.0, 3.0, 4.0]  # the inertia, by default
        gap.append(np.abs(np.array(lc["g"]) - np.array(classical["g"])).max())
    assert gap[1] < 1e-4 and 3.2 < gap[0] / gap[1] < 4.8, gap


def test_another_metric_gives_new_dynamics(tmp_path):
    a = solve_file(tmp_path, *FREE_BODY, "--N", "200", "--connection", "levi-civita", name="a.json")
    b = solve_file(tmp_path, *FREE_BODY, "--N", "200", "--connection", "levi-civita", "--metric", "1,2,3", name="b.json")
    assert np.abs(np.array(a["g"]) - np.array(b["g"])).max() > 1e-2


@pytest.mark.parametrize("args, fragment", [
    (["--connection", "levi-civita", "--lambda", "0.2"], "lambda = 0.2"),
    (["--metric", "1,2,3"], "metric = 1,2,3 is an option of --connection levi-civita only"),
    (["--connection", "levi-civita", "--metric", "1,-2,3"], "must be symmetric positive definite"),
    (["--connection", "levi-civita", "--metric", "1,2"], "metric = 1,2 must have 3 numbers (the diagonal) or 9"),
    (["--connection", "coefficients"], "alpha = (missing) is required"),
    (["--connection", "coefficients", "--alpha", "/nonexistent/alpha.json"], "alpha"),
    (["--alpha", "x.json"], "is an option of --connection coefficients only"),
    (["--connection", "torsion"], 'connection = "torsion" is not one of'),
    (["--connection", "levi-civita", "--method", "two-level"], "is not a method of --connection levi-civita"),
    (["--connection", "levi-civita", "--xi0", "0,0,0"], "xi0"),
])
def test_bad_connection_input_exits_2_naming_the_value(args, fragment):
    r = run("solve", "--a0", "1,0,0", "--aT", "0,1,0", *args)
    assert r.returncode == 2, r.stderr
    assert fragment in r.stderr and r.stderr.count("\n") == 1, r.stderr


def test_bad_alpha_file_shape(tmp_path):
    (tmp_path / "a.json").write_text("[[1, 2]]")
    r = run("solve", "--a0", "1,0,0", "--aT", "0,1,0", "--connection", "coefficients", "--alpha", str(tmp_path / "a.json"))
    assert r.returncode == 2 and "must hold a 3 x 3 x 3 array of numbers" in r.stderr


def test_verify_passes_connection_results_and_fails_them_for_another_connection(tmp_path):
    solve_file(tmp_path, *FREE_BODY, "--N", "300", "--connection", "levi-civita", "--metric", "1,2,3", "--order", "2")
    r = run("verify", str(tmp_path / "r.json"))
    assert r.returncode == 0 and "VERDICT: PASS" in r.stdout and "connection levi-civita" in r.stdout, r.stdout + r.stderr
    data = json.loads((tmp_path / "r.json").read_text())
    data["metric"] = [1.0, 2.0, 4.0]
    (tmp_path / "wrong.json").write_text(json.dumps(data))
    r = run("verify", str(tmp_path / "wrong.json"))
    assert r.returncode == 1 and "VERDICT: FAIL" in r.stdout, r.stdout
    data["metric"] = [1.0, -2.0, 3.0]
    (tmp_path / "bad.json").write_text(json.dumps(data))
    r = run("verify", str(tmp_path / "bad.json"))
    assert r.returncode == 2 and "metric = 1,-2,3 must be symmetric positive definite" in r.stderr


def test_sweep_solves_general_connections_as_cartan_solve_does():
    # The library picks the kernel for every point (api::solve): a sweep of Levi-Civita problems
    # runs the general solver, and each row is the `cartan solve` run of its point, bit for bit.
    base = [*FREE_BODY[:4], "--T", "2", "--N", "100", "--connection", "levi-civita", "--metric", "1,2,3"]
    r = run("sweep", *base, "--aT-list", "0.9,1,1;1,0.2,0.1", "--quiet")
    assert r.returncode == 0, r.stderr
    table = json.loads(r.stdout)
    assert table["points"] == 2 and table["converged"] == 2
    for row in table["rows"]:
        assert row["lambda"] is None and row["connection"] == "levi-civita"
        solved = json.loads(run("solve", *base, "--aT", ",".join(repr(x) for x in row["aT"])).stdout)
        for key in ["status", "message", "method", "branch", "terminal_error", "iterations"]:
            assert row[key] == solved[key], key
        assert row["v0"] == solved["v"][0]


def test_sweep_refuses_lambdas_on_another_connection():
    r = run("sweep", *FREE_BODY, "--connection", "levi-civita", "--lambdas", "0")
    assert r.returncode == 2 and "lambda = 0 is an option of --connection cartan-schouten only" in r.stderr, r.stderr


# ---- The hyperbolic plane --------------------------------------------------------------------------

def test_hyperbolic_plane_free_particle_runs_the_geodesic_and_verifies(tmp_path):
    # H^2 = {z^2 - x^2 - y^2 = 1, z > 0}: from the vertex to (sinh d, 0, cosh d) the geodesic is
    # (sinh(d t/T), 0, cosh(d t/T)) at the constant speed d/T along e1 = (1, 0, 0); e2 = (0, 1, 0).
    # qT is given off the sheet (times 2) and echoed on it. The pieces are geodesics: exact to the
    # solve's tolerance (1e-10 on the dimensionless residual; 1e-9 here).
    d, T = 0.9, 1.5
    qT = f"{2 * np.sinh(d)!r},0,{2 * np.cosh(d)!r}"
    r = solve_file(tmp_path, "--manifold", "hyperbolic-plane", "--q0", "0,0,1", "--qT", qT, "--T", repr(T), "--N", "30",
                   name="h.json")
    assert r["status"] == "converged" and r["manifold"] == "hyperbolic-plane", r["message"]
    np.testing.assert_allclose(r["qT"], [np.sinh(d), 0, np.cosh(d)], atol=1e-15)
    t, q, v = np.array(r["t"]), np.array(r["q"]), np.array(r["v"])
    np.testing.assert_allclose(q, np.stack([np.sinh(d * t / T), 0 * t, np.cosh(d * t / T)], axis=1), atol=1e-9)
    np.testing.assert_allclose(v, np.tile([d / T, 0], (len(t), 1)), atol=1e-9)
    np.testing.assert_allclose(r["frame0"], [[1, 0, 0], [0, 1, 0]], atol=1e-15)
    check = run("verify", str(tmp_path / "h.json"))
    assert check.returncode == 0 and "VERDICT: PASS" in check.stdout, check.stdout + check.stderr


def test_hyperbolic_plane_with_gravity_conserves_energy_at_second_order(tmp_path):
    # V = G z grows away from the vertex, so the particle is pulled back. The continuous problem
    # conserves the energy 1/2 v.A v + G z, because l does not depend on t. The order-2 scheme
    # conserves it to O(h^2), so halving h divides the spread by about 4. Measured: 1.9e-6 at
    # N = 100 and 3.9e-7 at N = 200, a ratio of 4.9.
    spreads = []
    for N in (100, 200):
        r = solve_file(tmp_path, "--manifold", "hyperbolic-plane", "--q0", "0.3,0,1", "--qT", "0,0.5,1", "--gravity", "1",
                       "--mass", "1,2", "--T", "2", "--N", str(N), "--order", "2", name=f"g{N}.json")
        assert r["status"] == "converged", r["message"]
        spreads.append(np.ptp(energy(r)))
    assert spreads[1] < 1e-5  # h^2 = 1e-4, times the motion's scale (energy ~1.2)
    assert 3 < spreads[0] / spreads[1] < 6  # order 2 (4), +- the higher terms at these steps


@pytest.mark.parametrize("args, needle", [
    (["--qT", "2,0,1"], "qT = 2,0,1 is not a point of the hyperbolic plane"),
    (["--qT", "0,0,-1"], "qT = 0,0,-1 is not a point of the hyperbolic plane"),
    (["--qT", "0,0,3", "--mass", "1,2"], "q0/qT = [0, 0, 1] / [0, 0, 1] are equal"),
])
def test_hyperbolic_plane_bad_points_are_refused_by_name(args, needle):
    r = run("solve", "--manifold", "hyperbolic-plane", "--q0", "0,0,1", *args)
    assert r.returncode == 2 and needle in r.stderr, r.stderr


def test_a_group_with_cartan_schouten_takes_the_lie_kernels_methods(tmp_path):
    """`--manifold so3` with the Cartan-Schouten connection runs general::solve on the Lie-group
    kernel, whose own methods (multiple shooting, two-level, continuation in lambda) are reachable
    from this door too, with the model's answer (`--group so3 --model free-rigid-body`, the same
    problem): the same converged v0 to the shooting tolerance. Other connections and spaces refuse
    them by name."""
    qT = "0.36,-0.48,0.8,0.8,0.6,0,-0.48,0.64,0.6"
    model = solve_file(tmp_path, "--group", "so3", "--model", "free-rigid-body", "--inertia", "2,3,4", "--gT", qT,
                       "--lambda", "0.3", "--T", "2", "--N", "100", name="model.json")
    for args in (["--method", "multiple-shooting", "--segments", "4"], ["--method", "two-level"],
                 ["--method", "shooting", "--continuation", "lambda"]):
        r = solve_file(tmp_path, "--manifold", "so3", "--mass", "2,3,4", "--qT", qT, "--lambda", "0.3", "--T", "2",
                       "--N", "100", *args, name="m.json")
        assert r["status"] == "converged" and r["method"] == args[1], (args, r["message"])
        # both converged to tol 1e-10 on the same discrete problem: v0 agrees to well within 1e-8
        np.testing.assert_allclose(r["v"][0], model["v"][0], atol=1e-8, err_msg=str(args))
        out = run("verify", str(tmp_path / "m.json"))
        assert out.returncode == 0 and "VERDICT: PASS" in out.stdout, out.stdout + out.stderr
    for args, fragment in ((["--manifold", "so3", "--connection", "levi-civita", "--method", "two-level"],
                            "is not a method of --manifold so3 (methods: auto, shooting, collocation)"),
                           (["--manifold", "so3", "--method", "variational"], "is not a method of --manifold so3"),
                           (["--manifold", "so3", "--segments", "4"], "segments = 4 is an option of --method "
                                                                      "multiple-shooting only")):
        r = run("solve", *args, "--qT", qT)
        assert r.returncode == 2 and fragment in r.stderr, r.stderr
