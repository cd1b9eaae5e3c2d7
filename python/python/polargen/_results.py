"""Result classes: a polar (:class:`Polar`), an operating point with its distributions
(:class:`Point`, :class:`Distribution`) and the result of table lookups (:class:`Lookup`).
Columns are NumPy arrays; ``to_pandas()`` gives a DataFrame when pandas is installed (it is
not a dependency of polargen)."""

from __future__ import annotations

from typing import Any, Dict, Optional

import numpy as np

POLAR_COLUMNS = (
    "alpha", "cl", "cd", "cdp", "cdf", "cm", "xtr_top", "xtr_bot", "converged",
    "iterations", "residual", "cpmin", "supercritical", "xsep_top", "xsep_bot",
    "massive_separation",
)
# Flags a table may not know (an empty CSV field): the core gives them as int8, −1 unknown.
FLAG_COLUMNS = ("supercritical", "massive_separation")
STATION_COLUMNS = (
    "s", "x", "y", "ue", "cp", "dstar", "theta", "cf", "h", "hk", "n_or_ctau", "turbulent",
)
LOOKUP_COLUMNS = (
    "cl", "cd", "cm", "re_clamped", "mach_clamped", "post_stall", "bridged", "supercritical",
    "supercritical_unknown", "massive_separation", "separation_unknown",
)


def _pandas():
    try:
        import pandas
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError("to_pandas() needs pandas: pip install pandas") from e
    return pandas


class Polar:
    """One polar at (``re``, ``mach``): NumPy columns in the order of the requested α.

    Columns (those of the CSV table): ``alpha`` [deg], ``cl``, ``cd`` (Squire–Young), ``cdp``
    (= cd − cdf), ``cdf`` (skin friction), ``cm`` (c/4), ``xtr_top``, ``xtr_bot`` (transition
    x/c), ``converged`` (bool), ``iterations``, ``residual``, ``cpmin`` (Karman–Tsien minimum
    Cp), ``supercritical`` (bool: Cp_min < Cp*, locally supersonic), ``xsep_top``,
    ``xsep_bot`` (x/c where the reversed flow reaching the trailing edge starts; 1 attached)
    and ``massive_separation`` (bool: separation ahead of mid-chord, outside the method's
    validity). Coefficients of points with ``converged == False`` are not results, nor those
    of points in massive separation: ``usable`` (``converged & ~massive_separation``) marks
    the points lookups use. A flag the table does not know (a file written without it) reads
    as False in the array; :meth:`unknown` gives the mask and ``to_pandas()`` shows it as
    ``<NA>``. ``meta`` holds the table metadata (airfoil, ncrit — None when ncrit_top and
    ncrit_bot differ —, trips, panels, solver).
    """

    alpha: np.ndarray
    cl: np.ndarray
    cd: np.ndarray
    cdp: np.ndarray
    cdf: np.ndarray
    cm: np.ndarray
    xtr_top: np.ndarray
    xtr_bot: np.ndarray
    converged: np.ndarray
    iterations: np.ndarray
    residual: np.ndarray
    cpmin: np.ndarray
    supercritical: np.ndarray
    xsep_top: np.ndarray
    xsep_bot: np.ndarray
    massive_separation: np.ndarray
    #: The core table the polar belongs to (set by :class:`Table`; used by :meth:`plot`).
    _table: Any = None

    def __init__(self, re: float, mach: float, columns: Dict[str, np.ndarray],
                 meta: Dict[str, Any]) -> None:
        self.re = re
        self.mach = mach
        self.meta = meta
        self._unknown: Dict[str, np.ndarray] = {}
        for name in POLAR_COLUMNS:
            value = columns[name]
            if name in FLAG_COLUMNS:
                coded = np.asarray(value)
                self._unknown[name] = coded < 0
                value = coded > 0
            setattr(self, name, value)
        self._summary = dict(columns.get("summary") or {})

    @property
    def usable(self) -> np.ndarray:
        """The points whose coefficients are results (those lookups use): converged and not
        in massive separation."""
        return self.converged & ~self.massive_separation

    def unknown(self, flag: str) -> np.ndarray:
        """Where the table does not know the flag ``"supercritical"`` or
        ``"massive_separation"`` (its array reads False there)."""
        return self._unknown[flag]

    def __len__(self) -> int:
        return len(self.alpha)

    def __repr__(self) -> str:
        return (f"Polar({self.meta.get('airfoil')!r}, re={self.re:g}, mach={self.mach:g}, "
                f"{int(self.converged.sum())}/{len(self)} converged)")

    def columns(self) -> Dict[str, np.ndarray]:
        """The columns as a dict of arrays."""
        return {name: getattr(self, name) for name in POLAR_COLUMNS}

    def summary(self) -> Dict[str, Any]:
        """What ``polargen summary`` prints for this polar: ``points``, ``trusted`` (converged
        and not supercritical), ``alpha_trusted_min``/``max`` (the run of trusted points
        around zero lift), ``alpha_zero_lift``, ``lift_slope`` [1/rad] and the α range it was
        fitted on (``lift_slope_alpha_min``/``max``), ``cl_max``, ``alpha_cl_max``,
        ``cl_max_at_edge`` (the stall peak was not reached by trusted points), ``cl_min``,
        ``alpha_cl_min``, ``cd_min``, ``cl_at_cd_min``, ``ld_max``, ``alpha_ld_max``,
        ``cm0``; None where the polar cannot give a number. Angles in degrees."""
        return dict(self._summary)

    def to_pandas(self):
        """The columns as a ``pandas.DataFrame`` (with ``re`` and ``mach`` columns); the
        flags a table may not know are nullable booleans (``<NA>`` where unknown)."""
        pandas = _pandas()
        frame = pandas.DataFrame(self.columns())
        for name in FLAG_COLUMNS:
            frame[name] = pandas.array(
                [None if u else bool(v) for v, u in zip(getattr(self, name), self._unknown[name])],
                dtype="boolean")
        frame.insert(0, "mach", self.mach)
        frame.insert(0, "re", self.re)
        return frame

    def plot(self, label: Optional[str] = None, title: Optional[str] = None,
             cd_axis: Any = "auto", fig: Any = None):
        """This polar drawn as ``polargen plot`` draws it, with matplotlib
        (:func:`polargen.plot.polars`); returns the matplotlib figure."""
        from . import plot

        return plot.polars([self], None if label is None else [label], title, cd_axis, fig)


