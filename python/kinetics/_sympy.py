"""SymPy from the trees of exact expressions the native module hands over.

A tree is a tuple: ``("number", p, q)``, ``("symbol", name, positive)``, ``("pi",)``,
``("add", terms)``, ``("mul", factors)``, ``("pow", base, exponent)`` or
``("function", name, argument)``. Each node becomes the SymPy object of that kind; a
symbol carries the scene's assumption (``positive=True`` for a mass, a length, a given
in kg, m, s, N or kg·m²; any other symbol a plain ``Symbol``), so SymPy simplifies as the
chapter does and the hand form can be written with ``sympy.symbols``.
No text is parsed.
"""

from __future__ import annotations

from typing import Any


def from_tree(tree: tuple) -> Any:
    """The SymPy expression of ``tree``."""
    import sympy

    functions = {
        "sin": sympy.sin,
        "cos": sympy.cos,
        "tan": sympy.tan,
        "abs": sympy.Abs,
        "acos": sympy.acos,
        "atan": sympy.atan,
    }

    def build(node: tuple) -> Any:
        kind = node[0]
        if kind == "number":
            return sympy.Rational(int(node[1]), int(node[2]))
        if kind == "symbol":
            name, positive = node[1], node[2]
            if positive:
                return sympy.Symbol(name, positive=True)
            return sympy.Symbol(name)
        if kind == "pi":
            return sympy.pi
        if kind == "add":
            return sympy.Add(*(build(t) for t in node[1]))
        if kind == "mul":
            return sympy.Mul(*(build(f) for f in node[1]))
        if kind == "pow":
            return sympy.Pow(build(node[1]), build(node[2]))
        if kind == "function":
            return functions[node[1]](build(node[2]))
        raise ValueError(f"not an expression tree: {node!r}")

    return build(tree)
