"""docs/PYTHON.md's worked example, run as written, and the numbers it prints against the
command line on the same Bandai waves."""

from __future__ import annotations

import json
import os
import pathlib
import re
import subprocess
import sys

import pytest

import bunraku
from conftest import BANDAI_DIR, SOURCE_DIR, run_cli, same_bits, take_matrix


def example_code() -> str:
    text = (SOURCE_DIR / "docs" / "PYTHON.md").read_text()
    section = text.split("## Worked example", 1)[1]
    match = re.search(r"```python\n(.*?)```", section, re.S)
    assert match, "docs/PYTHON.md has no python block in its worked example"
    return match.group(1)


@pytest.mark.bandai
def test_the_worked_example_runs_and_writes_its_plot(bandai_waves, tmp_path):
    package = pathlib.Path(bunraku.__file__).resolve().parents[1]  # the build tree's python/ (or dist-packages)
    env = dict(os.environ, BUNRAKU_BANDAI=str(BANDAI_DIR), MPLBACKEND="Agg", PYTHONPATH=str(package))
    result = subprocess.run([sys.executable, "-c", example_code()], cwd=tmp_path, env=env, capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    png = tmp_path / "waves-normalised.png"
    assert png.exists() and png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and png.stat().st_size > 10000
    out = result.stdout
    assert "15 takes" in out and "reference:" in out
    lines = out.splitlines()
    header = [i for i, line in enumerate(lines) if line.split() == ["normal", "active", "exhausted"]]
    assert header, out  # the amplitude table: a column per style, a row per channel
    rows = [line.split() for line in lines[header[-1] + 1:]]
    assert [row[0] for row in rows][:2] == ["head.x", "head.y"] and len(rows) == 24
    assert all(float(row[1]) == 0.0 for row in rows)  # the neutral style: z = 0 (hypothesis 4)


@pytest.mark.bandai
def test_the_examples_cell_matches_bunraku_normalise(cli, bandai_waves, tmp_path):
    folder = tmp_path / "waves"
    run_cli(cli, "corpus", *bandai_waves, "-o", folder, "--name", "waves")
    out = tmp_path / "cell"
    summary = json.loads(run_cli(cli, "normalise", folder, "--function", "wave-right-hand", "--emotion", "active",
                                 "-o", out, "--json").stdout)
    corpus = bunraku.Corpus.from_files([str(p) for p in bandai_waves], name="waves")
    cell = bunraku.normalise(corpus, function="wave-right-hand", emotion="active")
    assert [t.to_dict() for t in cell.takes] == summary["takes"]
    for t in cell.takes:
        path = out / f"wave-right-hand_active_{t.take}_normalised.csv"
        assert same_bits(t.normalised.values, take_matrix(path))
