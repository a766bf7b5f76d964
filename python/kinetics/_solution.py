"""Worked solutions: :func:`solve` and the :class:`Solution` and :class:`Result` it gives."""

from __future__ import annotations

import os
from typing import Any, Dict, List, NamedTuple, Optional, Tuple, Union

from . import _native
from ._scene import SceneSource, read
from ._sympy import from_tree

#: A result's numbers: one, a vector's three, a tensor's rows.
Value = Union[float, Tuple[float, ...], Tuple[Tuple[float, ...], ...]]


class Result:
    """One result of a worked solution: ``D_y = -3*M/(16*c) - 1/4*m*c*w^2 = -129.8 N``.

    ``value`` is the number in ``unit`` (the unit the page shows it in: SI, the scene's
    U.S. customary units, or the unit its ``find … in UNIT`` or its unknown declares), a
    tuple of three for a vector and of three rows for a tensor, None where a given has no
    value. ``text`` and ``latex`` are its exact form; :meth:`to_sympy` hands it to SymPy.
    """

    __slots__ = ("name", "name_latex", "text", "latex", "value", "unit", "kind",
                 "_form", "_value_text", "_value_latex", "_html")

    def __init__(self, answer: Dict[str, Any]) -> None:
        self.name: str = answer["name"]
        self.name_latex: str = answer["name_latex"]
        self.text: str = answer["text"]
        self.latex: str = answer["latex"]
        self.kind: str = answer["kind"]
        self.unit: Optional[str] = answer["unit"]
        self.value: Optional[Value] = _shaped(answer["value"])
        self._form = answer["form"]
        self._value_text: Optional[str] = answer["value_text"]
        self._value_latex: Optional[str] = answer["value_latex"]
        self._html: str = answer["html"]

    def to_sympy(self) -> Any:
        """The exact form as SymPy: an expression, or a ``Matrix`` (a 3×1 column for a
        vector, 3×3 for a tensor). Its symbols carry the scene's assumptions: masses,
        lengths and the givens in kg, m, s, N and kg·m² are positive, the others plain symbols.

        >>> import kinetics, sympy
        >>> s = kinetics.solve("examples/scenes/sp18_4_shaft_reactions.scene")
        >>> d_y = s.results["D_y"].to_sympy()
        >>> M, c, m, w = (s.symbols[n] for n in ("M", "c", "m", "w"))
        >>> sympy.simplify(d_y - (-3*M/(16*c) - m*c*w**2/4))
        0
        """
        import sympy

        if self.kind == "expr":
            return from_tree(self._form)
        if self.kind == "vector":
            return sympy.Matrix([from_tree(t) for t in self._form])
        if self.kind == "matrix":
            entries = [from_tree(t) for t in self._form]
            return sympy.Matrix(3, 3, entries)
        raise ValueError(f"{self.name} is {self.kind_words()}, not an expression: {self.text}")

    def kind_words(self) -> str:
        return {"words": "said in words", "number": "known only as a number"}.get(
            self.kind, "an expression")

    def __str__(self) -> str:
        if self._value_text is not None and self._a_number():
            return f"{self.name} = {self._value_text}"
        line = f"{self.name} = {self.text}"
        if self._value_text is not None and self._value_text != self.text:
            line += f" = {self._value_text}"
        return line

    def _a_number(self) -> bool:
        """Whether the result is a number alone (`A_z = 0 N`, a balance's angle): its value
        with its unit says all there is."""
        return self.kind == "number" or (self.kind == "expr" and self._form[0] == "number")

    def __repr__(self) -> str:
        return f"<Result {self}>"

    def _repr_html_(self) -> str:
        return self._html

    def _repr_latex_(self) -> str:
        return f"$${self._latex_line()}$$"

    def _repr_markdown_(self) -> str:
        return f"$${self._latex_line()}$$"

    def _latex_line(self) -> str:
        if self._value_latex is not None and self._a_number():
            return f"{self.name_latex} = {self._value_latex}"
        line = f"{self.name_latex} = {self.latex}"
        if self._value_latex is not None and self._value_latex != self.latex:
            line += f" = {self._value_latex}"
        return line


def _shaped(numbers: Optional[List[float]]) -> Optional[Value]:
    """One number as a float, three as a tuple, nine as three rows."""
    if numbers is None:
        return None
    if len(numbers) == 1:
        return numbers[0]
    if len(numbers) == 9:
        return tuple(tuple(numbers[3 * i:3 * i + 3]) for i in range(3))
    return tuple(numbers)


class Relation(NamedTuple):
    """A relation of a step, ``lhs = rhs`` (equal components on one row)."""

    text: str
    latex: str


