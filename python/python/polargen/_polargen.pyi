"""Type stubs of the compiled core ``polargen._polargen`` (the Rust library's Python layer).
The documented API is the package ``polargen``; ``Airfoil`` and ``NotConvergedError`` are
re-exported there."""

import os
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

ArrayLike = Union[Sequence[float], npt.NDArray[np.float64]]
PathLike = Union[str, "os.PathLike[str]"]

DEFAULT_RE: List[float]
DEFAULT_MACH: List[float]
DEFAULT_ALPHA: str
DEFAULT_TOLERANCE: float
DEFAULT_PANELS: int
VERSION: str

class NotConvergedError(RuntimeError):
    """No converged solution: a viscous point, a target lift coefficient, a trim or a takeoff."""

class Airfoil:
    """An airfoil contour in XFOIL order: upper trailing edge → leading edge → lower trailing
    edge."""

    @staticmethod
    def naca(designation: str) -> "Airfoil":
        """A NACA 4- or 5-digit section from XFOIL's generator conventions: ``"2412"``,
        ``"23012"``, ``"NACA 23012"``."""
    @staticmethod
    def named(name: str) -> "Airfoil":
        """What the command line's ``--airfoil`` accepts: ``naca8h12``, ``naca23012``, any
        NACA 4/5-digit name, or the path of a coordinate file."""
    @staticmethod
    def from_file(path: PathLike) -> "Airfoil":
        """A Selig, Lednicer or plain x-y coordinate file."""
    @staticmethod
    def from_coordinates(x: ArrayLike, y: ArrayLike, name: str = "airfoil") -> "Airfoil":
        """A contour from coordinate arrays in XFOIL order, checked like a file's points."""
    @property
    def name(self) -> str:
        """The airfoil's name."""
    @property
    def x(self) -> npt.NDArray[np.float64]:
        """x coordinates (XFOIL order)."""
    @property
    def y(self) -> npt.NDArray[np.float64]:
        """y coordinates (XFOIL order)."""
    @property
    def coordinates(self) -> npt.NDArray[np.float64]:
        """The points as an (n, 2) array of x, y."""
    def paneled(self, panels: int = 160) -> "Airfoil":
        """The nodes the solvers work on: in chord units and repaneled to ``panels`` nodes
        (XFOIL PANE), as ``polar``, ``point`` and ``table`` prepare the airfoil."""
    def to_selig(self) -> str:
        """The contour as Selig-format text (name line, then x y per line)."""
    def with_thickness(self, thickness: float) -> "Airfoil":
        """The section with maximum thickness ``thickness`` (chord units; XFOIL GDES TSET:
        the thickness line scaled, the camber line kept), as ``--thickness``."""
    def with_camber(self, camber: float) -> "Airfoil":
        """The section with maximum camber ``camber`` (chord units, signed; TSET scales the
        camber line and cannot create one), as ``--camber``."""
    def with_te_gap(self, gap: float, blend: float = 1.0) -> "Airfoil":
        """The section with trailing-edge gap ``gap`` (chord units), the change blended over
        ``blend`` of the chord (0…1; XFOIL TGAP), as ``--te-gap``."""
    def with_flap(self, x: float, y: float, deg: float) -> "Airfoil":
        """The section with a plain flap hinged at (``x``, ``y``) in chord units, deflected by
        ``deg`` degrees, positive trailing edge down (XFOIL FLAP), as ``--flap X:Y:DEG``."""
    def blended(self, other: "Airfoil", fraction: float) -> "Airfoil":
        """``1 - fraction`` of this section and ``fraction`` of ``other``, points paired by
        chordwise station on each surface (XFOIL INTX, as XFLR5), as ``--blend``."""
    def thickness_camber(self) -> Dict[str, float]:
        """Maximum thickness and camber and their chordwise positions, as XFOIL's GDES
        measures them: ``{"thickness", "x_thickness", "camber", "x_camber"}``."""
    @property
    def operations(self) -> List[str]:
        """The geometry operations that made this section, in their text form."""
    def __len__(self) -> int: ...

class PolarTable:
    """A table of polars, one per (Re, M) node (the library's ``PolarTable``)."""

    @staticmethod
    def read(
        path: PathLike,
        re: Optional[float] = None,
        mach: Optional[float] = None,
        user_prop: Optional[float] = None,
    ) -> Tuple["PolarTable", List[str]]: ...
    def summary(self) -> List[Dict[str, Any]]: ...
    def write(
        self, path: PathLike, format: Optional[str] = None, c81_re: Optional[float] = None
    ) -> List[str]: ...
    @property
    def re(self) -> npt.NDArray[np.float64]: ...
    @property
    def mach(self) -> npt.NDArray[np.float64]: ...
    @property
    def meta(self) -> Dict[str, Any]: ...
    @property
    def post_stall(self) -> Dict[str, float]: ...
    def with_post_stall(
        self, cd_max: float, cd_reverse: float, vc_min_junction_deg: float
    ) -> "PolarTable": ...
    def polars(self) -> List[Tuple[float, float, Dict[str, np.ndarray]]]: ...
    def polar(
        self, re: float, mach: float
    ) -> Optional[Tuple[float, float, Dict[str, np.ndarray]]]: ...
    def lookup(
        self, alpha: ArrayLike, re: ArrayLike, mach: ArrayLike
    ) -> Tuple[np.ndarray, ...]:
        """(cl, cd, cm, re_clamped, mach_clamped, post_stall, bridged, supercritical,
        supercritical_unknown, massive_separation, separation_unknown)."""
    def alpha_at_cl(
        self, cl: float, re: float, mach: float, alpha_min: float, alpha_max: float
    ) -> Optional[Tuple[float, Dict[str, Any]]]: ...
    @property
    def point_count(self) -> int: ...
    @property
    def converged_count(self) -> int: ...
    @property
    def usable_count(self) -> int: ...
    @property
    def has_lookup(self) -> bool: ...

