"""Sphinx configuration of cartan's documentation site (`make docs`; scripts/build-docs.sh).

The pages of this folder are thin: they include the Markdown the repository already has (README.md,
docs/*.md, bench/README.md) through MyST's include directive, so the site and the files read on a checkout are the
same text. The Python reference comes from the docstrings (autodoc) of the package
python/cartan together with the compiled module _cartan of a build tree; the C++ reference from
the /// comments of include/cartan (Doxygen XML rendered by Breathe); the gallery from the figures
and outputs that scripts/build-docs.sh makes with the scripts of `make run`.

Environment (scripts/build-docs.sh sets them; the defaults suit a checkout after `make build`):
  CARTAN_PYTHON_PATH   the folder holding the built package cartan/ (default build/python)
  CARTAN_DOCS_BUILD    the folder of generated inputs: doxygen/ (written here) and gallery/ (read)
                       (default build/docs)

Why Doxygen + Breathe for C++ (rather than Doxygen's own HTML, or no C++ reference): the headers
already carry /// comments, Doxygen is the one tool that parses C++20 templates and concepts well
enough to attach them, and Breathe puts the result into the same site (one navigation, one search,
one theme, the same link check) at the cost of one Sphinx extension. Doxygen's HTML would be a
second site of several hundred pages with its own scripts; hand-written C++ domain entries would
duplicate the headers.
"""
import importlib.util
import os
import re
import subprocess
import sys
from pathlib import Path

from docutils import nodes
from docutils.parsers.rst import directives
from breathe.directives.content_block import DoxygenNamespaceDirective
from docutils.statemachine import StringList
from sphinx.directives.patches import Figure
from sphinx.util import logging
from sphinx.util.docutils import SphinxDirective

SITE = Path(__file__).resolve().parent
ROOT = SITE.parents[1]
INCLUDE = ROOT / "include" / "cartan"
PYTHON_PATH = Path(os.environ.get("CARTAN_PYTHON_PATH", ROOT / "build" / "python")).resolve()
DOCS_BUILD = Path(os.environ.get("CARTAN_DOCS_BUILD", ROOT / "build" / "docs")).resolve()
DOXYGEN_OUTPUT = DOCS_BUILD / "doxygen"
GALLERY = DOCS_BUILD / "gallery"

logger = logging.getLogger("cartan-docs")

project = "cartan"
author = "the cartan developers"
copyright = "the cartan developers"
root_doc = "index"
extensions = ["myst_parser", "sphinx.ext.autodoc", "breathe"]
source_suffix = {".md": "markdown", ".rst": "restructuredtext"}
html_theme = "sphinx_rtd_theme"
html_title = "cartan"
html_show_sourcelink = False
html_copy_source = False
# The docstrings are reStructuredText (no Google or NumPy sections): autodoc alone, no napoleon.
# GitHub-style anchors for the headings the Markdown files link to (#1-concepts-and-headers).
myst_heading_anchors = 4
# No MathJax: the pages write formulas in Unicode, and a CDN script would not load offline.
myst_enable_extensions = []
autodoc_default_options = {"members": True, "undoc-members": True, "show-inheritance": False}
autodoc_member_order = "bysource"
breathe_projects = {"cartan": str(DOXYGEN_OUTPUT / "xml")}
breathe_default_project = "cartan"
breathe_default_members = ("members", "undoc-members")
primary_domain = "py"


def import_cartan():
    """The package from the source tree (its docstrings are the ones to document) with the compiled
    _cartan of the build tree beside it: both folders on the package's search path."""
    source = ROOT / "python" / "cartan"
    built = PYTHON_PATH / "cartan"
    if not any(built.glob("_cartan*.so")):
        raise RuntimeError(f"docs: no compiled module _cartan in {built} (set CARTAN_PYTHON_PATH to "
                           "the build tree's python folder, e.g. build/python after `make build`)")
    spec = importlib.util.spec_from_file_location("cartan", source / "__init__.py",
                                                  submodule_search_locations=[str(source), str(built)])
    module = importlib.util.module_from_spec(spec)
    sys.modules["cartan"] = module
    spec.loader.exec_module(module)


import_cartan()


def run_doxygen(app):
    DOXYGEN_OUTPUT.mkdir(parents=True, exist_ok=True)
    subprocess.run(["doxygen", "Doxyfile"], cwd=SITE, check=True,
                   env=dict(os.environ, CARTAN_DOXYGEN_OUTPUT=str(DOXYGEN_OUTPUT)))


def doxygen_namespaces():
    """The namespaces of cartan in Doxygen's index (cartan, cartan::groups, ...)."""
    index = (DOXYGEN_OUTPUT / "xml" / "index.xml").read_text()
    names = re.findall(r'kind="namespace"><name>([^<]+)</name>', index)
    return sorted(n for n in names if n == "cartan" or n.startswith("cartan::"))


