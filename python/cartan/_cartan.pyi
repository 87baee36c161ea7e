"""Type stubs of cartan._cartan, generated from the built module by scripts/generate_stubs.py:
do not edit; regenerate after changing the bindings (python/src)."""
import numpy
from numpy.typing import NDArray
from typing import Any, Optional

__version__: str

class _SolveRequest(metaclass=type):
    def __init__(self) -> None: ...
    method: str
    continuation: str
    order: int
    tol: float
    max_iterations: int
    segments: Optional[int]
    lambda_start: Optional[float]
    samples: int
    max_nodes: Optional[int]
    time_limit: Optional[float]

statuses: list[str]

defaults: dict[str, Any]

models: list[dict[str, Any]]

class _CancelToken(metaclass=type):
    """Solves started inside `with token:` on this thread stop (status interrupted) at their next iteration once token.cancel() is called, from any thread."""
    def __init__(self) -> None: ...
    def cancel(self) -> None: ...
    @property
    def cancelled(self) -> bool: ...
    def __enter__(self) -> None: ...
    def __exit__(self, *args: Any) -> None: ...

def _check_report(title: str, checks: list, samples: int) -> dict:
    """A CheckReport's dict from the dicts of its checks (cartan.testing), printed by the C++ CheckReport::text."""

class SO3(metaclass=type):
    """SO(3): elements are (3, 3) rotation matrices, hat(v) w = v x w (docs/conventions.md)."""
    def __init__(self, *args: Any, **kwargs: Any) -> None:
        """No constructor: raises TypeError."""
    name: str
    dim: int
    element_shape: tuple[int, ...]
    @staticmethod
    def identity() -> NDArray[numpy.float64]:
        """The identity element."""
    @staticmethod
    def compose(g: Any, h: Any) -> NDArray[numpy.float64]:
        """The product g h."""
    @staticmethod
    def inverse(g: Any) -> NDArray[numpy.float64]:
        """The inverse g^-1."""
    @staticmethod
    def exp(v: Any) -> NDArray[numpy.float64]:
        """The group exponential of v in the algebra (coordinates)."""
    @staticmethod
    def log(g: Any) -> NDArray[numpy.float64]:
        """The principal logarithm, in algebra coordinates."""
    @staticmethod
    def hat(v: Any) -> NDArray[numpy.float64]:
        """The matrix sum_i v_i E_i of algebra coordinates v."""
    @staticmethod
    def vee(X: Any) -> NDArray[numpy.float64]:
        """The coordinates of an algebra matrix (inverse of hat)."""
    @staticmethod
    def matrix(g: Any) -> NDArray[numpy.float64]:
        """A faithful matrix representation of g."""
    @staticmethod
    def Ad(g: Any) -> NDArray[numpy.float64]:
        """The matrix of Ad_g on algebra coordinates."""
    @staticmethod
    def ad(v: Any) -> NDArray[numpy.float64]:
        """The matrix of ad_v = [v, .] on algebra coordinates."""
    @staticmethod
    def ad_star(v: Any, mu: Any = ...) -> Any:
        """ad*_v mu = ad_v^T mu (docs/conventions.md); the matrix ad_v^T when mu is omitted."""
    @staticmethod
    def bracket(u: Any, v: Any) -> NDArray[numpy.float64]:
        """The Lie bracket [u, v] = ad_u v."""
    @staticmethod
    def left_translate(g: Any, v: Any) -> NDArray[numpy.float64]:
        """d(L_g)_e v, a tangent vector at g in ambient coordinates."""
    @staticmethod
    def left_trivialise(g: Any, X: Any) -> NDArray[numpy.float64]:
        """g^-1 X for a tangent vector X at g (ambient coordinates)."""
    @staticmethod
    def validate(g: Any) -> None:
        """Raises ValueError unless g is a valid element (to the group's tolerance)."""
    class Connection(metaclass=type):
        """An invariant affine connection given by its bilinear map on the algebra (left or right)."""
        def __init__(self, side: str, table: Any) -> None:
            """From a (n, n*n) table whose column i*n + j holds nabla_{E_i} E_j."""
        @property
        def side(self) -> str: ...
        @property
        def coefficients(self) -> NDArray[numpy.float64]:
            """Array (n, n, n): coefficients[i] is the matrix of w -> nabla_{E_i} w."""
        def nabla(self, u: Any, w: Any) -> NDArray[numpy.float64]:
            """The bilinear map nabla_u w."""
        def torsion(self, v: Any, w: Any) -> NDArray[numpy.float64]:
            """T(v, w) on invariant fields (cur-tor-left)."""
        def curvature(self, u: Any, v: Any, w: Any) -> NDArray[numpy.float64]:
            """R(u, v) w on invariant fields (cur-tor-left)."""
        def is_cartan(self) -> bool:
            """True when the bilinear map is skew (geodesics through e are one-parameter subgroups)."""
        def transport(self, u: Any, s: float, t: float, steps: int = ..., method: str = ..., nodes: bool = ...) -> NDArray[numpy.float64]:
            """P(s -> t) = Texp(-int_s^t nabla_u(r) dr) (cor-parr) for the trivialised velocity u(r), a callable returning an algebra vector; method lie-euler | magnus2 | magnus4."""
        def transport_sampled(self, u_nodes: Any, s: float, t: float, method: str = ..., u_midpoints: Any = ..., nodes: bool = ...) -> NDArray[numpy.float64]:
            """P(s -> t) from samples u(t_k) on a uniform grid (and u(t_k + h/2) for magnus4)."""
    @staticmethod
    def cartan_schouten(lam: float, side: str = ...) -> SO3.Connection:
        """The Cartan-Schouten connection of parameter lam: left map lam ad (CS-conn), right map (lam - 1) ad (CS-conn-right)."""
    @staticmethod
    def cartan_schouten_transport(lam: float, u: Any, s: float, t: float, steps: int = ..., method: str = ..., side: str = ..., nodes: bool = ...) -> NDArray[numpy.float64]:
        """P(s -> t) of the Cartan-Schouten connection (parr-tran-Cartan-lambda) computed in the group: P = Ad(Y)."""
    @staticmethod
    def _euler_poincare(side: str, lagrangian: Any, g0: Any, v0: Any, T: float, steps: int) -> dict: ...
    @staticmethod
    def _lie_poisson(side: str, hamiltonian: Any, g0: Any, mu0: Any, T: float, steps: int) -> dict: ...
    @staticmethod
    def _lagrangian_hessian(lagrangian: Any, t: float, g: Any, v: Any) -> dict: ...
    @staticmethod
    def _check_lagrangian(lagrangian: Any, samples: Any, seed: int, scale: float, side: str) -> dict: ...
    methods: list[str]
    @staticmethod
    def _solve(lagrangian: Any, lam: float, T: float, N: int, g0: Any, gT: Any, request: _SolveRequest, v0: Any, xi0: Any, guess: Any, progress: Any) -> dict: ...
    @staticmethod
    def _validate(lagrangian: Any, lam: float, T: float, N: int, g0: Any, gT: Any, request: _SolveRequest, v0: Any, xi0: Any, guess: Any, progress: Any) -> None: ...
    @staticmethod
    def _verify(lagrangian: Any, result: Any, lam: float, T: float, g0: Any, gT: Any, order: int, tol: float, status: str) -> dict: ...
    @staticmethod
    def _along(lagrangian: Any, result: Any, lam: float) -> dict: ...
    @staticmethod
    def _dense(result: Any, lam: float, method: str, times: Any) -> dict: ...
    @staticmethod
    def minimal_rotation(a: Any, b: Any) -> NDArray[numpy.float64]:
        """The rotation taking the direction of a to that of b about a x b (the paper's gT)."""
    @staticmethod
    def from_matrix(r: Any, tolerance: float = ...) -> NDArray[numpy.float64]:
        """Validates a near-rotation (within tolerance) and returns the nearest rotation."""

