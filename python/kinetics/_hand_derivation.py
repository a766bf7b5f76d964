"""Hand derivations checked line by line: :func:`check_derivation` and
:class:`DerivationCheck`."""

from __future__ import annotations

import html
from typing import Any, Dict, List, NamedTuple, Optional, Sequence, Tuple, Union

from . import _native
from ._scene import SceneSource, read
from ._verdict import verdict_colour


class CheckedLine(NamedTuple):
    """A line of a derivation and what the checker says of it.

    ``verdict``: ``holds``, ``differs`` (the slip is here), ``follows`` (wrong, but right
    from the earlier wrong lines ``follows_from``: it carries their slip), ``undecided`` or
    ``error`` (it could not be read: ``error`` says where and why). ``slip`` and
    ``explanation`` name the slip of a line that differs or follows."""

    number: int
    text: str
    verdict: str
    slip: Optional[str]
    explanation: Optional[str]
    follows_from: List[int]
    does_not_follow: List[int]
    error: Optional[str]


class DerivationCheck:
    """A derivation checked: ``lines`` (each a :class:`CheckedLine`), ``first_slip`` (the
    line where it first goes wrong and the slip's name, or None), ``holds`` (True when every
    line holds, False when one differs or follows, None when one is undecided or unread),
    and ``report``, the command line's report."""

    def __init__(self, checked: Dict[str, Any]) -> None:
        self.lines: List[CheckedLine] = [CheckedLine(**line) for line in checked["lines"]]
        self.first_slip: Optional[Tuple[int, Optional[str]]] = checked["first_slip"]
        self.report: str = checked["report"]
        verdicts = {line.verdict for line in self.lines}
        if verdicts & {"differs", "follows"}:
            self.holds: Optional[bool] = False
        elif verdicts <= {"holds"}:
            self.holds = True
        else:
            self.holds = None

    def __bool__(self) -> bool:
        return self.holds is True

    def __str__(self) -> str:
        return self.report

    def __repr__(self) -> str:
        first = f", first slip at line {self.first_slip[0]}" if self.first_slip else ""
        return f"<DerivationCheck {len(self.lines)} lines{first}>"

    def _repr_html_(self) -> str:
        rows = []
        for line in self.lines:
            note = line.explanation or line.error or ""
            if line.follows_from:
                froms = ", ".join(str(n) for n in line.follows_from)
                note = f"right from line {froms}, so it carries its slip"
            rows.append(
                f"<tr><td>{line.number}</td><td><code>{html.escape(line.text)}</code></td>"
                f'<td style="color:{verdict_colour(line.verdict)}">{line.verdict}</td>'
                f"<td>{html.escape(note)}</td></tr>")
        return ('<table class="kinetics-derivation"><tr><th>line</th><th>written</th>'
                "<th>verdict</th><th></th></tr>" + "".join(rows) + "</table>")

    def _repr_markdown_(self) -> str:
        rows = ["| line | written | verdict | |", "|---|---|---|---|"]
        for line in self.lines:
            note = line.explanation or line.error or ""
            if line.follows_from:
                note = "right from line " + ", ".join(str(n) for n in line.follows_from)
            text = line.text.replace("|", "\\|")
            rows.append(f"| {line.number} | `{text}` | {line.verdict} | {note} |")
        return "\n".join(rows)


def check_derivation(
    derivation: Union[str, Sequence[str]],
    scene: Optional[SceneSource] = None,
    principal: bool = False,
    fixed_point: bool = False,
    fixed_axis: bool = False,
    rtol: Optional[float] = None,
) -> DerivationCheck:
    """Checks a hand derivation line by line, as ``kinetics check --derivation``.

    ``derivation`` is its text (one equation a line, ``#`` comments, a blank line between
    independent parts) or a list of lines. Each line is checked against the mechanics; a
    wrong line that is right from the lines before it *follows* them, so the slip is named
    once, where it was made. The context is as :func:`check`'s.

    >>> import kinetics
    >>> work = kinetics.check_derivation([
    ...     "alpha = 3*M/(2*m*c^2)",
    ...     "D_y = -3*M/(16*c) + 1/4*m*c*w^2",
    ... ], scene="examples/scenes/sp18_4_shaft_reactions.scene")
    >>> [line.verdict for line in work.lines], work.first_slip
    (['holds', 'differs'], (2, 'cross-product-reversed'))
    """
    text = derivation if isinstance(derivation, str) else "\n".join(derivation)
    source = read(scene) if scene is not None else None
    return DerivationCheck(
        _native.check_derivation(text, source, principal, fixed_point, fixed_axis, rtol))