class Distribution:
    """Boundary-layer stations of one surface (stagnation point → trailing edge) or of the
    wake (trailing edge → end): ``s`` (ξ, arc length from the stagnation point), ``x``, ``y``,
    ``ue`` (Ue/V∞), ``cp`` (Karman–Tsien), ``dstar`` (δ*), ``theta`` (θ), ``cf`` (τw/½ρ∞V∞²),
    ``h``, ``hk``, ``n_or_ctau`` (N where laminar, Cτ where turbulent), ``turbulent``."""

    s: np.ndarray
    x: np.ndarray
    y: np.ndarray
    ue: np.ndarray
    cp: np.ndarray
    dstar: np.ndarray
    theta: np.ndarray
    cf: np.ndarray
    h: np.ndarray
    hk: np.ndarray
    n_or_ctau: np.ndarray
    turbulent: np.ndarray

    def __init__(self, columns: Dict[str, np.ndarray]) -> None:
        for name in STATION_COLUMNS:
            setattr(self, name, columns[name])

    def __len__(self) -> int:
        return len(self.x)

    def columns(self) -> Dict[str, np.ndarray]:
        """The columns as a dict of arrays."""
        return {name: getattr(self, name) for name in STATION_COLUMNS}

    def to_pandas(self):
        """The stations as a ``pandas.DataFrame``."""
        return _pandas().DataFrame(self.columns())


