"""The type stubs of the compiled module (python/cartan/_cartan.pyi) are true: they are what
scripts/generate_stubs.py makes of the built module, mypy's stubtest finds them consistent with it,
and mypy accepts a typed use of cartan (typing/typed_right.py) and rejects each wrong call of
typing/typed_wrong.py with the expected message."""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import cartan

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "scripts"))
import generate_stubs  # noqa: E402

STUB = ROOT / "python" / "cartan" / "_cartan.pyi"
EXAMPLES = Path(__file__).resolve().parent / "typing"
REGENERATE = ("after changing the bindings (python/src): rebuild cartan_python, run `PYTHONPATH=build/python "
              "/usr/bin/python3 scripts/generate_stubs.py` and commit python/cartan/_cartan.pyi")


@pytest.fixture(scope="module")
def mypy_env(tmp_path_factory):
    """mypy reads the committed stubs and the package from python/ (not PYTHONPATH), one shared cache."""
    env = dict(os.environ, MYPYPATH=str(ROOT / "python"))
    return env, tmp_path_factory.mktemp("mypy-cache")


def test_stub_is_what_the_built_module_gives():
    assert STUB.read_text(encoding="utf-8") == generate_stubs.generate(cartan._cartan), f"{STUB} is stale: {REGENERATE}"


def stubtest(env, cache):
    """mypy's stubtest of cartan._cartan: the stub found through env's MYPYPATH, the runtime module
    imported from PYTHONPATH (the built one)."""
    return subprocess.run([sys.executable, "-m", "mypy.stubtest", "cartan._cartan", "--mypy-config-file",
                           str(EXAMPLES / "mypy.ini")], capture_output=True, text=True,
                          env=dict(env, MYPY_CACHE_DIR=str(cache)), cwd=ROOT)


def test_stubtest_finds_the_stub_consistent_with_the_module(mypy_env):
    done = stubtest(*mypy_env)
    assert done.returncode == 0, f"stubtest: {done.stdout}{done.stderr}\n{REGENERATE}"


def test_stubtest_rejects_a_stub_that_misses_or_invents_a_method(mypy_env, tmp_path):
    # Negative control: the package's sources with a stub that lacks SO3.exp and declares SO3.expp.
    env, cache = mypy_env
    shutil.copytree(ROOT / "python" / "cartan", tmp_path / "cartan", ignore=shutil.ignore_patterns("__pycache__"))
    stub = tmp_path / "cartan" / "_cartan.pyi"
    text = stub.read_text(encoding="utf-8")
    assert text.count("    def exp(v: Any)") == 4  # SO3, Heisenberg, SE3, SE2
    stub.write_text(text.replace("    def exp(v: Any)", "    def expp(v: Any)", 1), encoding="utf-8")
    done = stubtest(dict(env, MYPYPATH=str(tmp_path)), cache)
    assert done.returncode == 1, done.stdout + done.stderr
    errors = sorted(line for line in done.stdout.splitlines() if line.startswith("error: "))
    assert errors == ["error: cartan._cartan.SO3.exp is not present in stub",
                      "error: cartan._cartan.SO3.expp is not present at runtime"], done.stdout


def expected_errors(path):
    """{line: message start} of the `# error: ...` markers of a file."""
    return {i: line.split("# error: ", 1)[1].strip()
            for i, line in enumerate(path.read_text().splitlines(), start=1) if "# error: " in line}


def test_mypy_accepts_right_calls_and_rejects_wrong_ones(mypy_env):
    env, cache = mypy_env
    right, wrong = EXAMPLES / "typed_right.py", EXAMPLES / "typed_wrong.py"
    done = subprocess.run([sys.executable, "-m", "mypy", "--config-file", str(EXAMPLES / "mypy.ini"), "--cache-dir",
                           str(cache), "--no-error-summary", str(right), str(wrong)],
                          capture_output=True, text=True, env=env, cwd=ROOT)
    found = {}
    for line in done.stdout.splitlines():
        if ": note: " in line:  # where a called function is defined
            continue
        match = re.match(r"(.*?):(\d+): error: (.*)", line)
        assert match, f"unexpected mypy output: {line}"
        assert (ROOT / match.group(1)).resolve() == wrong, f"mypy rejects the right use: {line}\n{REGENERATE}"
        found[int(match.group(2))] = match.group(3)
    expected = expected_errors(wrong)
    assert len(expected) == 4
    assert set(found) == set(expected), f"mypy: {done.stdout}{done.stderr}\n{REGENERATE}"
    for line, message in expected.items():
        assert found[line].startswith(message), (line, found[line])


def test_generator_reads_pybind11_signatures():
    # What the module does not use today but new bindings may: shapes, callables, defaults with
    # commas, keyword-only markers, overloads, and a C++ type pybind11 could not name.
    assert generate_stubs.annotation("numpy.ndarray[numpy.float64[3, 1], flags.writeable]") == "NDArray[numpy.float64]"
    assert generate_stubs.annotation("Callable[[float, numpy.ndarray[numpy.float64]], None]") \
        == "Callable[[float, NDArray[numpy.float64]], None]"
    assert generate_stubs.annotation("Dict[str, cartan._cartan.SO3.Connection]") == "Dict[str, SO3.Connection]"
    with pytest.raises(ValueError, match="cartan::Foo"):
        generate_stubs.annotation("cartan::Foo")
    name, params, result = generate_stubs.parse_signature(
        "f(self: cartan._cartan.X, a: Tuple[int, int] = (1, 2), *, b: str = 'x, y') -> List[float]")
    assert (name, result) == ("f", "List[float]")
    assert [generate_stubs.parameter(p, i, True) for i, p in enumerate(params)] \
        == ["self", "a: Tuple[int, int] = ...", "*", "b: str = ..."]

    def overloaded():
        pass
    overloaded.__doc__ = ("overloaded(*args, **kwargs)\nOverloaded function.\n\n"
                          "1. overloaded(x: int) -> int\n\nOn ints.\n\n2. overloaded(x: float) -> float\n")
    assert generate_stubs.function_stub("overloaded", overloaded, "", None) == (
        '@overload\ndef overloaded(x: int) -> int:\n    """On ints."""\n'
        "@overload\ndef overloaded(x: float) -> float: ...\n")