class Aircraft:
    """A gyroplane preset (rotor, airframe, propeller, takeoff data)."""

    @staticmethod
    def read(path: PathLike) -> "Aircraft": ...
    @staticmethod
    def from_toml(text: str, origin: str = "<string>") -> "Aircraft": ...
    @property
    def name(self) -> str: ...
    @property
    def mass_kg(self) -> float: ...
    def trim(
        self, table: PolarTable, speed_kt: float, mass_kg: Optional[float], altitude_m: float
    ) -> Tuple[str, List[str]]: ...
    def takeoff(
        self, table: PolarTable, mass_kg: Optional[float]
    ) -> Tuple[str, Dict[str, np.ndarray], List[str]]: ...

class Rotor:
    """The rotor of a preset alone."""

    @staticmethod
    def read(path: PathLike) -> "Rotor": ...
    @staticmethod
    def from_toml(text: str, origin: str = "<string>") -> "Rotor": ...
    @property
    def name(self) -> str: ...
    def autorotate(
        self, table: PolarTable, alpha_deg: float, speed_m_s: Optional[float], mu: Optional[float],
        reference_rpm: Optional[float], pitch_deg: Optional[float], altitude_m: float,
    ) -> Tuple[str, List[str]]: ...
    def autorotate_cases(
        self, table: PolarTable, alpha_deg: List[float], speed_m_s: List[float],
        pitch_deg: Optional[float], altitude_m: float,
    ) -> Tuple[str, List[str]]: ...

def alpha_range(text: str) -> npt.NDArray[np.float64]:
    """The α values of the range text ``A0:A1:DA`` (or one value), as the CLI's ``--alpha``."""

def estimate_seconds(points: int, polars: int, threads: int) -> float:
    """Estimated time to solve a table of ``points`` points in ``polars`` polars, in seconds."""

def table(
    airfoil: Airfoil, re: List[float], mach: List[float], alpha: List[float], xtr_top: float,
    xtr_bot: float, ncrit: Tuple[float, Optional[float], Optional[float]], panels: int, tolerance: float, threads: int,
    progress: Optional[Callable[[int, int], object]],
) -> PolarTable: ...
def point(
    airfoil: Airfoil, re: float, mach: float, alpha: Optional[float], cl: Optional[float],
    xtr_top: float, xtr_bot: float, ncrit: Tuple[float, Optional[float], Optional[float]], panels: int, tolerance: float,
) -> Dict[str, Dict[str, np.ndarray]]: ...
def aero(
    airfoil: Airfoil, alpha: List[float], re: List[float], mach: List[float],
    xtr_top: List[float], xtr_bot: List[float],
    ncrit: Tuple[float, Optional[float], Optional[float]], panels: int, tolerance: float,
    threads: int, progress: Optional[Callable[[int, int], object]],
) -> Dict[str, np.ndarray]:
    """The points (α, Re, M, trips) solved as warm-started polars per distinct condition:
    the columns of a polar, one value per point in the order given."""
def polar_figure(
    curves: List[Tuple[PolarTable, float, float]], labels: Optional[List[str]],
    title: Optional[str], cd_axis: str,
) -> str:
    """JSON of the ``polargen plot`` figure of the polars at (re, mach) of each table."""
def rotor_sweep(
    aircraft: Aircraft, table: PolarTable, speeds_kt: List[float], mass_kg: Optional[float]
) -> Tuple[str, List[str]]: ...
def rotor_compare(
    aircraft: Aircraft, clean: PolarTable, contaminated: PolarTable
) -> Tuple[str, List[str]]: ...
def rotor_study(
    kind: str, aircraft: PathLike, airfoil: Optional[str], airfoils: Optional[List[str]],
    trips: Optional[List[float]], ncrits: Optional[List[float]],
    outboard: Optional[List[float]], inboard: Optional[List[float]], xtr: Optional[float],
    speeds_kt: Optional[List[float]], areas_m2: Optional[List[float]],
    out: Optional[PathLike], cache: Optional[PathLike],
) -> Tuple[str, List[str], List[str]]: ...