class RigidBody(metaclass=type):
    """Free rigid body l(g, v) = 1/2 v.I v (body frame)."""
    def __init__(self, inertia: Any) -> None:
        """From a symmetric positive-definite inertia: a (n, n) matrix or its (n,) diagonal."""
    @property
    def inertia(self) -> NDArray[numpy.float64]:
        """The inertia, a symmetric (n, n) matrix."""
    def __getstate__(self) -> tuple: ...
    def __setstate__(self, arg0: tuple) -> None: ...
    group: type[SO3]
    side: str
    def value(self, t: float, g: Any, v: Any) -> float:
        """l(t, g, v)."""
    def momentum(self, t: float, g: Any, v: Any) -> NDArray[numpy.float64]:
        """mu = dl/dv (the reduced Legendre map)."""
    def group_gradient(self, t: float, g: Any, v: Any) -> NDArray[numpy.float64]:
        """zeta, the trivialised dl/dg at fixed v."""
    def velocity(self, t: float, g: Any, mu: Any) -> NDArray[numpy.float64]:
        """v with momentum(t, g, v) = mu (inverse Legendre map)."""

class SO3Oscillator(metaclass=type):
    """Harmonic oscillator l(g, v) = 1/2 v.I v - 1/2 (3 - tr g), restoring force zeta = -vee(Skew g) (docs/paper-notes.md#erratum-1)."""
    def __init__(self, inertia: Any) -> None:
        """From a symmetric positive-definite inertia: a (n, n) matrix or its (n,) diagonal."""
    @property
    def inertia(self) -> NDArray[numpy.float64]:
        """The inertia, a symmetric (n, n) matrix."""
    def __getstate__(self) -> tuple: ...
    def __setstate__(self, arg0: tuple) -> None: ...
    group: type[SO3]
    side: str
    def value(self, t: float, g: Any, v: Any) -> float:
        """l(t, g, v)."""
    def momentum(self, t: float, g: Any, v: Any) -> NDArray[numpy.float64]:
        """mu = dl/dv (the reduced Legendre map)."""
    def group_gradient(self, t: float, g: Any, v: Any) -> NDArray[numpy.float64]:
        """zeta, the trivialised dl/dg at fixed v."""
    def velocity(self, t: float, g: Any, mu: Any) -> NDArray[numpy.float64]:
        """v with momentum(t, g, v) = mu (inverse Legendre map)."""

class SpatialRigidBody(metaclass=type):
    """The free rigid body right-reduced (spatial velocity); for eq:EP-right."""
    def __init__(self, inertia: Any) -> None:
        """From a symmetric positive-definite inertia: a (n, n) matrix or its (n,) diagonal."""
    @property
    def inertia(self) -> NDArray[numpy.float64]:
        """The inertia, a symmetric (n, n) matrix."""
    def __getstate__(self) -> tuple: ...
    def __setstate__(self, arg0: tuple) -> None: ...
    group: type[SO3]
    side: str
    def value(self, t: float, g: Any, v: Any) -> float:
        """l(t, g, v)."""
    def momentum(self, t: float, g: Any, v: Any) -> NDArray[numpy.float64]:
        """mu = dl/dv (the reduced Legendre map)."""
    def group_gradient(self, t: float, g: Any, v: Any) -> NDArray[numpy.float64]:
        """zeta, the trivialised dl/dg at fixed v."""
    def velocity(self, t: float, g: Any, mu: Any) -> NDArray[numpy.float64]:
        """v with momentum(t, g, v) = mu (inverse Legendre map)."""

class RigidBodyHamiltonian(metaclass=type):
    """h(g, mu) = 1/2 mu.I^-1 mu."""
    def __init__(self, inertia: Any) -> None:
        """From a symmetric positive-definite inertia: a (n, n) matrix or its (n,) diagonal."""
    @property
    def inertia(self) -> NDArray[numpy.float64]:
        """The inertia, a symmetric (n, n) matrix."""
    def __getstate__(self) -> tuple: ...
    def __setstate__(self, arg0: tuple) -> None: ...
    group: type[SO3]
    side: str
    def value(self, t: float, g: Any, mu: Any) -> float:
        """h(t, g, mu)."""
    def velocity(self, t: float, g: Any, mu: Any) -> NDArray[numpy.float64]:
        """v = dh/dmu."""
    def group_gradient(self, t: float, g: Any, mu: Any) -> NDArray[numpy.float64]:
        """The trivialised dh/dg at fixed mu."""

class SO3OscillatorHamiltonian(metaclass=type):
    """h(g, mu) = 1/2 mu.I^-1 mu + 1/2 (3 - tr g)."""
    def __init__(self, inertia: Any) -> None:
        """From a symmetric positive-definite inertia: a (n, n) matrix or its (n,) diagonal."""
    @property
    def inertia(self) -> NDArray[numpy.float64]:
        """The inertia, a symmetric (n, n) matrix."""
    def __getstate__(self) -> tuple: ...
    def __setstate__(self, arg0: tuple) -> None: ...
    group: type[SO3]
    side: str
    def value(self, t: float, g: Any, mu: Any) -> float:
        """h(t, g, mu)."""
    def velocity(self, t: float, g: Any, mu: Any) -> NDArray[numpy.float64]:
        """v = dh/dmu."""
    def group_gradient(self, t: float, g: Any, mu: Any) -> NDArray[numpy.float64]:
        """The trivialised dh/dg at fixed mu."""

class SpatialRigidBodyHamiltonian(metaclass=type):
    """The free rigid body Hamiltonian right-reduced; for eq:LP-right."""
    def __init__(self, inertia: Any) -> None:
        """From a symmetric positive-definite inertia: a (n, n) matrix or its (n,) diagonal."""
    @property
    def inertia(self) -> NDArray[numpy.float64]:
        """The inertia, a symmetric (n, n) matrix."""
    def __getstate__(self) -> tuple: ...
    def __setstate__(self, arg0: tuple) -> None: ...
    group: type[SO3]
    side: str
    def value(self, t: float, g: Any, mu: Any) -> float:
        """h(t, g, mu)."""
    def velocity(self, t: float, g: Any, mu: Any) -> NDArray[numpy.float64]:
        """v = dh/dmu."""
    def group_gradient(self, t: float, g: Any, mu: Any) -> NDArray[numpy.float64]:
        """The trivialised dh/dg at fixed mu."""

