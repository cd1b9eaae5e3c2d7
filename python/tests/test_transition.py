"""A trip at the leading edge (x/c = 0) as the CLI and XFOIL 6.99 compute it (NACA 0012, Re
1e6, α 4°, ``VPAR XTR 0 0``: Cd 0.00937; free transition gives 0.00728), and the same range
of trip locations as the CLI: [0, 1]."""

from __future__ import annotations

import polargen as pg
import pytest

from conftest import floats, read_csv_columns


def test_a_trip_at_the_leading_edge_equals_the_cli_and_xfoil(cli, tmp_path):
    out = tmp_path / "cli.csv"
    cli.run("polargen", "--airfoil", "naca0012", "--re", "1e6", "--alpha", "2:4:2", "--xtr", "0",
            "--out", str(out))
    columns = read_csv_columns(out.read_text())
    pol = pg.polar("naca0012", re=1e6, alpha=[2, 4], xtr=0, threads=1)
    assert list(pol.cd) == list(floats(columns["cd"]))
    assert pol.meta["xtr_top_set"] == 0.0 and pol.meta["xtr_bot_set"] == 0.0
    assert abs(pol.cd[1] / 0.00937 - 1) < 1.5e-3 and abs(pol.cl[1] - 0.4141) < 1.5e-4
    # The upper surface trips at the leading edge; the stagnation point lies downstream of the
    # lower surface's trip, so that surface transitions freely (XFOIL: 0.9702).
    assert pol.xtr_top[1] < 1e-3 and abs(pol.xtr_bot[1] - 0.9702) < 1.5e-4
    point = pg.point("naca0012", re=1e6, alpha=4, xtr=(0, 1))
    assert point.xtr_top < 1e-3


@pytest.mark.parametrize("value", ["-0.1", "1.5", "nan"])
def test_trips_outside_zero_to_one_are_refused_as_by_the_cli(cli, value):
    run = cli.run("polargen", "--airfoil", "naca0012", "--re", "1e6", "--xtr", value, check=False)
    assert run.returncode != 0
    expected = run.stderr.strip().removeprefix("polargen: error: ")
    assert "must be in [0, 1] (0 = leading edge, 1 = free)" in expected
    with pytest.raises(ValueError) as caught:
        pg.polar("naca0012", re=1e6, xtr=float(value))
    assert str(caught.value) == expected.replace("--", "", 1)
