"""polargen — airfoil polars, Re × Mach × α tables and a gyroplane rotor model.

A thin Python layer over the polargen Rust library (an XFOIL-class viscous–inviscid solver):
the same computations as the ``polargen`` and ``gyro`` command-line tools, bit for bit, with
NumPy arrays in and out.

>>> import polargen as pg
>>> foil = pg.Airfoil.naca("23012")
>>> pol = pg.polar(foil, re=1.9e6, mach=0.41, alpha="-4:12:0.5", xtr=0.07)
>>> pol.cd[pol.usable]                                      # doctest: +SKIP

* :class:`Airfoil` — ``naca``, ``named`` (what ``--airfoil`` accepts), ``from_file``,
  ``from_coordinates``; ``coordinates``, ``x``, ``y``.
* :func:`polar` — one polar (:class:`Polar`: NumPy columns, ``to_pandas()``).
* :func:`aero` — the coefficients at any points (α, Re, M, trips as NumPy arrays,
  broadcast), solved as warm-started polars in parallel (:class:`Aero`).
* :mod:`polargen.plot` — the figures of ``polargen plot`` with matplotlib
  (``Polar.plot()``, ``plot.polars([...])``).
* :func:`point` — one operating point at α or at a target Cl with its surface and wake
  distributions (:class:`Point`).
* :func:`table` — a Re × M × α table (:class:`Table`) with progress (plain lines on stderr
  by default, :class:`PlainProgress`, or a callback);
  :meth:`Table.read`, :meth:`Table.write` in every CLI format; :meth:`Table.lookup`
  vectorised, with the clamping/bridging/post-stall flags and the 360° extension.
* :mod:`polargen.rotor` — the gyroplane: ``Aircraft.read``, ``trim``, ``takeoff``,
  ``sweep`` (trims over an array of speeds), ``compare`` (against the paper) and ``study``
  (``gyro study …``); ``Rotor.read``, ``autorotate`` (the rotor alone in a tunnel); with the
  fields of the ``gyro … --json`` output, as records or DataFrames.

Errors are exceptions with the command-line tools' one-line messages: ``ValueError`` for bad
input, ``OSError`` (``FileNotFoundError``, …) for files, :class:`NotConvergedError` when a
computation finds no solution. The solver runs with the GIL released.
"""

from __future__ import annotations

import os
import sys
import time
from typing import Callable, Optional, Sequence, TextIO, Tuple, Union

import numpy as np

from . import _polargen
from ._polargen import Airfoil, NotConvergedError
from ._aero import Aero, aero
from ._results import Distribution, Lookup, Point, Polar
from ._table import Table

__all__ = [
    "Aero",
    "Airfoil",
    "Distribution",
    "Lookup",
    "NotConvergedError",
    "PlainProgress",
    "Point",
    "Polar",
    "Table",
    "aero",
    "alpha_range",
    "point",
    "polar",
    "plot",
    "rotor",
    "table",
    "DEFAULT_ALPHA",
    "DEFAULT_MACH",
    "DEFAULT_PANELS",
    "DEFAULT_RE",
    "DEFAULT_TOLERANCE",
]

__version__: str = _polargen.VERSION

#: Reynolds numbers of the default rotor grid (``polargen`` without ``--re``).
DEFAULT_RE: Tuple[float, ...] = tuple(_polargen.DEFAULT_RE)
#: Mach numbers of the default rotor grid.
DEFAULT_MACH: Tuple[float, ...] = tuple(_polargen.DEFAULT_MACH)
#: α range of the default rotor grid, ``A0:A1:DA`` in degrees.
DEFAULT_ALPHA: str = _polargen.DEFAULT_ALPHA
#: Newton threshold of the viscous solver (the CLI's ``--tolerance`` default).
DEFAULT_TOLERANCE: float = _polargen.DEFAULT_TOLERANCE
#: Panel nodes after repaneling (the CLI's ``--panels`` default, XFOIL's 160).
DEFAULT_PANELS: int = _polargen.DEFAULT_PANELS

