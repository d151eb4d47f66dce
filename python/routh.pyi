"""Type stubs of the extension module `routh` (the nonholonomic Routh sphere).

Conventions: a phase-space point is x = (gamma1, gamma2, gamma3, M1, M2, M3), gamma the unit
normal of the plane pointing into it (downwards), M the angular momentum about the contact
point, both in the body frame; several points are the columns of an array (6, k), as in
SciPy. Units are those of the body's parameters (SI if they are SI); angles in radians.
"""

from os import PathLike
from typing import Any, Callable, Literal, Optional, Sequence, Tuple, Union, final

import numpy as np
import numpy.typing as npt

__all__ = [
    "__version__", "MAX_VALUES", "Ball", "Body", "DenseOutput", "Event", "ExactSolution", "HamiltonianFlow", "Problem", "Solution",
    "audit", "default_case", "diagram", "load_case", "lyapunov", "routh_threshold", "section", "simulate", "steady_precessions",
    "sleeping_tops", "sweep", "vertical_spin",
]
__version__: str
MAX_VALUES: int

_ArrayLike = npt.ArrayLike
_FloatArray = npt.NDArray[np.float64]
_EventFunction = Callable[[float, _FloatArray], float]
_EventLike = Union["Event", str, _EventFunction]
_Record = dict[str, Any]

@final
class Ball:
    """The general unbalanced ball: mass m, radius R, principal moments I1, I2, I3 about the
    centre of mass (each > 0, triangle inequalities), the centre of mass at com = (x, y, z)
    from the geometric centre in the body frame (|com| < R; Body's offset a is com = (0, 0, -a)),
    gravity G >= 0. Units: any consistent set (SI if the parameters are SI).

    model (decided with the relative tolerance 1e-12): "routh-sphere" (I1 = I2, com on e3:
    integrals H1, H2, H3, H4, K), "chaplygin" (com = 0: H1, H4, MM = (M, M),
    Mgamma = (M, gamma)) or "general" (H1 and H4 only; not integrable)."""

    def __new__(
        cls, m: float, R: float, I1: float, I2: float, I3: float,
        com: Optional[_ArrayLike] = None, G: float = 9.81,
    ) -> "Ball": ...
    @property
    def m(self) -> float: ...
    @property
    def R(self) -> float: ...
    @property
    def I1(self) -> float: ...
    @property
    def I2(self) -> float: ...
    @property
    def I3(self) -> float: ...
    @property
    def com(self) -> Tuple[float, float, float]: ...
    @property
    def G(self) -> float: ...
    @property
    def model(self) -> Literal["routh-sphere", "chaplygin", "general"]: ...
    def field(self, x: _ArrayLike, unit_tolerance: Optional[float] = ...) -> _FloatArray:
        """The vector field (mg-eq) dx/dt at x, shape (6,) or (6, k)."""
    def omega(self, x: _ArrayLike, unit_tolerance: Optional[float] = ...) -> _FloatArray:
        """The angular velocity omega = I_Q^-1 M (om-m), rad per unit time, body frame."""
    def integrals(
        self, x: _ArrayLike, unit_tolerance: Optional[float] = ...
    ) -> dict[str, Any]:
        """The integrals of the ball's model at x by name (only those it has): H1 (energy,
        int-g), H4 = |gamma|^2, and H2, H3, K (Routh sphere) or MM, Mgamma (Chaplygin)."""

@final
class Body:
    """The rolling ball: mass m, radius R, offset a of the centre of mass (at -a e3 from the
    geometric centre, |a| < R), principal moments I1, I2 (default I1), I3, gravity G >= 0."""

    def __new__(
        cls, m: float, R: float, a: float, I1: float, I3: float, G: float = 9.81,
        I2: Optional[float] = None,
    ) -> "Body": ...
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
    def field(self, x: _ArrayLike, unit_tolerance: Optional[float] = ...) -> _FloatArray:
        """dx/dt of (mg-eq) at x, shape (6,) or (6, k)."""
    def omega(self, x: _ArrayLike, unit_tolerance: Optional[float] = ...) -> _FloatArray:
        """omega = I_Q^{-1} M (rad per unit time, body frame), shape (3,) or (3, k)."""
    def integrals(
        self, x: _ArrayLike, unit_tolerance: Optional[float] = ...
    ) -> dict[str, Union[float, _FloatArray, None]]:
        """{H1, H2, H3, H4, K} at x (None where the body has no such integral)."""
    def state_from_omega(
        self, gamma: _ArrayLike, omega: _ArrayLike, normalize: bool = False
    ) -> _FloatArray:
        """The point (gamma, I_Q omega), shape (6,)."""

