"""Builds the Python package cartan with pip (pyproject.toml: setuptools' build backend).

    pip install --no-build-isolation .

``--no-build-isolation``: pip then uses the setuptools and wheel installed beside it (Debian's
python3-setuptools, python3-wheel) instead of downloading them from PyPI. The pure-Python package
is python/cartan with every subpackage found there at build time; the compiled extension
``cartan._cartan`` is built by the project's CMake (target ``_cartan``, python/CMakeLists.txt) in
build-pip/ (Release, ``-j`` from CMAKE_BUILD_PARALLEL_LEVEL, default 2; a compiler launcher such as
ccache only through the environment, CMAKE_CXX_COMPILER_LAUNCHER). The version is the CMake
project's VERSION (CMakeLists.txt), read here, never written twice.

CARTAN_PREBUILT_EXTENSION=<path to _cartan*.so> skips CMake and packages that file instead (it must
come from a build of the same sources for this interpreter; e.g. build/python/cartan/_cartan*.so
of `make build`): python/tests/test_packaging.py builds a wheel that way in seconds.
"""
import os
import re
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, find_packages, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent
PACKAGE_ROOT = "python"  # python/cartan is the package `cartan`


def project_version(cmakelists_text):
    """The VERSION of ``project(cartan VERSION x.y.z ...)`` in the text of CMakeLists.txt."""
    match = re.search(r"^\s*project\(\s*cartan\s+VERSION\s+([0-9]+(?:\.[0-9]+)*)", cmakelists_text, re.MULTILINE)
    if match is None:
        raise ValueError("CMakeLists.txt has no `project(cartan VERSION x.y.z ...)`: cannot read cartan's version")
    return match.group(1)


def cartan_packages(root=ROOT):
    """``cartan`` and every package below python/cartan (a directory with an __init__.py)."""
    return find_packages(where=str(Path(root) / PACKAGE_ROOT), include=["cartan", "cartan.*"])


def build_jobs(environ=os.environ):
    """The number of parallel compile jobs: CMAKE_BUILD_PARALLEL_LEVEL, or 2."""
    value = environ.get("CMAKE_BUILD_PARALLEL_LEVEL", "2")
    if not value.isdigit() or int(value) < 1:
        raise ValueError(f"CMAKE_BUILD_PARALLEL_LEVEL={value!r}: expected a positive integer")
    return int(value)


class CMakeBuildExt(build_ext):
    """Builds cartan._cartan with the project's CMake, or copies CARTAN_PREBUILT_EXTENSION."""

    def build_extension(self, ext):
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        prebuilt = os.environ.get("CARTAN_PREBUILT_EXTENSION")
        built = self._check_prebuilt(prebuilt) if prebuilt else self._cmake_build()
        shutil.copyfile(built, target)

    @staticmethod
    def _check_prebuilt(path):
        built = Path(path)
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        if not built.is_file() or not built.name.startswith("_cartan") or not built.name.endswith(suffix):
            raise ValueError(f"CARTAN_PREBUILT_EXTENSION={path!r}: expected an existing file _cartan{suffix} "
                             "built for this interpreter (e.g. build/python/cartan of `make build`)")
        return built

    def _cmake_build(self):
        tree = Path(self.build_temp).resolve() / "cmake"
        configure = [
            "cmake", "-S", str(ROOT), "-B", str(tree), "-DCMAKE_BUILD_TYPE=Release",
            f"-DPython3_EXECUTABLE={sys.executable}", "-DCARTAN_BUILD_PYTHON=ON",
            "-DCARTAN_BUILD_TESTS=OFF", "-DCARTAN_BUILD_EXAMPLES=OFF", "-DCARTAN_BUILD_BENCH=OFF",
            # The project's own trees treat warnings as errors; a user's compiler may warn where ours does not.
            "-DCARTAN_BUILD_CLI=OFF", "-DCARTAN_WERROR=OFF",
        ]
        subprocess.run(configure, check=True)
        subprocess.run(["cmake", "--build", str(tree), "--target", "_cartan", "-j", str(build_jobs())], check=True)
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = tree / "python" / "cartan" / f"_cartan{suffix}"
        if not built.is_file():
            raise RuntimeError(f"CMake built no {built} (python/CMakeLists.txt, target _cartan)")
        return built


if __name__ == "__main__":
    (ROOT / "build-pip").mkdir(exist_ok=True)  # egg_base must exist
    setup(
        version=project_version((ROOT / "CMakeLists.txt").read_text()),
        package_dir={"": PACKAGE_ROOT},
        packages=cartan_packages(),
        # The stubs of the compiled module and the PEP 561 marker, in every package that has them.
        package_data={"": ["*.pyi", "py.typed"]},
        ext_modules=[Extension("cartan._cartan", sources=[])],
        cmdclass={"build_ext": CMakeBuildExt},
        # Out of the CMake tree build/ of `make build`: setuptools' own build and metadata directories.
        options={"build": {"build_base": "build-pip"}, "egg_info": {"egg_base": "build-pip"}},
    )
