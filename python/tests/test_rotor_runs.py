"""The rotor in Python as on the command line: ``Aircraft.sweep`` is ``gyro sweep --json``,
``rotor.compare`` is ``gyro compare --json``, ``rotor.study`` is ``gyro study … --json``; the
results are records with the JSON keys (and DataFrames of them); bad settings stop before any
work with the command line's messages."""

from __future__ import annotations

import json
import warnings

import polargen as pg
import pytest


@pytest.fixture(scope="module")
def clean(repo):
    return pg.Table.read(repo / "polars" / "naca8h12_free.csv")


@pytest.fixture(scope="module")
def tripped(repo):
    return pg.Table.read(repo / "polars" / "naca8h12_xtr0.07.csv")


@pytest.fixture(scope="module")
def aircraft(repo):
    return pg.rotor.Aircraft.read(repo / "aircraft" / "mtosport.toml")


def test_sweep_is_gyro_sweep_json(cli, aircraft, clean):
    expected = json.loads(cli.run(
        "gyro", "sweep", "--aircraft", "aircraft/mtosport.toml", "--table",
        "polars/naca8h12_free.csv", "--from-kt", "40", "--to-kt", "70", "--step-kt", "10",
        "--json").stdout)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        records = aircraft.sweep(clean, [40, 50, 60, 70])
        by_function = pg.rotor.sweep(aircraft, clean, range(40, 80, 10))
    assert [r.to_dict() for r in records] == expected
    assert [dict(r) for r in by_function] == expected
    frame = records.to_pandas()
    assert list(frame.columns) == list(expected[0]) and len(frame) == 4
    assert frame["speed_kt"].tolist() == [40.0, 50.0, 60.0, 70.0]


def test_compare_is_gyro_compare_json(cli, aircraft, clean, tripped):
    expected = json.loads(cli.run(
        "gyro", "compare", "--aircraft", "aircraft/mtosport.toml", "--clean",
        "polars/naca8h12_free.csv", "--contaminated", "polars/naca8h12_xtr0.07.csv",
        "--json").stdout)
    with pytest.warns(UserWarning, match="clean: during the takeoff"):
        result = pg.rotor.compare(aircraft, clean, tripped)
    assert {k: [dict(r) for r in v] for k, v in result.items()} == expected
    # The notes gyro compare prints: each case's trim and takeoff lookup shares.
    assert any(n.startswith("note: contaminated: at 60.0 kt, ") for n in result["trim"].notes)
    assert set(result["trim"].to_pandas().columns) == {
        "quantity", "paper_clean", "paper_contaminated", "ours_clean", "ours_contaminated"}


def test_bad_sweeps_and_studies_stop_before_any_work(aircraft, clean, repo, tmp_path):
    with pytest.raises(ValueError, match="speeds_kt -5"):
        aircraft.sweep(clean, [60, -5])
    with pytest.raises(ValueError, match="speeds_kt: 0 speeds"):
        aircraft.sweep(clean, [])
    with pytest.raises(ValueError, match="unknown study 'noise'"):
        pg.rotor.study("noise", repo / "aircraft" / "mtosport.toml")
    with pytest.raises(ValueError, match="1.5"):
        pg.rotor.study("contamination", repo / "aircraft" / "mtosport.toml", trips=[1.5],
                       cache=tmp_path)
    with pytest.raises(FileNotFoundError):
        pg.rotor.study("wing", tmp_path / "missing.toml", cache=tmp_path)
    assert not any(tmp_path.iterdir()), "nothing solved or written"


def test_study_is_gyro_study_json(cli, repo, tmp_path):
    """The wing study at one area and speed: the clean 8-H-12 table is solved once into the
    cache folder, the command line then reads it and prints the same records."""
    cache = tmp_path / "cache"
    records = pg.rotor.study("wing", repo / "aircraft" / "mtosport.toml", areas_m2=[0, 1.7],
                             speeds_kt=[60], cache=cache)
    expected = json.loads(cli.run(
        "gyro", "study", "wing", "--aircraft", "aircraft/mtosport.toml", "--areas", "0,1.7",
        "--speeds", "60", "--cache", str(cache), "--json").stdout)
    assert [dict(r) for r in records] == expected
    assert records.to_pandas()["wing_area_m2"].tolist() == [0.0, 1.7]
