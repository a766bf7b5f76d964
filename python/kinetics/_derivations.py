"""The chapter's equations for a general body: :func:`derive` and :class:`Derivations`."""

from __future__ import annotations

from typing import Any, Dict, List, NamedTuple, Optional, Sequence, Union

from . import _native
from ._sympy import from_tree


class Derived(NamedTuple):
    """One derivation's result: its name (``H_G``, ``euler``), its title and its relations
    as text, as LaTeX and as SymPy equations."""

    name: str
    title: str
    text: List[str]
    latex: List[str]
    trees: List[tuple]

    def to_sympy(self) -> List[Any]:
        """The relations as ``sympy.Eq(lhs, rhs)``."""
        import sympy

        return [sympy.Eq(from_tree(lhs), from_tree(rhs), evaluate=False)
                for lhs, rhs in self.trees]


class Derivations:
    """Derived equations: ``derivations["euler"]`` is a :class:`Derived`; the page is
    written by :meth:`to_text`, :meth:`to_latex`, :meth:`to_markdown`, :meth:`to_html`,
    :meth:`to_json`, and shows itself in a notebook."""

    def __init__(self, derived: "_native.Derived") -> None:
        self._derived = derived
        self._results: Dict[str, Derived] = {}
        for d in derived.results():
            relations = d["relations"]
            self._results[d["name"]] = Derived(
                d["name"], d["title"],
                [r[2] for r in relations], [r[3] for r in relations],
                [(r[0], r[1]) for r in relations])

    def __getitem__(self, name: str) -> Derived:
        return self._results[name]

    def __iter__(self):
        return iter(self._results.values())

    def __len__(self) -> int:
        return len(self._results)

    def to_text(self, steps: bool = False) -> str:
        return self._derived.render("text", steps=steps)

    def to_latex(self, steps: bool = False, standalone: bool = False) -> str:
        return self._derived.render("latex", steps=steps, standalone=standalone)

    def to_markdown(self, steps: bool = False) -> str:
        return self._derived.render("markdown", steps=steps)

    def to_html(self, steps: bool = False) -> str:
        return self._derived.render("html", steps=steps)

    def to_json(self) -> str:
        return self._derived.render("json")

    def __repr__(self) -> str:
        return "<Derivations " + ", ".join(self._results) + ">"

    def _repr_html_(self) -> str:
        return self._derived.render("html-fragment")

    def _repr_markdown_(self) -> str:
        return self.to_markdown()


def derive(only: Union[str, Sequence[str], None] = None, principal: bool = False,
           axis: str = "z") -> Derivations:
    """Derives the chapter's equations for a general body, as ``kinetics derive --general``.

    ``only`` names the derivation or derivations (``H_G``, ``H_O``, ``T``, ``T_O``, ``T_plane``,
    ``impulse``, ``Hdot``, ``euler``, ``fixed_axis``, ``reactions``, ``balancing``,
    ``gyroscope``, …; all when None); ``principal`` takes principal axes (every product of
    inertia zero); ``axis`` is the fixed axis of rotation of the fixed-axis derivations.

    >>> import kinetics
    >>> euler = kinetics.derive(["euler"], principal=True)["euler"]
    >>> euler.text[0]
    'SumM_x = I_x*wdot_x - (I_y - I_z)*w_y*w_z'
    """
    names = [only] if isinstance(only, str) else list(only or [])
    return Derivations(_native.derive(names, principal, axis))
