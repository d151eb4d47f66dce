"""Type stubs of the extension module `routh` (the nonholonomic Routh sphere).

Conventions: a phase-space point is x = (gamma1, gamma2, gamma3, M1, M2, M3), gamma the unit
normal of the plane pointing into it (downwards), M the angular momentum about the contact
point, both in the body frame; several points are the columns of an array (6, k), as in
SciPy. Units are those of the body's parameters (SI if they are SI); angles in radians.
"""

from os import PathLike
from typing import Any, Callable, Literal, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str
MAX_VALUES: int

ArrayLike = npt.ArrayLike
FloatArray = npt.NDArray[np.float64]
EventFunction = Callable[[float, FloatArray], float]
EventLike = Union["Event", str, EventFunction]
Record = dict[str, Any]

class Body:
    """The rolling ball: mass m, radius R, offset a of the centre of mass (at -a e3 from the
    geometric centre, |a| < R), principal moments I1, I2 (default I1), I3, gravity G >= 0."""

    def __init__(
        self, m: float, R: float, a: float, I1: float, I3: float, G: float = 9.81,
        I2: Optional[float] = None,
    ) -> None: ...
    @property
    def m(self) -> float: ...
    @property
    def R(self) -> float: ...
    @property
    def a(self) -> float: ...
    @property
    def I1(self) -> float: ...
    @property
    def I2(self) -> float: ...
    @property
    def I3(self) -> float: ...
    @property
    def G(self) -> float: ...
    @property
    def is_symmetric(self) -> bool: ...
    def field(self, x: ArrayLike, unit_tolerance: Optional[float] = 1e-12) -> FloatArray:
        """dx/dt of (mg-eq) at x, shape (6,) or (6, k)."""
    def omega(self, x: ArrayLike, unit_tolerance: Optional[float] = 1e-12) -> FloatArray:
        """omega = I_Q^{-1} M (rad per unit time, body frame), shape (3,) or (3, k)."""
    def integrals(
        self, x: ArrayLike, unit_tolerance: Optional[float] = 1e-12
    ) -> dict[str, Union[float, FloatArray, None]]:
        """{H1, H2, H3, H4, K} at x (None where the body has no such integral)."""
    def state_from_omega(
        self, gamma: ArrayLike, omega: ArrayLike, normalize: bool = False
    ) -> FloatArray:
        """The point (gamma, I_Q omega), shape (6,)."""

class Event:
    """A named event ("theta_dot", "gamma3=<value>", "theta=<radians>") or a callable
    g(t, y); terminal: False, True or a count; direction as in SciPy."""

    def __init__(
        self, what: Union[str, EventFunction], terminal: Union[bool, int, None] = None,
        direction: float = 0.0,
    ) -> None: ...
    @property
    def terminal(self) -> int: ...
    @property
    def direction(self) -> float: ...

class DenseOutput:
    """The state at any time of the span, as SciPy's OdeSolution."""

    @property
    def t_min(self) -> float: ...
    @property
    def t_max(self) -> float: ...
    @property
    def ts(self) -> FloatArray: ...
    @property
    def ys(self) -> FloatArray: ...
    def __call__(self, t: ArrayLike) -> FloatArray: ...

class Solution:
    """The result of simulate, with the attributes of SciPy's solve_ivp result."""

    t: FloatArray
    y: FloatArray
    sol: Optional[DenseOutput]
    t_events: list[FloatArray]
    y_events: list[FloatArray]
    nfev: int
    njev: int
    nlu: int
    status: Literal[-1, 0, 1]
    message: str
    success: bool
    steps: int
    rejected: int
    method: str
    projected: bool
    elapsed_s: float
    integrals: dict[str, dict[str, float]]
    t_span: Tuple[float, float]
    y0: FloatArray
    y_final: FloatArray
    space: Optional[dict[str, FloatArray]]
    def __getitem__(self, key: str) -> Any: ...

class Problem:
    """An initial-value problem: body, x0, t_span and the integration settings."""

    def __init__(
        self, body: Body, x0: ArrayLike, t_span: Union[float, Sequence[float]],
        rtol: float = 1e-12, atol: float = 1e-12, method: str = "dop853",
        project: bool = False, full: bool = False,
    ) -> None: ...
    @staticmethod
    def from_case(
        path: Union[str, PathLike[str], None] = None, full: bool = False
    ) -> "Problem": ...
    @property
    def body(self) -> Body: ...
    @property
    def x0(self) -> FloatArray: ...
    @property
    def t_span(self) -> Tuple[float, float]: ...
    @property
    def rtol(self) -> float: ...
    @property
    def atol(self) -> float: ...
    @property
    def method(self) -> str: ...
    @property
    def project(self) -> bool: ...
    @property
    def full(self) -> bool: ...
    def solve(
        self, t_eval: Optional[ArrayLike] = None, samples: int = 0,
        events: Union[EventLike, Sequence[EventLike], None] = None,
        dense_output: bool = False,
    ) -> Solution: ...

def simulate(
    body: Body, x0: ArrayLike, t_span: Union[float, Sequence[float], None] = None,
    rtol: float = 1e-12, atol: float = 1e-12, method: str = "dop853",
    project: bool = False, samples: int = 0, *, t_eval: Optional[ArrayLike] = None,
    events: Union[EventLike, Sequence[EventLike], None] = None,
    dense_output: bool = False, full: bool = False,
    t_end: Union[float, Sequence[float], None] = None,
) -> Solution:
    """Integrate (mg-eq) from x0 over t_span (see the module README)."""

class ExactSolution:
    """The exact solution through x0 by quadrature (Routh sphere, I1 = I2)."""

    def __init__(self, body: Body, x0: ArrayLike) -> None: ...
    def __call__(self, t: ArrayLike) -> FloatArray: ...
    @property
    def body(self) -> Body: ...
    @property
    def x0(self) -> FloatArray: ...
    @property
    def motion(self) -> Literal["steady", "nutation"]: ...
    @property
    def turning_points(self) -> Tuple[float, float]: ...
    @property
    def theta_range(self) -> Tuple[float, float]: ...
    @property
    def period(self) -> Optional[float]: ...
    @property
    def precession_advance(self) -> Optional[float]: ...
    @property
    def precession_rate(self) -> float: ...
    @property
    def passes_through_axis(self) -> bool: ...
    @property
    def nodes(self) -> Optional[int]: ...
    @property
    def integrals(self) -> dict[str, float]: ...

def vertical_spin(body: Body, pole: float, spin: float) -> Record: ...
def steady_precessions(body: Body, theta: float, spin: float) -> list[Record]: ...
def routh_threshold(body: Body, pole: float) -> float: ...
def audit(points: int = 20, seed: int = 1) -> list[Record]: ...
def default_case() -> Tuple[Body, FloatArray, float, float, float]: ...
def load_case(
    path: Union[str, PathLike[str]]
) -> Tuple[Body, FloatArray, float, float, float]: ...