AirfoilLike = Union[Airfoil, str, "os.PathLike[str]"]
AlphaLike = Union[str, float, Sequence[float], np.ndarray]
Transition = Union[float, Tuple[float, float]]
Progress = Union[Callable[[int, int], object], object, str, None]


def alpha_range(text: str) -> np.ndarray:
    """The α values of ``"A0:A1:DA"`` (inclusive) or ``"A"``, as the CLI's ``--alpha``."""
    return _polargen.alpha_range(text)


def _airfoil(airfoil: AirfoilLike) -> Airfoil:
    if isinstance(airfoil, Airfoil):
        return airfoil
    if isinstance(airfoil, (str, os.PathLike)):
        return Airfoil.named(os.fspath(airfoil))
    raise TypeError(
        f"airfoil: expected an Airfoil, a name or a path, got {type(airfoil).__name__}"
    )


def _alphas(alpha: AlphaLike) -> list:
    if isinstance(alpha, str):
        return _polargen.alpha_range(alpha).tolist()
    values = np.asarray(alpha, dtype=float)
    if values.ndim > 1:
        raise ValueError(f"alpha: expected a 1-D list of angles, got shape {values.shape}")
    return values.reshape(-1).tolist()


def _axis(name: str, values: Union[float, Sequence[float], np.ndarray]) -> list:
    array = np.asarray(values, dtype=float)
    if array.ndim > 1:
        raise ValueError(f"{name}: expected a 1-D list, got shape {array.shape}")
    return array.reshape(-1).tolist()


def _scalar(name: str, value: object, several: str) -> float:
    """``value`` as one number; a list, an array or text names the argument and says where
    several values go (``several``)."""
    if isinstance(value, (str, bytes)):
        raise TypeError(f"{name}: expected one number, got {type(value).__name__}")
    if np.ndim(value) != 0:
        raise TypeError(f"{name}: expected one number, got {type(value).__name__} of "
                        f"{np.size(value)} values; {several}")
    try:
        return float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise TypeError(f"{name}: expected a number, got {type(value).__name__}") from None


_SEVERAL = "for several values use pg.table(...) (a Re x M grid) or pg.aero(...) (any points)"


def _transition(xtr: Transition) -> Tuple[float, float]:
    if isinstance(xtr, (tuple, list)):
        if len(xtr) != 2:
            raise ValueError(f"xtr: expected one value or (top, bottom), got {len(xtr)} values")
        return (_scalar("xtr", xtr[0], "give (top, bottom)"),
                _scalar("xtr", xtr[1], "give (top, bottom)"))
    value = _scalar("xtr", xtr, "give one value or (top, bottom); pg.aero takes arrays")
    return value, value


class PlainProgress:
    """Progress as plain lines on a stream (``sys.stderr``), as the command-line tools print it
    when stderr is not a terminal: the work and an estimate when it starts, then
    ``done/total points, elapsed …, about … left`` at most every ``interval`` seconds. The
    default ``progress`` of :func:`table`; call it with ``(done, total)``."""

    def __init__(self, what: str, polars: int, threads: int = 0, interval: float = 15.0,
                 stream: Optional[TextIO] = None) -> None:
        self.what, self.polars, self.threads, self.interval = what, polars, threads, interval
        self.stream = stream
        self.start: Optional[float] = None
        self.last = 0.0

    def _say(self, text: str) -> None:
        stream = self.stream if self.stream is not None else sys.stderr
        try:
            print(f"polargen: {text}", file=stream, flush=True)
        except (OSError, ValueError):
            pass  # progress is best-effort: a closed or full stream costs no result

    def __call__(self, done: int, total: int) -> None:
        now = time.monotonic()
        if self.start is None:
            self.start = self.last = now
            estimate = _polargen.estimate_seconds(total, self.polars, self.threads)
            about = "under 1 s" if estimate < 1.0 else f"about {_duration(estimate)}"
            self._say(f"{self.what}: {total} points, {about}")
            return
        if done < total and now - self.last >= self.interval:
            self.last = now
            elapsed = now - self.start
            line = f"{done}/{total} points, elapsed {_duration(elapsed)}"
            if done > 0:
                line += f", about {_duration(elapsed * (total - done) / done)} left"
            self._say(line)


