"""Fixtures of the pytest suite of the Python module (bindings/python/tests, run by ctest).

The command line is the peer: every binding is checked against the files `bunraku` writes for
the same input, bit for bit (the data files hold shortest round-trip numbers, so a value read
back is the double the pipeline computed). Inputs: the demo corpus (`bunraku demo -o DIR`) and
the shared Bandai waves (../shared/data/bandai): when those are missing, a test fails under
CI=true and is skipped otherwise, its reason starting "bunraku-test: skipped:" (what ctest's
SKIP_REGULAR_EXPRESSION looks for, as tests/support/peer.h prints it).
"""

from __future__ import annotations

import json
import os
import pathlib
import subprocess
from typing import Dict, List

import numpy as np
import pytest

import bunraku

SOURCE_DIR = pathlib.Path(os.environ.get("BUNRAKU_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[3]))
SHARED_DIR = pathlib.Path(os.environ.get("BUNRAKU_SHARED_DIR", SOURCE_DIR.parent / "shared"))
BANDAI_DIR = SHARED_DIR / "data" / "bandai"
WAVE_STYLES = ["normal", "active", "exhausted"]


def wave_files() -> List[pathlib.Path]:
    return [BANDAI_DIR / f"wave-right-hand_{style}_00{k}.bvh" for style in WAVE_STYLES for k in range(1, 6)]


def pytest_configure(config):
    config.addinivalue_line("markers", "bandai: needs the shared Bandai waves (../shared/data/bandai)")


def require_peer(available: bool, what: str) -> None:
    """The missing-peer rule: fail under CI=true, skip (never pass) otherwise."""
    if available:
        return
    message = f"bunraku-test: skipped: {what} missing"
    if os.environ.get("CI") == "true":
        pytest.fail(message + " (CI=true)")
    pytest.skip(message)


@pytest.fixture(scope="session")
def cli() -> pathlib.Path:
    path = pathlib.Path(os.environ.get("BUNRAKU_CLI", SOURCE_DIR / "build" / "bin" / "bunraku"))
    if not path.exists():
        pytest.fail(f"the command line {path} is not built (set BUNRAKU_CLI)")
    return path


def run_cli(cli: pathlib.Path, *args: str, check: bool = True) -> subprocess.CompletedProcess:
    result = subprocess.run([str(cli), *map(str, args)], capture_output=True, text=True)
    if check and result.returncode != 0:
        raise AssertionError(f"bunraku {' '.join(map(str, args))} failed: {result.stderr}")
    return result


def cli_error(cli: pathlib.Path, *args: str) -> str:
    """The one-line message `bunraku` prints for a failing command, without "bunraku: error: "."""
    result = run_cli(cli, *args, check=False)
    assert result.returncode != 0, f"bunraku {' '.join(map(str, args))} succeeded"
    lines = [line for line in result.stderr.splitlines() if line.startswith("bunraku: error: ")]
    assert lines, result.stderr
    return lines[-1][len("bunraku: error: "):]


@pytest.fixture(scope="session")
def demo_dir(cli, tmp_path_factory) -> pathlib.Path:
    folder = tmp_path_factory.mktemp("demo") / "corpus"
    run_cli(cli, "demo", "-o", folder)
    return folder


@pytest.fixture(scope="session")
def demo_corpus(demo_dir) -> bunraku.Corpus:
    return bunraku.Corpus.open(str(demo_dir))


@pytest.fixture(scope="session")
def demo_cli_analysis(cli, demo_dir, tmp_path_factory) -> pathlib.Path:
    """`bunraku analyse` of the demo corpus: the peer's data files."""
    folder = tmp_path_factory.mktemp("demo-analysis") / "out"
    run_cli(cli, "analyse", demo_dir, "-o", folder)
    return folder


@pytest.fixture(scope="session")
def demo_analysis(demo_corpus) -> bunraku.Analysis:
    return bunraku.analyse(demo_corpus)


@pytest.fixture(scope="session")
def bandai_waves() -> List[pathlib.Path]:
    files = wave_files()
    require_peer(all(f.exists() for f in files), f"the Bandai waves ({BANDAI_DIR})")
    return files


def read_take_csv(path: pathlib.Path) -> Dict[str, np.ndarray]:
    """A take CSV as the program wrote it: {column: values}; each number parsed by float(),
    which reads a shortest round-trip number back as the same double."""
    lines = [line for line in path.read_text().splitlines() if line and not line.startswith("#")]
    header = lines[0].split(",")
    rows = [[float(x) for x in line.split(",")] for line in lines[1:]]
    table = np.array(rows, dtype=np.float64).reshape(len(rows), len(header))
    return {name: table[:, i] for i, name in enumerate(header)}


def take_matrix(path: pathlib.Path) -> np.ndarray:
    """frames x channels of a take CSV (time_s left out)."""
    columns = read_take_csv(path)
    return np.column_stack([v for k, v in columns.items() if k != "time_s"])


def read_csv_rows(path: pathlib.Path) -> List[List[str]]:
    return [line.split(",") for line in path.read_text().splitlines() if line]


def same_bits(a: np.ndarray, b: np.ndarray) -> bool:
    """Equal shapes and every double equal bit for bit (NaNs of the same pattern too)."""
    a = np.ascontiguousarray(a, dtype=np.float64)
    b = np.ascontiguousarray(b, dtype=np.float64)
    return a.shape == b.shape and a.tobytes() == b.tobytes()


def load_json(path: pathlib.Path):
    return json.loads(path.read_text())
