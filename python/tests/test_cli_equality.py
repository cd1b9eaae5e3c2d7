"""The Python results are the command-line tools' results, bit for bit, on the same cases:
polars and tables (the CSV the CLI writes, byte for byte, and every column parsed back), one
operating point's distributions (``plot-point --csv``), and trim/takeoff (``gyro --json``)."""

from __future__ import annotations

import json
import math
import warnings

import numpy as np
import polargen as pg
import pytest

from conftest import floats, read_csv_columns, same

COLUMNS = ("alpha", "cl", "cd", "cdp", "cm", "xtr_top", "xtr_bot", "cdf", "residual")


def cli_polar_csv(cli, tmp_path, *args: str) -> str:
    out = tmp_path / "cli.csv"
    cli.run("polargen", *args, "--out", str(out))
    return out.read_text()


def assert_polar_equals_csv(pol: pg.Polar, text: str) -> None:
    columns = read_csv_columns(text)
    for name in COLUMNS:
        assert same(getattr(pol, name), floats(columns[name])), name
    assert list(pol.converged) == [v == "true" for v in columns["converged"]]
    assert list(pol.iterations) == [int(v) for v in columns["iterations"]]


def test_paper_polar_with_trip_equals_the_cli(cli, tmp_path):
    """The paper's condition (NACA 8-H-12, Re 1.9e6, M 0.41, trip at 7 %): columns and file."""
    args = ("--airfoil", "naca8h12", "--re", "1.9e6", "--mach", "0.41", "--alpha", "-4:12:0.5",
            "--xtr", "0.07")
    text = cli_polar_csv(cli, tmp_path, *args)
    pol = pg.polar("naca8h12", re=1.9e6, mach=0.41, alpha="-4:12:0.5", xtr=0.07)
    assert_polar_equals_csv(pol, text)
    assert pol.converged.sum() >= 30
    # The same computation written by the package is the CLI's file, byte for byte.
    table = pg.table("naca8h12", re=[1.9e6], mach=[0.41], alpha="-4:12:0.5", xtr=0.07)
    written = table.write(tmp_path / "py.csv")
    assert written == [str(tmp_path / "py.csv")]
    assert (tmp_path / "py.csv").read_text() == text


def test_per_side_transition_ncrit_panels_and_tolerance_equal_the_cli(cli, tmp_path):
    args = ("--airfoil", "naca23012", "--re", "1e6", "--mach", "0.2", "--alpha", "-2:6:2",
            "--xtr-top", "0.3", "--xtr-bot", "0.9", "--ncrit", "7", "--panels", "140",
            "--tolerance", "1e-4")
    text = cli_polar_csv(cli, tmp_path, *args)
    pol = pg.polar(pg.Airfoil.naca("23012"), re=1e6, mach=0.2, alpha=[-2, 0, 2, 4, 6],
                   xtr=(0.3, 0.9), ncrit=7, panels=140, tolerance=1e-4, threads=1)
    assert_polar_equals_csv(pol, text)
    assert pol.meta["xtr_top_set"] == 0.3 and pol.meta["xtr_bot_set"] == 0.9
    assert np.all(pol.xtr_bot[pol.converged] <= 0.9)


def test_per_side_ncrit_equals_the_cli(cli, tmp_path):
    args = ("--airfoil", "naca0012", "--re", "1e6", "--alpha", "0:2:1", "--ncrit-top", "9",
            "--ncrit-bot", "3")
    text = cli_polar_csv(cli, tmp_path, *args)
    pol = pg.polar("naca0012", re=1e6, alpha="0:2:1", ncrit_top=9, ncrit_bot=3, threads=1)
    assert_polar_equals_csv(pol, text)
    assert (pol.meta["ncrit"], pol.meta["ncrit_top"], pol.meta["ncrit_bot"]) == (None, 9.0, 3.0)
    # One side given: the other takes ncrit; both equal is the plain ncrit, bit for bit.
    same = pg.polar("naca0012", re=1e6, alpha="0:2:1", ncrit=3, ncrit_top=9, threads=1)
    assert np.array_equal(same.cl, pol.cl)
    plain = pg.polar("naca0012", re=1e6, alpha="0:2:1", ncrit=5, threads=1)
    sides = pg.polar("naca0012", re=1e6, alpha="0:2:1", ncrit_top=5, ncrit_bot=5, threads=1)
    assert np.array_equal(plain.cd, sides.cd) and plain.meta["ncrit"] == 5.0
    # The lower surface's N_crit 3 moves its transition ahead: lift at alpha 0 (XFOIL 0.0107).
    at_zero = pg.point("naca0012", re=1e6, alpha=0, ncrit_top=9, ncrit_bot=3)
    assert abs(at_zero.cl - pol.cl[0]) < 1e-12 and at_zero.xtr_bot < at_zero.xtr_top


