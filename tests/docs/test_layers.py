"""The headers keep the layers of DESIGN.md and docs/architecture.md ("Layout"): a layer includes
only the layers below it, and the two kernels never include each other.

* principle/ (the vocabulary: methods, options, defaults, result parts) includes no kernel, no
  driver (solvers/), no verifier and no api;
* solvers/ (the drivers every kernel shares) includes the vocabulary and numerics, no kernel;
* verify/ (the verdict, its figures and their assembly: every kernel's) includes no kernel and no
  driver; each kernel's verifier (kernels/<kernel>/verify*.hpp) runs its kernel's arithmetic on
  given samples and includes no driver and none of its kernel's solvers;
* kernels/lie_group/ and kernels/manifold/ include neither each other nor kernels/*.hpp, the one
  place a kernel is chosen (kernels/solve.hpp) and the Lie-group kernel presented in the manifold
  kernel's vocabulary (kernels/lie_group_as_manifold.hpp), which include both;
* api/ declares in the vocabulary's words, with no kernel and no driver;
* no two folders include each other, directly or through others (kernels/<kernel> counts as a
  folder);
* the edges (apps/, python/src/) include of a kernel only what the library compiles for them: its
  compiled solves' declarations (compiled.hpp) and its dense output (dense.hpp), never a driver
  (solvers/) nor the choice (kernels/*.hpp);
* the forwarding headers of the old paths (transported/, general/, verify/report.hpp,
  verify/checks.hpp), kept for one release, each include the one header that replaced them, and
  nothing of the project includes them.
"""
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
INCLUDE = ROOT / "include" / "cartan"
DIRECTIVE = re.compile(r'^\s*#\s*include\s+"cartan/([^"]+)"', re.MULTILINE)
KERNELS = ("kernels/lie_group", "kernels/manifold")
FORWARDING = ("transported", "general")
FORWARDING_FILES = {"verify/report.hpp": "kernels/lie_group/verify.hpp",
                    "verify/checks.hpp": "kernels/lie_group/verify_checks.hpp"}


def includes(header):
    return DIRECTIVE.findall(header.read_text(encoding="utf-8"))


def folder_of(path):
    """The layer of a header path relative to include/cartan: its folder, kernels/<kernel> for a
    kernel's header, "kernels" for the choice, "." for a header at the top."""
    parts = path.split("/")
    if parts[0] == "kernels" and len(parts) > 2:
        return "/".join(parts[:2])
    return parts[0] if len(parts) > 1 else "."


def is_forwarding(path):
    return path.split("/")[0] in FORWARDING or path in FORWARDING_FILES


def headers(folder=None):
    """Each header (path relative to include/cartan) of `folder`, or of every folder; never the
    forwarding headers."""
    for header in sorted(INCLUDE.rglob("*.hpp")):
        path = header.relative_to(INCLUDE).as_posix()
        if is_forwarding(path) or (folder is not None and folder_of(path) != folder):
            continue
        yield path, header


def crossings(folder, forbidden):
    """Each `folder/header -> include` whose include's layer is in `forbidden`."""
    return [f"{path} -> {target}" for path, header in headers(folder)
            for target in includes(header) if folder_of(target) in forbidden]


def test_the_folders_exist():
    for folder in ("principle", "solvers", "verify", "api", "kernels", *KERNELS):
        assert list(headers(folder)), folder


def test_the_vocabulary_includes_no_kernel_driver_verifier_or_api():
    assert crossings("principle", {"kernels", *KERNELS, "solvers", "api", "verify"}) == []


def test_the_drivers_include_no_kernel():
    assert crossings("solvers", {"kernels", *KERNELS, "api", "verify"}) == []


def test_the_kernels_include_neither_each_other_nor_the_choice():
    for kernel in KERNELS:
        others = {"kernels", *KERNELS} - {kernel}
        assert crossings(kernel, others) == [], kernel


def test_the_choice_includes_both_kernels():
    # kernels/*.hpp is where the kernels meet: the check above would hold vacuously without it.
    choice = {folder_of(t) for _, h in headers("kernels") for t in includes(h)}
    assert set(KERNELS) <= choice


def test_the_verdict_is_every_kernels():
    assert crossings("verify", {"kernels", *KERNELS, "solvers", "api"}) == []