class Heisenberg(metaclass=type):
    """The Heisenberg group H3: elements are coordinates (a, b, c), [E1, E2] = E3 (ad-Heis)."""
    def __init__(self, *args: Any, **kwargs: Any) -> None:
        """No constructor: raises TypeError."""
    name: str
    dim: int
    element_shape: tuple[int, ...]
    @staticmethod
    def identity() -> NDArray[numpy.float64]:
        """The identity element."""
    @staticmethod
    def compose(g: Any, h: Any) -> NDArray[numpy.float64]:
        """The product g h."""
    @staticmethod
    def inverse(g: Any) -> NDArray[numpy.float64]:
        """The inverse g^-1."""
    @staticmethod
    def exp(v: Any) -> NDArray[numpy.float64]:
        """The group exponential of v in the algebra (coordinates)."""
    @staticmethod
    def log(g: Any) -> NDArray[numpy.float64]:
        """The principal logarithm, in algebra coordinates."""
    @staticmethod
    def hat(v: Any) -> NDArray[numpy.float64]:
        """The matrix sum_i v_i E_i of algebra coordinates v."""
    @staticmethod
    def vee(X: Any) -> NDArray[numpy.float64]:
        """The coordinates of an algebra matrix (inverse of hat)."""
    @staticmethod
    def matrix(g: Any) -> NDArray[numpy.float64]:
        """A faithful matrix representation of g."""
    @staticmethod
    def Ad(g: Any) -> NDArray[numpy.float64]:
        """The matrix of Ad_g on algebra coordinates."""
    @staticmethod
    def ad(v: Any) -> NDArray[numpy.float64]:
        """The matrix of ad_v = [v, .] on algebra coordinates."""
    @staticmethod
    def ad_star(v: Any, mu: Any = ...) -> Any:
        """ad*_v mu = ad_v^T mu (docs/conventions.md); the matrix ad_v^T when mu is omitted."""
    @staticmethod
    def bracket(u: Any, v: Any) -> NDArray[numpy.float64]:
        """The Lie bracket [u, v] = ad_u v."""
    @staticmethod
    def left_translate(g: Any, v: Any) -> NDArray[numpy.float64]:
        """d(L_g)_e v, a tangent vector at g in ambient coordinates."""
    @staticmethod
    def left_trivialise(g: Any, X: Any) -> NDArray[numpy.float64]:
        """g^-1 X for a tangent vector X at g (ambient coordinates)."""
    @staticmethod
    def validate(g: Any) -> None:
        """Raises ValueError unless g is a valid element (to the group's tolerance)."""
    class Connection(metaclass=type):
        """An invariant affine connection given by its bilinear map on the algebra (left or right)."""
        def __init__(self, side: str, table: Any) -> None:
            """From a (n, n*n) table whose column i*n + j holds nabla_{E_i} E_j."""
        @property
        def side(self) -> str: ...
        @property
        def coefficients(self) -> NDArray[numpy.float64]:
            """Array (n, n, n): coefficients[i] is the matrix of w -> nabla_{E_i} w."""
        def nabla(self, u: Any, w: Any) -> NDArray[numpy.float64]:
            """The bilinear map nabla_u w."""
        def torsion(self, v: Any, w: Any) -> NDArray[numpy.float64]:
            """T(v, w) on invariant fields (cur-tor-left)."""
        def curvature(self, u: Any, v: Any, w: Any) -> NDArray[numpy.float64]:
            """R(u, v) w on invariant fields (cur-tor-left)."""
        def is_cartan(self) -> bool:
            """True when the bilinear map is skew (geodesics through e are one-parameter subgroups)."""
        def transport(self, u: Any, s: float, t: float, steps: int = ..., method: str = ..., nodes: bool = ...) -> NDArray[numpy.float64]:
            """P(s -> t) = Texp(-int_s^t nabla_u(r) dr) (cor-parr) for the trivialised velocity u(r), a callable returning an algebra vector; method lie-euler | magnus2 | magnus4."""
        def transport_sampled(self, u_nodes: Any, s: float, t: float, method: str = ..., u_midpoints: Any = ..., nodes: bool = ...) -> NDArray[numpy.float64]:
            """P(s -> t) from samples u(t_k) on a uniform grid (and u(t_k + h/2) for magnus4)."""
    @staticmethod
    def cartan_schouten(lam: float, side: str = ...) -> Heisenberg.Connection:
        """The Cartan-Schouten connection of parameter lam: left map lam ad (CS-conn), right map (lam - 1) ad (CS-conn-right)."""
    @staticmethod
    def cartan_schouten_transport(lam: float, u: Any, s: float, t: float, steps: int = ..., method: str = ..., side: str = ..., nodes: bool = ...) -> NDArray[numpy.float64]:
        """P(s -> t) of the Cartan-Schouten connection (parr-tran-Cartan-lambda) computed in the group: P = Ad(Y)."""
    @staticmethod
    def _euler_poincare(side: str, lagrangian: Any, g0: Any, v0: Any, T: float, steps: int) -> dict: ...
    @staticmethod
    def _lie_poisson(side: str, hamiltonian: Any, g0: Any, mu0: Any, T: float, steps: int) -> dict: ...
    @staticmethod
    def _lagrangian_hessian(lagrangian: Any, t: float, g: Any, v: Any) -> dict: ...
    @staticmethod
    def _check_lagrangian(lagrangian: Any, samples: Any, seed: int, scale: float, side: str) -> dict: ...
    methods: list[str]
    @staticmethod
    def _solve(lagrangian: Any, lam: float, T: float, N: int, g0: Any, gT: Any, request: _SolveRequest, v0: Any, xi0: Any, guess: Any, progress: Any) -> dict: ...
    @staticmethod
    def _validate(lagrangian: Any, lam: float, T: float, N: int, g0: Any, gT: Any, request: _SolveRequest, v0: Any, xi0: Any, guess: Any, progress: Any) -> None: ...
    @staticmethod
    def _verify(lagrangian: Any, result: Any, lam: float, T: float, g0: Any, gT: Any, order: int, tol: float, status: str) -> dict: ...
    @staticmethod
    def _along(lagrangian: Any, result: Any, lam: float) -> dict: ...
    @staticmethod
    def _dense(result: Any, lam: float, method: str, times: Any) -> dict: ...

class H3Oscillator(metaclass=type):
    """l(g, v) = 1/2 v.I v - 1/2 (a^2 + b^2 + c^2); the paper's I is the identity."""
    def __init__(self, inertia: Any = ...) -> None:
        """From a symmetric positive-definite inertia: a (n, n) matrix or its (n,) diagonal."""
    @property
    def inertia(self) -> NDArray[numpy.float64]:
        """The inertia, a symmetric (n, n) matrix."""
    def __getstate__(self) -> tuple: ...
    def __setstate__(self, arg0: tuple) -> None: ...
    group: type[Heisenberg]
    side: str
    def value(self, t: float, g: Any, v: Any) -> float:
        """l(t, g, v)."""
    def momentum(self, t: float, g: Any, v: Any) -> NDArray[numpy.float64]:
        """mu = dl/dv (the reduced Legendre map)."""
    def group_gradient(self, t: float, g: Any, v: Any) -> NDArray[numpy.float64]:
        """zeta, the trivialised dl/dg at fixed v."""
    def velocity(self, t: float, g: Any, mu: Any) -> NDArray[numpy.float64]:
        """v with momentum(t, g, v) = mu (inverse Legendre map)."""

class H3OscillatorHamiltonian(metaclass=type):
    """h(g, mu) = 1/2 mu.I^-1 mu + 1/2 (a^2 + b^2 + c^2)."""
    def __init__(self, inertia: Any = ...) -> None:
        """From a symmetric positive-definite inertia: a (n, n) matrix or its (n,) diagonal."""
    @property
    def inertia(self) -> NDArray[numpy.float64]:
        """The inertia, a symmetric (n, n) matrix."""
    def __getstate__(self) -> tuple: ...
    def __setstate__(self, arg0: tuple) -> None: ...
    group: type[Heisenberg]
    side: str
    def value(self, t: float, g: Any, mu: Any) -> float:
        """h(t, g, mu)."""
    def velocity(self, t: float, g: Any, mu: Any) -> NDArray[numpy.float64]:
        """v = dh/dmu."""
    def group_gradient(self, t: float, g: Any, mu: Any) -> NDArray[numpy.float64]:
        """The trivialised dh/dg at fixed mu."""

