"""The Re × M × α table: files in every format of the CLI, its polars, vectorised lookups."""

from __future__ import annotations

import os
import warnings
from typing import Any, Dict, List, Optional, Tuple, Union

import numpy as np

from . import _polargen
from ._results import LOOKUP_COLUMNS, Lookup, Polar

PathLike = Union[str, "os.PathLike[str]"]


class Table:
    """A table of polars, one per (Re, M) node, as ``polargen`` writes and reads it.

    Lookups (:meth:`lookup`) interpolate like the rotor model: monotone cubic (PCHIP) in α over
    the usable points (converged, not in massive separation), linear in ln Re and in M between
    polars, the edge value outside the Re and Mach axes (flagged), and beyond the usable α
    range the 360° extension (Viterna–Corrigan to ±90°, a flat plate beyond; flagged
    ``post_stall``, and ``massive_separation`` where it stands in for such points).
    """

    def __init__(self, core: "_polargen.PolarTable") -> None:
        self._core = core

    @classmethod
    def read(cls, path: PathLike, re: Optional[float] = None, mach: Optional[float] = None,
             user_prop: Optional[float] = None) -> "Table":
        """Reads a table file as ``polargen convert`` does: a polargen CSV, JSON or JSON Lines
        table, an XFOIL polar file (``.pol``), a C81 deck, an OpenFAST AeroDyn airfoil file
        (recognised by its content, whatever its extension) or a single-polar CSV (columns
        alpha, cl, cd, …). ``re`` is the Reynolds number of a C81 deck (it carries none; 1e6
        when not given), ``mach`` the Mach number of an AeroDyn file from another tool (0),
        ``user_prop`` the tables to read of an AeroDyn file whose tables differ in UserProp.
        What the reader assumed is issued as a ``UserWarning``."""
        core, notes = _polargen.PolarTable.read(os.fspath(path), re, mach, user_prop)
        for note in notes:
            warnings.warn(note, stacklevel=2)
        return cls(core)

    def summary(self) -> List[Dict[str, Any]]:
        """Per polar, Re-major, what ``polargen summary`` prints: dicts with ``airfoil``,
        ``re``, ``mach`` and the fields of :meth:`Polar.summary`, the columns of
        ``polargen summary --csv`` (``pandas.DataFrame(table.summary())`` gives that frame)."""
        return self._core.summary()

    def write(self, path: PathLike, format: Optional[str] = None,
              c81_re: Optional[float] = None) -> List[str]:
        """Writes the table as ``polargen convert`` does: ``format`` ``"csv"``, ``"json"``,
        ``"jsonl"`` (JSON Lines, ``pandas.read_json(path, lines=True)``), ``"xfoil"`` (one
        ``.pol`` per node), ``"c81"`` (one file per Re, or only at ``c81_re``) or
        ``"aerodyn"`` (one file per Mach number); from the extension of ``path`` when None.
        Files are written atomically; returns the paths written."""
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
        """How the table was made: airfoil, ncrit (None when the surfaces differ), ncrit_top,
        ncrit_bot, xtr_top_set, xtr_bot_set, thickness (t/c), panels, solver; NaN where the
        file did not say (a C81 deck has no N_crit or transition setting)."""
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
    def usable_count(self) -> int:
        """Number of usable points: converged and not in massive separation (the points
        lookups use)."""
        return self._core.usable_count

    @property
    def has_lookup(self) -> bool:
        """Whether lookups are possible (some polar has two usable points)."""
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
        return Lookup(dict(zip(LOOKUP_COLUMNS, columns)), shape)

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
