"""The Re × M × α table: files in every format of the CLI, its polars, vectorised lookups."""

from __future__ import annotations

import os
from typing import Any, Dict, List, Optional, Tuple, Union

import numpy as np

from . import _polargen
from ._results import Lookup, Polar

PathLike = Union[str, "os.PathLike[str]"]


class Table:
    """A table of polars, one per (Re, M) node, as ``polargen`` writes and reads it.

    Lookups (:meth:`lookup`) interpolate like the rotor model: monotone cubic (PCHIP) in α over
    the converged points, linear in ln Re and in M between polars, the edge value outside the
    Re and Mach axes (flagged), and beyond the converged α range the 360° extension
    (Viterna–Corrigan to ±90°, a flat plate beyond; flagged ``post_stall``).
    """

    def __init__(self, core: "_polargen.PolarTable") -> None:
        self._core = core

    @classmethod
    def read(cls, path: PathLike) -> "Table":
        """Reads a table file as ``polargen convert`` does, recognising the layout: polargen
        CSV or JSON, an XFOIL polar file (``.pol``), a C81 deck or a single-polar CSV
        (columns alpha, cl, cd, …)."""
        return cls(_polargen.PolarTable.read(os.fspath(path)))

    def write(self, path: PathLike, format: Optional[str] = None,
              c81_re: Optional[float] = None) -> List[str]:
        """Writes the table as ``polargen convert`` does: ``format`` ``"csv"``, ``"json"``,
        ``"xfoil"`` (one ``.pol`` per node), ``"c81"`` (one file per Re, or only at
        ``c81_re``) or ``"aerodyn"`` (OpenFAST AeroDyn airfoil files); from the extension of
        ``path`` when None. Files are written atomically; returns the paths written."""
        written = self._core.write(os.fspath(path), format, c81_re)
        return [os.fspath(p) for p in written]

    @property
    def re(self) -> np.ndarray:
        """Reynolds-number axis (strictly increasing)."""
        return self._core.re

    @property
    def mach(self) -> np.ndarray:
        """Mach-number axis (strictly increasing)."""
        return self._core.mach

    @property
    def meta(self) -> Dict[str, Any]:
        """How the table was made: airfoil, ncrit (None when the
        surfaces differ), ncrit_top, ncrit_bot, xtr_top_set, xtr_bot_set, panels, solver."""
        return self._core.meta

    @property
    def post_stall(self) -> Dict[str, float]:
        """Parameters of the 360° extension: cd_max, cd_reverse, vc_min_junction_deg."""
        return self._core.post_stall

    def with_post_stall(self, cd_max: Optional[float] = None,
                        cd_reverse: Optional[float] = None,
                        vc_min_junction_deg: Optional[float] = None) -> "Table":
        """The same table with other 360°-extension parameters (unchanged where None)."""
        p = self.post_stall
        return Table(self._core.with_post_stall(
            p["cd_max"] if cd_max is None else float(cd_max),
            p["cd_reverse"] if cd_reverse is None else float(cd_reverse),
            p["vc_min_junction_deg"] if vc_min_junction_deg is None
            else float(vc_min_junction_deg),
        ))

    @property
    def point_count(self) -> int:
        """Number of points, converged or not."""
        return self._core.point_count

    @property
    def converged_count(self) -> int:
        """Number of converged points."""
        return self._core.converged_count

    @property
    def has_lookup(self) -> bool:
        """Whether lookups are possible (some polar has two converged points)."""
        return self._core.has_lookup

    def polars(self) -> List[Polar]:
        """Every polar, Re-major (``index = i_re·len(mach) + i_mach``)."""
        meta = self.meta
        return [self._polar(re, mach, columns, meta)
                for re, mach, columns in self._core.polars()]

    def _polar(self, re: float, mach: float, columns: Dict[str, np.ndarray],
               meta: Dict[str, Any]) -> Polar:
        """A polar of this table that knows its table (for :meth:`Polar.plot`)."""
        polar = Polar(re, mach, columns, meta)
        polar._table = self._core
        return polar

    def polar(self, re: float, mach: float) -> Polar:
        """The polar at the node (``re``, ``mach``) (relative tolerance 1e-9)."""
        found = self._core.polar(float(re), float(mach))
        if found is None:
            axis = lambda values: ", ".join(f"{v:g}" for v in values)  # noqa: E731
            raise KeyError(f"no polar at Re {re:g}, M {mach:g} (axes: Re {axis(self.re)}; "
                           f"M {axis(self.mach)})")
        return self._polar(*found, self.meta)

    def lookup(self, alpha, re, mach) -> Lookup:
        """Section coefficients at angles ``alpha`` [deg] (any value, wrapped to ±180°),
        Reynolds numbers ``re`` and Mach numbers ``mach``: scalars or arrays, broadcast
        against each other (NumPy rules). A table without two converged points in any polar
        gives NaN."""
        a, r, m = np.broadcast_arrays(
            np.asarray(alpha, dtype=float), np.asarray(re, dtype=float),
            np.asarray(mach, dtype=float))
        shape = a.shape
        flat = [np.ascontiguousarray(v).reshape(-1) for v in (a, r, m)]
        columns = self._core.lookup(*flat)
        return Lookup(dict(zip(("cl", "cd", "cm", "re_clamped", "mach_clamped", "post_stall",
                                "bridged"), columns)), shape)

    def alpha_at_cl(self, cl: float, re: float, mach: float, alpha_min: float = -10.0,
                    alpha_max: float = 20.0) -> Optional[Tuple[float, Dict[str, Any]]]:
        """The smallest α in [alpha_min, alpha_max] at which the looked-up lift coefficient
        rises through ``cl`` (the attached branch; the paper's Table 5 reads Cd at Cl = 0.8
        this way), with the lookup there; None when Cl stays on one side of ``cl``."""
        return self._core.alpha_at_cl(float(cl), float(re), float(mach), float(alpha_min),
                                      float(alpha_max))

    def to_pandas(self):
        """Every point as one ``pandas.DataFrame`` (columns ``re``, ``mach`` and the polar
        columns), Re-major like the CSV file."""
        from ._results import _pandas

        pandas = _pandas()
        return pandas.concat([p.to_pandas() for p in self.polars()], ignore_index=True)

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Table):
            return NotImplemented
        return self._core == other._core

    def __repr__(self) -> str:
        return (f"Table({self.meta['airfoil']!r}, {len(self.re)} Re x {len(self.mach)} M, "
                f"{self.converged_count}/{self.point_count} converged)")
