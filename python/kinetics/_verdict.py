"""Hand-written claims checked: :func:`check` and the :class:`Verdict` it gives."""

from __future__ import annotations

import html
from typing import Any, Dict, List, Optional

from . import _native
from ._scene import SceneSource, read
from ._sympy import from_tree


#: A component both sides of a vector claim leave at zero (the checker leaves it out).
_ZERO = {"correct": ("number", "0", "1"), "claimed": ("number", "0", "1"),
         "correct_text": "0", "claimed_text": "0", "correct_latex": "0",
         "claimed_latex": "0", "correct_mathml": "<mn>0</mn>", "claimed_mathml": "<mn>0</mn>"}


def verdict_colour(verdict: str) -> str:
    """The colour a verdict is shown in: green holds, red differs, orange follows (a carried
    slip), amber undecided or unread."""
    return {"holds": "#176f2c", "differs": "#a61b1b", "follows": "#a65f1b"}.get(verdict, "#8a5a00")


class Side:
    """One side of a claim as the checker read it: a scalar, or a vector's x, y and z
    components (a component zero on both sides is 0). ``text`` and ``latex`` write it,
    :meth:`to_sympy` gives an expression or a 3×1 ``Matrix``."""

    def __init__(self, components: List[Dict[str, Any]], side: str) -> None:
        if components[0]["axis"] is not None:
            by_axis = {c["axis"]: c for c in components}
            components = [by_axis.get(axis, _ZERO) for axis in ("x", "y", "z")]
        self._components = components
        self._side = side
        texts = [c[f"{side}_text"] for c in components]
        self.text: str = texts[0] if len(texts) == 1 else "(" + ", ".join(texts) + ")"
        latex = [c[f"{side}_latex"] for c in components]
        self.latex: str = (latex[0] if len(latex) == 1
                           else r"\left(" + r",\ ".join(latex) + r"\right)")
        mathml = [c[f"{side}_mathml"] for c in components]
        self.mathml: str = (mathml[0] if len(mathml) == 1
                            else "<mo>(</mo>" + "<mo>,</mo>".join(mathml) + "<mo>)</mo>")

    def to_sympy(self) -> Any:
        trees = [c[self._side] for c in self._components]
        if len(trees) == 1:
            return from_tree(trees[0])
        import sympy

        return sympy.Matrix([from_tree(t) for t in trees])

    def __str__(self) -> str:
        return self.text

    def __repr__(self) -> str:
        return f"<Side {self.text}>"


class Verdict:
    """What the checker says of a claim.

    ``holds`` is True, False (the claim differs) or None (undecided); ``slip`` names the
    physics slip that turns the correct side into the claimed one (``cross-product-reversed``,
    ``omega-for-Omega``, ``parallel-axis-missing``, …) where one explains it, and
    ``explanation`` says it in words; ``correct`` is the side taken as correct
    (``.text``, ``.latex``, ``.to_sympy()``); ``report`` is the command line's report.
    """

    def __init__(self, checked: Dict[str, Any]) -> None:
        self.claim: str = checked["claim"]
        self.verdict: str = checked["verdict"]
        self.holds: Optional[bool] = {"holds": True, "differs": False}.get(self.verdict)
        self.slip: Optional[str] = checked["slip"]
        self.explanation: Optional[str] = checked["explanation"]
        self._explanation_html: Optional[str] = checked["explanation_html"]
        self.report: str = checked["report"]
        self.report_latex: str = checked["report_latex"]
        self.correct_side: str = checked["correct_side"]
        self.claimed_side: str = checked["claimed_side"]
        components = checked["components"]
        #: For a claim in numbers, each component's sentence: how far from the exact value.
        self.numbers: List[str] = [c["numbers"] for c in components if c["numbers"]]
        self.correct: Optional[Side] = Side(components, "correct") if components else None
        self.claimed: Optional[Side] = Side(components, "claimed") if components else None

    def __bool__(self) -> bool:
        """True only when the claim holds (an autograder's ``assert``)."""
        return self.holds is True

    def message(self) -> str:
        """One paragraph for a student: the verdict, the slip in words, the correct side."""
        if self.holds:
            return f"{self.claim}: holds"
        if self.holds is None:
            return f"{self.claim}: undecided\n{self.report}"
        said = f"{self.claim}: differs"
        if self.explanation:
            said += f" — {self.explanation}"
        for sentence in self.numbers:
            said += f"\n{sentence}"
        if self.correct is not None:
            said += f"\ncorrect: {self.correct_side} = {self.correct.text}"
        return said

    def __str__(self) -> str:
        return self.report

    def __repr__(self) -> str:
        slip = f" ({self.slip})" if self.slip else ""
        return f"<Verdict {self.verdict}{slip}: {self.claim}>"

    def _repr_html_(self) -> str:
        colour = verdict_colour(self.verdict)
        slip = f" ({html.escape(self.slip)})" if self.slip else ""
        out = [f'<div class="kinetics-verdict"><p><b style="color:{colour}">{self.verdict}</b>'
               f"{slip}: <code>{html.escape(self.claim)}</code></p>"]
        words = self._explanation_html or (html.escape(self.explanation) if self.explanation else "")
        if words:
            out.append(f"<p>{words[:1].upper()}{words[1:]}.</p>")
        out.extend(f"<p>{html.escape(sentence)}.</p>" for sentence in self.numbers)
        if self.correct is not None and self.claimed is not None and not self.holds:
            rows = [("as claimed", self.claimed.mathml), ("correct", self.correct.mathml)]
            cells = "".join(f'<tr><td style="padding-right:1em">{label}</td>'
                            f"<td><math displaystyle=\"true\">{maths}</math></td></tr>"
                            for label, maths in rows)
            out.append(f"<table>{cells}</table>")
        out.append("</div>")
        return "".join(out)

    def _repr_latex_(self) -> str:
        slip = f" ({self.slip})" if self.slip else ""
        head = rf"&\text{{{self.verdict}{slip}}}"
        if self.correct is None or self.claimed is None or self.holds:
            return f"$$\\begin{{aligned}}{head}\\end{{aligned}}$$"
        return (rf"$$\begin{{aligned}}{head} \\ "
                rf"&\text{{as claimed: }} {self.claimed.latex} \\ "
                rf"&\text{{correct: }} {self.correct.latex}\end{{aligned}}$$")

    def _repr_markdown_(self) -> str:
        return self._repr_latex_()


def check(
    claim: str,
    scene: Optional[SceneSource] = None,
    principal: bool = False,
    fixed_point: bool = False,
    fixed_axis: bool = False,
    rtol: Optional[float] = None,
) -> Verdict:
    """Checks a hand-written claim ``lhs = rhs`` against the derivations.

    Against a scene (a path or its text) the claim may use the scene's givens, unknowns
    and derived quantities; without one, a general body in body-fixed axes
    (``principal``: every product of inertia zero; ``fixed_point``: about a fixed point O;
    ``fixed_axis``: rotation about z at ``w``, ``alpha``). ``rtol`` is how close a claim in
    numbers must come (default 0.005). A claim that cannot be read raises
    :class:`kinetics.SceneError` at its place.

    >>> import kinetics
    >>> v = kinetics.check("D_y = -3*M/(16*c) + 1/4*m*c*w^2",
    ...                    scene="examples/scenes/sp18_4_shaft_reactions.scene")
    >>> v.holds, v.slip
    (False, 'cross-product-reversed')
    >>> v.correct.text
    '-3*M/(16*c) - 1/4*m*c*w^2'
    """
    source = read(scene) if scene is not None else None
    return Verdict(_native.check(claim, source, principal, fixed_point, fixed_axis, rtol))