class Step(NamedTuple):
    """A step of the plan, as the worked solution shows it."""

    title: str
    title_latex: str
    relations: List[Relation]


class Solution:
    """A scene's worked solution.

    ``results`` maps each name (``D_y``, ``H_G``, ``I_1``) to its :class:`Result`, in the
    scene's order; ``steps`` are the steps of the plan; ``symbols`` the scene's symbols
    as SymPy, with their assumptions. The page is written on demand in any format:
    :meth:`to_text`, :meth:`to_latex`, :meth:`to_markdown`, :meth:`to_html`,
    :meth:`to_json`. In a notebook the solution shows itself as its page.
    """

    def __init__(self, solved: "_native.Solved") -> None:
        self._solved = solved
        self._results: Optional[Dict[str, Result]] = None
        self._steps: Optional[List[Step]] = None

    @property
    def title(self) -> Optional[str]:
        return self._solved.title

    @property
    def results(self) -> Dict[str, Result]:
        if self._results is None:
            self._results = {a["name"]: Result(a) for a in self._solved.answers()}
        return self._results

    @property
    def steps(self) -> List[Step]:
        if self._steps is None:
            self._steps = [
                Step(title, title_latex, [Relation(t, l) for t, l in relations])
                for title, title_latex, relations in self._solved.steps()
            ]
        return self._steps

    @property
    def symbols(self) -> Dict[str, Any]:
        """The scene's symbols (its givens and unknowns) and those of its results, by name,
        as SymPy symbols with the scene's assumptions, so that an expression built from
        them compares equal to a result's :meth:`Result.to_sympy`. Names are spelled as the
        page spells them: a given written ``w1`` is ``w_1``."""
        return {name: from_tree(("symbol", name, positive))
                for name, positive in self._solved.symbols()}

    def figure_svg(self) -> Optional[str]:
        """The scene's figure (the body, its axes and loads) as SVG; None where it cannot
        be drawn (a size without a number)."""
        return self._solved.figure_svg()

    def to_text(self, numbers: bool = False) -> str:
        """The page as plain text (``numbers``: the engineer's page, values only)."""
        return self._solved.render("text", numbers=numbers)

    def to_latex(self, standalone: bool = False, numbers: bool = False) -> str:
        """The page as LaTeX; ``standalone`` a whole document that compiles with pdflatex."""
        return self._solved.render("latex", standalone=standalone, numbers=numbers)

    def to_markdown(self, numbers: bool = False, figure: Optional[str] = None) -> str:
        """The page as Markdown, its maths in ``$…$``; with ``figure``, a path, the figure
        is written there as SVG and the page shows it as that image (a path relative to
        where the page will stand)."""
        figure_file = None
        if figure is not None:
            svg = self.figure_svg()
            if svg is not None:
                with open(figure, "w", encoding="utf-8") as f:
                    f.write(svg)
                figure_file = os.path.basename(figure)
        return self._solved.render("markdown", numbers=numbers, figure_file=figure_file)

    def to_html(self, numbers: bool = False) -> str:
        """One self-contained HTML page, the mathematics in MathML."""
        return self._solved.render("html", numbers=numbers)

    def to_json(self, numbers: bool = False) -> str:
        """The page as JSON (``docs/solution.schema.json``)."""
        return self._solved.render("json", numbers=numbers)

    def __repr__(self) -> str:
        lines = "\n".join(f"  {r}" for r in self.results.values())
        return f"<Solution {self.title or ''}\n{lines}\n>"

    def _repr_html_(self) -> str:
        return self._solved.render("html-fragment")

    def _repr_latex_(self) -> str:
        rows = r" \\ ".join(
            r._latex_line().replace(" = ", " &= ", 1) for r in self.results.values()
        )
        return rf"$$\begin{{aligned}} {rows} \end{{aligned}}$$"

    def _repr_markdown_(self) -> str:
        return self.to_markdown()


def solve(scene: SceneSource, units: Optional[str] = None) -> Solution:
    """Solves a scene: a path, or the scene's text.

    ``units`` shows the values in ``"si"`` or ``"us"`` (U.S. customary, any case); by default in
    the system the givens are written in. A scene that cannot be read or solved raises
    :class:`kinetics.SceneError` with its line, column, message and hint.

    >>> import kinetics
    >>> s = kinetics.solve("examples/scenes/sp18_4_shaft_reactions.scene")
    >>> round(s.results["D_y"].value, 1), s.results["D_y"].unit
    (-129.8, 'N')
    >>> print(s.results["alpha"])
    alpha = 3*M/(2*m*c^2) = 3000 rad/s²
    """
    name, text = read(scene)
    return Solution(_native.solve(name, text, units.lower() if units else None))

