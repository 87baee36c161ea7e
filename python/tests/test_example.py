"""The Python examples run and report what they claim: examples/python_tour.py (same solution as the
built-in model), custom_lagrangian.py and general_connections.py (their own checks)."""
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_python_tour_runs():
    out = subprocess.run([sys.executable, str(ROOT / "examples" / "python_tour.py")], capture_output=True, text=True,
                         timeout=600, env=dict(os.environ))
    assert out.returncode == 0, out.stderr
    assert "same solution as the built-in model: True" in out.stdout
    assert "status='converged'" in out.stdout
    assert "transport P(0 -> 1) is orthogonal: True" in out.stdout


def test_custom_lagrangian_example_passes_its_checks():
    """examples/custom_lagrangian.py (docs/user-guide.md): a Python Lagrangian on SE(2); the script
    exits non-zero when one of its own checks fails (hessian, convergence, agreement, lambda = 0 limit)."""
    out = subprocess.run([sys.executable, str(ROOT / "examples" / "custom_lagrangian.py")], capture_output=True,
                         text=True, timeout=600, env=dict(os.environ))
    assert out.returncode == 0, out.stdout + out.stderr
    assert "all checks passed" in out.stdout
    assert "FAILED" not in out.stdout


def test_general_connections_example_passes_its_checks():
    """examples/general_connections.py (docs/user-guide.md, "General manifolds and connections"): the
    spherical pendulum against the classical equation, SO(3) against cartan.solve, energy on R^2 with
    torsion; the script exits non-zero when one of its checks fails."""
    out = subprocess.run([sys.executable, str(ROOT / "examples" / "general_connections.py")], capture_output=True,
                         text=True, timeout=600, env=dict(os.environ))
    assert out.returncode == 0, out.stdout + out.stderr
    assert "all checks passed" in out.stdout
    assert "FAILED" not in out.stdout
