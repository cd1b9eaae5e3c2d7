"""Errors: Python exceptions carrying the CLI's one-line messages (ValueError for bad input,
OSError and its subclasses for files, NotConvergedError where no solution exists), raised
before any computation; nothing panics across the boundary."""

from __future__ import annotations

import numpy as np
import polargen as pg
import pytest


def cli_error(cli, tool: str, *args: str) -> str:
    """The one-line error of a failing CLI run, without the tool's prefix."""
    run = cli.run(tool, *args, check=False)
    assert run.returncode != 0
    line = run.stderr.strip()
    assert "\n" not in line
    for prefix in ("polargen: error: ", "gyro: error: "):
        if line.startswith(prefix):
            return line[len(prefix):]
    return line


@pytest.mark.parametrize(
    "flags, call",
    [
        (("--re", "-1"), lambda: pg.polar("naca0012", re=-1)),
        (("--re", "1e6", "--mach", "1"), lambda: pg.polar("naca0012", re=1e6, mach=1.0)),
        (("--re", "1e6", "--xtr", "1.5"), lambda: pg.polar("naca0012", re=1e6, xtr=1.5)),
        (("--re", "1e6", "--ncrit", "0"), lambda: pg.polar("naca0012", re=1e6, ncrit=0)),
        (("--re", "1e6", "--tolerance", "2"), lambda: pg.polar("naca0012", re=1e6, tolerance=2)),
        (("--re", "1e6", "--panels", "5"), lambda: pg.polar("naca0012", re=1e6, panels=5)),
        (("--re", "1e6", "--alpha", "0:4:0"), lambda: pg.polar("naca0012", re=1e6, alpha="0:4:0")),
    ],
)
def test_bad_arguments_give_the_cli_message_naming_the_argument(cli, flags, call):
    expected = cli_error(cli, "polargen", "--airfoil", "naca0012", *flags)
    with pytest.raises(ValueError) as caught:
        call()
    # The CLI names the flag (--re), Python the argument (re); the rest is the same line.
    assert str(caught.value) == expected.replace("--", "", 1)


def test_bad_airfoils_give_the_cli_message(cli, repo, tmp_path):
    for name in ("naca99999", "nosuchfoil"):
        expected = cli_error(cli, "polargen", "--airfoil", name, "--re", "1e6")
        with pytest.raises(ValueError) as caught:
            pg.polar(name, re=1e6)
        assert "--airfoil: " + str(caught.value) == expected
    bad = repo / "tests" / "data" / "geometry" / "bad_crossing.dat"
    with pytest.raises(ValueError, match="surfaces cross"):
        pg.Airfoil.from_file(bad)
    with pytest.raises(FileNotFoundError, match="cannot read airfoil file .*: no such file"):
        pg.Airfoil.from_file(tmp_path / "missing.dat")
    with pytest.raises(ValueError, match="x has 3 values but y has 2"):
        pg.Airfoil.from_coordinates([1, 0, 1], [0, 0])
    with pytest.raises(ValueError, match="only 3 points"):
        pg.Airfoil.from_coordinates([1, 0, 1], [0.01, 0, -0.01])


def test_alpha_lists_are_checked_before_solving():
    with pytest.raises(ValueError, match="alpha 2: given twice"):
        pg.polar("naca0012", re=1e6, alpha=[0, 2, 2])
    with pytest.raises(ValueError, match=r"alpha 200: outside -180…180 deg"):
        pg.polar("naca0012", re=1e6, alpha=[0, 200])
    with pytest.raises(ValueError, match="alpha NaN: not a finite number"):
        pg.polar("naca0012", re=1e6, alpha=[0, np.nan])
    with pytest.raises(ValueError, match="alpha: no values given"):
        pg.polar("naca0012", re=1e6, alpha=[])
    with pytest.raises(ValueError, match="re 1000000: given twice"):
        pg.table("naca0012", re=[1e6, 1e6])
    with pytest.raises(ValueError, match=r"mach 1.2: the Mach number must be in \[0, 1\)"):
        pg.table("naca0012", mach=[0.0, 1.2])
    with pytest.raises(ValueError, match="xtr: expected one value or"):
        pg.polar("naca0012", re=1e6, xtr=(0.1, 0.2, 0.3))


