"""Typed use of cartan that mypy must accept (python/tests/test_stubs.py; its negative control is
typed_wrong.py): the stubs of cartan._cartan give these calls their types."""
import numpy as np
from numpy.typing import NDArray

import cartan

g: NDArray[np.float64] = cartan.SO3.exp(np.array([0.1, 0.2, 0.3]))
v: NDArray[np.float64] = cartan.SO3.log(g)
dim: int = cartan.SO3.dim
name: str = cartan.Heisenberg.name
connection = cartan.SO3.cartan_schouten(0.5, side="left")
torsion: NDArray[np.float64] = connection.torsion(v, v)
model = cartan.RigidBody([2.0, 3.0, 4.0])
version: str = cartan.__version__
