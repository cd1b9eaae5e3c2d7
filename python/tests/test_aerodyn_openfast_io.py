"""AeroDyn airfoil files written by polargen, read back with OpenFAST's own Python reader.

Skipped when `openfast_io` (PyPI `openfast-io`) is not installed or no polargen binary is
built. Run from the repository root after `cargo build --release`:

    pip install openfast-io pytest && pytest python/tests/test_aerodyn_openfast_io.py
"""

import csv
import math
import os
import pathlib
import subprocess

import pytest

FAST_reader = pytest.importorskip("openfast_io.FAST_reader")

ROOT = pathlib.Path(__file__).resolve().parents[2]
TABLE = ROOT / "tests" / "data" / "xfoil" / "naca8h12_Re1.9e6_M0.41_free.csv"
GRID = ROOT / "polars" / "naca8h12_free.csv"


def polargen():
    """The polargen binary: in $POLARGEN_BIN_DIR (as .ci/run sets it), else target/release or
    target/debug."""
    bin_dir = os.environ.get("POLARGEN_BIN_DIR")
    for candidate in (
        bin_dir and pathlib.Path(bin_dir) / "polargen",
        ROOT / "target" / "release" / "polargen",
        ROOT / "target" / "debug" / "polargen",
    ):
        if candidate and pathlib.Path(candidate).is_file():
            return str(candidate)
    pytest.skip("no polargen binary built")


def read_aerodyn(path):
    """The list of tables openfast_io reads from one AeroDyn airfoil file."""
    reader = FAST_reader.InputReader_OpenFAST()
    ad = reader.fst_vt["AeroDyn"]
    ad.update(NumAFfiles=1, AFNames=[str(path)], InCol_Alfa=1, InCol_Cl=2, InCol_Cd=3,
              InCol_Cm=4, InCol_Cpmin=0)
    reader.read_AeroDynPolar()
    return ad["af_data"][0]


def convert(table, out, *extra):
    subprocess.run([polargen(), "convert", str(table), "--format", "aerodyn", "--out",
                    str(out), "-q", *extra], check=True)


def test_one_polar_reads_back_with_the_table_values(tmp_path):
    out = tmp_path / "naca8h12.dat"
    convert(TABLE, out, "--cd-max", "1.8")
    tables = read_aerodyn(out)
    assert len(tables) == 1
    t = tables[0]
    assert math.isclose(t["Re"], 1.9e6, rel_tol=1e-12)
    assert t["InclUAdata"] is True
    alpha, cl, cd, cm = t["Alpha"], t["Cl"], t["Cd"], t["Cm"]
    assert len(alpha) == t["NumAlf"]
    assert alpha[0] == -180.0 and alpha[-1] == 180.0
    assert all(b > a for a, b in zip(alpha, alpha[1:]))
    assert (cl[0], cd[0], cm[0]) == (cl[-1], cd[-1], cm[-1])
    # Every point of the source polar appears with its exact values.
    rows = list(csv.DictReader(open(TABLE)))
    assert rows
    for row in rows:
        k = alpha.index(float(row["alpha"]))
        assert cl[k] == float(row["cl"])
        assert cd[k] == float(row["cd"])
        assert cm[k] == float(row["cm"])
    # The broadside drag of the 360-degree extension is the requested Cd_max.
    assert math.isclose(cd[alpha.index(90.0)], 1.8, rel_tol=1e-9)


def test_a_grid_gives_one_file_per_mach_with_one_table_per_re(tmp_path):
    convert(GRID, tmp_path / "grid.dat")
    files = sorted(p.name for p in tmp_path.iterdir())
    assert files == ["grid_M0.2.dat", "grid_M0.3.dat", "grid_M0.4.dat", "grid_M0.5.dat",
                     "grid_M0.55.dat", "grid_M0.6.dat", "grid_M0.65.dat", "grid_M0.dat"]
    tables = read_aerodyn(tmp_path / "grid_M0.3.dat")
    res = [t["Re"] for t in tables]
    assert len(res) == 8
    for got, want in zip(res, [1e5, 2e5, 4e5, 7e5, 1e6, 1.5e6, 2e6, 3e6]):
        assert math.isclose(got, want, rel_tol=1e-12)


def test_a_flap_sweep_is_one_file_with_one_table_per_deflection(tmp_path):
    """--flap-deg with --format aerodyn: one file for the one (Re, M), one table per
    deflection, as OpenFAST's AFTabMod 3 needs them (one Re, UserProp increasing)."""
    out = tmp_path / "flap.dat"
    subprocess.run([polargen(), "--airfoil", "naca0012", "--re", "1e6", "--alpha", "-4:8:4",
                    "--flap", "0.75:0", "--flap-deg", "5,-5,0", "--format", "aerodyn",
                    "--out", str(out), "-q"], check=True)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["flap.dat"]
    tables = read_aerodyn(out)
    # openfast_io 5.0 reads UserProp as an integer where it can (a string otherwise).
    assert [t["UserProp"] for t in tables] == [-5, 0, 5]
    assert [t["Re"] for t in tables] == [1e6, 1e6, 1e6]
    assert all(t["InclUAdata"] is True for t in tables)
    # The symmetric section's lift at alpha 0 is the flap's: -, 0, + (thin-airfoil theory for
    # a 25 % flap: 0.33 for 5 degrees); the zero-lift angle moves the other way.
    cl0 = [t["Cl"][t["Alpha"].index(0.0)] for t in tables]
    assert cl0[0] < -0.25 and abs(cl0[1]) < 1e-3 and cl0[2] > 0.25
    assert tables[0]["alpha0"] > 1.0 and abs(tables[1]["alpha0"]) < 0.1
    assert tables[2]["alpha0"] < -1.0
