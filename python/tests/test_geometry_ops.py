"""Geometry operations in Python (``Airfoil.with_thickness``, ``with_camber``, ``with_te_gap``,
``with_flap``, ``blended``) give the command line's sections and tables, bit for bit, and record
the operations in the table's metadata."""

from __future__ import annotations

import polargen as pg
import pytest


def test_shaped_table_equals_the_cli_table(cli, tmp_path):
    """``with_thickness(0.15).with_flap(0.75, 0, 10)`` is ``--thickness 0.15 --flap
    0.75:0:10``: the same CSV, byte for byte, with the operations in its metadata."""
    out = tmp_path / "cli.csv"
    cli.run("polargen", "--airfoil", "naca2412", "--re", "1e6", "--alpha", "0:4:2",
            "--thickness", "0.15", "--flap", "0.75:0:10", "--out", str(out))
    foil = pg.Airfoil.naca("2412").with_thickness(0.15).with_flap(0.75, 0, 10)
    assert foil.name == "NACA 2412 (thickness 0.15; flap 0.75:0:10)"
    assert foil.operations == ["thickness 0.15", "flap 0.75:0:10"]
    table = pg.table(foil, re=[1e6], mach=[0.0], alpha="0:4:2")
    assert table.meta["geometry"] == ["thickness 0.15", "flap 0.75:0:10"]
    assert table.meta["flap_deg"] == 10.0
    table.write(tmp_path / "py.csv")
    assert (tmp_path / "py.csv").read_text() == out.read_text()


def test_geometry_equals_polargen_geometry(cli, tmp_path):
    out = tmp_path / "cli.dat"
    cli.run("polargen", "geometry", "naca2412", "--blend", "naca0012:0.5", "--te-gap",
            "0.005:0.5", "--out", str(out))
    foil = pg.Airfoil.naca("2412").blended(pg.Airfoil.naca("0012"), 0.5).with_te_gap(0.005, 0.5)
    # The same points; the name records the partner as each was given (a name on the command
    # line, the partner's own name in Python).
    assert foil.to_selig().split("\n")[1:] == out.read_text().split("\n")[1:]
    assert foil.name == "NACA 2412 (blend NACA 0012:0.5; te-gap 0.005:0.5)"
    measured = foil.thickness_camber()
    assert abs(measured["thickness"] - 0.12) < 1e-3
    assert abs(measured["camber"] - 0.01) < 1e-3


def test_bad_values_raise_value_errors():
    foil = pg.Airfoil.naca("2412")
    for call, words in [
        (lambda: foil.with_thickness(0.0), "thickness"),
        (lambda: foil.with_camber(0.5), "camber"),
        (lambda: foil.with_te_gap(0.01, 2.0), "blending"),
        (lambda: foil.with_flap(1.2, 0.0, 10.0), "inside the chord"),
        (lambda: foil.blended(pg.Airfoil.naca("0012"), 1.5), "fraction"),
        (lambda: pg.Airfoil.naca("0012").with_camber(0.02), "no camber line"),
    ]:
        with pytest.raises(ValueError, match=words):
            call()
