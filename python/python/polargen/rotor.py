"""The gyroplane: the aircraft preset, level-cruise trim and takeoff, driven by a polar table.

>>> import polargen as pg
>>> ac = pg.rotor.Aircraft.read("aircraft/mtosport.toml")          # doctest: +SKIP
>>> t = ac.trim(pg.Table.read("polars/naca8h12_free.csv"), speed_kt=60)  # doctest: +SKIP
>>> t.rotor_rpm, t["engine_rpm"]                                       # doctest: +SKIP

Results hold exactly the fields ``gyro trim --json`` and ``gyro takeoff --json`` print (a
mapping: ``result["rotor_rpm"]``, and attributes: ``result.rotor_rpm``). Runs of many results
— ``Aircraft.sweep`` (``gyro sweep``), :func:`compare` (``gyro compare``), :func:`study`
(``gyro study``) — return :class:`Records` of them, with ``to_pandas()``:

>>> ac.sweep(table, speeds_kt=range(30, 95, 5)).to_pandas()           # doctest: +SKIP
>>> pg.rotor.study("speed", "aircraft/mtosport.toml").to_pandas()      # doctest: +SKIP

The rotor alone in a wind tunnel (``gyro autorotate``):

>>> r = pg.rotor.Rotor.read("aircraft/pca2.toml")                      # doctest: +SKIP
>>> a = r.autorotate(pg.Table.read("polars/goe429_xtr0.07.csv"), alpha_deg=8.3, speed_m_s=15.7)  # doctest: +SKIP
>>> a.rotor_rpm, a.cl, a.b1_deg                                        # doctest: +SKIP
"""

from __future__ import annotations

import json
import os
import warnings
from typing import Any, Dict, Iterable, Iterator, List, Mapping, Optional, Sequence, Union

import numpy as np

from . import _polargen
from ._results import _pandas
from ._table import Table

__all__ = [
    "Aircraft", "AutorotationResult", "Records", "Rotor", "TakeoffResult", "TrimResult",
    "autorotate", "compare", "study", "sweep", "takeoff", "trim",
]

PathLike = Union[str, "os.PathLike[str]"]


class _Fields(Mapping[str, Any]):
    """A read-only mapping of the JSON fields of a result, also readable as attributes."""

    def __init__(self, fields: Dict[str, Any]) -> None:
        self._fields = fields

    def __getitem__(self, key: str) -> Any:
        return self._fields[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._fields)

    def __len__(self) -> int:
        return len(self._fields)

    def __getattr__(self, name: str) -> Any:
        try:
            return self.__dict__["_fields"][name]
        except KeyError:
            raise AttributeError(name) from None

    def to_dict(self) -> Dict[str, Any]:
        """The fields as a plain dict (what ``gyro … --json`` prints)."""
        return dict(self._fields)

    def __repr__(self) -> str:
        inner = ", ".join(f"{k}={v!r}" for k, v in self._fields.items())
        return f"{type(self).__name__}({inner})"


class TrimResult(_Fields):
    """Trimmed level flight with the fields of ``gyro trim --json``: ``rotor_rpm``,
    ``rotor_aoa_deg`` (tip-path plane), ``engine_rpm`` (None above the engine's maximum),
    ``rotor_drag_n``, ``parasitic_drag_n``, ``prop_thrust_n``, ``lift_to_drag``,
    ``hub_aoa_deg``, ``power_required_kw``, ``beta1c_deg``, ``beta1s_deg``, ``speed_kt``.
    ``notes`` holds what ``gyro`` prints beside the result (also issued as warnings)."""

    def __init__(self, fields: Dict[str, Any], notes: List[str]) -> None:
        super().__init__(fields)
        self.__dict__["notes"] = list(notes)


