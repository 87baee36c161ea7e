"""The glue (bindings, CLI) is compiled at -O1 and the library at -O3 (cmake/CartanGlue.cmake); an
inline function both instantiate exists once in a binary, the copy the linker met first. The
library's archive is loaded before the glue's objects, so every such function of the module and
of the CLI is the library's own copy: its size is the size of one of the library's copies (a
-O1 copy differs: SO(3)'s exp is 0x30e bytes at -O1 and 0x35c at -O3 with GCC 12)."""
import collections
import os
import shutil
import subprocess
from pathlib import Path

import pytest

import cartan

BUILD = Path(os.environ.get("CARTAN_BUILD_DIR", Path(__file__).resolve().parents[2] / "build"))
LIBRARY = BUILD / "libcartan.a"
CLI = os.environ.get("CARTAN_BIN", str(BUILD / "cartan"))

pytestmark = pytest.mark.skipif(shutil.which("nm") is None or not LIBRARY.exists(),
                                reason="needs binutils' nm and the build tree's libcartan.a")


def shared_functions(path):
    """Each global function or weak (inline, template) symbol defined in `path`, with the set of
    the sizes of its definitions (an archive holds one per object)."""
    out = subprocess.run(["nm", "-S", "--defined-only", str(path)], capture_output=True, text=True,
                         check=True).stdout
    sizes = collections.defaultdict(set)
    for line in out.splitlines():
        fields = line.split()
        if len(fields) == 4 and fields[2] in ("W", "T"):
            sizes[fields[3]].add(int(fields[1], 16))
    return sizes


@pytest.mark.parametrize("binary", ["module", "cli"])
def test_the_library_s_copy_of_every_shared_function_is_the_one_linked(binary):
    path = cartan._cartan.__file__ if binary == "module" else CLI
    library = shared_functions(LIBRARY)
    linked = shared_functions(path)
    shared = [name for name in linked if name in library]
    assert len(shared) > 1000, "the binary shares the library's functions"  # 3400 and 3600 at 5ce4f6c
    other = [name for name in shared if not linked[name] <= library[name]]
    assert other == [], f"{len(other)} functions of {path} are not the library's copy, e.g. {other[:3]}"