class SE3(metaclass=type):
    """SE(3): elements are (4, 4) matrices [[R, t], [0, 1]]; algebra coordinates (rho, omega)."""
    def __init__(self, *args: Any, **kwargs: Any) -> None:
        """No constructor: raises TypeError."""
    name: str
    dim: int
    element_shape: tuple[int, ...]
    @staticmethod
    def identity() -> NDArray[numpy.float64]:
        """The identity element."""
    @staticmethod
    def compose(g: Any, h: Any) -> NDArray[numpy.float64]:
        """The product g h."""
    @staticmethod
    def inverse(g: Any) -> NDArray[numpy.float64]:
        """The inverse g^-1."""
    @staticmethod
    def exp(v: Any) -> NDArray[numpy.float64]:
        """The group exponential of v in the algebra (coordinates)."""
    @staticmethod
    def log(g: Any) -> NDArray[numpy.float64]:
        """The principal logarithm, in algebra coordinates."""
    @staticmethod
    def hat(v: Any) -> NDArray[numpy.float64]:
        """The matrix sum_i v_i E_i of algebra coordinates v."""
    @staticmethod
    def vee(X: Any) -> NDArray[numpy.float64]:
        """The coordinates of an algebra matrix (inverse of hat)."""
    @staticmethod
    def matrix(g: Any) -> NDArray[numpy.float64]:
        """A faithful matrix representation of g."""
    @staticmethod
    def Ad(g: Any) -> NDArray[numpy.float64]:
        """The matrix of Ad_g on algebra coordinates."""
    @staticmethod
    def ad(v: Any) -> NDArray[numpy.float64]:
        """The matrix of ad_v = [v, .] on algebra coordinates."""
    @staticmethod
    def ad_star(v: Any, mu: Any = ...) -> Any:
        """ad*_v mu = ad_v^T mu (docs/conventions.md); the matrix ad_v^T when mu is omitted."""
    @staticmethod
    def bracket(u: Any, v: Any) -> NDArray[numpy.float64]:
        """The Lie bracket [u, v] = ad_u v."""
    @staticmethod
    def left_translate(g: Any, v: Any) -> NDArray[numpy.float64]:
        """d(L_g)_e v, a tangent vector at g in ambient coordinates."""
    @staticmethod
    def left_trivialise(g: Any, X: Any) -> NDArray[numpy.float64]:
        """g^-1 X for a tangent vector X at g (ambient coordinates)."""
    @staticmethod
    def validate(g: Any) -> None:
        """Raises ValueError unless g is a valid element (to the group's tolerance)."""
    class Connection(metaclass=type):
        """An invariant affine connection given by its bilinear map on the algebra (left or right)."""
        def __init__(self, side: str, table: Any) -> None:
            """From a (n, n*n) table whose column i*n + j holds nabla_{E_i} E_j."""
        @property
        def side(self) -> str: ...
        @property
        def coefficients(self) -> NDArray[numpy.float64]:
            """Array (n, n, n): coefficients[i] is the matrix of w -> nabla_{E_i} w."""
        def nabla(self, u: Any, w: Any) -> NDArray[numpy.float64]:
            """The bilinear map nabla_u w."""
        def torsion(self, v: Any, w: Any) -> NDArray[numpy.float64]:
            """T(v, w) on invariant fields (cur-tor-left)."""
        def curvature(self, u: Any, v: Any, w: Any) -> NDArray[numpy.float64]:
            """R(u, v) w on invariant fields (cur-tor-left)."""
        def is_cartan(self) -> bool:
            """True when the bilinear map is skew (geodesics through e are one-parameter subgroups)."""
        def transport(self, u: Any, s: float, t: float, steps: int = ..., method: str = ..., nodes: bool = ...) -> NDArray[numpy.float64]:
            """P(s -> t) = Texp(-int_s^t nabla_u(r) dr) (cor-parr) for the trivialised velocity u(r), a callable returning an algebra vector; method lie-euler | magnus2 | magnus4."""
        def transport_sampled(self, u_nodes: Any, s: float, t: float, method: str = ..., u_midpoints: Any = ..., nodes: bool = ...) -> NDArray[numpy.float64]:
            """P(s -> t) from samples u(t_k) on a uniform grid (and u(t_k + h/2) for magnus4)."""
    @staticmethod
    def cartan_schouten(lam: float, side: str = ...) -> SE3.Connection:
        """The Cartan-Schouten connection of parameter lam: left map lam ad (CS-conn), right map (lam - 1) ad (CS-conn-right)."""
    @staticmethod
    def cartan_schouten_transport(lam: float, u: Any, s: float, t: float, steps: int = ..., method: str = ..., side: str = ..., nodes: bool = ...) -> NDArray[numpy.float64]:
        """P(s -> t) of the Cartan-Schouten connection (parr-tran-Cartan-lambda) computed in the group: P = Ad(Y)."""
    @staticmethod
    def _euler_poincare(side: str, lagrangian: Any, g0: Any, v0: Any, T: float, steps: int) -> dict: ...
    @staticmethod
    def _lie_poisson(side: str, hamiltonian: Any, g0: Any, mu0: Any, T: float, steps: int) -> dict: ...
    @staticmethod
    def _lagrangian_hessian(lagrangian: Any, t: float, g: Any, v: Any) -> dict: ...
    @staticmethod
    def _check_lagrangian(lagrangian: Any, samples: Any, seed: int, scale: float, side: str) -> dict: ...
    methods: list[str]
    @staticmethod
    def _solve(lagrangian: Any, lam: float, T: float, N: int, g0: Any, gT: Any, request: _SolveRequest, v0: Any, xi0: Any, guess: Any, progress: Any) -> dict: ...
    @staticmethod
    def _validate(lagrangian: Any, lam: float, T: float, N: int, g0: Any, gT: Any, request: _SolveRequest, v0: Any, xi0: Any, guess: Any, progress: Any) -> None: ...
    @staticmethod
    def _verify(lagrangian: Any, result: Any, lam: float, T: float, g0: Any, gT: Any, order: int, tol: float, status: str) -> dict: ...
    @staticmethod
    def _along(lagrangian: Any, result: Any, lam: float) -> dict: ...
    @staticmethod
    def _dense(result: Any, lam: float, method: str, times: Any) -> dict: ...
    @staticmethod
    def from_rotation_translation(R: Any, t: Any) -> NDArray[numpy.float64]:
        """[[R, t], [0, 1]] (not validated)."""

class SE3FreeBody(metaclass=type):
    """Free body in space l(g, v) = 1/2 v.I v, v = (rho, omega) in the body frame; diag(m, m, m, J1, J2, J3) about the centre of mass along principal axes (the CLI's se3 model free-body)."""
    def __init__(self, inertia: Any) -> None:
        """From a symmetric positive-definite inertia: a (n, n) matrix or its (n,) diagonal."""
    @property
    def inertia(self) -> NDArray[numpy.float64]:
        """The inertia, a symmetric (n, n) matrix."""
    def __getstate__(self) -> tuple: ...
    def __setstate__(self, arg0: tuple) -> None: ...
    group: type[SE3]
    side: str
    def value(self, t: float, g: Any, v: Any) -> float:
        """l(t, g, v)."""
    def momentum(self, t: float, g: Any, v: Any) -> NDArray[numpy.float64]:
        """mu = dl/dv (the reduced Legendre map)."""
    def group_gradient(self, t: float, g: Any, v: Any) -> NDArray[numpy.float64]:
        """zeta, the trivialised dl/dg at fixed v."""
    def velocity(self, t: float, g: Any, mu: Any) -> NDArray[numpy.float64]:
        """v with momentum(t, g, v) = mu (inverse Legendre map)."""

class SE3FreeBodyHamiltonian(metaclass=type):
    """h(g, mu) = 1/2 mu.I^-1 mu on SE(3)."""
    def __init__(self, inertia: Any) -> None:
        """From a symmetric positive-definite inertia: a (n, n) matrix or its (n,) diagonal."""
    @property
    def inertia(self) -> NDArray[numpy.float64]:
        """The inertia, a symmetric (n, n) matrix."""
    def __getstate__(self) -> tuple: ...
    def __setstate__(self, arg0: tuple) -> None: ...
    group: type[SE3]
    side: str
    def value(self, t: float, g: Any, mu: Any) -> float:
        """h(t, g, mu)."""
    def velocity(self, t: float, g: Any, mu: Any) -> NDArray[numpy.float64]:
        """v = dh/dmu."""
    def group_gradient(self, t: float, g: Any, mu: Any) -> NDArray[numpy.float64]:
        """The trivialised dh/dg at fixed mu."""

