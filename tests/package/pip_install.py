"""`pip install --no-build-isolation <fresh clone>` into a fresh virtual environment, then `import
cartan` from elsewhere: the package must come from the environment, carry the CMake project's
VERSION, ship its stubs, and solve. The clone is of the checkout's HEAD (commit it first: the
working tree's changes are not in the clone).

    /usr/bin/python3 tests/package/pip_install.py [--source DIR] [--keep]

ctest runs it as `pip_install_fresh_clone` (label `install`, `make test-install`; not in `make test`:
it compiles the module from scratch, about 15-20 CPU-minutes). Set CMAKE_CXX_COMPILER_LAUNCHER=ccache
in the environment to reuse a compiler cache, CMAKE_BUILD_PARALLEL_LEVEL for the number of jobs.
python/tests/test_packaging.py uses the helpers below with a prebuilt extension instead.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

# Runs in the virtual environment, from a directory without cartan: where cartan comes from, its
# version, its stubs, and a small solve of the rigid body (eq:reduced-system) with the distance of
# the end point from gT measured here, independently of the solver's own terminal_error.
PROBE = """
import json, pathlib
import numpy as np
import cartan
gT = cartan.SO3.exp([0.3, -0.2, 0.4])
r = cartan.solve(cartan.RigidBody([2.0, 3.0, 4.0]), lam=0.5, T=1.0, N=40, gT=gT, tol=1e-10)
miss = cartan.SO3.log(cartan.SO3.compose(cartan.SO3.inverse(gT), r.g[-1]))
package = pathlib.Path(cartan.__file__).parent
print(json.dumps({"file": cartan.__file__, "version": cartan.__version__, "status": r.status,
                  "miss": float(np.linalg.norm(miss)),
                  "files": sorted(str(p.relative_to(package)) for p in package.rglob("*") if p.is_file())}))
"""


def cmake_version(cmakelists):
    """The VERSION of project(cartan ...) in a CMakeLists.txt (read here independently of setup.py)."""
    return re.search(r"project\(cartan VERSION ([0-9.]+)", Path(cmakelists).read_text()).group(1)


def clean_environment(**extra):
    """os.environ without PYTHONPATH (so that cartan can only come from the environment), plus extra."""
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PIP_REQUIRE_VIRTUALENV")}
    env.update(extra)
    return env


def make_venv(path, with_pip=True):
    """A fresh virtual environment of Debian's Python that sees Debian's NumPy and SciPy."""
    command = [sys.executable, "-m", "venv", "--system-site-packages", str(path)]
    subprocess.run(command + ([] if with_pip else ["--without-pip"]), check=True)
    python = Path(path) / "bin" / "python"
    assert python.exists(), python
    return python


def run(command, log, **kwargs):
    """Runs command with its output in the file log; raises with the log's tail if it fails."""
    with open(log, "w") as out:
        done = subprocess.run(command, stdout=out, stderr=subprocess.STDOUT, text=True, **kwargs)
    if done.returncode != 0:
        tail = Path(log).read_text()[-6000:]
        raise RuntimeError(f"{' '.join(map(str, command))} failed ({done.returncode}); end of {log}:\n{tail}")


def probe(python, cwd):
    """The PROBE's report from the environment of `python`, run in cwd without PYTHONPATH."""
    done = subprocess.run([str(python), "-c", PROBE], cwd=cwd, env=clean_environment(), capture_output=True,
                          text=True)
    if done.returncode != 0:
        raise RuntimeError(f"import cartan from the environment failed:\n{done.stderr}")
    return json.loads(done.stdout)


def check_installed(report, venv, version, package_files):
    """Raises AssertionError unless the probe's report shows an installed, working cartan."""
    file = Path(report["file"]).resolve()
    assert Path(venv).resolve() in file.parents, f"cartan imported from {file}, not from the environment {venv}"
    assert report["version"] == version, f"cartan.__version__ = {report['version']}, CMakeLists.txt: {version}"
    assert report["status"] == "converged", report["status"]
    # The end point's distance from gT: solved to tol = 1e-10 on an N = 40 mesh, so 1e-8 leaves
    # room for the rounding of exp/log and of the Newton iterate's last update.
    assert report["miss"] < 1e-8, report["miss"]
    missing = set(package_files) - set(report["files"])
    assert not missing, f"installed package lacks {sorted(missing)}"
    assert any(re.fullmatch(r"_cartan\..*\.so", f) for f in report["files"]), report["files"]


def source_package_files(source):
    """Every file of python/cartan in a source tree (without bytecode): what the wheel must ship."""
    package = Path(source) / "python" / "cartan"
    return sorted(str(p.relative_to(package)) for p in package.rglob("*")
                  if p.is_file() and "__pycache__" not in p.parts)


def fresh_clone_install(source, work):
    """Clones source's HEAD into work, pip-installs the clone into a fresh venv, checks; times."""
    head = subprocess.run(["git", "-C", str(source), "rev-parse", "HEAD"], check=True, capture_output=True,
                          text=True).stdout.strip()
    dirty = subprocess.run(["git", "-C", str(source), "status", "--porcelain", "--untracked-files=no"], check=True,
                           capture_output=True, text=True).stdout
    if dirty:
        print(f"pip_install: uncommitted changes in {source} are not tested (the clone is of HEAD {head})")
    clone, venv = Path(work) / "clone", Path(work) / "venv"
    subprocess.run(["git", "clone", "--quiet", "--no-checkout", str(source), str(clone)], check=True)
    subprocess.run(["git", "-C", str(clone), "checkout", "--quiet", head], check=True)
    python = make_venv(venv)
    start = time.monotonic()
    run([str(python), "-m", "pip", "install", "--no-build-isolation", "-v", str(clone)], Path(work) / "pip.log",
        env=clean_environment())
    seconds = time.monotonic() - start
    elsewhere = Path(work) / "elsewhere"
    elsewhere.mkdir()
    report = probe(python, elsewhere)
    check_installed(report, venv, cmake_version(clone / "CMakeLists.txt"), source_package_files(clone))
    print(f"pip_install: {head[:7]} installed from a fresh clone in {seconds:.0f} s; cartan {report['version']} "
          f"imports from {report['file']}, solves (end point {report['miss']:.1e} from gT)")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--source", type=Path, default=ROOT, help="the repository to clone (default: this one)")
    parser.add_argument("--keep", action="store_true", help="keep the temporary directory (printed)")
    args = parser.parse_args(argv)
    work = Path(tempfile.mkdtemp(prefix="cartan-pip-"))
    try:
        fresh_clone_install(args.source, work)
    finally:
        if args.keep:
            print(f"pip_install: kept {work}")
        else:
            shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
