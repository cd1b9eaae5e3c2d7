"""Result classes: a polar (:class:`Polar`), an operating point with its distributions
(:class:`Point`, :class:`Distribution`) and the result of table lookups (:class:`Lookup`).
Columns are NumPy arrays; ``to_pandas()`` gives a DataFrame when pandas is installed (it is
not a dependency of polargen)."""

from __future__ import annotations

from typing import Any, Dict, Optional

import numpy as np

POLAR_COLUMNS = (
    "alpha", "cl", "cd", "cdp", "cdf", "cm", "xtr_top", "xtr_bot", "converged",
    "iterations", "residual",
)
STATION_COLUMNS = (
    "s", "x", "y", "ue", "cp", "dstar", "theta", "cf", "h", "hk", "n_or_ctau", "turbulent",
)
LOOKUP_COLUMNS = ("cl", "cd", "cm", "re_clamped", "mach_clamped", "post_stall", "bridged")


def _pandas():
    try:
        import pandas
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError("to_pandas() needs pandas: pip install pandas") from e
    return pandas


class Polar:
    """One polar at (``re``, ``mach``): NumPy columns in the order of the requested α.

    Columns: ``alpha`` [deg], ``cl``, ``cd`` (Squire–Young), ``cdp`` (= cd − cdf), ``cdf``
    (skin friction), ``cm`` (c/4), ``xtr_top``, ``xtr_bot`` (transition x/c), ``converged``
    (bool), ``iterations``, ``residual``. Coefficients of points with ``converged == False``
    are not results. ``meta`` holds the table metadata (airfoil, ncrit — None when
    ncrit_top and ncrit_bot differ —, trips, panels, solver).
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
    #: The core table the polar belongs to (set by :class:`Table`; used by :meth:`plot`).
    _table: Any = None

    def __init__(self, re: float, mach: float, columns: Dict[str, np.ndarray],
                 meta: Dict[str, Any]) -> None:
        self.re = re
        self.mach = mach
        self.meta = meta
        for name in POLAR_COLUMNS:
            setattr(self, name, columns[name])

    def __len__(self) -> int:
        return len(self.alpha)

    def __repr__(self) -> str:
        return (f"Polar({self.meta.get('airfoil')!r}, re={self.re:g}, mach={self.mach:g}, "
                f"{int(self.converged.sum())}/{len(self)} converged)")

    def columns(self) -> Dict[str, np.ndarray]:
        """The columns as a dict of arrays."""
        return {name: getattr(self, name) for name in POLAR_COLUMNS}

    def to_pandas(self):
        """The columns as a ``pandas.DataFrame`` (with ``re`` and ``mach`` columns)."""
        frame = _pandas().DataFrame(self.columns())
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
    ``cdf``, ``cm``, ``xtr_top``, ``xtr_bot``, ``iterations``, ``residual``) and the
    distributions ``upper``, ``lower`` and ``wake`` (:class:`Distribution`)."""

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
    axis, edge value used), ``post_stall`` (from the 360° extension) and ``bridged``
    (interpolated across unconverged points, or from a neighbouring polar)."""

    cl: np.ndarray
    cd: np.ndarray
    cm: np.ndarray
    re_clamped: np.ndarray
    mach_clamped: np.ndarray
    post_stall: np.ndarray
    bridged: np.ndarray

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
