"""Messages and docstrings a newcomer reads: one number where one is expected (naming the
argument and where several values go), a missing polar named with plain numbers, 6-series
designations refused as such, and the table docstrings listing every format."""

from __future__ import annotations

import polargen as pg
import pytest


@pytest.mark.parametrize("call, text", [
    (lambda: pg.polar("naca0012", re=[1e6, 2e6]),
     "re: expected one number, got list of 2 values; for several values use pg.table"),
    (lambda: pg.polar("naca0012", re=1e6, mach=[0.1, 0.2]), "mach: expected one number"),
    (lambda: pg.polar("naca0012", re=1e6, xtr=[0.1, 0.2, 0.3]), "xtr: expected one value"),
    (lambda: pg.point("naca0012", re=[1e6], alpha=2.0), "re: expected one number"),
    (lambda: pg.polar("naca0012", re="1e6"), "re: expected one number, got str"),
])
def test_a_list_where_one_number_goes_is_named(call, text):
    with pytest.raises((TypeError, ValueError)) as caught:
        call()
    assert text in str(caught.value), str(caught.value)


def test_a_missing_polar_is_named_in_plain_numbers(repo):
    table = pg.Table.read(repo / "polars" / "naca8h12_free.csv")
    with pytest.raises(KeyError) as caught:
        table.polar(1.9e6, 0.41)
    message = str(caught.value)
    assert "np.float64" not in message and "axes: Re 100000, 200000" in message, message


def test_six_series_is_refused_as_such():
    for name in ("64-212", "NACA 65A010"):
        with pytest.raises(ValueError, match="6-series sections .* are not supported"):
            pg.Airfoil.naca(name)
    with pytest.raises(ValueError, match="6-series"):
        pg.polar("naca64-212", re=1e6)


def test_table_docstrings_list_every_format():
    assert "C81" in pg.Table.read.__doc__ and "cannot" not in pg.Table.read.__doc__
    assert '"aerodyn"' in pg.Table.write.__doc__
