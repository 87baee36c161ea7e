"""The headers keep the layers of DESIGN.md and docs/architecture.md ("Layout"): a layer includes
only the layers below it, and no kernel includes the other or a driver.

* principle/ (the vocabulary: methods, options, defaults, result parts, each kernel's problem)
  includes no kernel, no method, no driver (solvers/), no verifier and no api;
* mechanics/ (the Lagrangians of both kernels, models, integrators) and the geometry (manifolds/,
  groups/, connections/, transport/) include no kernel, no method, no driver, no verifier and no
  api: what the bindings and the api read of them stays below the kernels;
* solvers/ (the drivers every kernel's methods share, over the interfaces they declare) includes
  the vocabulary and numerics, no kernel and no method;
* kernels/lie_group/ and kernels/manifold/ (the arithmetic: problems, schemes, sweeps, tangent
  maps, actions, dense output, verifiers) include neither each other, nor a driver, nor a method;
* methods/lie_group/ and methods/manifold/ (each method on its kernel: the drivers' interfaces
  implemented) include neither each other nor methods/*.hpp, where the two meet: the one place a
  kernel is chosen (methods/solve.hpp) and the Lie-group kernel presented in the manifold kernel's
  vocabulary (methods/lie_group_as_manifold.hpp);
* verify/ (the verdict, its figures and their assembly: every kernel's) includes no kernel, no
  method and no driver;
* api/ declares in the vocabulary's words, with no kernel, method or driver;
* no two folders include each other, directly or through others (kernels/<k> and methods/<k>
  count as folders);
* the edges (apps/, python/src/) reach no kernel, method or driver, directly or through the headers
  they include: only the api (api/solve.hpp for problems by names, api/erased.hpp for problems
  given as objects) and the vocabulary, geometry and mechanics it is written in (numerics/, below
  the kernels, is one of these: cartan.solve_bvp calls its collocation);
* the forwarding headers of the old paths (transported/, general/, verify/report.hpp,
  verify/checks.hpp, and the kernels' headers that moved to mechanics/ and principle/), kept for
  one release, each include the one header that replaced them, and nothing of the project
  includes them.
"""
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
INCLUDE = ROOT / "include" / "cartan"
DIRECTIVE = re.compile(r'^\s*#\s*include\s+"cartan/([^"]+)"', re.MULTILINE)
KERNELS = ("kernels/lie_group", "kernels/manifold")
METHODS = ("methods/lie_group", "methods/manifold")
FORWARDING = ("transported", "general")
FORWARDING_FILES = {"verify/report.hpp": "kernels/lie_group/verify.hpp",
                    "verify/checks.hpp": "kernels/lie_group/verify_checks.hpp",
                    "general/lie_kernel.hpp": "methods/lie_group_as_manifold.hpp",
                    # the manifold kernel's Lagrangians, beside the group's, and both problems
                    **{f"kernels/manifold/{name}.hpp": f"mechanics/manifold_{name}.hpp"
                       for name in ("lagrangian", "lagrangian_hessian", "erased_lagrangian", "particle",
                                    "check_lagrangian")},
                    "kernels/manifold/problem.hpp": "principle/manifold_problem.hpp",
                    "kernels/lie_group/problem.hpp": "principle/group_problem.hpp"}
GEOMETRY = ("manifolds", "groups", "connections", "transport")


def includes(header):
    return DIRECTIVE.findall(header.read_text(encoding="utf-8"))


def folder_of(path):
    """The layer of a header path relative to include/cartan: its folder, kernels/<k> or
    methods/<k> for a kernel's or a method's header, "." for a header at the top."""
    parts = path.split("/")
    if parts[0] in ("kernels", "methods") and len(parts) > 2:
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


ABOVE_THE_KERNELS = {"methods", *METHODS, "solvers", "api"}


def test_the_folders_exist():
    for folder in ("principle", "solvers", "verify", "api", "methods", *KERNELS, *METHODS):
        assert list(headers(folder)), folder


def test_the_vocabulary_includes_no_kernel_method_driver_verifier_or_api():
    assert crossings("principle", {*KERNELS, *ABOVE_THE_KERNELS, "verify"}) == []


