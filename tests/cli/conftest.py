"""pytest configuration of tests/cli: the tests import cli_support (this directory) and the
Python implementations of the paper's scheme they are checked against (bench/python:
paper_scheme, h3_scipy)."""
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1] / "bench" / "python"))
sys.path.insert(0, str(HERE))