def test_coordinate_file_and_arrays_give_the_cli_polar(cli, repo, tmp_path):
    path = repo / "tests" / "data" / "xfoil" / "naca2412_buffer.dat"
    text = cli_polar_csv(cli, tmp_path, "--airfoil", str(path), "--re", "1e6", "--mach", "0",
                         "--alpha",
                         "0:4:2")
    from_file = pg.Airfoil.from_file(path)
    assert_polar_equals_csv(pg.polar(from_file, re=1e6, alpha="0:4:2"), text)
    arrays = pg.Airfoil.from_coordinates(from_file.x, from_file.y, name=from_file.name)
    assert_polar_equals_csv(pg.polar(arrays, re=1e6, alpha="0:4:2"), text)
    assert np.array_equal(arrays.coordinates[:, 0], from_file.x)


def test_table_equals_the_cli_table(cli, tmp_path):
    args = ("--airfoil", "naca0012", "--re", "5e5,2e6", "--mach", "0,0.3", "--alpha",
            "-2:8:1", "--xtr", "0.5")
    text = cli_polar_csv(cli, tmp_path, *args)
    table = pg.table(pg.Airfoil.naca("0012"), re=[5e5, 2e6], mach=[0.0, 0.3], alpha="-2:8:1",
                     xtr=0.5)
    table.write(tmp_path / "py.csv")
    assert (tmp_path / "py.csv").read_text() == text
    assert table == pg.Table.read(tmp_path / "py.csv")
    frame_rows = sum(len(p) for p in table.polars())
    assert frame_rows == table.point_count == 44


@pytest.mark.parametrize("at", [("--alpha", "3"), ("--cl", "0.8")])
def test_point_distributions_equal_plot_point_csv(cli, tmp_path, at):
    csv_path = tmp_path / "point.csv"
    cli.run("polargen", "plot-point", "--airfoil", "naca8h12", "--re", "1.9e6", "--mach",
            "0.41", "--xtr", "0.07", *at, "--out", str(tmp_path / "point.svg"), "--csv",
            str(csv_path))
    columns = read_csv_columns(csv_path.read_text())
    kwargs = {"alpha": 3.0} if at[0] == "--alpha" else {"cl": 0.8}
    pt = pg.point("naca8h12", re=1.9e6, mach=0.41, xtr=0.07, **kwargs)
    assert pt.converged
    surfaces = np.array(columns["surface"])
    for surface in ("upper", "lower", "wake"):
        dist = getattr(pt, surface)
        rows = surfaces == surface
        assert rows.sum() == len(dist) > 0
        for name in ("s", "x", "y", "ue", "cp", "dstar", "theta", "cf", "h", "hk",
                     "n_or_ctau"):
            assert same(getattr(dist, name), floats(columns[name])[rows]), (surface, name)
        assert list(dist.turbulent) == [v == "true" for v in np.array(columns["turbulent"])[rows]]
    assert same(np.full(len(surfaces), pt.alpha), floats(columns["alpha"]))
    if at[0] == "--cl":
        assert abs(pt.cl - 0.8) <= 1e-4


@pytest.fixture(scope="module")
def section(repo):
    return pg.Table.read(repo / "polars" / "naca8h12_free.csv")


@pytest.fixture(scope="module")
def aircraft(repo):
    return pg.rotor.Aircraft.read(repo / "aircraft" / "mtosport.toml")


def test_trim_has_the_fields_and_values_of_gyro_trim_json(cli, repo, section, aircraft):
    args = ("trim", "--aircraft", "aircraft/mtosport.toml", "--table",
            "polars/naca8h12_free.csv", "--json")
    for extra, kwargs in [((), {}), (("--speed-kt", "70", "--mass", "420", "--altitude-m",
                                      "500"), {"speed_kt": 70, "mass_kg": 420,
                                               "altitude_m": 500})]:
        run = cli.run("gyro", *args, *extra)
        expected = json.loads(run.stdout)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            result = aircraft.trim(section, **kwargs)
        assert result.to_dict() == expected
        assert list(result) == list(expected)
        assert result.rotor_rpm == expected["rotor_rpm"]
        # The notes gyro prints on stderr, also issued as warnings.
        notes = [line[len("gyro: "):] for line in run.stderr.splitlines()]
        assert result.notes == notes
        assert [str(w.message) for w in caught] == notes