def test_file_errors_are_os_errors_with_the_cli_message(cli, repo, tmp_path):
    missing = tmp_path / "missing.csv"
    expected = cli_error(cli, "polargen", "convert", str(missing), "--out",
                         str(tmp_path / "x.json"))
    with pytest.raises(FileNotFoundError) as caught:
        pg.Table.read(missing)
    assert str(caught.value) == expected
    with pytest.raises(IsADirectoryError, match="is a folder"):
        pg.Table.read(tmp_path)
    table = pg.Table.read(repo / "polars" / "naca8h12_free.csv")
    with pytest.raises(ValueError, match="unknown table format 'xls'"):
        table.write(tmp_path / "t.xls", format="xls")
    with pytest.raises(ValueError, match="cannot infer table format"):
        table.write(tmp_path / "t.xls")
    blocker = tmp_path / "file"
    blocker.write_text("x")
    with pytest.raises(OSError):
        table.write(blocker / "t.csv")
    bad = tmp_path / "bad.csv"
    bad.write_text("airfoil,re,mach\nx,1,0\n")
    expected = cli_error(cli, "polargen", "convert", str(bad), "--out", str(tmp_path / "o.json"))
    with pytest.raises(ValueError) as caught:
        pg.Table.read(bad)
    assert str(caught.value) == expected


def test_rotor_errors_give_the_gyro_message(cli, repo, tmp_path):
    table = pg.Table.read(repo / "polars" / "naca8h12_free.csv")
    aircraft = pg.rotor.Aircraft.read(repo / "aircraft" / "mtosport.toml")
    base = ("trim", "--aircraft", "aircraft/mtosport.toml", "--table", "polars/naca8h12_free.csv")
    for flags, kwargs in [(("--speed-kt", "0"), {"speed_kt": 0}),
                          (("--mass", "-5"), {"mass_kg": -5}),
                          (("--altitude-m", "20000"), {"altitude_m": 20000})]:
        expected = cli_error(cli, "gyro", *base, *flags)
        with pytest.raises(ValueError) as caught:
            aircraft.trim(table, **kwargs)
        # gyro names the flag (--mass), Python the argument (mass_kg).
        assert str(caught.value).split(" ", 1)[1] == expected.split(" ", 1)[1]
    with pytest.raises(FileNotFoundError):
        pg.rotor.Aircraft.read(tmp_path / "none.toml")
    with pytest.raises(ValueError, match="bad aircraft file <string>"):
        pg.rotor.Aircraft.from_toml("name = 1")
    expected = cli_error(cli, "gyro", *base, "--speed-kt", "10")
    with pytest.raises(pg.NotConvergedError) as caught:
        aircraft.trim(table, speed_kt=10)
    assert str(caught.value) == expected


def test_a_point_that_does_not_converge_is_an_error_not_a_result():
    with pytest.raises(pg.NotConvergedError, match="did not converge at alpha 70 deg"):
        pg.point("naca0012", re=1e6, alpha=70)
    with pytest.raises(pg.NotConvergedError, match="to Cl 4"):
        pg.point("naca0012", re=1e6, cl=4.0)
    with pytest.raises(ValueError, match="give alpha or cl"):
        pg.point("naca0012", re=1e6)
    with pytest.raises(ValueError, match="alpha NaN: not a finite angle"):
        pg.point("naca0012", re=1e6, alpha=float("nan"))
    # The CLI's bounds: α within ±180°, Re from 10³.
    with pytest.raises(ValueError, match="alpha 1e\\+?308: outside -180"):
        pg.point("naca0012", re=1e6, alpha=1e308)
    with pytest.raises(ValueError, match="re 500: the viscous solver takes Reynolds numbers from"):
        pg.point("naca0012", re=500, alpha=2.0)


def test_unconverged_polar_points_are_flagged_never_dropped():
    pol = pg.polar("naca0012", re=2e5, alpha=[0.0, 2.0, 70.0])
    assert len(pol) == 3 and list(pol.alpha) == [0.0, 2.0, 70.0]
    assert pol.converged[:2].all() and not pol.converged[2:].any()


def test_empty_table_lookups_are_nan_and_the_rotor_refuses_it(repo):
    empty = pg.table("naca0012", re=[2e5], mach=[0.0], alpha=[60.0])
    assert not empty.has_lookup and empty.converged_count == 0
    assert np.isnan(empty.lookup(0.0, 2e5, 0.0).cl)
    aircraft = pg.rotor.Aircraft.read(repo / "aircraft" / "mtosport.toml")
    with pytest.raises(ValueError, match="table: empty table: no polar has at least 2"):
        aircraft.trim(empty)