class SE2(metaclass=type):
    """SE(2): elements are (3, 3) matrices [[R, t], [0, 1]]; algebra coordinates (x, y, theta)."""
    def __init__(self, *args: Any, **kwargs: Any) -> None:
        """No constructor: raises TypeError."""
    name: str
    dim: int
    element_shape: tuple[int, ...]
    @staticmethod
    def identity() -> NDArray[numpy.float64]:
        """The identity element."""
    @staticmethod
    def compose(g: Any, h: Any) -> NDArray[numpy.float64]:
        """The product g h."""
    @staticmethod
    def inverse(g: Any) -> NDArray[numpy.float64]:
        """The inverse g^-1."""
    @staticmethod
    def exp(v: Any) -> NDArray[numpy.float64]:
        """The group exponential of v in the algebra (coordinates)."""
    @staticmethod
    def log(g: Any) -> NDArray[numpy.float64]:
        """The principal logarithm, in algebra coordinates."""
    @staticmethod
    def hat(v: Any) -> NDArray[numpy.float64]:
        """The matrix sum_i v_i E_i of algebra coordinates v."""
    @staticmethod
    def vee(X: Any) -> NDArray[numpy.float64]:
        """The coordinates of an algebra matrix (inverse of hat)."""
    @staticmethod
    def matrix(g: Any) -> NDArray[numpy.float64]:
        """A faithful matrix representation of g."""
    @staticmethod
    def Ad(g: Any) -> NDArray[numpy.float64]:
        """The matrix of Ad_g on algebra coordinates."""
    @staticmethod
    def ad(v: Any) -> NDArray[numpy.float64]:
        """The matrix of ad_v = [v, .] on algebra coordinates."""
    @staticmethod
    def ad_star(v: Any, mu: Any = ...) -> Any:
        """ad*_v mu = ad_v^T mu (docs/conventions.md); the matrix ad_v^T when mu is omitted."""
    @staticmethod
    def bracket(u: Any, v: Any) -> NDArray[numpy.float64]:
        """The Lie bracket [u, v] = ad_u v."""
    @staticmethod
    def left_translate(g: Any, v: Any) -> NDArray[numpy.float64]:
        """d(L_g)_e v, a tangent vector at g in ambient coordinates."""
    @staticmethod
    def left_trivialise(g: Any, X: Any) -> NDArray[numpy.float64]:
        """g^-1 X for a tangent vector X at g (ambient coordinates)."""
    @staticmethod
    def validate(g: Any) -> None:
        """Raises ValueError unless g is a valid element (to the group's tolerance)."""
    class Connection(metaclass=type):
        """An invariant affine connection given by its bilinear map on the algebra (left or right)."""
        def __init__(self, side: str, table: Any) -> None:
            """From a (n, n*n) table whose column i*n + j holds nabla_{E_i} E_j."""
        @property
        def side(self) -> str: ...
        @property
        def coefficients(self) -> NDArray[numpy.float64]:
            """Array (n, n, n): coefficients[i] is the matrix of w -> nabla_{E_i} w."""
        def nabla(self, u: Any, w: Any) -> NDArray[numpy.float64]:
            """The bilinear map nabla_u w."""
        def torsion(self, v: Any, w: Any) -> NDArray[numpy.float64]:
            """T(v, w) on invariant fields (cur-tor-left)."""
        def curvature(self, u: Any, v: Any, w: Any) -> NDArray[numpy.float64]:
            """R(u, v) w on invariant fields (cur-tor-left)."""
        def is_cartan(self) -> bool:
            """True when the bilinear map is skew (geodesics through e are one-parameter subgroups)."""
        def transport(self, u: Any, s: float, t: float, steps: int = ..., method: str = ..., nodes: bool = ...) -> NDArray[numpy.float64]:
            """P(s -> t) = Texp(-int_s^t nabla_u(r) dr) (cor-parr) for the trivialised velocity u(r), a callable returning an algebra vector; method lie-euler | magnus2 | magnus4."""
        def transport_sampled(self, u_nodes: Any, s: float, t: float, method: str = ..., u_midpoints: Any = ..., nodes: bool = ...) -> NDArray[numpy.float64]:
            """P(s -> t) from samples u(t_k) on a uniform grid (and u(t_k + h/2) for magnus4)."""
    @staticmethod
    def cartan_schouten(lam: float, side: str = ...) -> SE2.Connection:
        """The Cartan-Schouten connection of parameter lam: left map lam ad (CS-conn), right map (lam - 1) ad (CS-conn-right)."""
    @staticmethod
    def cartan_schouten_transport(lam: float, u: Any, s: float, t: float, steps: int = ..., method: str = ..., side: str = ..., nodes: bool = ...) -> NDArray[numpy.float64]:
        """P(s -> t) of the Cartan-Schouten connection (parr-tran-Cartan-lambda) computed in the group: P = Ad(Y)."""
    @staticmethod
    def _euler_poincare(side: str, lagrangian: Any, g0: Any, v0: Any, T: float, steps: int) -> dict: ...
    @staticmethod
    def _lie_poisson(side: str, hamiltonian: Any, g0: Any, mu0: Any, T: float, steps: int) -> dict: ...
    @staticmethod
    def _lagrangian_hessian(lagrangian: Any, t: float, g: Any, v: Any) -> dict: ...
    @staticmethod
    def _check_lagrangian(lagrangian: Any, samples: Any, seed: int, scale: float, side: str) -> dict: ...
    methods: list[str]
    @staticmethod
    def _solve(lagrangian: Any, lam: float, T: float, N: int, g0: Any, gT: Any, request: _SolveRequest, v0: Any, xi0: Any, guess: Any, progress: Any) -> dict: ...
    @staticmethod
    def _validate(lagrangian: Any, lam: float, T: float, N: int, g0: Any, gT: Any, request: _SolveRequest, v0: Any, xi0: Any, guess: Any, progress: Any) -> None: ...
    @staticmethod
    def _verify(lagrangian: Any, result: Any, lam: float, T: float, g0: Any, gT: Any, order: int, tol: float, status: str) -> dict: ...
    @staticmethod
    def _along(lagrangian: Any, result: Any, lam: float) -> dict: ...
    @staticmethod
    def _dense(result: Any, lam: float, method: str, times: Any) -> dict: ...

class SE2FreeBody(metaclass=type):
    """Free body in the plane l(g, v) = 1/2 v.I v, v = (x, y, theta) in the body frame; diag(m, m, J) for mass m and moment J about the centre of mass (the CLI's se2 model free-body)."""
    def __init__(self, inertia: Any) -> None:
        """From a symmetric positive-definite inertia: a (n, n) matrix or its (n,) diagonal."""
    @property
    def inertia(self) -> NDArray[numpy.float64]:
        """The inertia, a symmetric (n, n) matrix."""
    def __getstate__(self) -> tuple: ...
    def __setstate__(self, arg0: tuple) -> None: ...
    group: type[SE2]
    side: str
    def value(self, t: float, g: Any, v: Any) -> float:
        """l(t, g, v)."""
    def momentum(self, t: float, g: Any, v: Any) -> NDArray[numpy.float64]:
        """mu = dl/dv (the reduced Legendre map)."""
    def group_gradient(self, t: float, g: Any, v: Any) -> NDArray[numpy.float64]:
        """zeta, the trivialised dl/dg at fixed v."""
    def velocity(self, t: float, g: Any, mu: Any) -> NDArray[numpy.float64]:
        """v with momentum(t, g, v) = mu (inverse Legendre map)."""

class SE2FreeBodyHamiltonian(metaclass=type):
    """h(g, mu) = 1/2 mu.I^-1 mu on SE(2)."""
    def __init__(self, inertia: Any) -> None:
        """From a symmetric positive-definite inertia: a (n, n) matrix or its (n,) diagonal."""
    @property
    def inertia(self) -> NDArray[numpy.float64]:
        """The inertia, a symmetric (n, n) matrix."""
    def __getstate__(self) -> tuple: ...
    def __setstate__(self, arg0: tuple) -> None: ...
    group: type[SE2]
    side: str
    def value(self, t: float, g: Any, mu: Any) -> float:
        """h(t, g, mu)."""
    def velocity(self, t: float, g: Any, mu: Any) -> NDArray[numpy.float64]:
        """v = dh/dmu."""
    def group_gradient(self, t: float, g: Any, mu: Any) -> NDArray[numpy.float64]:
        """The trivialised dh/dg at fixed mu."""