def test_takeoff_has_the_fields_values_and_history_of_gyro_takeoff(cli, tmp_path, section,
                                                                   aircraft):
    history = tmp_path / "history.csv"
    expected = json.loads(cli.run(
        "gyro", "takeoff", "--aircraft", "aircraft/mtosport.toml", "--table",
        "polars/naca8h12_free.csv", "--json", "--history", str(history)).stdout)
    run = cli.run("gyro", "takeoff", "--aircraft", "aircraft/mtosport.toml", "--table",
                  "polars/naca8h12_free.csv")
    printed = [line.removeprefix("gyro: ") for line in run.stderr.splitlines()
               if "during the takeoff" in line]
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = pg.rotor.takeoff(aircraft, section)
    assert result.to_dict() == expected
    assert printed and result.notes == printed
    assert [str(w.message) for w in caught] == printed
    columns = read_csv_columns(history.read_text())
    for name, values in result.history.items():
        assert same(values, floats(columns[name])), name


def test_autorotate_has_the_fields_and_values_of_gyro_autorotate_json(cli, repo):
    """The PCA-2 rotor in the tunnel (NACA Report 515, Table III row μ .216, α 8.3°), by wind
    speed and by μ at the row's rotor speed, with a pitch override."""
    table = pg.Table.read(repo / "polars" / "goe429_xtr0.07.csv")
    rotor = pg.rotor.Rotor.read(repo / "aircraft" / "pca2.toml")
    base = ("autorotate", "--aircraft", "aircraft/pca2.toml", "--table",
            "polars/goe429_xtr0.07.csv", "--json", "--alpha-deg", "8.3")
    for extra, kwargs in [(("--speed-m-s", "15.7"), {"speed_m_s": 15.7}),
                          (("--mu", "0.216", "--reference-rpm", "100.5", "--pitch-deg", "2.7"),
                           {"mu": 0.216, "reference_rpm": 100.5, "pitch_deg": 2.7})]:
        run = cli.run("gyro", *base, *extra)
        expected = json.loads(run.stdout)
        with warnings.catch_warnings(record=True):
            warnings.simplefilter("always")
            result = rotor.autorotate(table, alpha_deg=8.3, **kwargs)
        assert result.to_dict() == expected
        assert list(result) == list(expected)
        notes = [line[len("gyro: "):] for line in run.stderr.splitlines()]
        assert result.notes == notes
    with pytest.raises(ValueError, match="alpha_deg"):
        rotor.autorotate(table, alpha_deg=95.0, speed_m_s=20.0)


def test_autorotate_cases_are_the_rows_of_gyro_autorotate_cases(cli, repo, tmp_path):
    """Three tunnel cases, one of them (α 1°, 10 m/s) without autorotation: the records are the
    rows of ``gyro autorotate --cases --json`` (NaN where the JSON has null), in order."""
    table = pg.Table.read(repo / "polars" / "goe429_xtr0.07.csv")
    rotor = pg.rotor.Rotor.read(repo / "aircraft" / "pca2.toml")
    alphas, speeds = [8.3, 4.1, 1.0], [15.7, 25.0, 10.0]
    cases = tmp_path / "cases.csv"
    cases.write_text("alpha_deg,speed_m_s\n" +
                     "".join(f"{a},{v}\n" for a, v in zip(alphas, speeds)))
    run = cli.run("gyro", "autorotate", "--aircraft", "aircraft/pca2.toml", "--table",
                  "polars/goe429_xtr0.07.csv", "--cases", str(cases), "--json")
    expected = json.loads(run.stdout)
    with warnings.catch_warnings(record=True):
        warnings.simplefilter("always")
        records = rotor.autorotate_cases(table, alphas, speeds)
    assert len(records) == len(expected) == 3
    for got, want in zip(records, expected):
        assert list(got) == list(want)
        for key, value in want.items():
            if value is None:
                assert math.isnan(got[key]), key
            else:
                assert got[key] == value, key
    assert records[0]["error"] == "" and records[2]["error"] != ""
    assert list(records.to_pandas().columns) == list(expected[0])
    with pytest.raises(ValueError, match="same number of cases"):
        rotor.autorotate_cases(table, [8.3], [15.7, 20.0])
