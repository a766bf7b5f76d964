"""The tests run from the repository's root or anywhere: scenes are found beside them."""

import os
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(autouse=True)
def at_the_root(monkeypatch):
    """Each test runs in the repository's root, where the docstrings' paths are."""
    monkeypatch.chdir(ROOT)


def scene(name: str) -> str:
    return os.fspath(ROOT / "examples" / "scenes" / name)