class BvpSolution(metaclass=type):
    """The C^1 piecewise-cubic dense output of cartan.solve_bvp: sol(x) is y(x), sol(x, 1) is y'(x); (n,) for a number x, (n, q) for q times."""
    def __init__(self, *args: Any, **kwargs: Any) -> None:
        """No constructor: raises TypeError."""
    def __call__(self, x: Any, nu: int = ...) -> NDArray[numpy.float64]: ...
    @property
    def x(self) -> NDArray[numpy.float64]:
        """The mesh."""

def _solve_bvp(fun: Any, bc: Any, x: Any, y: Any, p: Any, fun_jac: Any, bc_jac: Any, tol: float, max_nodes: int, bc_tol: Optional[float], max_newton_iterations: int, max_refinements: int, fd_step: float, linear_solver: str) -> dict: ...

def _scipy_refinement(x: Any, y: Any, yp: Any, rms: Any, tol: float) -> tuple: ...

class Sphere(metaclass=type):
    """The unit sphere S^2 in R^3 with its Levi-Civita connection: points are unit vectors, tangent vectors ambient (3,) vectors, Gamma_q(x, y) = q (x . y)."""
    def __init__(self) -> None: ...
    @property
    def name(self) -> str:
        """The manifold's name ("sphere", "hyperbolic-plane", "euclidean", or the group's)."""
    @property
    def dim(self) -> int:
        """m, the dimension (the length of v and mu)."""
    @property
    def ambient_dim(self) -> int:
        """d >= m, the length of the vectors that represent tangent vectors."""
    @property
    def point_shape(self) -> tuple:
        """The shape of a point: (3,) on the quadrics, (m,) in R^m, the group element's shape."""
    def christoffel(self, q: Any, x: Any, y: Any) -> NDArray[numpy.float64]:
        """Gamma_q(x, y): nabla_{q'} Y = y' + Gamma_q(u, y) for a curve with represented velocity u."""
    def frame_bracket(self, x: Any, y: Any) -> NDArray[numpy.float64]:
        """The bracket of the constant fields x, y (0, or [x, y] on a group)."""
    def torsion(self, q: Any, x: Any, y: Any) -> NDArray[numpy.float64]:
        """T(x, y) = nabla_x y - nabla_y x - [x, y] at q."""
    def curvature(self, q: Any, x: Any, y: Any, z: Any) -> NDArray[numpy.float64]:
        """R(x, y) z = nabla_x nabla_y z - nabla_y nabla_x z - nabla_[x,y] z at q."""
    def step(self, q: Any, x: Any) -> NDArray[numpy.float64]:
        """The end of the manifold's piece s -> step(q, s x) at s = 1 (q + x, a geodesic, g exp(x))."""
    def difference(self, a: Any, b: Any) -> NDArray[numpy.float64]:
        """The x with step(a, x) = b (the local inverse of step)."""
    def transport_along_step(self, q: Any, x: Any) -> NDArray[numpy.float64]:
        """The (d, d) matrix of parallel transport along s -> step(q, s x), s in [0, 1]."""
    def _dense(self, result: Any, method: str, times: Any) -> dict: ...
    def tangent_basis(self, q: Any) -> NDArray[numpy.float64]:
        """A (d, m) basis of T_qQ (orthonormal where there is a metric)."""
    def default_frame(self, q0: Any, qT: Any) -> NDArray[numpy.float64]:
        """The default frame0 of a problem from q0 to qT, (d, m): on the sphere and the hyperbolic plane e1 the unit tangent along the minimal geodesic towards qT and e2 = J (q0 x e1) (where that is undefined, equal or antipodal endpoints, tangent_basis(q0), and a Lagrangian that depends on the frame needs frame0); elsewhere tangent_basis(q0)."""
    def metric(self, q: Any) -> Any:
        """The (d, d) matrix of the metric the connection preserves, or None."""
    def torsion_components(self, q: Any, frame: Any = ...) -> NDArray[numpy.float64]:
        """T[i, j, k] = T_ij^k with T(e_i, e_j) = T_ij^k e_k in the frame (default tangent_basis(q))."""
    def curvature_components(self, q: Any, frame: Any = ...) -> NDArray[numpy.float64]:
        """R[i, j, k, l] = R_ijk^l with R(e_i, e_j) e_k = R_ijk^l e_l in the frame (default tangent_basis(q))."""
    def has_parallel_torsion_and_curvature(self) -> bool:
        """True when nabla T = nabla R = 0 (the solver then computes the frame components once)."""
    def validate(self, q: Any) -> None:
        """Raises ValueError unless q is a valid point of the manifold."""
    def __repr__(self) -> str: ...
    def __getstate__(self) -> tuple: ...
    def __setstate__(self, arg0: tuple) -> None: ...
    @staticmethod
    def point(x: Any) -> NDArray[numpy.float64]:
        """The point of S^2 in the direction of x (x / |x|)."""

class HyperbolicPlane(metaclass=type):
    """The hyperbolic plane H^2 as the upper sheet of q1^2 + q2^2 - q3^2 = -1 in R^3 (Minkowski product), with its Levi-Civita connection: Gamma_q(x, y) = -q <x, y>."""
    def __init__(self) -> None: ...
    @property
    def name(self) -> str:
        """The manifold's name ("sphere", "hyperbolic-plane", "euclidean", or the group's)."""
    @property
    def dim(self) -> int:
        """m, the dimension (the length of v and mu)."""
    @property
    def ambient_dim(self) -> int:
        """d >= m, the length of the vectors that represent tangent vectors."""
    @property
    def point_shape(self) -> tuple:
        """The shape of a point: (3,) on the quadrics, (m,) in R^m, the group element's shape."""
    def christoffel(self, q: Any, x: Any, y: Any) -> NDArray[numpy.float64]:
        """Gamma_q(x, y): nabla_{q'} Y = y' + Gamma_q(u, y) for a curve with represented velocity u."""
    def frame_bracket(self, x: Any, y: Any) -> NDArray[numpy.float64]:
        """The bracket of the constant fields x, y (0, or [x, y] on a group)."""
    def torsion(self, q: Any, x: Any, y: Any) -> NDArray[numpy.float64]:
        """T(x, y) = nabla_x y - nabla_y x - [x, y] at q."""
    def curvature(self, q: Any, x: Any, y: Any, z: Any) -> NDArray[numpy.float64]:
        """R(x, y) z = nabla_x nabla_y z - nabla_y nabla_x z - nabla_[x,y] z at q."""
    def step(self, q: Any, x: Any) -> NDArray[numpy.float64]:
        """The end of the manifold's piece s -> step(q, s x) at s = 1 (q + x, a geodesic, g exp(x))."""
    def difference(self, a: Any, b: Any) -> NDArray[numpy.float64]:
        """The x with step(a, x) = b (the local inverse of step)."""
    def transport_along_step(self, q: Any, x: Any) -> NDArray[numpy.float64]:
        """The (d, d) matrix of parallel transport along s -> step(q, s x), s in [0, 1]."""
    def _dense(self, result: Any, method: str, times: Any) -> dict: ...
    def tangent_basis(self, q: Any) -> NDArray[numpy.float64]:
        """A (d, m) basis of T_qQ (orthonormal where there is a metric)."""
    def default_frame(self, q0: Any, qT: Any) -> NDArray[numpy.float64]:
        """The default frame0 of a problem from q0 to qT, (d, m): on the sphere and the hyperbolic plane e1 the unit tangent along the minimal geodesic towards qT and e2 = J (q0 x e1) (where that is undefined, equal or antipodal endpoints, tangent_basis(q0), and a Lagrangian that depends on the frame needs frame0); elsewhere tangent_basis(q0)."""
    def metric(self, q: Any) -> Any:
        """The (d, d) matrix of the metric the connection preserves, or None."""
    def torsion_components(self, q: Any, frame: Any = ...) -> NDArray[numpy.float64]:
        """T[i, j, k] = T_ij^k with T(e_i, e_j) = T_ij^k e_k in the frame (default tangent_basis(q))."""
    def curvature_components(self, q: Any, frame: Any = ...) -> NDArray[numpy.float64]:
        """R[i, j, k, l] = R_ijk^l with R(e_i, e_j) e_k = R_ijk^l e_l in the frame (default tangent_basis(q))."""
    def has_parallel_torsion_and_curvature(self) -> bool:
        """True when nabla T = nabla R = 0 (the solver then computes the frame components once)."""
    def validate(self, q: Any) -> None:
        """Raises ValueError unless q is a valid point of the manifold."""
    def __repr__(self) -> str: ...
    def __getstate__(self) -> tuple: ...
    def __setstate__(self, arg0: tuple) -> None: ...
    @staticmethod
    def point(x1: float, x2: float) -> NDArray[numpy.float64]:
        """The point (x1, x2, sqrt(1 + x1^2 + x2^2)) of H^2."""

