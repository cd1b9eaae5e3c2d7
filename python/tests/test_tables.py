"""Tables: every file format of the CLI, and lookups — against the library's lookups as the
CLI writes them (the C81 decks of ``polargen convert``), against the interpolation rules, and
with the flags and the 360° extension."""

from __future__ import annotations

import math

import numpy as np
import polargen as pg
import pytest

from conftest import floats, read_csv_columns, same


@pytest.fixture(scope="module")
def shipped(repo):
    return pg.Table.read(repo / "polars" / "naca8h12_xtr0.07.csv")


@pytest.mark.parametrize("fmt, ext", [("csv", "csv"), ("json", "json"), ("xfoil", "pol"),
                                      ("c81", "c81")])
def test_every_format_is_the_cli_convert_output(cli, repo, tmp_path, shipped, fmt, ext):
    source = repo / "polars" / "naca8h12_xtr0.07.csv"
    (tmp_path / "cli").mkdir()
    (tmp_path / "py").mkdir()
    cli.run("polargen", "convert", str(source), "--out", str(tmp_path / "cli" / f"t.{ext}"),
            "--format", fmt)
    written = shipped.write(tmp_path / "py" / f"t.{ext}", format=fmt)
    cli_files = sorted(p.name for p in (tmp_path / "cli").iterdir())
    assert sorted(p.rsplit("/", 1)[-1] for p in written) == cli_files
    for name in cli_files:
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes()


def test_csv_and_json_read_back_exactly_and_xfoil_polars_read(tmp_path, shipped):
    for ext in ("csv", "json"):
        shipped.write(tmp_path / f"t.{ext}")
        assert pg.Table.read(tmp_path / f"t.{ext}") == shipped
    files = shipped.write(tmp_path / "p.pol")
    assert len(files) == len(shipped.re) * len(shipped.mach)
    one = pg.Table.read(files[0])
    assert len(one.re) == 1 and len(one.mach) == 1
    node = shipped.polar(one.re[0], one.mach[0])
    with pytest.raises(KeyError, match="no polar at Re 1.234e"):
        shipped.polar(1.234e6, 0.0)
    pol = one.polars()[0]
    keep = node.converged
    # The .pol text keeps XFOIL's fixed decimals.
    assert np.allclose(pol.cl, node.cl[keep], atol=5e-5)
    assert np.allclose(pol.alpha, node.alpha[keep], atol=5e-4)
    deck = pg.Table.read(shipped.write(tmp_path / "t.c81")[0])
    assert len(deck.re) == 1 and np.allclose(deck.mach, shipped.mach)


def c81_blocks(text: str):
    """(mach, alpha rows, [cl, cd, cm] fields as text) of a C81 deck."""
    lines = text.splitlines()
    nm, na = int(lines[0][30:32]), int(lines[0][32:34])
    per_row = lambda n: 1 + (n - 1) // 9  # lines per row of n values  # noqa: E731
    fields = lambda line: [line[k:k + 7] for k in range(7, len(line), 7)]  # noqa: E731
    k, blocks, mach, alphas = 1, [], None, []
    for _ in range(3):
        header = [f for line in lines[k:k + per_row(nm)] for f in fields(line)]
        mach = [float(f) for f in header]
        k += per_row(nm)
        rows, alphas = [], []
        for _ in range(na):
            alphas.append(float(lines[k][:7]))
            rows.append([f for line in lines[k:k + per_row(nm)] for f in fields(line)])
            k += per_row(nm)
        blocks.append(rows)
    return np.array(mach), np.array(alphas), blocks


def c81_matches(field: str, v: float) -> bool:
    """A C81 field (one decimal count per block, ≤ 4; negatives as `-.0100`) holds `v` to
    its last printed digit."""
    decimals = len(field.strip().split(".")[1]) if "." in field else 0
    return abs(float(field) - v) <= 0.5 * 10.0 ** -decimals * (1 + 1e-9) + 1e-12