@final
class Event:
    """A named event ("theta_dot", "gamma3=<value>", "theta=<radians>") or a callable
    g(t, y); terminal: False, True or a count; direction as in SciPy."""

    def __new__(
        cls, what: Union[str, _EventFunction], terminal: Union[bool, int, None] = None,
        direction: float = 0.0,
    ) -> "Event": ...
    @property
    def terminal(self) -> int: ...
    @property
    def direction(self) -> float: ...

@final
class DenseOutput:
    """The state at any time of the span, as SciPy's OdeSolution."""

    def __new__(
        cls, body: Union[Body, Ball], level: Optional[Sequence[float]], times: Sequence[float],
        nodes: Sequence[float], t_last: float,
    ) -> "DenseOutput":
        """Rebuild from pickled fields (used by pickle)."""

    @property
    def t_min(self) -> float: ...
    @property
    def t_max(self) -> float: ...
    @property
    def ts(self) -> _FloatArray: ...
    @property
    def ys(self) -> _FloatArray: ...
    def __call__(self, t: _ArrayLike) -> _FloatArray: ...

@final
class Solution:
    """The result of simulate, with the attributes of SciPy's solve_ivp result."""

    t: _FloatArray
    y: _FloatArray
    sol: Optional[DenseOutput]
    t_events: list[_FloatArray]
    y_events: list[_FloatArray]
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
    y0: _FloatArray
    y_final: _FloatArray
    space: Optional[dict[str, _FloatArray]]
    def __new__(
        cls, t: Any, y: Any, sol: Any, t_events: Any, y_events: Any, nfev: int, status: int,
        message: str, steps: int, rejected: int, method: str, projected: bool,
        elapsed_s: float, integrals: Any, t_span: Tuple[float, float], y0: Any,
        y_final: Any, space: Any,
    ) -> "Solution":
        """Rebuild from pickled fields (used by pickle)."""
    def __getitem__(self, key: str, /) -> Any: ...

@final
class Problem:
    """An initial-value problem: body, x0, t_span and the integration settings."""

    def __new__(
        cls, body: Union[Body, Ball], x0: _ArrayLike, t_span: Union[float, Sequence[float]],
        rtol: float = 1e-12, atol: float = 1e-12, method: str = "dop853",
        project: bool = False, full: bool = False, project_every: int = 1,
    ) -> "Problem": ...
    @staticmethod
    def from_case(
        path: Union[str, PathLike[str], None] = None, full: bool = False
    ) -> "Problem": ...
    @property
    def body(self) -> Union[Body, Ball]: ...
    @property
    def x0(self) -> _FloatArray: ...
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
    @property
    def project_every(self) -> int: ...
    def solve(
        self, t_eval: Optional[_ArrayLike] = None, samples: int = 0,
        events: Union[_EventLike, Sequence[_EventLike], None] = None,
        dense_output: bool = False,
    ) -> Solution: ...

def simulate(
    body: Union[Body, Ball], x0: _ArrayLike, t_span: Union[float, Sequence[float], None] = None,
    rtol: float = 1e-12, atol: float = 1e-12, method: str = "dop853",
    project: bool = False, samples: int = 0, *, t_eval: Optional[_ArrayLike] = None,
    events: Union[_EventLike, Sequence[_EventLike], None] = None,
    dense_output: bool = False, full: bool = False,
    t_end: Union[float, Sequence[float], None] = None, project_every: int = 1,
) -> Solution:
    """Integrate (mg-eq) from x0 over t_span (see the module README)."""

@final
class ExactSolution:
    """The exact solution through x0 by quadrature (Routh sphere, I1 = I2)."""

    def __new__(cls, body: Body, x0: _ArrayLike) -> "ExactSolution": ...
    def __call__(self, t: _ArrayLike) -> _FloatArray: ...
    @property
    def body(self) -> Union[Body, Ball]: ...
    @property
    def x0(self) -> _FloatArray: ...
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

