"""pytest configuration: `import cartan` must find the built module. ctest sets PYTHONPATH to
<build>/python; run by hand with PYTHONPATH=build/python /usr/bin/python3 -m pytest python/tests."""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