def test_mechanics_and_the_geometry_include_no_kernel_method_driver_verifier_or_api():
    for folder in ("mechanics", *GEOMETRY):
        assert list(headers(folder)), folder
        assert crossings(folder, {*KERNELS, *ABOVE_THE_KERNELS, "verify"}) == [], folder


def test_the_drivers_include_no_kernel_and_no_method():
    assert crossings("solvers", {*KERNELS, "methods", *METHODS, "api", "verify"}) == []


def test_the_kernels_include_neither_each_other_nor_a_driver_nor_a_method():
    for kernel in KERNELS:
        assert crossings(kernel, {*KERNELS, *ABOVE_THE_KERNELS} - {kernel}) == [], kernel


def test_the_methods_of_one_kernel_include_neither_the_other_kernel_nor_where_they_meet():
    for methods, kernel in zip(METHODS, KERNELS):
        other_kernel = set(KERNELS) - {kernel}
        other_methods = set(METHODS) - {methods}
        assert crossings(methods, {*other_kernel, *other_methods, "methods", "api"}) == [], methods


def test_where_the_kernels_meet_includes_both():
    # methods/*.hpp is where the kernels meet: the checks above would hold vacuously without it.
    met = {folder_of(t) for _, h in headers("methods") for t in includes(h)}
    assert set(KERNELS) <= met and set(METHODS) <= met


def test_the_verdict_is_every_kernels():
    assert crossings("verify", {*KERNELS, *ABOVE_THE_KERNELS}) == []


def test_the_api_declares_without_a_solver():
    assert crossings("api", {*KERNELS, "methods", *METHODS, "solvers"}) == []


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
    assert {*KERNELS, *METHODS} <= set(graph)  # the graph sees the kernels and their methods
    assert cycles(graph) == []


def test_the_cycle_check_sees_a_cycle():
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [("a", "b"), ("b", "c"), ("c", "a")]


def edge_includes():
    """Each `file -> include` of the CLI and of the Python module's sources."""
    for folder in ("apps", "python/src"):
        for source in sorted((ROOT / folder).rglob("*.[ch]pp")):
            for target in includes(source):
                yield f"{source.relative_to(ROOT)} -> {target}", target


def include_closure(target):
    """Every header of include/cartan reached from `target` (itself included)."""
    seen, todo = set(), [target]
    while todo:
        t = todo.pop()
        if t not in seen and (INCLUDE / t).is_file():
            seen.add(t)
            todo.extend(includes(INCLUDE / t))
    return seen


def test_the_edges_include_no_kernel_method_or_driver():
    forbidden = {*KERNELS, "methods", *METHODS, "solvers"}
    found = [f"{line} (reaches {t})" for line, target in edge_includes() for t in sorted(include_closure(target))
             if folder_of(t) in forbidden or is_forwarding(t)]
    assert found == []
    assert any(target == "api/erased.hpp" for _, target in edge_includes())  # the check sees the edges' includes


def test_the_closure_follows_includes():
    assert "kernels/lie_group/solution.hpp" in include_closure("kernels/lie_group/compiled.hpp")


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
        elif path == "general/solve.hpp":  # the general solve is where the kernels meet
            assert targets[0] == "methods/solve.hpp"
        else:  # the header of the same name in the kernel or in its methods, or where it moved since
            kernel = "lie_group" if path.startswith("transported/") else "manifold"
            in_kernel = f"kernels/{kernel}/{header.name}"
            assert targets[0] in (in_kernel, f"methods/{kernel}/{header.name}", FORWARDING_FILES.get(in_kernel)), path
    users = [f"{source.relative_to(ROOT)} -> {t}" for source in project_sources()
             if not (source.is_relative_to(INCLUDE) and is_forwarding(source.relative_to(INCLUDE).as_posix()))
             for t in includes(source) if is_forwarding(t)]
    assert users == []


def test_the_check_sees_a_crossing(tmp_path, monkeypatch):
    # The check itself can fail: a header of a fake tree that crosses is reported.
    fake = tmp_path / "cartan"
    (fake / "kernels" / "manifold").mkdir(parents=True)
    (fake / "kernels" / "manifold" / "bad.hpp").write_text('#include "cartan/solvers/shooting.hpp"\n')
    monkeypatch.setattr(__import__(__name__), "INCLUDE", fake)
    assert crossings("kernels/manifold", {"solvers"}) == ["kernels/manifold/bad.hpp -> solvers/shooting.hpp"]
