"""`pip install .` without compiling (setup.py, pyproject.toml): the version read from CMakeLists.txt,
the packages found under python/cartan, and a wheel built around the already-built extension
(CARTAN_PREBUILT_EXTENSION) that installs into a fresh virtual environment and imports from
elsewhere. The real thing, a fresh clone compiled by pip, is tests/package/pip_install.py
(`make test-install`)."""
import importlib.util
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

import cartan

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests" / "package"))
import pip_install  # noqa: E402  (tests/package/pip_install.py: venv, probe and checks)


def load_setup(root=ROOT):
    """setup.py as a module (its setup() call only runs as __main__)."""
    spec = importlib.util.spec_from_file_location("cartan_setup", root / "setup.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_version_is_read_from_cmakelists():
    setup = load_setup()
    # The compiled module's __version__ is CMake's PROJECT_VERSION: the same source, another reader.
    assert setup.project_version((ROOT / "CMakeLists.txt").read_text()) == cartan.__version__
    assert setup.project_version("cmake_minimum_required(VERSION 3.25)\nproject(cartan VERSION 2.10.3 LANGUAGES CXX)") \
        == "2.10.3"
    with pytest.raises(ValueError, match="project\\(cartan VERSION"):
        setup.project_version("cmake_minimum_required(VERSION 3.25)\nproject(other VERSION 1.0)")


def test_packages_are_every_package_under_python_cartan():
    setup = load_setup()
    package = ROOT / "python" / "cartan"
    expected = {".".join(d.relative_to(package.parent).parts) for d in [package, *package.rglob("*")]
                if d.is_dir() and (d / "__init__.py").exists()}
    assert set(setup.cartan_packages()) == expected
    assert "cartan" in expected


def test_build_jobs_from_the_environment():
    setup = load_setup()
    assert setup.build_jobs({}) == 2
    assert setup.build_jobs({"CMAKE_BUILD_PARALLEL_LEVEL": "7"}) == 7
    with pytest.raises(ValueError, match="CMAKE_BUILD_PARALLEL_LEVEL='many'"):
        setup.build_jobs({"CMAKE_BUILD_PARALLEL_LEVEL": "many"})


def copy_source(target):
    """The files `pip install .` reads, copied from this working tree (uncommitted changes included)."""
    target.mkdir()
    for name in ("setup.py", "pyproject.toml", "README.md", "CMakeLists.txt"):
        (target / name).write_bytes((ROOT / name).read_bytes())
    for file in pip_install.source_package_files(ROOT):
        (target / "python" / "cartan" / file).parent.mkdir(parents=True, exist_ok=True)
        (target / "python" / "cartan" / file).write_bytes((ROOT / "python" / "cartan" / file).read_bytes())


def build_wheel(source, out, extension):
    env = pip_install.clean_environment(CARTAN_PREBUILT_EXTENSION=str(extension))
    pip_install.run([sys.executable, "-m", "pip", "wheel", "--no-build-isolation", "--no-deps", "--no-index",
                     "-w", str(out), str(source)], out / "pip-wheel.log", env=env)
    wheels = list(out.glob("cartan-*.whl"))
    assert len(wheels) == 1, wheels
    return wheels[0]


def test_wheel_around_the_built_extension_installs_and_imports(tmp_path):
    source = tmp_path / "source"
    copy_source(source)
    # A subpackage that no list names: the wheel must pick it up (package discovery, not a list).
    (source / "python" / "cartan" / "_probe_subpackage").mkdir()
    (source / "python" / "cartan" / "_probe_subpackage" / "__init__.py").write_text("")
    extension = Path(cartan._cartan.__file__)
    wheel = build_wheel(source, tmp_path, extension)
    assert wheel.name.startswith(f"cartan-{cartan.__version__}-")
    expected = pip_install.source_package_files(source)
    with zipfile.ZipFile(wheel) as archive:
        names = archive.namelist()
        assert archive.read(f"cartan/{extension.name}") == extension.read_bytes()
    assert {"__init__.py", "_bvp.py", "_sweep.py", "_cartan.pyi", "py.typed", "_probe_subpackage/__init__.py"} \
        <= set(expected)
    assert {f"cartan/{f}" for f in expected} <= set(names), sorted(set(names))

    venv = tmp_path / "venv"
    python = pip_install.make_venv(venv, with_pip=False)
    pip_install.run([sys.executable, "-m", "pip", "--python", str(python), "install", "--no-deps", "--no-index",
                     str(wheel)], tmp_path / "pip-install.log", env=pip_install.clean_environment())
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    report = pip_install.probe(python, elsewhere)
    pip_install.check_installed(report, venv, pip_install.cmake_version(ROOT / "CMakeLists.txt"), expected)


def test_prebuilt_extension_must_be_an_extension_for_this_interpreter(tmp_path):
    source = tmp_path / "source"
    copy_source(source)
    wrong = tmp_path / "libcartan.so"
    wrong.write_bytes(b"")
    env = pip_install.clean_environment(CARTAN_PREBUILT_EXTENSION=str(wrong))
    done = subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-build-isolation", "--no-deps", "--no-index",
                           "-w", str(tmp_path), str(source)], capture_output=True, text=True, env=env)
    assert done.returncode != 0
    assert f"CARTAN_PREBUILT_EXTENSION={str(wrong)!r}" in done.stdout + done.stderr
    assert not list(tmp_path.glob("*.whl"))

