"""`cmake --install <build> --component python` gives a package that imports from the install
prefix alone (not from the build tree)."""
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BUILD = os.environ.get("CARTAN_BUILD_DIR", str(ROOT / "build"))
CMAKE = os.environ.get("CMAKE_COMMAND", "cmake")


def test_installed_package_imports(tmp_path):
    prefix = tmp_path / "prefix"
    subprocess.run([CMAKE, "--install", BUILD, "--component", "python", "--prefix", str(prefix)], check=True,
                   capture_output=True, text=True)
    sites = list(prefix.glob("lib*/python3*/site-packages"))
    assert len(sites) == 1, sites
    # The stubs of the compiled module and the PEP 561 marker go with it (python/CMakeLists.txt).
    stub = "cartan/_cartan.pyi"
    assert (sites[0] / stub).read_bytes() == (ROOT / "python" / stub).read_bytes()
    assert (sites[0] / "cartan" / "py.typed").exists()
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(sites[0])
    code = ("import cartan, cartan.testing; print(cartan.__file__); print(cartan.testing.__file__); "
            "print(cartan.SO3.log(cartan.SO3.exp([0.1, 0.2, 0.3])))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    assert out.stdout.startswith(str(sites[0] / "cartan"))
    assert str(sites[0] / "cartan" / "testing" / "__init__.py") in out.stdout  # the subpackage is installed
    assert "[0.1 0.2 0.3]" in out.stdout


def test_version_is_the_projects():
    # cartan.__version__ is the VERSION of the top-level CMakeLists.txt's project(), compiled in.
    import re

    import cartan

    version = re.search(r"project\(cartan VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text()).group(1)
    assert cartan.__version__ == version