def _duration(seconds: float) -> str:
    """A duration in words, as the command-line tools write it: ``12 s``, ``3 min 05 s``."""
    s = int(round(max(seconds, 0.0)))
    if s < 60:
        return f"{s} s"
    if s < 3600:
        return f"{s // 60} min {s % 60:02d} s"
    return f"{s // 3600} h {(s % 3600) // 60:02d} min"


def _progress(progress: Progress, what: str = "table", polars: int = 1,
              threads: int = 0) -> Optional[Callable[[int, int], object]]:
    """A callback ``(done, total)``: ``"lines"`` makes a :class:`PlainProgress`; a
    tqdm-like object (``update(n)``) gets one made for it; ``None`` reports nothing."""
    if progress is None:
        return None
    if isinstance(progress, str):
        if progress != "lines":
            raise ValueError(f"progress: expected \"lines\", None, a callable or a tqdm-like "
                             f"object, got {progress!r}")
        return PlainProgress(what, polars, threads)
    update = getattr(progress, "update", None)
    if callable(update):
        last = [0]

        def forward(done: int, total: int) -> None:
            if getattr(progress, "total", None) != total:
                try:
                    progress.total = total
                except AttributeError:
                    pass
            update(done - last[0])
            last[0] = done

        return forward
    if callable(progress):
        return progress
    raise TypeError("progress: expected a callable (done, total) or an object with update(n)")


def _ncrit(ncrit: float, top: Optional[float], bot: Optional[float]):
    """The (ncrit, ncrit_top, ncrit_bot) argument of the extension."""
    return (float(ncrit), None if top is None else float(top), None if bot is None else float(bot))


def polar(
    airfoil: AirfoilLike,
    re: float,
    mach: float = 0.0,
    alpha: AlphaLike = DEFAULT_ALPHA,
    xtr: Transition = 1.0,
    ncrit: float = 9.0,
    ncrit_top: Optional[float] = None,
    ncrit_bot: Optional[float] = None,
    panels: int = DEFAULT_PANELS,
    tolerance: float = DEFAULT_TOLERANCE,
    threads: int = 0,
) -> Polar:
    """One viscous polar at Reynolds number ``re`` and Mach number ``mach``.

    Computed exactly as ``polargen --airfoil … --re RE --mach M --alpha …`` computes it: the
    airfoil in chord units, repaneled to ``panels`` nodes, a warm-started sweep from the α
    nearest 0° up and down with recovery of failed points. Points that did not converge are
    kept with ``converged == False``, points that converged in massive separation with
    ``massive_separation == True``: the coefficients of either are not results
    (``Polar.usable`` marks those that are).

    Parameters
    ----------
    airfoil : Airfoil, or a name / path as ``--airfoil`` accepts (``"naca8h12"``, ``"naca23012"``).
    re : chord Reynolds number.
    mach : free-stream Mach number, 0 ≤ M < 1 (Karman–Tsien).
    alpha : angles of attack [deg]: ``"A0:A1:DA"`` or a list/array.
    xtr : forced transition x/c on both surfaces, or ``(top, bottom)``, along the chord line from
        the leading edge; 0 = leading edge, 1 = free (e^n).
    ncrit : critical amplification ratio N of the e^n criterion, both surfaces.
    ncrit_top, ncrit_bot : N_crit of the upper / lower surface (XFOIL ``NT``, ``NB``) if it
        differs from ``ncrit``, as ``--ncrit-top``, ``--ncrit-bot``.
    panels : panel nodes after repaneling.
    tolerance : Newton threshold on the RMS relative change.
    threads : worker threads (0 = all cores); the result does not depend on it.
    """
    top, bot = _transition(xtr)
    result = _polargen.table(
        _airfoil(airfoil), [_scalar("re", re, _SEVERAL)], [_scalar("mach", mach, _SEVERAL)],
        _alphas(alpha), top, bot,
        _ncrit(ncrit, ncrit_top, ncrit_bot), int(panels), float(tolerance), int(threads), None,
    )
    return Table(result).polars()[0]


