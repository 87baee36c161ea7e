"""The documents that tie the code to the paper stay complete:

* every `\\label{...}` of the paper (listed in docs/paper-labels.txt) appears as a whole token in a
  table row of docs/equations.md: with its implementation and test, as a label without computable
  content, or as not yet implemented; a label named only in a heading or the prose is missing;
* docs/equations.md has a row for every paper label cited in the code's comments, prefixed (eq:,
  disc-, ...) or not (CS-conn, cor-parr, para-trans-Heis, ...), and for every prefixed label-like
  token (so a misspelt label is reported too);
* every citation `docs/paper-notes.md#<anchor>` in the repository names an anchor of
  docs/paper-notes.md, and the notes kept outside the repository (../shared) are no longer cited.

The paper is not in the repository. docs/paper-labels.txt was generated from its LaTeX source once:
    grep -o '\\label{[^}]*}' PAPER.tex | sed 's/^\\label{//; s/}$//' | LC_ALL=C sort -u
"""
import functools
import os
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SOURCES = ("include", "src", "python/src", "python/cartan", "apps")
LABELS_FILE = ROOT / "docs" / "paper-labels.txt"

# A label is matched as a whole token: not preceded or followed by a label character.
LABEL_CHAR = "A-Za-z0-9:-"
PREFIXED = re.compile(r"(?<![\w-])((?:eq:|disc-|thm-|lem:|sec-app-)[A-Za-z0-9]+(?:-[A-Za-z0-9]+)*)")

NOTES_FILE = "docs/paper-notes.md"
NOTES = ROOT / NOTES_FILE
CITATION = re.compile(re.escape(NOTES_FILE) + r"#([A-Za-z0-9_-]+)")
ANCHOR = re.compile(r'^<a id="([^"]+)"></a>$', re.M)
OLD_NOTES = "PAPER" + "-NOTES"  # split so that this file does not cite it
REQUIRED_ANCHORS = {
    "convention-trivialisation", "convention-transport-operator", "convention-dual-transport",
    "convention-coadjoint-so3", "convention-target-rotation", "convention-shooting-residual",
    *(f"erratum-{i}" for i in range(1, 8)),
    "general-local-form", "general-energy", "general-metric-connections", "independent-checks",
}
# Not part of the repository's text: git metadata, caches, build trees and outputs (.gitignore).
SKIP_DIRS = {".git", "__pycache__", ".pytest_cache"}
SKIP_TOP_DIRS = re.compile(r"build.*|out")


def paper_labels():
    return LABELS_FILE.read_text().split()


def token(*labels):
    """Any of `labels` as a whole token (longest first, so a label is not cut to a shorter one)."""
    alternatives = "|".join(re.escape(label) for label in sorted(labels, key=len, reverse=True))
    return re.compile(rf"(?<![{LABEL_CHAR}])(?:{alternatives})(?![{LABEL_CHAR}])")


def labels_in(text, labels):
    """The paper labels cited in `text` as whole tokens, and the prefixed label-like tokens."""
    return set(token(*labels).findall(text)) | set(PREFIXED.findall(text))


def mapped(label, table):
    return token(label).search(table) is not None


def unmapped(cited, table):
    return {label for label in cited if not mapped(label, table)}


@functools.cache
def cited_labels():
    labels, found = paper_labels(), {}
    for folder in SOURCES:
        for path in sorted((ROOT / folder).rglob("*")):
            if path.suffix in {".hpp", ".cpp", ".py"}:
                for label in sorted(labels_in(path.read_text(), labels)):
                    found.setdefault(label, path.relative_to(ROOT))
    return found


def repository_texts():
    """(relative path, text) of every text file of the source tree."""
    for folder, dirs, files in os.walk(ROOT):
        top = Path(folder) == ROOT
        dirs[:] = sorted(d for d in dirs if d not in SKIP_DIRS and not (top and SKIP_TOP_DIRS.fullmatch(d)))
        for name in sorted(files):
            path = Path(folder) / name
            try:
                yield path.relative_to(ROOT), path.read_text(encoding="utf-8")
            except (UnicodeDecodeError, OSError):
                continue


def anchors(text):
    return ANCHOR.findall(text)


# ---------------------------------------------------------------------------------------------
# Paper labels -> docs/equations.md


def test_paper_labels_file_is_sorted_unique_labels():
    labels = paper_labels()
    assert len(labels) >= 90  # the paper defines 100
    assert labels == sorted(set(labels))
    assert all(re.fullmatch(r"[A-Za-z0-9:_-]+", label) for label in labels)
    assert {"eq:reduced-system", "disc-exp", "CS-conn", "cor-parr", "para-trans-Heis", "para-trans-heis"} \
        <= set(labels)


def test_code_cites_labels():
    assert {"eq:reduced-system", "disc-exp", "thm-EP", "CS-conn", "cor-parr", "para-trans-Heis"} <= set(cited_labels())


def test_prefixed_labels_cited_in_code_are_paper_labels():
    labels = set(paper_labels())
    unknown = {label: str(where) for label, where in cited_labels().items() if label not in labels}
    assert not unknown, f"labels cited in code that the paper does not define: {unknown}"


