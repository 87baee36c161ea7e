"""docs/user-guide.md and the README quote the examples: every code block announced by a comment
`<!-- snippet: FILE -->` must appear in FILE (line by line, in order, ignoring indentation), so
that the code they show is the code ctest compiles and runs."""
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
GUIDE = ROOT / "docs" / "user-guide.md"
README = ROOT / "README.md"
SNIPPET = re.compile(r"<!-- snippet: (\S+) -->\s*\n\s*```\w*\n(.*?)\n\s*```", re.S)


def snippets(document=GUIDE):
    return SNIPPET.findall(document.read_text())


def lines(text):
    return [line.strip() for line in text.splitlines() if line.strip()]


def contains_in_order(haystack, needle):
    """True if `needle` occurs as a contiguous run of lines of `haystack`."""
    return any(haystack[i:i + len(needle)] == needle for i in range(len(haystack) - len(needle) + 1))


def test_guide_has_snippets():
    assert len(snippets()) >= 8


def test_readme_has_snippets():
    assert len(snippets(README)) >= 1


def test_every_snippet_matches_its_file():
    for document in (GUIDE, README):
        for name, code in snippets(document):
            source = ROOT / name
            assert source.is_file(), f"{name} (quoted in {document.name}) does not exist"
            assert contains_in_order(lines(source.read_text()), lines(code)), \
                f"a snippet of {document.relative_to(ROOT)} is not in {name}:\n{code}"


def test_mismatch_is_detected():
    """The check itself can fail: a changed line is not found."""
    assert not contains_in_order(["a", "b", "c"], ["a", "c"])
    assert contains_in_order(["a", "b", "c"], ["b", "c"])
