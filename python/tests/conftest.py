"""Shared fixtures: the repository's data files and the command-line tools the Python results
are compared with.

The tools are looked up in ``$POLARGEN_BIN_DIR`` (CI sets it to the folder ``cargo test``
built them in; then they must be there), else in ``target/release`` and ``target/debug`` of
the repository; tests that need them are skipped, saying why, when none is found."""

from __future__ import annotations

import csv
import io
import os
import subprocess
from pathlib import Path
from typing import Dict, List

import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]


def _tool_dir() -> Path | None:
    given = os.environ.get("POLARGEN_BIN_DIR")
    if given:
        folder = Path(given)
        for tool in ("polargen", "gyro"):
            if not (folder / tool).is_file():
                raise RuntimeError(f"POLARGEN_BIN_DIR={given}: no {tool} binary there")
        return folder
    for profile in ("release", "debug"):
        folder = REPO / "target" / profile
        if (folder / "polargen").is_file() and (folder / "gyro").is_file():
            return folder
    return None


class Cli:
    """Runs the command-line tools of the repository."""

    def __init__(self, folder: Path) -> None:
        self.folder = folder

    def run(self, tool: str, *args: str, check: bool = True) -> subprocess.CompletedProcess:
        result = subprocess.run(
            [str(self.folder / tool), *args], capture_output=True, text=True, cwd=REPO
        )
        if check and result.returncode != 0:
            raise AssertionError(f"{tool} {' '.join(args)} failed: {result.stderr}")
        return result


@pytest.fixture(scope="session")
def cli() -> Cli:
    folder = _tool_dir()
    if folder is None:
        pytest.skip("no polargen/gyro binaries: run cargo build first or set POLARGEN_BIN_DIR")
    return Cli(folder)


@pytest.fixture(scope="session")
def repo() -> Path:
    return REPO


def read_csv_columns(text: str) -> Dict[str, List[str]]:
    """The columns of CSV text, as strings."""
    rows = list(csv.DictReader(io.StringIO(text)))
    return {name: [r[name] for r in rows] for name in rows[0]} if rows else {}


def floats(values: List[str]) -> np.ndarray:
    """CSV fields written by Rust (shortest round-trip, NaN, inf) as exact floats."""
    return np.array([float(v) for v in values], dtype=float)


def same(a: np.ndarray, b: np.ndarray) -> bool:
    """Bit-for-bit equal arrays (NaN equal to NaN)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and bool(np.all((a == b) | (np.isnan(a) & np.isnan(b))))
