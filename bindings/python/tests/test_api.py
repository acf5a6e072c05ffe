"""The package's surface: the names the issue promises, a docstring on each, the type stub
declaring each, and the module importable from the build tree."""

from __future__ import annotations

import ast
import inspect
import pathlib

import bunraku

PROMISED = ["read_take", "Corpus", "Take", "preprocess", "normalise", "decompose", "fluctuations", "emotion_weight",
            "motion_axis", "phase", "gains", "design", "analyse", "Error", "__version__"]


def stub_names() -> set:
    stub = pathlib.Path(bunraku.__file__).with_name("__init__.pyi")
    tree = ast.parse(stub.read_text())
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.add(node.target.id)
        elif isinstance(node, ast.Assign):
            names.update(t.id for t in node.targets if isinstance(t, ast.Name))
    return names


def test_the_promised_names_exist():
    for name in PROMISED:
        assert hasattr(bunraku, name), name
    for name in ("open", "from_files", "write"):
        assert hasattr(bunraku.Corpus, name)
    assert issubclass(bunraku.Error, ValueError)


def test_every_public_name_has_a_docstring_and_a_stub():
    declared = stub_names()
    for name in bunraku.__all__:
        assert name in declared, f"{name} is not declared in __init__.pyi"
        if name == "__version__":
            continue
        value = getattr(bunraku, name)
        assert inspect.getdoc(value), f"{name} has no docstring"
    assert "eq. 3.28" in bunraku.normalise.__doc__ and "eq. 4.45" in bunraku.emotion_weight.__doc__
    assert "read-only NumPy view" in bunraku.Take.__doc__


def test_the_package_is_the_build_trees():
    path = pathlib.Path(bunraku.__file__).resolve()
    assert path.parent.name == "bunraku"
    assert any(p.name.startswith("_bunraku.") and p.suffix == ".so" for p in path.parent.iterdir())


def test_mypy_checks_scripts_against_the_stub(tmp_path):
    """The stub makes mypy check calls: a correct script passes, wrong types are reported."""
    import importlib.util
    import subprocess
    import sys

    from conftest import require_peer

    require_peer(importlib.util.find_spec("mypy") is not None, "mypy (Debian: mypy)")
    (tmp_path / "good.py").write_text(
        "import numpy as np\nimport bunraku\n"
        "corpus = bunraku.Corpus.open('demo')\n"
        "cell = bunraku.normalise(corpus, function='greeting', emotion='friendly', tau=6)\n"
        "values: np.ndarray = corpus.takes[0].values\n"
        "total: float = sum(t.variance_normalised for t in cell.takes)\n"
        "z = bunraku.decompose(cell).z('greeting', 'friendly')\n")
    (tmp_path / "bad.py").write_text(
        "import bunraku\n"
        "corpus = bunraku.Corpus.open('demo')\n"
        "cell = bunraku.normalise(corpus, tau='six')\n"
        "name: int = corpus.takes[0].name\n")
    package = pathlib.Path(bunraku.__file__).resolve().parents[1]
    result = subprocess.run([sys.executable, "-m", "mypy", "--no-incremental", "--cache-dir=/dev/null",
                             "--ignore-missing-imports", "good.py", "bad.py"],
                            cwd=tmp_path, capture_output=True, text=True, env={"MYPYPATH": str(package), "PATH": "/usr/bin:/bin"})
    errors = [line for line in result.stdout.splitlines() if ": error:" in line]
    assert all(line.startswith("bad.py:") for line in errors), result.stdout
    assert any(line.startswith("bad.py:3:") and '"tau"' in line for line in errors), result.stdout
    assert any(line.startswith("bad.py:4:") for line in errors), result.stdout
