"""``aero``: section coefficients at any operating points (NumPy broadcasting, as NeuralFoil's
``get_aero_from_airfoil``), computed by the viscous solver: every distinct condition (Re, M,
trips) is one warm-started polar over its distinct α values, the polars are solved in
parallel with the GIL released, and the results come back in the shape of the inputs."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Dict, Iterator, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _polargen

if TYPE_CHECKING:  # pragma: no cover
    from . import AirfoilLike, Progress

ArrayLike = Union[float, Sequence[float], "np.ndarray"]


class Aero(Mapping[str, np.ndarray]):
    """Per-point results of :func:`aero`, each an array in the broadcast shape of the inputs:
    ``alpha``, ``re``, ``mach`` (the inputs), and every per-point field of a polar (``cl``,
    ``cd``, ``cdp``, ``cdf``, ``cm``, ``xtr_top``, ``xtr_bot``, ``converged``, ``iterations``,
    ``residual``, …, the columns of :class:`Polar`). Coefficients where ``converged`` is False
    are not results. Read as a mapping (``r["cd"]``) or as attributes (``r.cd``)."""

    def __init__(self, columns: Dict[str, np.ndarray]) -> None:
        self.__dict__["_columns"] = columns

    def __getitem__(self, key: str) -> np.ndarray:
        return self._columns[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._columns)

    def __len__(self) -> int:
        return len(self._columns)

    def __getattr__(self, name: str) -> Any:
        try:
            return self.__dict__["_columns"][name]
        except KeyError:
            raise AttributeError(name) from None

    @property
    def shape(self) -> Tuple[int, ...]:
        """The broadcast shape of the inputs."""
        return self._columns["alpha"].shape

    def to_pandas(self) -> Any:
        """One row per point (flattened, in C order) as a ``pandas.DataFrame``."""
        from ._results import _pandas

        return _pandas().DataFrame({k: np.ravel(v) for k, v in self._columns.items()})

    def __repr__(self) -> str:
        converged = int(np.count_nonzero(self._columns["converged"]))
        return f"Aero(shape={self.shape}, {converged}/{self._columns['alpha'].size} converged)"


def _array(name: str, value: ArrayLike) -> np.ndarray:
    if isinstance(value, (str, bytes)):
        raise TypeError(f"{name}: expected numbers, got {type(value).__name__}")
    try:
        return np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{name}: expected a number or an array of numbers") from None


def aero(airfoil: "AirfoilLike", alpha: ArrayLike, re: ArrayLike, mach: ArrayLike = 0.0,
         xtr: Union[ArrayLike, Tuple[ArrayLike, ArrayLike]] = 1.0, ncrit: float = 9.0,
         ncrit_top: Optional[float] = None, ncrit_bot: Optional[float] = None,
         panels: Optional[int] = None, tolerance: Optional[float] = None, threads: int = 0,
         progress: "Progress" = None) -> Aero:
    """Section coefficients at angles ``alpha`` [deg], Reynolds numbers ``re`` and Mach
    numbers ``mach``: scalars or arrays, broadcast against each other (NumPy rules), with
    forced transition ``xtr`` (x/c on both surfaces, scalar or array; a tuple ``(top,
    bottom)`` gives each surface its own, each scalar or array; 1 = free, e^n with
    ``ncrit``).

    Solved by the viscous solver, not a surrogate: the points that share a condition (Re, M
    and trips) form one warm-started polar over their distinct α values — the polar
    ``polar(airfoil, re, mach, alpha=sorted α values, xtr)`` computes, point for point —
    and the polars run in parallel (``threads``, 0 = all cores) with the GIL released.
    ``progress`` as in :func:`table`. Returns an :class:`Aero` of arrays in the broadcast
    shape, in input order; points that did not converge are flagged (``converged``), never
    dropped.

    >>> import numpy as np, polargen as pg
    >>> r = pg.aero("naca2412", alpha=np.linspace(-2, 8, 11), re=1e6)      # doctest: +SKIP
    >>> r.cl, r.cd, r.converged                                           # doctest: +SKIP
    """
    from . import DEFAULT_PANELS, DEFAULT_TOLERANCE, _airfoil, _ncrit, _progress

    if isinstance(xtr, tuple):
        if len(xtr) != 2:
            raise ValueError(f"xtr: a tuple is (top, bottom), got {len(xtr)} values")
        top, bot = _array("xtr", xtr[0]), _array("xtr", xtr[1])
    else:
        top = bot = _array("xtr", xtr)
    arrays = [_array("alpha", alpha), _array("re", re), _array("mach", mach), top, bot]
    try:
        broadcast = np.broadcast_arrays(*arrays)
    except ValueError:
        shapes = ", ".join(f"{n} {a.shape}" for n, a in
                           zip(("alpha", "re", "mach", "xtr_top", "xtr_bot"), arrays))
        raise ValueError(f"alpha, re, mach and xtr do not broadcast together: {shapes}") from None
    shape = broadcast[0].shape
    flat = [np.ascontiguousarray(a).reshape(-1).tolist() for a in broadcast]
    columns = _polargen.aero(
        _airfoil(airfoil), *flat, _ncrit(ncrit, ncrit_top, ncrit_bot),
        int(DEFAULT_PANELS if panels is None else panels),
        float(DEFAULT_TOLERANCE if tolerance is None else tolerance), int(threads),
        _progress(progress),
    )
    result = {"alpha": broadcast[0].reshape(shape).copy(), "re": broadcast[1].reshape(shape).copy(),
              "mach": broadcast[2].reshape(shape).copy()}
    for name, values in columns.items():
        if name != "alpha":
            result[name] = np.asarray(values).reshape(shape)
    return Aero(result)