@final
class HamiltonianFlow:
    """The flow of X1, X2 or Xhat2 of the first bracket (p-br) by quadrature (I1 = I2)."""

    def __new__(
        cls, body: Body, x0: _ArrayLike, flow: Literal["X1", "X2", "Xhat2"],
        condition: Literal["cond", "cond2", "conformal"] = "cond", alpha: float = 1.0,
    ) -> "HamiltonianFlow": ...
    def __call__(self, t: _ArrayLike) -> _FloatArray: ...
    def field(self, x: _ArrayLike) -> _FloatArray: ...
    @property
    def theta_range(self) -> Tuple[float, float]: ...
    @property
    def period(self) -> Optional[float]: ...
    @property
    def precession_advance(self) -> Optional[float]: ...
    @property
    def precession_rate(self) -> Optional[float]: ...
    @property
    def b(self) -> float: ...
    @property
    def energy(self) -> float: ...

def vertical_spin(body: Body, pole: float, spin: float) -> _Record: ...
def steady_precessions(body: Body, theta: float, spin: float) -> list[_Record]: ...
def routh_threshold(body: Body, pole: float) -> float: ...
def audit(points: int = 20, seed: int = 1) -> list[_Record]: ...
def lyapunov(
    body: Union[Body, Ball], x0: _ArrayLike, t_end: float = 100.0, *,
    transient: Optional[float] = None, interval: Optional[float] = None,
    method: str = "dop853", rtol: float = 1e-12, atol: float = 1e-12,
) -> _Record:
    """The five Lyapunov exponents on |gamma| = 1 (the keys of `routh lyapunov --json`)."""
def section(
    body: Union[Body, Ball], x0: _ArrayLike, surface: str, t_end: float = 100.0, *,
    direction: str = "up", initial: int = 20, method: str = "dop853",
    rtol: float = 1e-12, atol: float = 1e-12,
) -> _Record:
    """The Poincaré section on the energy level of x0 through the plane `surface`
    ("NAME = NUMBER"): the keys of `routh section --json` and the arrays `run`, `t`,
    `x` (6, k) and `initial_states_x` (6, n)."""
def sweep(
    path: Optional[Union[str, PathLike[str]]] = None,
    *,
    text: Optional[str] = None,
    t_end: Optional[float] = None,
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    method: str = "auto",
    threads: Optional[int] = None,
    start: int = 0,
    stop: Optional[int] = None,
    columns: Optional[Sequence[str]] = None,
    events: Optional[Sequence[str]] = None,
) -> Any:
    """The runs `start <= run < stop` of the sweep in the case file `path` (or the case text
    `text`), on `threads` threads (default: one per core), as a `pyarrow.Table`, one row per
    run in the order of `run` (`.to_pandas()` for a DataFrame). `columns` (names and groups,
    as `routh sweep --columns`: "final", "integrals", "events", "quadrature", "nutation",
    "all", or single columns) chooses the columns, and only what they need is computed;
    default: the `[sweep]` table's `columns`, else ["final", "integrals"] (with "user_events"
    when events are given). `events` (as `[sweep] events` or `routh sweep --events`: planes
    "NAME = NUMBER" each with an optional direction "up", "down" or "both") adds the columns
    `event{k}_count` and `event{k}_first_t`; it overrides the table's key. The schema's metadata holds the
    case text (`routh.case`) and the version (`routh.version`). Every run gives the numbers of
    `routh simulate` on its case, whatever the thread count or the slicing. The interpreter
    lock is released while the runs are computed."""
    ...
def diagram(
    body: Body,
    h3: float,
    *,
    tilts: Optional[int] = None,
    grid: Optional[int] = None,
    loop_points: Optional[int] = None,
) -> _Record:
    """The energy-momentum diagram of `body` (I1 = I2) in the plane (K, H1) at Jellett's
    `h3`, with the keys of `routh diagram --json`: `H3`, `window`, `vertical_spins`,
    `critical_curves` (each with `stability` and `points`), `focus_focus` (each with `H1`,
    `H3`, `K`, `state`), `monodromy` (`loop`, `matrix`: 2 x 2 integers; None without a
    focus-focus point), `tori`. The interpreter lock is released while it is computed."""
    ...
def sleeping_tops(body: Body, h3_max: float, samples: int = 200) -> list[_Record]:
    """The vertical spins of `body` for |H3| <= `h3_max` (`samples` per pole, 2 to 5000),
    one record per pole (`pole`, `spins` with their stability type, `threshold_h3`)."""
    ...
def default_case() -> Tuple[Body, _FloatArray, float, float, float]: ...
def load_case(
    path: Union[str, PathLike[str]]
) -> Tuple[Union[Body, Ball], _FloatArray, float, float, float]: ...