class TakeoffResult(_Fields):
    """A takeoff run with the fields of ``gyro takeoff --json`` (``takeoff_roll_m``,
    ``distance_15m_m``, ``max_flapping_deg``, ``liftoff_speed_kt``, ``screen_speed_kt``,
    ``liftoff_rotor_rpm``, ``screen_time_s``, and the largest shares of one rotor solution's
    blade-element lookups over the run ``max_table_clamped_fraction``,
    ``max_table_supercritical_fraction``, ``max_table_separated_fraction``, with the time
    ``max_table_separated_time_s`` and airspeed ``max_table_separated_speed_kt`` of the
    solution with the largest separated share) and ``history``,
    the time history of ``gyro takeoff --history`` as NumPy columns (t, x, h, v, rotor_rpm,
    alpha_r_deg, beta_deg). ``notes`` holds what ``gyro`` prints beside the result (also issued as
    warnings)."""

    def __init__(self, fields: Dict[str, Any], history: Dict[str, np.ndarray],
                 notes: Optional[List[str]] = None) -> None:
        super().__init__(fields)
        self.__dict__["history"] = history
        self.__dict__["notes"] = list(notes or [])

    def history_to_pandas(self):
        """The time history as a ``pandas.DataFrame``."""
        return _pandas().DataFrame(self.history)


class Records(List[Mapping[str, Any]]):
    """Results with the fields of a ``gyro … --json`` array, one mapping per record (a trim,
    a study setting, a row of the comparison): a list, with :meth:`to_pandas` for a
    DataFrame whose columns are the JSON keys. ``notes`` holds what ``gyro`` prints beside
    the records (also issued as warnings)."""

    def __init__(self, records: Iterable[Mapping[str, Any]] = (),
                 notes: Optional[List[str]] = None) -> None:
        super().__init__(records)
        self.notes: List[str] = list(notes or [])
        #: Files a study wrote (``out``).
        self.files: List[str] = []

    def to_pandas(self) -> Any:
        """One row per record, the JSON keys as columns."""
        return _pandas().DataFrame([dict(r) for r in self])


def _warn(notes: List[str]) -> None:
    for note in notes:
        warnings.warn(note, UserWarning, stacklevel=3)


class AutorotationResult(_Fields):
    """The autorotating rotor in a tunnel with the fields of ``gyro autorotate --json``:
    ``alpha_deg``, ``speed_m_s``, ``rotor_rpm``, ``mu``, ``cl``, ``cd`` (wind axes, on
    q·πR²), ``lift_to_drag``, ``coning_deg``, ``a1_deg``, ``b1_deg`` (NACA signs),
    ``thrust_coefficient``, ``inflow_ratio`` and the shares of reverse flow, clamped and
    supercritical lookups. ``notes`` holds what ``gyro`` prints beside it."""

    def __init__(self, fields: Dict[str, Any], notes: List[str]) -> None:
        super().__init__(fields)
        self.__dict__["notes"] = list(notes)


class Rotor:
    """The rotor of a preset alone (an aircraft's, or a rotor-only preset such as
    ``aircraft/pca2.toml``), as ``gyro autorotate`` reads it."""

    def __init__(self, core: "_polargen.Rotor") -> None:
        self._core = core

    @classmethod
    def read(cls, path: PathLike) -> "Rotor":
        """Reads and checks the rotor of a TOML preset, as ``gyro autorotate --aircraft``."""
        return cls(_polargen.Rotor.read(os.fspath(path)))

    @classmethod
    def from_toml(cls, text: str, origin: str = "<string>") -> "Rotor":
        """Parses and checks the rotor of a TOML preset held in a string."""
        return cls(_polargen.Rotor.from_toml(text, origin))

    @property
    def name(self) -> str:
        """The preset's name."""
        return self._core.name

    def autorotate(self, table: Table, alpha_deg: float, speed_m_s: Optional[float] = None,
                   mu: Optional[float] = None, reference_rpm: Optional[float] = None,
                   pitch_deg: Optional[float] = None,
                   altitude_m: float = 0.0) -> AutorotationResult:
        """The rotor autorotating in a tunnel at shaft angle ``alpha_deg`` and wind speed
        ``speed_m_s`` (or tip-speed ratio ``mu`` at ``reference_rpm``), ISA ``altitude_m``,
        blade pitch setting ``pitch_deg`` (the preset's when None), as ``gyro autorotate``."""
        opt = lambda v: None if v is None else float(v)  # noqa: E731
        text, notes = self._core.autorotate(_core(table), float(alpha_deg), opt(speed_m_s),
                                            opt(mu), opt(reference_rpm), opt(pitch_deg),
                                            float(altitude_m))
        for note in notes:
            warnings.warn(note, UserWarning, stacklevel=2)
        return AutorotationResult(json.loads(text), notes)

    def autorotate_cases(self, table: Table, alpha_deg: Iterable[float],
                         speed_m_s: Iterable[float], pitch_deg: Optional[float] = None,
                         altitude_m: float = 0.0) -> Records:
        """Every tunnel case (``alpha_deg[i]``, ``speed_m_s[i]``), in parallel, as ``gyro
        autorotate --cases FILE --json``: records with the fields of :meth:`autorotate` and
        ``error`` (empty when the case autorotates; the results are NaN when it does not),
        ``to_pandas()`` for a DataFrame (Report 515's Table III in one call)."""
        alphas = [float(a) for a in alpha_deg]
        speeds = [float(v) for v in speed_m_s]
        opt = None if pitch_deg is None else float(pitch_deg)
        text, notes = self._core.autorotate_cases(_core(table), alphas, speeds, opt,
                                                  float(altitude_m))
        _warn(notes)
        rows = [{k: (float("nan") if v is None else v) for k, v in r.items()}
                for r in json.loads(text)]
        return Records(rows, notes)

    def __repr__(self) -> str:
        return f"Rotor({self.name!r})"