class Euclidean(metaclass=type):
    """R^2 or R^3 with a constant linear connection nabla_{e_i} e_j = Gamma^k_ij e_k (any torsion and curvature); points and vectors are coordinates."""
    def __init__(self, christoffel: Any = ..., *, dim: Any = ...) -> None:
        """christoffel: a (m, m, m) array with christoffel[k, i, j] = Gamma^k_ij (m = 2 or 3), or None with dim = m for the flat, torsion-free connection (also Euclidean(m), m an integer)."""
    @property
    def name(self) -> str:
        """The manifold's name ("sphere", "hyperbolic-plane", "euclidean", or the group's)."""
    @property
    def dim(self) -> int:
        """m, the dimension (the length of v and mu)."""
    @property
    def ambient_dim(self) -> int:
        """d >= m, the length of the vectors that represent tangent vectors."""
    @property
    def point_shape(self) -> tuple:
        """The shape of a point: (3,) on the quadrics, (m,) in R^m, the group element's shape."""
    def christoffel(self, q: Any, x: Any, y: Any) -> NDArray[numpy.float64]:
        """Gamma_q(x, y): nabla_{q'} Y = y' + Gamma_q(u, y) for a curve with represented velocity u."""
    def frame_bracket(self, x: Any, y: Any) -> NDArray[numpy.float64]:
        """The bracket of the constant fields x, y (0, or [x, y] on a group)."""
    def torsion(self, q: Any, x: Any, y: Any) -> NDArray[numpy.float64]:
        """T(x, y) = nabla_x y - nabla_y x - [x, y] at q."""
    def curvature(self, q: Any, x: Any, y: Any, z: Any) -> NDArray[numpy.float64]:
        """R(x, y) z = nabla_x nabla_y z - nabla_y nabla_x z - nabla_[x,y] z at q."""
    def step(self, q: Any, x: Any) -> NDArray[numpy.float64]:
        """The end of the manifold's piece s -> step(q, s x) at s = 1 (q + x, a geodesic, g exp(x))."""
    def difference(self, a: Any, b: Any) -> NDArray[numpy.float64]:
        """The x with step(a, x) = b (the local inverse of step)."""
    def transport_along_step(self, q: Any, x: Any) -> NDArray[numpy.float64]:
        """The (d, d) matrix of parallel transport along s -> step(q, s x), s in [0, 1]."""
    def _dense(self, result: Any, method: str, times: Any) -> dict: ...
    def tangent_basis(self, q: Any) -> NDArray[numpy.float64]:
        """A (d, m) basis of T_qQ (orthonormal where there is a metric)."""
    def default_frame(self, q0: Any, qT: Any) -> NDArray[numpy.float64]:
        """The default frame0 of a problem from q0 to qT, (d, m): on the sphere and the hyperbolic plane e1 the unit tangent along the minimal geodesic towards qT and e2 = J (q0 x e1) (where that is undefined, equal or antipodal endpoints, tangent_basis(q0), and a Lagrangian that depends on the frame needs frame0); elsewhere tangent_basis(q0)."""
    def metric(self, q: Any) -> Any:
        """The (d, d) matrix of the metric the connection preserves, or None."""
    def torsion_components(self, q: Any, frame: Any = ...) -> NDArray[numpy.float64]:
        """T[i, j, k] = T_ij^k with T(e_i, e_j) = T_ij^k e_k in the frame (default tangent_basis(q))."""
    def curvature_components(self, q: Any, frame: Any = ...) -> NDArray[numpy.float64]:
        """R[i, j, k, l] = R_ijk^l with R(e_i, e_j) e_k = R_ijk^l e_l in the frame (default tangent_basis(q))."""
    def has_parallel_torsion_and_curvature(self) -> bool:
        """True when nabla T = nabla R = 0 (the solver then computes the frame components once)."""
    def validate(self, q: Any) -> None:
        """Raises ValueError unless q is a valid point of the manifold."""
    @property
    def christoffel_symbols(self) -> NDArray[numpy.float64]:
        """The (m, m, m) array christoffel[k, i, j] = Gamma^k_ij."""
    def __repr__(self) -> str: ...
    def __getstate__(self) -> tuple: ...
    def __setstate__(self, arg0: tuple) -> None: ...

class Chart(metaclass=type):
    """A manifold of your own in one chart: points are coordinates q in an open set of R^m (m = 2 or 3) and the connection any field of Christoffel symbols q -> Gamma^k_ij(q) (torsion allowed); pieces are coordinate lines, transport along them is integrated by RK4 (include/cartan/manifolds/chart.hpp)."""
    def __init__(self, christoffel: Any, *, dim: Any, metric: Any = ..., name: str = ..., parallel: bool = ...) -> None:
        """christoffel(q) -> a (m, m, m) array with christoffel[k, i, j] = Gamma^k_ij at q (as Euclidean); non-finite values (or an exception) mark points outside the chart. metric(q) -> (m, m), optional (a metric the connection preserves; the default frame tangent_basis(q) is then the coordinate basis orthonormalised in it, so that l = 1/2 |v|^2 is 1/2 g(q', q')). parallel: declare nabla T = nabla R = 0 (e.g. constant curvature), which lets the solver compute the frame components once; only when true."""
    @property
    def name(self) -> str:
        """The manifold's name ("sphere", "hyperbolic-plane", "euclidean", or the group's)."""
    @property
    def dim(self) -> int:
        """m, the dimension (the length of v and mu)."""
    @property
    def ambient_dim(self) -> int:
        """d >= m, the length of the vectors that represent tangent vectors."""
    @property
    def point_shape(self) -> tuple:
        """The shape of a point: (3,) on the quadrics, (m,) in R^m, the group element's shape."""
    def christoffel(self, q: Any, x: Any, y: Any) -> NDArray[numpy.float64]:
        """Gamma_q(x, y): nabla_{q'} Y = y' + Gamma_q(u, y) for a curve with represented velocity u."""
    def frame_bracket(self, x: Any, y: Any) -> NDArray[numpy.float64]:
        """The bracket of the constant fields x, y (0, or [x, y] on a group)."""
    def torsion(self, q: Any, x: Any, y: Any) -> NDArray[numpy.float64]:
        """T(x, y) = nabla_x y - nabla_y x - [x, y] at q."""
    def curvature(self, q: Any, x: Any, y: Any, z: Any) -> NDArray[numpy.float64]:
        """R(x, y) z = nabla_x nabla_y z - nabla_y nabla_x z - nabla_[x,y] z at q."""
    def step(self, q: Any, x: Any) -> NDArray[numpy.float64]:
        """The end of the manifold's piece s -> step(q, s x) at s = 1 (q + x, a geodesic, g exp(x))."""
    def difference(self, a: Any, b: Any) -> NDArray[numpy.float64]:
        """The x with step(a, x) = b (the local inverse of step)."""
    def transport_along_step(self, q: Any, x: Any) -> NDArray[numpy.float64]:
        """The (d, d) matrix of parallel transport along s -> step(q, s x), s in [0, 1]."""
    def _dense(self, result: Any, method: str, times: Any) -> dict: ...
    def tangent_basis(self, q: Any) -> NDArray[numpy.float64]:
        """A (d, m) basis of T_qQ (orthonormal where there is a metric)."""
    def default_frame(self, q0: Any, qT: Any) -> NDArray[numpy.float64]:
        """The default frame0 of a problem from q0 to qT, (d, m): on the sphere and the hyperbolic plane e1 the unit tangent along the minimal geodesic towards qT and e2 = J (q0 x e1) (where that is undefined, equal or antipodal endpoints, tangent_basis(q0), and a Lagrangian that depends on the frame needs frame0); elsewhere tangent_basis(q0)."""
    def metric(self, q: Any) -> Any:
        """The (d, d) matrix of the metric the connection preserves, or None."""
    def torsion_components(self, q: Any, frame: Any = ...) -> NDArray[numpy.float64]:
        """T[i, j, k] = T_ij^k with T(e_i, e_j) = T_ij^k e_k in the frame (default tangent_basis(q))."""
    def curvature_components(self, q: Any, frame: Any = ...) -> NDArray[numpy.float64]:
        """R[i, j, k, l] = R_ijk^l with R(e_i, e_j) e_k = R_ijk^l e_l in the frame (default tangent_basis(q))."""
    def has_parallel_torsion_and_curvature(self) -> bool:
        """True when nabla T = nabla R = 0 (the solver then computes the frame components once)."""
    def validate(self, q: Any) -> None:
        """Raises ValueError unless q is a valid point of the manifold."""
    def __repr__(self) -> str: ...

