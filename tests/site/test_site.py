"""The documentation site in a real browser (site_check.py: headless Chromium by WebDriver).

test_site loads every page of the built site (CARTAN_DOCS_HTML, default build/docs/html: `make docs`,
or the ctest fixture docs_site_build) and requires no console error, every image rendered, every
internal link and anchor resolved, and the parts the site promises: the user guide, the equation
map, the paper notes, the gallery's figures, the Python and the C++ reference.
test_checker_finds_* show on a small synthetic site that the checker reports each kind of fault."""
import base64
import os
from pathlib import Path

import pytest

from site_check import check_site, chromium

ROOT = Path(__file__).resolve().parents[2]
HTML = Path(os.environ.get("CARTAN_DOCS_HTML", ROOT / "build" / "docs" / "html"))
# A 1x1 PNG.
PIXEL = base64.b64decode("iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8BQDwAEhQGAhKmMIQAAAABJRU5ErkJggg==")


@pytest.fixture(scope="module")
def browser():
    with chromium() as driver:
        yield driver


def page(title, body, head=""):
    return f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>{title}</title>{head}</head><body>{body}</body></html>"


def synthetic_site(folder, *, broken):
    """index.html and sub/other.html linking to each other; with broken=True, one fault of each kind."""
    (folder / "sub").mkdir()
    (folder / "pixel.png").write_bytes(PIXEL)
    (folder / "style.css").write_text("body { color: black; }")
    links = ["<a href='sub/other.html'>other</a>", "<a href='sub/other.html#here'>anchor</a>",
             "<a href='#top'>top</a>", "<a href='https://example.org/'>external</a>"]
    images = ["<img src='pixel.png' alt='pixel'>"]
    head = "<link rel='stylesheet' href='style.css'>"
    if broken:
        links += ["<a href='missing.html'>missing</a>", "<a href='sub/other.html#nowhere'>bad anchor</a>"]
        images += ["<img src='missing.png' alt='missing'>", "<img src='empty.png' alt='empty'>"]
        (folder / "empty.png").write_bytes(b"not a png")
        head += "<link rel='stylesheet' href='missing.css'><link rel='next' href='sub/missing.html'>"
    (folder / "index.html").write_text(page("index", "<h1 id='top'>top</h1>" + " ".join(links + images), head))
    (folder / "sub" / "other.html").write_text(page("other", "<p id='here'>here</p><a href='../index.html'>back</a>"))


def test_checker_passes_a_clean_site(tmp_path, browser):
    synthetic_site(tmp_path, broken=False)
    report = check_site(tmp_path, browser)
    assert report.problems == []
    assert report.pages == ["index.html", "sub/other.html"]
    assert report.internal_links == 5 and report.external_links == 1   # 4 <a>, 1 <link> on index.html
    assert len(report.images["index.html"]) == 1


def test_checker_finds_each_kind_of_fault(tmp_path, browser):
    synthetic_site(tmp_path, broken=True)
    problems = check_site(tmp_path, browser).problems

    def found(*words):
        return [p for p in problems if all(w in p for w in words)]

    assert found("index.html: broken link", "missing.html", "HTTP 404")
    assert found("index.html: broken anchor", "other.html#nowhere", "'nowhere'")
    assert found("index.html: image not rendered", "missing.png")
    assert found("index.html: image not rendered", "empty.png")
    assert found("index.html: browser console", "missing.css", "404")
    assert found("index.html: browser console", "missing.png", "404")
    assert found("index.html: broken link", "sub/missing.html", "HTTP 404")   # <link rel="next">
    assert not found("other.html#here") and not found("pixel.png") and not found("style.css")


def test_site(browser):
    assert (HTML / "index.html").is_file(), f"no site in {HTML}: build it with `make docs` (or set CARTAN_DOCS_HTML)"
    report = check_site(HTML, browser)
    assert report.problems == [], "\n".join(report.problems)

    pages = set(report.pages)
    for name in ("index", "reference", "user-guide", "architecture", "conventions", "general-connections",
                 "verify", "equations", "paper-notes", "benchmarks", "gallery", "api-python", "api-cpp"):
        assert f"{name}.html" in pages
    layers = ("core", "groups", "connections", "transport", "mechanics", "numerics", "transported",
              "verify", "manifolds", "general", "models")
    for layer in layers:
        assert f"cpp/{layer}.html" in pages
    # The gallery shows the five figures of `make run`.
    figures = [Path(src).name for src in report.images["gallery.html"]]
    assert sorted(figures) == sorted(["fig_so3_free-rigid-body.png", "fig_so3_oscillator.png", "fig_heisenberg.png",
                                      "fig_sphere_particle.png", "fig_so3_connections.png"]), figures
    # The references document the API: Python from the docstrings, C++ from the headers.
    for name in ("cartan.solve", "cartan.solve_bvp", "cartan.verify", "cartan.SO3.exp",
                 "cartan.Result", "cartan.Problem", "cartan.Sphere"):
        assert name in report.ids["api-python.html"], name
    cpp = {path: " ".join(ids) for path, ids in report.ids.items() if path.startswith("cpp/")}
    assert "transported5solve" in cpp["cpp/transported.html"]   # Sphinx's id of cartan::transported::solve
    assert "groups3SO3" in cpp["cpp/groups.html"]
    # The paper notes' stable anchors, cited across the code as docs/paper-notes.md#erratum-1.
    for anchor in ("erratum-1", "erratum-4", "convention-trivialisation", "independent-checks"):
        assert anchor in report.ids["paper-notes.html"], anchor
    assert report.internal_links > 1000