class Aircraft:
    """A gyroplane preset: rotor, airframe, propeller/engine and takeoff data (TOML, every
    value with its source; see ``aircraft/mtosport.toml``)."""

    def __init__(self, core: "_polargen.Aircraft") -> None:
        self._core = core

    @classmethod
    def read(cls, path: PathLike) -> "Aircraft":
        """Reads and checks a TOML preset, as ``gyro --aircraft`` does."""
        return cls(_polargen.Aircraft.read(os.fspath(path)))

    @classmethod
    def from_toml(cls, text: str, origin: str = "<string>") -> "Aircraft":
        """Parses and checks a TOML preset held in a string."""
        return cls(_polargen.Aircraft.from_toml(text, origin))

    @property
    def name(self) -> str:
        """The aircraft's name."""
        return self._core.name

    @property
    def mass_kg(self) -> float:
        """The preset's takeoff mass [kg]."""
        return self._core.mass_kg

    def trim(self, table: Table, speed_kt: float = 60.0, mass_kg: Optional[float] = None,
             altitude_m: float = 0.0) -> TrimResult:
        """Level-cruise trim at ``speed_kt`` [kt], ISA ``altitude_m`` and ``mass_kg`` (the
        preset's when None) with the blade section ``table``, as ``gyro trim``: the rotor in
        autorotation carrying the weight, its drag, the airframe drag and the propeller."""
        text, notes = self._core.trim(_core(table), float(speed_kt),
                                      None if mass_kg is None else float(mass_kg),
                                      float(altitude_m))
        for note in notes:
            warnings.warn(note, UserWarning, stacklevel=2)
        return TrimResult(json.loads(text), notes)

    def takeoff(self, table: Table, mass_kg: Optional[float] = None) -> TakeoffResult:
        """The takeoff from brake release to the screen height, as ``gyro takeoff``."""
        text, history, notes = self._core.takeoff(_core(table),
                                                  None if mass_kg is None else float(mass_kg))
        _warn(notes)
        return TakeoffResult(json.loads(text), history, notes)

    def sweep(self, table: Table, speeds_kt: Union[float, Sequence[float], np.ndarray],
              mass_kg: Optional[float] = None) -> Records:
        """Level-cruise trims at each airspeed of ``speeds_kt`` [kt] (a list or array) with
        the blade section ``table``, at ``mass_kg`` (the preset's when None), ISA sea level,
        as ``gyro sweep``: a :class:`Records` of :class:`TrimResult` (the speeds that trim, in
        increasing speed; a speed that does not is left out and named in ``notes``)."""
        speeds = [float(v) for v in np.atleast_1d(np.asarray(speeds_kt, dtype=float)).ravel()]
        text, notes = _polargen.rotor_sweep(self._core, _core(table), speeds,
                                            None if mass_kg is None else float(mass_kg))
        _warn(notes)
        return Records((TrimResult(t, []) for t in json.loads(text)), notes)

    def __repr__(self) -> str:
        return f"Aircraft({self.name!r}, {self.mass_kg:g} kg)"


def _core(table: Table) -> "_polargen.PolarTable":
    if not isinstance(table, Table):
        raise TypeError(f"table: expected a polargen.Table, got {type(table).__name__}")
    return table._core


