"""The example script runs headless and reproduces the paper's comparison (skipped without
matplotlib, which is not a dependency of polargen)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "clean_vs_contaminated.py"


def test_clean_vs_contaminated_example(tmp_path):
    pytest.importorskip("matplotlib")
    out = tmp_path / "figure.png"
    run = subprocess.run([sys.executable, str(EXAMPLE), "--out", str(out)], capture_output=True,
                         text=True, cwd=tmp_path, timeout=300)
    assert run.returncode == 0, run.stderr
    assert out.stat().st_size > 10_000 and out.read_bytes()[:4] == b"\x89PNG"
    lines = run.stdout.splitlines()
    # Table 5 rows: Cd at Cl = 0.8 clean / contaminated, each with the paper's values beside.
    rows = {line.split()[0]: line.split() for line in lines if line.startswith("  naca")}
    assert set(rows) == {"naca8h12", "naca23012"}
    for name, row in rows.items():
        clean, dirty = float(row[1]), float(row[3])
        assert 0.004 < clean < dirty < 0.02, row