def test_each_kernels_verifier_runs_no_solver():
    # A kernel's verifier runs the kernel's arithmetic (its scheme, transport and action) on given
    # samples; it includes none of the drivers nor the kernel's solvers that produce them.
    solvers = {"kernels/lie_group/" + name for name in ("shooting.hpp", "solve.hpp", "continuation.hpp",
                                                          "multiple_shooting.hpp", "two_level.hpp",
                                                          "variational.hpp", "collocation_solution.hpp")}
    solvers |= {"kernels/manifold/" + name for name in ("shooting.hpp", "solve.hpp", "collocation.hpp")}
    verifiers = [(p, h) for p, h in headers() if folder_of(p) in KERNELS and Path(p).name.startswith("verify")]
    assert len(verifiers) >= 3  # the Lie-group kernel's two, the manifold kernel's one
    found = [f"{p} -> {t}" for p, h in verifiers for t in includes(h)
             if t in solvers or folder_of(t) in ("solvers", "kernels")]
    assert found == []


def test_the_api_declares_without_a_solver():
    assert crossings("api", {"kernels", *KERNELS, "solvers"}) == []


def folder_graph():
    graph = {}
    for path, header in headers():
        source = folder_of(path)
        for target in includes(header):
            if folder_of(target) != source:
                graph.setdefault(source, set()).add(folder_of(target))
    return graph


def cycles(graph):
    """Each pair (a, b) with a -> b and b reaching a back."""
    def reaches(start, goal):
        seen, todo = set(), [start]
        while todo:
            node = todo.pop()
            if node == goal:
                return True
            if node not in seen:
                seen.add(node)
                todo.extend(graph.get(node, ()))
        return False
    return sorted((a, b) for a, targets in graph.items() for b in targets if reaches(b, a))


def test_no_include_cycle_between_folders():
    graph = folder_graph()
    assert "kernels/lie_group" in graph and "kernels/manifold" in graph  # the graph sees the kernels
    assert cycles(graph) == []


def test_the_cycle_check_sees_a_cycle():
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [("a", "b"), ("b", "c"), ("c", "a")]


def edge_includes():
    """Each `file -> include` of the CLI and of the Python module's sources."""
    for folder in ("apps", "python/src"):
        for source in sorted((ROOT / folder).rglob("*.[ch]pp")):
            for target in includes(source):
                yield f"{source.relative_to(ROOT)} -> {target}", target


def test_the_edges_include_no_solver():
    compiled = {f"{kernel}/{name}" for kernel in KERNELS for name in ("compiled.hpp", "dense.hpp")}
    found = [line for line, target in edge_includes()
             if folder_of(target) in ("solvers", "kernels") or is_forwarding(target)
             or (folder_of(target) in KERNELS and target not in compiled)]
    assert found == []
    assert any(target == "api/solve.hpp" for _, target in edge_includes())  # the check sees the edges' includes


def project_sources():
    for folder in ("include", "src", "apps", "python/src", "tests", "bench", "examples"):
        yield from sorted((ROOT / folder).rglob("*.[ch]pp"))


def test_the_forwarding_headers_forward_and_nothing_uses_them():
    forwarding = sorted(p for p in INCLUDE.rglob("*.hpp") if is_forwarding(p.relative_to(INCLUDE).as_posix()))
    assert len(forwarding) >= len(FORWARDING_FILES) + 2
    for header in forwarding:
        path = header.relative_to(INCLUDE).as_posix()
        targets = includes(header)
        assert len(targets) == 1 and (INCLUDE / targets[0]).is_file(), path
        if path in FORWARDING_FILES:
            assert targets[0] == FORWARDING_FILES[path]
        else:  # same name in its kernel, but for the two headers that left the manifold kernel
            moved = {"general/solve.hpp": "kernels/solve.hpp",
                     "general/lie_kernel.hpp": "kernels/lie_group_as_manifold.hpp"}
            kernel = "kernels/lie_group" if path.startswith("transported/") else "kernels/manifold"
            assert targets[0] == moved.get(path, f"{kernel}/{header.name}"), path
    users = [f"{source.relative_to(ROOT)} -> {t}" for source in project_sources()
             if not is_forwarding(source.relative_to(INCLUDE).as_posix() if source.is_relative_to(INCLUDE) else "")
             for t in includes(source) if is_forwarding(t)]
    assert users == []


def test_the_check_sees_a_crossing(tmp_path, monkeypatch):
    # The check itself can fail: a header of a fake tree that crosses is reported.
    fake = tmp_path / "cartan"
    (fake / "kernels" / "manifold").mkdir(parents=True)
    (fake / "kernels" / "manifold" / "bad.hpp").write_text('#include "cartan/kernels/lie_group/solve.hpp"\n')
    monkeypatch.setattr(__import__(__name__), "INCLUDE", fake)
    assert crossings("kernels/manifold", {"kernels/lie_group"}) == ["kernels/manifold/bad.hpp -> kernels/lie_group/solve.hpp"]
