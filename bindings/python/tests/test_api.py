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
