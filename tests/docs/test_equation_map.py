"""docs/equations.md has a row for every paper label of the prefixed kinds (eq:, disc-, thm-, lem:,
sec-app-) cited in the code's comments, so the guide's equation map stays complete."""
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
LABEL = re.compile(r"(?<![\w-])((?:eq:|disc-|thm-|lem:|sec-app-)[A-Za-z0-9]+(?:-[A-Za-z0-9]+)*)")
SOURCES = ("include", "src", "python/src", "python/cartan", "apps")


def cited_labels():
    labels = {}
    for folder in SOURCES:
        for path in sorted((ROOT / folder).rglob("*")):
            if path.suffix in {".hpp", ".cpp", ".py"}:
                for label in LABEL.findall(path.read_text()):
                    labels.setdefault(label, path.relative_to(ROOT))
    return labels


def mapped(label, table):
    return re.search(r"(?<![\w-])" + re.escape(label) + r"(?![\w-])", table) is not None


def test_code_cites_labels():
    assert {"eq:reduced-system", "disc-exp", "thm-EP"} <= set(cited_labels())


def test_every_cited_label_is_mapped():
    table = (ROOT / "docs" / "equations.md").read_text()
    missing = {label: str(where) for label, where in cited_labels().items() if not mapped(label, table)}
    assert not missing, f"labels cited in code but not in docs/equations.md: {missing}"


def test_unmapped_label_is_detected():
    assert not mapped("eq:EP", "(eq:EP-left)")
    assert mapped("eq:EP-left", "(eq:EP-left), (eq:EP-right)")
