"""The README's Python section as a user pastes it: its install line names the extras its
Python blocks need (declared in python/pyproject.toml; CI installs with the same line), and
every ```python block of the README runs as written, in a fresh folder holding the shipped
inputs, with matplotlib drawing off screen (Agg).

The shell blocks are run by the Rust test tests/readme_examples.rs; the Python blocks are run
here because they need the installed package, which only this suite has."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path
from typing import List, Tuple

import pytest

from conftest import REPO

#: The shipped folders the README's examples read.
INPUTS = ("aircraft", "geometry", "polars")


def blocks(language: str) -> List[Tuple[int, str]]:
    """The README's fenced blocks in ``language``: (first line number, text)."""
    found, inside, start, lines = [], False, 0, []
    for number, line in enumerate((REPO / "README.md").read_text().splitlines(), 1):
        if line.strip().startswith("```"):
            if inside:
                found.append((start, "\n".join(lines)))
                inside = False
            elif line.strip()[3:].strip() == language:
                inside, start, lines = True, number + 1, []
            continue
        if inside:
            lines.append(line)
    return found


def extras() -> dict:
    """The optional dependencies of python/pyproject.toml: extra → requirement names."""
    text = (REPO / "python" / "pyproject.toml").read_text()
    section = text.split("[project.optional-dependencies]", 1)[1].split("\n[", 1)[0]
    declared = {}
    for name, value in re.findall(r"^(\w+)\s*=\s*\[(.*)\]", section, re.M):
        declared[name] = [re.split(r"[<>=!~ ]", v.strip().strip('"'))[0]
                          for v in value.split(",") if v.strip()]
    return declared


def test_the_install_line_declares_what_the_python_blocks_import():
    lines = [line for _, block in blocks("sh") for line in block.splitlines()
             if line.strip().startswith("pip install") and "python" in line]
    assert lines, "no pip install line for the Python package in the README"
    asked = re.search(r'"\./python\[([\w,]+)\]"', lines[0])
    assert asked, f"the README's install line names no extras: {lines[0]}"
    declared = extras()
    wanted = asked.group(1).split(",")
    assert set(wanted) <= set(declared), (wanted, declared)
    installed = {req for name in wanted for req in declared[name]}
    code = "\n".join(block for _, block in blocks("python"))
    assert "to_pandas" not in code or "pandas" in installed
    assert ".plot" not in code or "matplotlib" in installed
    ci = (REPO / ".ci" / "run").read_text()
    assert "./python[" + ",".join(wanted) in ci, "CI does not install as the README says"


@pytest.mark.parametrize("line, code", blocks("python"), ids=lambda v: str(v)[:12])
def test_the_readme_python_block_runs_as_pasted(tmp_path, line, code):
    for folder in INPUTS:
        shutil.copytree(REPO / folder, tmp_path / folder)
    env = dict(os.environ, MPLBACKEND="Agg")
    run = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, env=env,
                         capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, f"README.md line {line}:\n{run.stderr}"
    left = sorted(p.name for p in tmp_path.iterdir() if p.name not in INPUTS)
    assert not left, f"README.md line {line} leaves files behind: {left}"


def test_the_readme_has_a_python_block():
    assert blocks("python"), "no ```python block in the README"