class GroupManifold(metaclass=type):
    """A Lie group (so3, heisenberg, se2, se3) with a left-invariant connection, as a manifold: points are group elements, vectors left-trivialised algebra coordinates, the Christoffel map is the connection's bilinear map alpha."""
    def __init__(self, group: Any, connection: Any = ..., *, lam: Any = ..., metric: Any = ..., alpha: Any = ...) -> None:
        """group: "so3", "heisenberg", "se2", "se3" or the group class. connection: "cartan-schouten" (with lam: alpha = lam ad), "levi-civita" (with metric, a symmetric positive-definite (n, n) matrix or its (n,) diagonal), "coefficients" (with alpha, a (n, n, n) array: alpha(e_i, e_j) = sum_k alpha[i, j, k] e_k), or a left <Group>.Connection object."""
    @property
    def name(self) -> str:
        """The manifold's name ("sphere", "hyperbolic-plane", "euclidean", or the group's)."""
    @property
    def dim(self) -> int:
        """m, the dimension (the length of v and mu)."""
    @property
    def ambient_dim(self) -> int:
        """d >= m, the length of the vectors that represent tangent vectors."""
    @property
    def point_shape(self) -> tuple:
        """The shape of a point: (3,) on the quadrics, (m,) in R^m, the group element's shape."""
    def christoffel(self, q: Any, x: Any, y: Any) -> NDArray[numpy.float64]:
        """Gamma_q(x, y): nabla_{q'} Y = y' + Gamma_q(u, y) for a curve with represented velocity u."""
    def frame_bracket(self, x: Any, y: Any) -> NDArray[numpy.float64]:
        """The bracket of the constant fields x, y (0, or [x, y] on a group)."""
    def torsion(self, q: Any, x: Any, y: Any) -> NDArray[numpy.float64]:
        """T(x, y) = nabla_x y - nabla_y x - [x, y] at q."""
    def curvature(self, q: Any, x: Any, y: Any, z: Any) -> NDArray[numpy.float64]:
        """R(x, y) z = nabla_x nabla_y z - nabla_y nabla_x z - nabla_[x,y] z at q."""
    def step(self, q: Any, x: Any) -> NDArray[numpy.float64]:
        """The end of the manifold's piece s -> step(q, s x) at s = 1 (q + x, a geodesic, g exp(x))."""
    def difference(self, a: Any, b: Any) -> NDArray[numpy.float64]:
        """The x with step(a, x) = b (the local inverse of step)."""
    def transport_along_step(self, q: Any, x: Any) -> NDArray[numpy.float64]:
        """The (d, d) matrix of parallel transport along s -> step(q, s x), s in [0, 1]."""
    def _dense(self, result: Any, method: str, times: Any) -> dict: ...
    def tangent_basis(self, q: Any) -> NDArray[numpy.float64]:
        """A (d, m) basis of T_qQ (orthonormal where there is a metric)."""
    def default_frame(self, q0: Any, qT: Any) -> NDArray[numpy.float64]:
        """The default frame0 of a problem from q0 to qT, (d, m): on the sphere and the hyperbolic plane e1 the unit tangent along the minimal geodesic towards qT and e2 = J (q0 x e1) (where that is undefined, equal or antipodal endpoints, tangent_basis(q0), and a Lagrangian that depends on the frame needs frame0); elsewhere tangent_basis(q0)."""
    def metric(self, q: Any) -> Any:
        """The (d, d) matrix of the metric the connection preserves, or None."""
    def torsion_components(self, q: Any, frame: Any = ...) -> NDArray[numpy.float64]:
        """T[i, j, k] = T_ij^k with T(e_i, e_j) = T_ij^k e_k in the frame (default tangent_basis(q))."""
    def curvature_components(self, q: Any, frame: Any = ...) -> NDArray[numpy.float64]:
        """R[i, j, k, l] = R_ijk^l with R(e_i, e_j) e_k = R_ijk^l e_l in the frame (default tangent_basis(q))."""
    def has_parallel_torsion_and_curvature(self) -> bool:
        """True when nabla T = nabla R = 0 (the solver then computes the frame components once)."""
    def validate(self, q: Any) -> None:
        """Raises ValueError unless q is a valid point of the manifold."""
    @property
    def group(self) -> Any:
        """The group class (cartan.SO3, ...)."""
    @property
    def lam(self) -> Any:
        """lam for a Cartan-Schouten connection, else None."""
    @property
    def alpha(self) -> NDArray[numpy.float64]:
        """The bilinear map as a (n, n, n) array: alpha(e_i, e_j) = sum_k alpha[i, j, k] e_k."""
    def __getstate__(self) -> tuple: ...
    def __setstate__(self, arg0: tuple) -> None: ...
    @property
    def connection(self) -> Any:
        """The connection as a <Group>.Connection object."""
    def __repr__(self) -> str: ...

class _GeneralRequest(metaclass=type):
    def __init__(self) -> None: ...
    method: str
    continuation: str
    order: int
    tol: float
    max_iterations: int
    segments: Optional[int]
    lambda_start: Optional[float]
    samples: int
    max_nodes: Optional[int]
    time_limit: Optional[float]
    T: float
    N: int
    q0: Any
    qT: Any
    inertia: Any
    potential: Any
    potential_gradient: Any
    gravity: Any
    lagrangian: Any
    frame0: Any
    v0: Any
    Xi0: Any
    progress: Any
    guess: Any

def _solve_general(manifold: Any, request: _GeneralRequest) -> dict: ...

def _validate_general(manifold: Any, request: _GeneralRequest) -> None: ...

def _along_general(manifold: Any, request: _GeneralRequest, fields: dict, named_only: bool) -> dict: ...

def _verify_general(manifold: Any, request: _GeneralRequest, result: Any) -> dict: ...

def _check_general_lagrangian(manifold: Any, request: _GeneralRequest, samples: Any, seed: int, scale: float, q: Any) -> dict: ...

def _result_text(fields: dict) -> str:
    """The result file's text (one line of JSON) of a SolveResult's fields: the library's writer, the CLI's."""

def _read_result(text: str, where: str) -> dict:
    """The fields of a result file's text: the library's reader, the CLI's (every key checked; ValueError naming it)."""

spaces: list[dict[str, Any]]