class Point:
    """One converged operating point: the coefficients (``alpha``, ``cl``, ``cd``, ``cdp``,
    ``cdf``, ``cm``, ``xtr_top``, ``xtr_bot``, ``iterations``, ``residual``), ``cpmin`` and
    ``supercritical``, ``xsep_top``, ``xsep_bot`` and ``massive_separation`` (as
    :class:`Polar`: a point in massive separation converged, but its coefficients are outside
    the method's validity) and the distributions ``upper``, ``lower`` and ``wake``
    (:class:`Distribution`)."""

    def __init__(self, re: float, mach: float, result: Dict[str, Any]) -> None:
        self.re = re
        self.mach = mach
        point = result["point"]
        self.alpha: float = float(point["alpha"][0])
        self.cl: float = float(point["cl"][0])
        self.cd: float = float(point["cd"][0])
        self.cdp: float = float(point["cdp"][0])
        self.cdf: float = float(point["cdf"][0])
        self.cm: float = float(point["cm"][0])
        self.xtr_top: float = float(point["xtr_top"][0])
        self.xtr_bot: float = float(point["xtr_bot"][0])
        self.converged: bool = bool(point["converged"][0])
        self.iterations: int = int(point["iterations"][0])
        self.residual: float = float(point["residual"][0])
        self.cpmin: float = float(point["cpmin"][0])
        self.supercritical: bool = bool(point["supercritical"][0] > 0)
        self.xsep_top: float = float(point["xsep_top"][0])
        self.xsep_bot: float = float(point["xsep_bot"][0])
        self.massive_separation: bool = bool(point["massive_separation"][0] > 0)
        self.upper = Distribution(result["upper"])
        self.lower = Distribution(result["lower"])
        self.wake = Distribution(result["wake"])

    def __repr__(self) -> str:
        return (f"Point(re={self.re:g}, mach={self.mach:g}, alpha={self.alpha:.4f}, "
                f"cl={self.cl:.4f}, cd={self.cd:.5f}, cm={self.cm:.4f})")

    def to_pandas(self):
        """Every station as one ``pandas.DataFrame`` with a ``surface`` column (``upper``,
        ``lower``, ``wake``): the rows of ``polargen plot-point --csv``."""
        pandas = _pandas()
        frames = []
        for surface in ("upper", "lower", "wake"):
            frame = getattr(self, surface).to_pandas()
            frame.insert(0, "surface", surface)
            frames.append(frame)
        return pandas.concat(frames, ignore_index=True)


class Lookup:
    """Section coefficients from table lookups, in the broadcast shape of (α, Re, M):
    ``cl``, ``cd``, ``cm`` and the flags ``re_clamped``, ``mach_clamped`` (outside the table's
    axis, edge value used), ``post_stall`` (from the 360° extension), ``bridged``
    (interpolated across unconverged points or points in massive separation, or from a
    neighbouring polar), ``supercritical`` (a table point it leans on is supercritical),
    ``supercritical_unknown`` (one does not say), ``massive_separation`` (the table's points
    at this α are in massive separation and were not used: the extension or a bridge stands
    in) and ``separation_unknown`` (a point it leans on does not say)."""

    cl: np.ndarray
    cd: np.ndarray
    cm: np.ndarray
    re_clamped: np.ndarray
    mach_clamped: np.ndarray
    post_stall: np.ndarray
    bridged: np.ndarray
    supercritical: np.ndarray
    supercritical_unknown: np.ndarray
    massive_separation: np.ndarray
    separation_unknown: np.ndarray

    def __init__(self, columns: Dict[str, np.ndarray], shape: Optional[tuple] = None) -> None:
        for name in LOOKUP_COLUMNS:
            value = np.asarray(columns[name])
            setattr(self, name, value.reshape(shape) if shape is not None else value)

    def columns(self) -> Dict[str, np.ndarray]:
        """The columns as a dict of arrays."""
        return {name: getattr(self, name) for name in LOOKUP_COLUMNS}

    def to_pandas(self):
        """The lookups (flattened) as a ``pandas.DataFrame``."""
        return _pandas().DataFrame({k: np.ravel(v) for k, v in self.columns().items()})

    def __repr__(self) -> str:
        return f"Lookup(shape={self.cl.shape})"
