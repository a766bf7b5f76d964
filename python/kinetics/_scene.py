"""A scene given as a path or as its text, read into ``(name, text)``."""

from __future__ import annotations

import os
from typing import Tuple, Union

SceneSource = Union[str, "os.PathLike[str]"]


def read(scene: SceneSource) -> Tuple[str, str]:
    """``(name, text)`` of ``scene``: a path (an ``os.PathLike``, or a string of one line)
    is read; a string of several lines is the scene's text, named ``<scene>`` in errors."""
    if isinstance(scene, os.PathLike):
        path = os.fspath(scene)
    elif isinstance(scene, str) and "\n" not in scene:
        path = scene
    elif isinstance(scene, str):
        return "<scene>", scene
    else:
        raise TypeError(f"a scene is a path or its text, not {type(scene).__name__}")
    with open(path, encoding="utf-8") as f:
        return path, f.read()
