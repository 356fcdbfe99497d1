"""The .pyi stub next to the module parses and declares every public name of the module."""
import ast
from pathlib import Path

import hlens


def test_stub_declares_the_module():
    stub = Path(hlens.__file__).with_name("hlens.pyi")
    tree = ast.parse(stub.read_text())
    declared = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    public = {n for n in dir(hlens) if not n.startswith("_")}
    assert public <= declared, public - declared
    classes = {n.name: n for n in tree.body if isinstance(n, ast.ClassDef)}
    for cls in ("Result", "OneSided", "BatchFailure", "TargetSolver"):
        members = {m.target.id for m in classes[cls].body if isinstance(m, ast.AnnAssign)} | \
                  {m.name for m in classes[cls].body if isinstance(m, ast.FunctionDef)}
        real = {n for n in dir(getattr(hlens, cls)) if not n.startswith("_")}
        assert real <= members, (cls, real - members)


def test_docstrings_explain_the_arguments():
    assert "one_sided" in hlens.distance.__doc__ and "ValueError" in hlens.distance.__doc__
    assert "weld" in hlens.load.__doc__
    assert "per_arc" in hlens.TargetSolver.domains.__doc__
