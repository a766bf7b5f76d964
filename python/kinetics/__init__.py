"""kinetics: kinetics of rigid bodies in three dimensions, from Python.

Solve a scene and read its results, exactly and in numbers::

    >>> import kinetics
    >>> s = kinetics.solve("examples/scenes/sp18_4_shaft_reactions.scene")
    >>> print(s.results["D_y"])
    D_y = -3*M/(16*c) - 1/4*m*c*w^2 = -129.8 N

Check a hand-written claim, and name the slip::

    >>> v = kinetics.check("D_y = -3*M/(16*c) + 1/4*m*c*w^2",
    ...                    scene="examples/scenes/sp18_4_shaft_reactions.scene")
    >>> v.holds, v.slip
    (False, 'cross-product-reversed')

:func:`solve`, :func:`check`, :func:`check_derivation`, :func:`derive` and
:func:`simulate` are the whole surface;
a :class:`Solution`, a :class:`Result`, a :class:`Verdict` and :class:`Derivations` show
themselves in a notebook (MathML, LaTeX, Markdown), and :meth:`Result.to_sympy` hands a
result to SymPy. An input refused at a place in it raises :class:`SceneError`.
"""

from ._native import SceneError
from ._derivations import Derivations, Derived, derive
from ._hand_derivation import CheckedLine, DerivationCheck, check_derivation
from ._simulation import Simulation, simulate
from ._solution import Relation, Result, Solution, Step, solve
from ._verdict import Side, Verdict, check

__all__ = [
    "SceneError",
    "solve",
    "check",
    "check_derivation",
    "derive",
    "simulate",
    "Solution",
    "Result",
    "Step",
    "Relation",
    "Verdict",
    "Side",
    "DerivationCheck",
    "CheckedLine",
    "Derivations",
    "Derived",
    "Simulation",
]
