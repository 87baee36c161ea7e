"""Wrong uses of cartan that mypy must reject, one per line marked `# error:` with the start of
mypy's message (python/tests/test_stubs.py): without the stubs mypy sees none of them."""
import numpy as np

import cartan

cartan.SO3.exp(np.zeros(3), tolerance=1e-9)  # error: Unexpected keyword argument "tolerance"
cartan.SO3.expp(np.zeros(3))  # error: "Type[SO3]" has no attribute "expp"
name: int = cartan.SO3.name  # error: Incompatible types in assignment
cartan.SO3.cartan_schouten("half")  # error: Argument 1 to "cartan_schouten" of "SO3" has incompatible type "str"
