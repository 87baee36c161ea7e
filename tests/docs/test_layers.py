"""The headers keep the layers of DESIGN.md and docs/architecture.md: a layer includes only the
layers above it, never a sibling's solver.

* principle/ (the vocabulary: methods, options, defaults, result parts) includes no kernel
  (transported/, general/), no driver (solvers/) and no api;
* solvers/ (the drivers every kernel shares) includes the vocabulary and numerics, no kernel;
* general/ (the general kernel) includes the Lie-group kernel (transported/) only where it hands
  a problem to it: lie_kernel.hpp (the kernel's adapter) and solve.hpp (its compiled solve);
* verify/ runs a kernel's arithmetic on given samples and includes no driver;
* api/ declares in the vocabulary's words, with no solver of either kernel;
* the edges (apps/, python/src/) include of a kernel only what the library compiles for them: its
  compiled solves' declarations (compiled.hpp) and its dense output (dense.hpp), and never a
  driver (solvers/).
"""
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
INCLUDE = ROOT / "include" / "cartan"
DIRECTIVE = re.compile(r'^\s*#\s*include\s+"cartan/([^"]+)"', re.MULTILINE)


def includes(header):
    return DIRECTIVE.findall(header.read_text(encoding="utf-8"))


def crossings(folder, forbidden, allowed=()):
    """Each `folder/header -> include` whose include starts with a forbidden folder, unless allowed."""
    found = []
    for header in sorted((INCLUDE / folder).glob("*.hpp")):
        for target in includes(header):
            if target.split("/")[0] in forbidden and (header.name, target) not in allowed:
                found.append(f"{folder}/{header.name} -> {target}")
    return found


def test_the_folders_exist():
    for folder in ("principle", "solvers", "general", "transported", "api"):
        assert list((INCLUDE / folder).glob("*.hpp")), folder


def test_the_vocabulary_includes_no_kernel_driver_or_api():
    assert crossings("principle", {"transported", "general", "solvers", "api", "verify"}) == []


def test_the_drivers_include_no_kernel():
    assert crossings("solvers", {"transported", "general", "api", "verify"}) == []


def test_the_general_kernel_includes_the_lie_group_kernel_only_where_it_hands_over():
    allowed = {("lie_kernel.hpp", "transported/continuation.hpp"), ("solve.hpp", "transported/compiled.hpp")}
    assert crossings("general", {"transported"}, allowed) == []


def test_verify_checks_results_without_a_solver():
    # verify/ runs the kernel's arithmetic (its scheme, transport and action) on given samples;
    # it includes none of the drivers that produce them.
    drivers = {"transported/" + name for name in ("shooting.hpp", "solve.hpp", "continuation.hpp",
                                                    "multiple_shooting.hpp", "two_level.hpp", "variational.hpp",
                                                    "collocation_solution.hpp")}
    drivers |= {"general/" + name for name in ("shooting.hpp", "solve.hpp", "collocation.hpp", "lie_kernel.hpp")}
    verifiers = sorted((INCLUDE / "verify").glob("*.hpp")) + [INCLUDE / "general" / "verify.hpp"]
    found = [f"{h.parent.name}/{h.name} -> {t}" for h in verifiers for t in includes(h)
             if t in drivers or t.startswith("solvers/")]
    assert found == []


def test_the_api_declares_without_a_solver():
    assert crossings("api", {"transported", "general", "solvers"}) == []


def edge_includes():
    """Each `file -> include` of the CLI and of the Python module's sources."""
    for folder in ("apps", "python/src"):
        for source in sorted((ROOT / folder).rglob("*.[ch]pp")):
            for target in includes(source):
                yield f"{source.relative_to(ROOT)} -> {target}", target


def test_the_edges_include_no_solver():
    kernels_compiled = {f"{kernel}/{name}" for kernel in ("transported", "general") for name in ("compiled.hpp", "dense.hpp")}
    found = [line for line, target in edge_includes()
             if target.startswith("solvers/")
             or (target.split("/")[0] in ("transported", "general") and target not in kernels_compiled)]
    assert found == []
    assert any(target == "api/solve.hpp" for _, target in edge_includes())  # the check sees the edges' includes


def test_the_check_sees_a_crossing(tmp_path, monkeypatch):
    # The check itself can fail: a header of a fake tree that crosses is reported.
    fake = tmp_path / "cartan"
    (fake / "principle").mkdir(parents=True)
    (fake / "principle" / "bad.hpp").write_text('#include "cartan/transported/solve.hpp"\n')
    monkeypatch.setattr(__import__(__name__), "INCLUDE", fake)
    assert crossings("principle", {"transported"}) == ["principle/bad.hpp -> transported/solve.hpp"]