class CartanNamespace(SphinxDirective):
    """``cartan-namespace:: NAME``: the C++ reference of the namespace NAME (one layer of
    include/cartan): its classes, functions, types and variables with their /// comments, from
    Doxygen's XML through Breathe's doxygennamespace. One namespace a page keeps every declaration
    in one place (Breathe's per-file listing repeats the namespaces of each header, which Sphinx's
    C++ domain reports as duplicate declarations)."""
    required_arguments = 1

    def run(self):
        name = self.arguments[0]
        self.env.cartan_namespaces = getattr(self.env, "cartan_namespaces", {})
        self.env.cartan_namespaces.setdefault(self.env.docname, set()).add(name)
        for header in INCLUDE.rglob("*.hpp"):
            self.env.note_dependency(str(header))
        options = {"project": "cartan", "content-only": None, "members": None, "undoc-members": None}
        return DoxygenNamespaceDirective("doxygennamespace", [name], options, StringList(), self.lineno,
                                         self.content_offset, self.block_text, self.state, self.state_machine).run()


class GalleryFigure(Figure, SphinxDirective):
    """``gallery-figure:: NAME``: a figure of the gallery folder (CARTAN_DOCS_BUILD/gallery), which
    scripts/build-docs.sh fills with the figures of `make run`'s scripts."""

    def run(self):
        path = GALLERY / self.arguments[0]
        if not path.is_file():
            raise self.error(f"gallery figure {path} does not exist (scripts/build-docs.sh makes it)")
        self.env.note_dependency(str(path))
        # Sphinx resolves image paths against the source folder; a relative path may leave it.
        self.arguments[0] = os.path.relpath(path, Path(self.env.doc2path(self.env.docname)).parent)
        return super().run()


class GalleryOutput(SphinxDirective):
    """``gallery-output:: NAME``: the text an example printed (a file of the gallery folder)."""
    required_arguments = 1
    option_spec = {"lines": directives.unchanged}

    def run(self):
        path = GALLERY / self.arguments[0]
        if not path.is_file():
            raise self.error(f"gallery output {path} does not exist (scripts/build-docs.sh makes it)")
        self.env.note_dependency(str(path))
        block = nodes.literal_block(path.read_text(), path.read_text())
        block["language"] = "text"
        return [block]


HTML_ANCHOR = re.compile(r'<a\s+id="([^"]+)"\s*>')


def register_html_anchors(app, doctree):
    """The Markdown files mark stable anchors with raw HTML, <a id="erratum-1"></a> (GitHub shows
    them; docs/paper-notes.md). The HTML goes through unchanged; registering each id as a label of
    its page, under the key MyST gives heading anchors ("paper-notes.md#erratum-1"), lets MyST
    resolve [text](#erratum-1) and [text](paper-notes.md#erratum-1) and flag a missing one."""
    env = app.env
    std = env.get_domain("std")
    page = env.doc2path(env.docname, base=False)
    for raw in doctree.findall(nodes.raw):
        if raw.get("format") != "html":
            continue
        for anchor in HTML_ANCHOR.findall(raw.astext()):
            key = f"{page}#{anchor}"
            section = raw.parent
            while section is not None and not isinstance(section, nodes.section):
                section = section.parent
            title = section[0].astext() if section is not None and section.children else anchor
            std.anonlabels[key] = (env.docname, anchor)
            std.labels[key] = (env.docname, anchor, title)


def plain_text_bars(app, what, name, obj, options, lines):
    """The compiled module's docstrings (pybind11, python/src) are plain text that writes norms as
    |x|, which reStructuredText reads as a substitution: there a bar is a bar."""
    if getattr(obj, "__module__", None) == "cartan._cartan" or name.startswith("cartan._cartan"):
        lines[:] = [line.replace("|", "\\|") for line in lines]


def check_every_namespace(app, env):
    """Every namespace of cartan (a layer of include/cartan) has a page in the C++ reference."""
    shown = set().union(*getattr(env, "cartan_namespaces", {}).values())
    missing = sorted(set(doxygen_namespaces()) - shown)
    if missing:
        logger.warning("namespaces without a page in the C++ reference (add a cartan-namespace directive): %s",
                       ", ".join(missing))


def purge_namespaces(app, env, docname):
    getattr(env, "cartan_namespaces", {}).pop(docname, None)


def setup(app):
    app.connect("env-purge-doc", purge_namespaces)
    app.connect("doctree-read", register_html_anchors)
    app.connect("autodoc-process-docstring", plain_text_bars)
    app.connect("builder-inited", run_doxygen)
    app.connect("env-check-consistency", check_every_namespace)
    app.add_directive("cartan-namespace", CartanNamespace)
    app.add_directive("gallery-figure", GalleryFigure)
    app.add_directive("gallery-output", GalleryOutput)
