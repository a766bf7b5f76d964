"""Type stubs of kinetics._native, the Rust half of the package (python/src)."""

from typing import Any, Dict, List, Optional, Sequence, Tuple

Tree = Tuple[Any, ...]

class SceneError(ValueError):
    """An input refused at a place in it; its message is the command line's."""

    source_name: str
    line: int
    column: int
    message: str
    hint: Optional[str]
    source_line: str

class Solved:
    @property
    def title(self) -> Optional[str]: ...
    def answers(self) -> List[Dict[str, Any]]: ...
    def steps(self) -> List[Tuple[str, str, List[Tuple[str, str]]]]: ...
    def render(self, format: str, standalone: bool = False, numbers: bool = False) -> str: ...

class Derived:
    def results(self) -> List[Dict[str, Any]]: ...
    def render(self, format: str, steps: bool = False, standalone: bool = False) -> str: ...

def solve(name: str, text: str, units: Optional[str] = None) -> Solved: ...
def check(
    claim: str,
    scene: Optional[Tuple[str, str]] = None,
    principal: bool = False,
    fixed_point: bool = False,
    fixed_axis: bool = False,
    rtol: Optional[float] = None,
) -> Dict[str, Any]: ...
def check_derivation(
    text: str,
    scene: Optional[Tuple[str, str]] = None,
    principal: bool = False,
    fixed_point: bool = False,
    fixed_axis: bool = False,
    rtol: Optional[float] = None,
) -> Dict[str, Any]: ...
def derive(only: List[str], principal: bool = False, axis: str = "z") -> Derived: ...
def simulate(
    name: str,
    text: str,
    until: Optional[float] = None,
    every: Optional[float] = None,
    at: Optional[Sequence[float]] = None,
    method: str = "auto",
    rtol: Optional[float] = None,
    step: Optional[float] = None,
) -> Dict[str, Any]: ...
