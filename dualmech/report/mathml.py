"""Equations as MathML (sympy's presentation printer): browsers render it with no script.

Coordinates are printed as plain letters with dots for their rates (``theta'`` as a theta
with a dot above, ``theta''`` with two), Greek names as Greek letters and trailing digits as
subscripts, so an equation reads like the worked solution.

Example
-------
>>> import sympy as sp
>>> from dualmech import coordinate, t
>>> th = coordinate("theta")
>>> "&#952;&#775;" in equation(th.diff(t)**2 + sp.sin(th), 0)
True
"""
from __future__ import annotations

import re

import sympy as sp
from sympy.printing.mathml import mathml
from sympy.printing.pretty.pretty_symbology import greek_unicode

from ..kinematics import t

__all__ = ["expression", "equation", "display_symbols"]

_DOTS = {1: "\u0307", 2: "\u0308", 3: "\u20db"}


def _name(base: str, order: int = 0) -> str:
    """``theta1`` with ``order`` dots -> a symbol name the printer shows as a dotted theta_1."""
    m = re.fullmatch(r"([A-Za-z]+?)(\d*)", base)
    stem, digits = (m.group(1), m.group(2)) if m else (base, "")
    letter = greek_unicode.get(stem, stem)
    dots = _DOTS.get(order, "'" * order)
    if len(letter) > 1 and order:               # a multi-letter name: dot over its last letter
        letter = letter[:-1] + letter[-1] + dots
    else:
        letter += dots
    return letter + (f"_{digits}" if digits else "")


def display_symbols(expr) -> sp.Expr:
    """``expr`` with ``q(t)`` and its derivatives replaced by dotted display symbols."""
    expr = sp.sympify(expr, strict=True)
    rules = {}
    for d in expr.atoms(sp.Derivative):
        f = d.expr
        if isinstance(f, sp.core.function.AppliedUndef) and all(v == t for v in d.variables):
            rules[d] = sp.Symbol(_name(f.func.__name__, d.derivative_count))
    expr = expr.xreplace(rules)
    plain = {f: sp.Symbol(_name(f.func.__name__)) for f in
             expr.atoms(sp.core.function.AppliedUndef) if f.args == (t,)}
    return expr.xreplace(plain)


def expression(expr) -> str:
    """``<math>`` markup of ``expr`` (display style, block)."""
    return _wrap(mathml(display_symbols(expr), printer="presentation"))


def equation(lhs, rhs=0) -> str:
    """``<math>`` markup of ``lhs = rhs``."""
    left = mathml(display_symbols(lhs), printer="presentation")
    right = mathml(display_symbols(rhs), printer="presentation")
    return _wrap(f"{left}<mo>=</mo>{right}")


def _wrap(body: str) -> str:
    return ('<math xmlns="http://www.w3.org/1998/Math/MathML" display="block">'
            f"<mrow>{body}</mrow></math>")
