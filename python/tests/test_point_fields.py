"""Every per-point field of the CSV table is a column in Python (``Polar.columns()``,
``to_pandas()``), with the values the CLI writes; lookups carry every flag of the library's
lookups; points in massive separation are marked and left out of ``usable``."""

from __future__ import annotations

import numpy as np
import polargen as pg
import pytest

from conftest import floats, read_csv_columns, same

# Columns of the CSV that describe the table, not the point (repeated on every row).
TABLE_COLUMNS = {"airfoil", "re", "mach", "ncrit", "ncrit_top", "ncrit_bot", "xtr_top_set",
                 "xtr_bot_set", "panels", "solver", "thickness"}


@pytest.fixture(scope="module")
def post_stall(cli, tmp_path_factory):
    """NACA 0012, Re 2·10⁵, α 0…30° in 10° steps, as the CLI writes it: the points at 20°
    and 30° converge in massive separation."""
    path = tmp_path_factory.mktemp("sep") / "t.csv"
    cli.run("polargen", "--airfoil", "naca0012", "--re", "2e5", "--alpha", "0:30:10", "-q",
            "--out", str(path))
    return path


def test_polar_columns_are_the_csv_point_columns(post_stall):
    csv = read_csv_columns(post_stall.read_text())
    pol = pg.Table.read(post_stall).polars()[0]
    assert set(pol.columns()) == set(csv) - TABLE_COLUMNS
    for name, values in pol.columns().items():
        if name in ("converged", "supercritical", "massive_separation"):
            assert [str(bool(v)).lower() for v in values] == csv[name], name
        else:
            assert same(values, floats(csv[name])), name
    assert list(pol.massive_separation) == [False, False, True, True]
    assert list(pol.usable) == [True, True, False, False]
    assert np.all(pol.xsep_top[2:] < 0.01) and np.all(pol.xsep_top[:2] == 1.0)
    frame = pol.to_pandas()
    assert list(frame.columns) == ["re", "mach", *pol.columns()]
    assert str(frame["massive_separation"].dtype) == "boolean"
    assert frame["massive_separation"].tolist() == [False, False, True, True]


def test_a_table_without_the_flags_says_it_does_not_know(tmp_path):
    path = tmp_path / "old.csv"
    path.write_text(
        "airfoil,re,mach,ncrit,xtr_top_set,xtr_bot_set,alpha,cl,cd,cdp,cm,xtr_top,xtr_bot,"
        "converged\n"
        "foil,1e6,0.6,9,1,1,0,0.1,0.01,0.004,-0.01,0.5,0.9,true\n"
        "foil,1e6,0.6,9,1,1,2,0.3,0.01,0.004,-0.01,0.5,0.9,true\n")
    table = pg.Table.read(path)
    pol = table.polars()[0]
    assert np.isnan(pol.cpmin).all() and np.isnan(pol.xsep_top).all()
    for flag in ("supercritical", "massive_separation"):
        assert pol.unknown(flag).all() and not getattr(pol, flag).any()
        assert pol.to_pandas()[flag].isna().all()
    assert table.usable_count == 2
    look = table.lookup(1.0, 1e6, 0.6)
    assert bool(look.supercritical_unknown) and bool(look.separation_unknown)
    assert not bool(look.massive_separation)


def test_lookups_carry_every_flag(post_stall):
    table = pg.Table.read(post_stall)
    assert (table.converged_count, table.usable_count) == (4, 2)
    look = table.lookup([5.0, 20.0, 30.0, 60.0], 2e5, 0.0)
    assert set(look.columns()) == {
        "cl", "cd", "cm", "re_clamped", "mach_clamped", "post_stall", "bridged",
        "supercritical", "supercritical_unknown", "massive_separation", "separation_unknown"}
    # Past the last usable point (10°) the 360° extension stands in for the points in massive
    # separation at 20° and 30°: flagged, and not their coefficients.
    assert list(look.post_stall) == [False, True, True, True]
    assert list(look.massive_separation) == [False, True, True, False]
    pol = table.polars()[0]
    assert abs(look.cl[2] - pol.cl[3]) > 0.05
    assert not look.supercritical.any() and not look.separation_unknown.any()
    assert look.to_pandas().shape == (4, 11)


def test_a_point_carries_its_separation():
    p = pg.point("naca0012", re=2e6, alpha=4.0)
    assert p.xsep_top == 1.0 and not p.massive_separation and not p.supercritical
    assert -2.0 < p.cpmin < -0.5
