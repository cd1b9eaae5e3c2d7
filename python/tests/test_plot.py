"""``Polar.plot()`` and ``pg.plot.polars`` draw with matplotlib (headless, Agg) the figure
``polargen plot`` draws: its panels, axis labels and limits, legend labels and point symbols,
unconverged points left out."""

from __future__ import annotations

import json

import matplotlib

matplotlib.use("Agg")

import polargen as pg  # noqa: E402
import pytest  # noqa: E402

from polargen import _polargen  # noqa: E402

PANELS = ["Lift", "Drag polar", "Transition: upper solid, lower dashed", "Lift-to-drag ratio",
          "Pitching moment"]


@pytest.fixture(scope="module")
def polars():
    clean = pg.polar("naca0012", re=1e6, alpha="-4:14:1")
    tripped = pg.polar("naca0012", re=1e6, alpha="-4:14:1", xtr=0.1)
    return clean, tripped


def test_the_figure_has_the_cli_panels_and_labels(polars, tmp_path):
    clean, tripped = polars
    fig = pg.plot.polars([clean, tripped])
    axes = [ax for ax in fig.axes if ax.get_title()]
    assert [ax.get_title() for ax in axes] == PANELS
    assert fig._suptitle.get_text() == "NACA 0012 free vs NACA 0012 xtr 0.1 — Re 1e6, M 0"
    lift = axes[0]
    assert lift.get_xlabel() == "α [deg]" and lift.get_ylabel() == "Cl [-]"
    # only converged points are drawn
    x = lift.get_lines()[0].get_xdata()
    assert len(x) == int(clean.converged.sum())
    # the legend (in the free sixth cell) names both polars
    legend = [t.get_text() for ax in fig.axes if ax.get_legend() for t in ax.get_legend().texts]
    assert legend == ["NACA 0012 free", "NACA 0012 xtr 0.1"]
    out = tmp_path / "polars.png"
    fig.savefig(out)
    assert out.read_bytes()[:4] == b"\x89PNG"


def test_limits_and_symbols_are_the_librarys(polars):
    clean, _ = polars
    spec = json.loads(_polargen.polar_figure([(clean._table, clean.re, clean.mach)], None,
                                             None, "auto"))
    fig = clean.plot(label="clean")
    axes = [ax for ax in fig.axes if ax.get_title()]
    for ax, panel in zip(axes, spec["panels"]):
        assert ax.get_xlim() == pytest.approx(panel["x_limits"])
        assert ax.get_ylim() == pytest.approx(panel["y_limits"])
        symbols = panel["series"][0]["symbols"]
        assert (ax.get_lines()[0].get_marker() == "o") == symbols
    # 1° steps over the panel: sparse, so every line carries its points (docs/plots.md)
    assert spec["panels"][0]["series"][0]["symbols"]
    assert fig.axes[-1].get_legend().texts[0].get_text() == "clean"


def test_bad_arguments(polars):
    clean, tripped = polars
    with pytest.raises(ValueError, match="labels: 1 labels for 2 polars"):
        pg.plot.polars([clean, tripped], labels=["one"])
    with pytest.raises(ValueError, match="cd_axis"):
        clean.plot(cd_axis="wide")
    with pytest.raises(TypeError, match="expected a polargen Polar"):
        pg.plot.polars(["naca0012"])