def table_rows(text):
    """The lines of a Markdown text that are table rows."""
    return "\n".join(line for line in text.splitlines() if line.startswith("|"))


def equation_rows():
    """The table rows of docs/equations.md (a label named only in a heading or the prose is not mapped)."""
    return table_rows((ROOT / "docs" / "equations.md").read_text())


def test_every_paper_label_is_mapped():
    table = equation_rows()
    missing = [label for label in paper_labels() if not mapped(label, table)]
    assert not missing, f"paper labels with no table row in docs/equations.md: {missing}"


def test_paper_label_removed_from_the_table_is_reported():
    """A label deleted from its row, or left only in a heading or the prose, is reported; the
    other labels of the same row, and a longer label that contains it, do not hide it."""
    labels = ["CS-conn", "CS-conn-right", "eq:HE-1", "fig:trajectories"]
    document = "\n".join([
        "## Connections (CS-conn)",
        "| label | implementation | checked by |",
        "|---|---|---|",
        "| (CS-conn), (CS-conn-right) | `cartan_schouten` | ... |",
        "| (fig:trajectories) | figure label |",
        "| (eq:HE-1) | not yet implemented |",
    ])
    assert unmapped(labels, table_rows(document)) == set()
    removed = document.replace("| (CS-conn), (CS-conn-right) |", "| (CS-conn-right) |")
    assert unmapped(labels, table_rows(removed)) == {"CS-conn"}
    moved_to_prose = document.replace("| (eq:HE-1) | not yet implemented |", "(eq:HE-1) is not yet implemented.")
    assert unmapped(labels, table_rows(moved_to_prose)) == {"eq:HE-1"}


def test_every_cited_label_is_mapped():
    table = equation_rows()
    missing = {label: str(where) for label, where in cited_labels().items() if not mapped(label, table)}
    assert not missing, f"labels cited in code but not in docs/equations.md: {missing}"


def test_unmapped_label_is_detected():
    assert not mapped("eq:EP", "(eq:EP-left)")
    assert mapped("eq:EP-left", "(eq:EP-left), (eq:EP-right)")


def test_unmapped_unprefixed_label_is_detected():
    """Unprefixed labels are found as whole tokens (CS-conn is not cited by CS-conn-right), case
    matters (para-trans-heis and para-trans-Heis are two labels), and one missing from the table
    is reported."""
    labels = paper_labels()
    code = "// P = Ad(Y) (CS-conn-right; para-trans-Heis), not eq:parr-left-dual-ish"
    cited = labels_in(code, labels)
    assert {"CS-conn-right", "para-trans-Heis"} <= cited
    assert not {"CS-conn", "para-trans-heis", "eq:parr-left-dual", "eq:parr-left"} & cited
    table = "| (CS-conn), (CS-conn-right) | `cartan_schouten` | ... |"
    assert unmapped({"CS-conn-right", "para-trans-Heis"}, table) == {"para-trans-Heis"}
    assert unmapped({"cor-parr"}, "| (cor-parr-x) |") == {"cor-parr"}


# ---------------------------------------------------------------------------------------------
# Citations of docs/paper-notes.md


def test_paper_notes_has_every_anchor_once_each_before_a_heading():
    text = NOTES.read_text()
    ids = anchors(text)
    assert len(ids) == len(set(ids)), f"duplicate anchors: {sorted(i for i in ids if ids.count(i) > 1)}"
    assert REQUIRED_ANCHORS <= set(ids), f"missing anchors: {sorted(REQUIRED_ANCHORS - set(ids))}"
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if ANCHOR.fullmatch(line):
            assert i + 1 < len(lines) and lines[i + 1].startswith("## "), f"{line} is not followed by a heading"
    links = set(re.findall(r"\]\(#([^)]*)\)", text))
    assert links <= set(ids), f"internal links to missing anchors: {sorted(links - set(ids))}"


def test_every_cited_paper_notes_anchor_exists():
    ids = set(anchors(NOTES.read_text()))
    bad, count = {}, 0
    for where, text in repository_texts():
        for anchor in CITATION.findall(text):
            count += 1
            if anchor not in ids:
                bad.setdefault(str(where), []).append(anchor)
    assert count >= 30, f"only {count} citations of {NOTES_FILE} found"
    assert not bad, f"citations of anchors that {NOTES_FILE} does not define: {bad}"


def test_no_citation_of_the_old_notes_remains():
    left = [str(where) for where, text in repository_texts() if OLD_NOTES in text and where != Path(NOTES_FILE)]
    assert not left, f"{OLD_NOTES} is still cited in: {left} (cite {NOTES_FILE}#<anchor>)"


def test_bad_citation_is_detected():
    ids = set(anchors('<a id="erratum-1"></a>\n## Erratum 1\n'))
    assert ids == {"erratum-1"}
    cited = CITATION.findall(f"see {NOTES_FILE}#erratum-1 and {NOTES_FILE}#erratum-10; {NOTES_FILE}#<anchor>")
    assert cited == ["erratum-1", "erratum-10"]
    assert [c for c in cited if c not in ids] == ["erratum-10"]
