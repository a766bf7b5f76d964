"""The type stubs of the native module name exactly what it has."""

import ast
import pathlib

import kinetics
from kinetics import _native


def test_native_stubs_match_the_module():
    stub = pathlib.Path(kinetics.__file__).with_name("_native.pyi")
    tree = ast.parse(stub.read_text())
    stubbed = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    present = {n for n in dir(_native) if not n.startswith("_")}
    assert stubbed == present
    assert (stub.parent / "py.typed").exists()
