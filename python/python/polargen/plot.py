"""Figures with matplotlib (the optional extra ``plot``: ``pip install "./python[plot]"``):
the panels ``polargen plot`` draws, built by the library — the same series, axis limits,
drag-axis rule, point symbols and legend labels — and drawn here on a matplotlib figure.

>>> import polargen as pg
>>> clean = pg.polar("naca8h12", re=1.9e6, mach=0.41, alpha="-4:12:0.5")     # doctest: +SKIP
>>> tripped = pg.polar("naca8h12", re=1.9e6, mach=0.41, alpha="-4:12:0.5", xtr=0.07)  # doctest: +SKIP
>>> fig = pg.plot.polars([clean, tripped])                                 # doctest: +SKIP
>>> fig.savefig("clean_vs_trip.png")                                       # doctest: +SKIP
"""

from __future__ import annotations

import json
from typing import Any, Dict, List, Optional, Sequence, Union

from . import _polargen
from ._results import Polar

__all__ = ["draw", "polars"]

#: The palette of the library's renderer: matplotlib's "tab10" colours, by index.
TAB10 = ("#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2",
         "#7f7f7f", "#bcbd22", "#17becf")


def _pyplot() -> Any:
    try:
        import matplotlib.pyplot as plt
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError('plotting needs matplotlib: pip install "./python[plot]" '
                          "(or pip install matplotlib)") from e
    return plt


def polars(curves: Union[Polar, Sequence[Polar]], labels: Optional[Sequence[str]] = None,
           title: Optional[str] = None, cd_axis: Union[str, float] = "auto",
           fig: Any = None) -> Any:
    """The polar figure of ``polargen plot`` for ``curves`` (:class:`Polar` objects, e.g. from
    :func:`polargen.polar` or :meth:`Table.polar`): Cl–α, the drag polar Cl–Cd, the
    transition locations Cl–x_tr (upper solid, lower dashed; left out when no polar has
    them), Cl/Cd–α and Cm–α, unconverged points left out. ``labels`` name the curves (default:
    airfoil and transition setting), ``title`` the figure (default: the names and the flow
    condition), ``cd_axis`` is ``"auto"`` (the attached-flow drag), ``"all"`` or a Cd value,
    as ``--cd-axis``. Draws on ``fig`` (a matplotlib Figure, cleared) or a new one; returns
    the figure."""
    if isinstance(curves, Polar):
        curves = [curves]
    entries = []
    for i, p in enumerate(curves):
        table = getattr(p, "_table", None)
        if not isinstance(p, Polar) or table is None:
            raise TypeError(f"curves[{i}]: expected a polargen Polar, got {type(p).__name__}")
        entries.append((table, float(p.re), float(p.mach)))
    if not entries:
        raise ValueError("curves: no polar to draw")
    spec = json.loads(_polargen.polar_figure(
        entries, None if labels is None else [str(label) for label in labels],
        None if title is None else str(title), str(cd_axis)))
    return draw(spec, fig)


def draw(spec: Dict[str, Any], fig: Any = None) -> Any:
    """Draws a figure description of the library (title, grid, panels with their limits,
    series and markers) on ``fig`` (cleared) or a new matplotlib Figure; one legend for all
    panels, in the free grid cell after the last panel or below the panels."""
    plt = _pyplot()
    rows, cols = spec["grid"]
    if fig is None:
        fig = plt.figure(figsize=(4.6 * cols, 3.6 * rows + 0.9), layout="constrained")
    else:
        fig.clear()
    fig.suptitle(spec["title"])
    handles: List[Any] = []
    seen: set = set()
    axes = []
    for i, panel in enumerate(spec["panels"]):
        ax = fig.add_subplot(rows, cols, i + 1)
        axes.append(ax)
        ax.set_title(panel["title"], fontsize="medium")
        ax.set_xlabel(panel["x_label"])
        ax.set_ylabel(panel["y_label"])
        ax.grid(True, color="0.9")
        for s in panel["series"]:
            x = [float("nan") if v is None else v for v in s["x"]]
            y = [float("nan") if v is None else v for v in s["y"]]
            color = TAB10[s["color"] % len(TAB10)]
            style = {"solid": "-", "dashed": "--", "none": ""}[s["line"]]
            (line,) = ax.plot(x, y, linestyle=style or "None", color=color,
                              marker="o" if s["symbols"] else None, markersize=3.5,
                              label=s["label"])
            key = (s["label"], s["color"], s["line"])
            if s["label"] and key not in seen:
                seen.add(key)
                handles.append(line)
            if panel["mark_clipped"]:
                _mark_clipped(ax, x, y, panel["x_limits"], panel["y_limits"], color)
        for m in panel["markers"]:
            color = TAB10[m["color"] % len(TAB10)]
            if m["kind"] == "vline":
                artist = ax.axvline(m["x"], color=color, linestyle="--", label=m["label"])
            elif m["kind"] == "hline":
                artist = ax.axhline(m["y"], color=color, linestyle="--", label=m["label"])
            else:
                (artist,) = ax.plot([m["x"]], [m["y"]], "D", color=color, label=m["label"])
            if m["label"] and (m["label"], m["kind"]) not in seen:
                seen.add((m["label"], m["kind"]))
                handles.append(artist)
        ax.set_xlim(*panel["x_limits"])
        ax.set_ylim(*panel["y_limits"])
    if handles:
        free = rows * cols > len(spec["panels"])
        if free:
            cell = fig.add_subplot(rows, cols, len(spec["panels"]) + 1)
            cell.axis("off")
            cell.legend(handles=handles, loc="center", frameon=False)
        else:
            fig.legend(handles=handles, loc="outside lower center",
                       ncols=min(len(handles), 4), frameon=False)
    return fig


def _mark_clipped(ax: Any, x: List[float], y: List[float], xlim: Sequence[float],
                  ylim: Sequence[float], color: str) -> None:
    """Arrowheads at the edge of the axes for points outside the limits, as the library's
    renderer marks drag beyond the drag polar's Cd axis."""
    (x0, x1), (y0, y1) = sorted(xlim), sorted(ylim)
    for xv, yv in zip(x, y):
        if xv != xv or yv != yv:
            continue
        if xv > x1 and y0 <= yv <= y1:
            ax.plot([x1], [yv], marker=">", color=color, markersize=5, clip_on=False)
        elif xv < x0 and y0 <= yv <= y1:
            ax.plot([x0], [yv], marker="<", color=color, markersize=5, clip_on=False)