def trim(aircraft: Aircraft, table: Table, speed_kt: float = 60.0,
         mass_kg: Optional[float] = None, altitude_m: float = 0.0) -> TrimResult:
    """:meth:`Aircraft.trim` of ``aircraft``."""
    return aircraft.trim(table, speed_kt=speed_kt, mass_kg=mass_kg, altitude_m=altitude_m)


def takeoff(aircraft: Aircraft, table: Table, mass_kg: Optional[float] = None) -> TakeoffResult:
    """:meth:`Aircraft.takeoff` of ``aircraft``."""
    return aircraft.takeoff(table, mass_kg=mass_kg)


def sweep(aircraft: Aircraft, table: Table, speeds_kt: Union[float, Sequence[float], np.ndarray],
          mass_kg: Optional[float] = None) -> Records:
    """:meth:`Aircraft.sweep` of ``aircraft``."""
    return aircraft.sweep(table, speeds_kt, mass_kg=mass_kg)


def compare(aircraft: Aircraft, clean: Table, contaminated: Table) -> Dict[str, Records]:
    """The clean and the contaminated rotor against the paper, as ``gyro compare --json``:
    ``{"trim": Records, "takeoff": Records}``, each record a quantity with ``paper_clean``,
    ``paper_contaminated``, ``ours_clean`` and ``ours_contaminated``. Each part's ``notes``
    holds what ``gyro compare`` prints beside the tables (also issued as warnings)."""
    text, notes = _polargen.rotor_compare(aircraft._core, _core(clean), _core(contaminated))
    _warn(notes)
    return {part: Records(rows, notes) for part, rows in json.loads(text).items()}


STUDIES = ("contamination", "airfoil", "speed", "wing")


def study(kind: str, aircraft: PathLike = "aircraft/mtosport.toml", *,
          airfoil: Optional[str] = None, airfoils: Optional[Sequence[str]] = None,
          trips: Optional[Sequence[float]] = None, ncrits: Optional[Sequence[float]] = None,
          outboard: Optional[Sequence[float]] = None, inboard: Optional[Sequence[float]] = None,
          xtr: Optional[float] = None, speeds_kt: Optional[Sequence[float]] = None,
          areas_m2: Optional[Sequence[float]] = None, out: Optional[PathLike] = None,
          cache: Optional[PathLike] = None) -> Records:
    """A study beyond the paper, as ``gyro study KIND --json`` (docs/studies.md): ``kind`` is
    ``"contamination"`` (``airfoil``, ``trips``, ``ncrits``, ``outboard``, ``inboard``),
    ``"airfoil"`` (``airfoils``), ``"speed"`` (``airfoil``, ``xtr``, ``speeds_kt``) or
    ``"wing"`` (``airfoil``, ``areas_m2``, ``speeds_kt``, ``xtr``); settings not given are the
    command line's defaults. The section tables are solved once and kept in ``cache`` (the
    command line's cache folder when None): a cold run takes minutes to half an hour. ``out``
    also writes the CSV table and the figures there. Returns a :class:`Records` of the JSON
    records (``notes``: settings without a result), ``files`` the paths written."""
    if kind not in STUDIES:
        raise ValueError(f"study: unknown study {kind!r} (one of {', '.join(STUDIES)})")
    def floats(v: Optional[Sequence[float]]) -> Optional[List[float]]:
        return None if v is None else [float(x) for x in np.atleast_1d(np.asarray(v, float))]

    text, notes, written = _polargen.rotor_study(
        kind, os.fspath(aircraft), airfoil, None if airfoils is None else list(airfoils),
        floats(trips), floats(ncrits), floats(outboard), floats(inboard),
        None if xtr is None else float(xtr), floats(speeds_kt), floats(areas_m2),
        None if out is None else os.fspath(out), None if cache is None else os.fspath(cache))
    _warn(notes)
    records = Records(json.loads(text), notes)
    records.files = [os.fspath(p) for p in written]
    return records


def autorotate(rotor: Rotor, table: Table, alpha_deg: float, speed_m_s: Optional[float] = None,
               mu: Optional[float] = None, reference_rpm: Optional[float] = None,
               pitch_deg: Optional[float] = None, altitude_m: float = 0.0) -> AutorotationResult:
    """:meth:`Rotor.autorotate` of ``rotor``."""
    return rotor.autorotate(table, alpha_deg, speed_m_s=speed_m_s, mu=mu,
                            reference_rpm=reference_rpm, pitch_deg=pitch_deg,
                            altitude_m=altitude_m)