def test_lookups_are_the_library_lookups_of_the_c81_deck(cli, repo, tmp_path, shipped):
    """Every value of the CLI's C81 deck (the library's lookups over −180…180°, the 360°
    extension included, at every Mach of one Re) equals the Python lookup there."""
    out = tmp_path / "deck.c81"
    cli.run("polargen", "convert", str(repo / "polars" / "naca8h12_xtr0.07.csv"), "--out",
            str(out), "--format", "c81")
    decks = {float(p.stem.split("_Re")[1]): p for p in tmp_path.glob("deck_Re*.c81")}
    assert sorted(decks) == list(shipped.re)
    re = shipped.re[2]
    deck = decks[re]
    mach, alphas, blocks = c81_blocks(deck.read_text())
    assert np.allclose(mach, shipped.mach) and alphas[0] == -180 and alphas[-1] == 180
    looked = shipped.lookup(alphas[:, None], re, shipped.mach[None, :])
    assert looked.cl.shape == (len(alphas), len(mach))
    assert looked.post_stall[0].all() and not looked.post_stall[len(alphas) // 2].any()
    for block, values in zip(blocks, (looked.cl, looked.cd, looked.cm)):
        for row, fields in zip(values, block):
            assert all(c81_matches(f, v) for f, v in zip(fields, row)), (fields, row)


def test_lookups_broadcast_and_follow_the_interpolation_rules(shipped):
    # Exact at the usable nodes (converged, not in massive separation).
    node = shipped.polars()[7]
    keep = node.usable
    at = shipped.lookup(node.alpha[keep], node.re, node.mach)
    assert same(at.cl, node.cl[keep]) and same(at.cd, node.cd[keep]) and same(at.cm, node.cm[keep])
    assert not (at.re_clamped.any() or at.mach_clamped.any() or at.post_stall.any())
    # Linear in ln Re between two nodes, at a node α and Mach.
    r0, r1 = shipped.re[1], shipped.re[2]
    w = 0.3
    re = math.exp((1 - w) * math.log(r0) + w * math.log(r1))
    a, m = 2.0, shipped.mach[1]
    mid, lo, hi = (shipped.lookup(a, r, m) for r in (re, r0, r1))
    assert abs(float(mid.cd) - ((1 - w) * float(lo.cd) + w * float(hi.cd))) < 1e-15
    # Broadcasting: a (3, 1) × (4,) grid equals the scalar lookups.
    alphas, res = np.array([[-3.0], [4.25], [30.0]]), np.array([3e5, 1e6, 1.9e6, 4e6])
    grid = shipped.lookup(alphas, res, 0.41)
    assert grid.cd.shape == (3, 4)
    for i in range(3):
        for j in range(4):
            one = shipped.lookup(alphas[i, 0], res[j], 0.41)
            assert one.cd.shape == ()
            assert float(one.cd) == grid.cd[i, j] and bool(one.post_stall) == grid.post_stall[i, j]
    assert grid.re_clamped[:, 3].all() and not grid.re_clamped[:, 1].any()
    assert grid.post_stall[2].all() and not grid.post_stall[1].any()
    frame = pytest.importorskip("pandas") and grid.to_pandas()
    assert len(frame) == 12


def test_the_360_degree_extension_is_the_flat_plate_past_90_degrees(shipped):
    p = shipped.post_stall
    assert p == {"cd_max": 2.0, "cd_reverse": 0.03, "vc_min_junction_deg": 3.0}
    for table, cd_max in ((shipped, 2.0), (shipped.with_post_stall(cd_max=1.8), 1.8)):
        l = table.lookup([90.0, -90.0, 180.0, -180.0, 120.0, 370.0], 1e6, 0.2)
        assert np.allclose(l.cl[:4], 0.0, atol=1e-12)
        assert np.allclose(l.cd[:2], cd_max) and np.allclose(l.cd[2:4], 0.03)
        # Flat plate: cm = −¼·cd_max·sin α·(1 − cos α).
        assert np.allclose(l.cm[:2], [-0.25 * cd_max, 0.25 * cd_max])
        a = math.radians(120.0)
        assert np.isclose(l.cl[4], cd_max * math.sin(a) * math.cos(a))
        assert l.post_stall[:5].all() and float(l.cl[5]) == float(table.lookup(10.0, 1e6, 0.2).cl)
    with pytest.raises(ValueError, match="post-stall parameter cd_max = -1 is invalid"):
        shipped.with_post_stall(cd_max=-1)


def test_alpha_at_cl_reads_the_paper_table5_way(shipped):
    alpha, at = shipped.alpha_at_cl(0.8, 1.9e6, 0.41)
    assert abs(at["cl"] - 0.8) < 1e-9
    assert float(shipped.lookup(alpha, 1.9e6, 0.41).cd) == at["cd"]
    assert shipped.alpha_at_cl(5.0, 1.9e6, 0.41) is None


def test_table_frames_and_metadata(shipped, repo):
    pandas = pytest.importorskip("pandas")
    frame = shipped.to_pandas()
    columns = read_csv_columns((repo / "polars" / "naca8h12_xtr0.07.csv").read_text())
    assert len(frame) == shipped.point_count == len(columns["alpha"])
    assert same(frame["cd"].to_numpy(), floats(columns["cd"]))
    assert same(frame["re"].to_numpy(), floats(columns["re"]))
    assert isinstance(frame, pandas.DataFrame)
    assert shipped.meta["xtr_top_set"] == 0.07 and shipped.meta["panels"] == 160