def point(
    airfoil: AirfoilLike,
    re: float,
    mach: float = 0.0,
    alpha: Optional[float] = None,
    cl: Optional[float] = None,
    xtr: Transition = 1.0,
    ncrit: float = 9.0,
    ncrit_top: Optional[float] = None,
    ncrit_bot: Optional[float] = None,
    panels: int = DEFAULT_PANELS,
    tolerance: float = DEFAULT_TOLERANCE,
) -> Point:
    """One operating point at angle ``alpha`` [deg] or at lift coefficient ``cl`` (give one),
    with the distributions of both surfaces and the wake (x, y, Cp, Ue, δ*, θ, Cf, H, N or Cτ).

    Solved as ``polargen plot-point`` solves it: at α one solve from a fresh start; at Cl a
    secant search on α with warm starts (XFOIL's ``CL`` command). A point that does not
    converge raises :class:`NotConvergedError`.
    """
    top, bot = _transition(xtr)
    several = "pg.point solves one operating point; use pg.polar or pg.aero for several"
    result = _polargen.point(
        _airfoil(airfoil), _scalar("re", re, several), _scalar("mach", mach, several),
        None if alpha is None else _scalar("alpha", alpha, several),
        None if cl is None else _scalar("cl", cl, several),
        top, bot, _ncrit(ncrit, ncrit_top, ncrit_bot), int(panels), float(tolerance),
    )
    return Point(float(re), float(mach), result)


def table(
    airfoil: AirfoilLike,
    re: Union[float, Sequence[float], np.ndarray] = DEFAULT_RE,
    mach: Union[float, Sequence[float], np.ndarray] = DEFAULT_MACH,
    alpha: AlphaLike = DEFAULT_ALPHA,
    xtr: Transition = 1.0,
    ncrit: float = 9.0,
    ncrit_top: Optional[float] = None,
    ncrit_bot: Optional[float] = None,
    panels: int = DEFAULT_PANELS,
    tolerance: float = DEFAULT_TOLERANCE,
    threads: int = 0,
    progress: Progress = "lines",
) -> Table:
    """A Re × M × α table (default: the rotor grid of ``polargen`` without ``--re``/``--mach``).

    The polars are solved in parallel with the GIL released; other Python threads run
    meanwhile. ``progress`` is a callable ``progress(done_points, total_points)`` or a
    tqdm-like object (its ``update(n)`` is called), called on the calling thread when the
    build starts (``done`` 0) and as polars finish; the default ``"lines"`` prints the work
    with an estimate, then a line every 15 s on ``sys.stderr`` (:class:`PlainProgress`);
    ``None`` prints nothing. Ctrl-C (or an exception from ``progress``) stops the build once
    the polars under way have finished.
    """
    top, bot = _transition(xtr)
    foil = _airfoil(airfoil)
    res, machs = _axis("re", re), _axis("mach", mach)
    polars = len(res) * len(machs)
    what = f"{polars} polar{'' if polars == 1 else 's'} of {foil.name}"
    result = _polargen.table(
        foil, res, machs, _alphas(alpha), top, bot,
        _ncrit(ncrit, ncrit_top, ncrit_bot), int(panels), float(tolerance), int(threads),
        _progress(progress, what, polars, int(threads)),
    )
    return Table(result)


from . import plot, rotor  # noqa: E402  (they use Table and Polar)
