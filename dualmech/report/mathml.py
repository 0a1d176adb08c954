"""Equations as MathML (presentation markup): browsers render it with no script.

Coordinates are printed as plain letters with dots for their rates (``theta'`` as a theta
with a dot above, ``theta''`` with two), Greek names as Greek letters and trailing digits as
subscripts, so an equation reads like the worked solution (:func:`dualmech.notation.mathml`).

Example
-------
>>> import sympy as sp
>>> from dualmech import coordinate, t
>>> th = coordinate("theta")
>>> "<mi>&#952;&#775;</mi>" in equation(th.diff(t)**2 + sp.sin(th), 0)
True
"""
from __future__ import annotations

import html

from .. import notation

__all__ = ["expression", "equation", "inline", "sentence"]


def expression(expr, notation_: str = "dots") -> str:
    """``<math>`` markup of ``expr`` (display style, block)."""
    return _wrap(notation.mathml(expr, notation_))


def inline(expr, notation_: str = "dots") -> str:
    """``<math>`` markup of ``expr`` to sit inside a sentence."""
    return _wrap(notation.mathml(expr, notation_), block=False)


def equation(lhs, rhs=0, notation_: str = "dots") -> str:
    """``<math>`` markup of ``lhs = rhs``."""
    return _wrap(f"{notation.mathml(lhs, notation_)}<mo>=</mo>"
                 f"{notation.mathml(rhs, notation_)}")


def sentence(parts, notation_: str = "dots") -> str:
    """A sentence -- text and expressions -- as HTML: the text escaped, each expression
    typeset inline (a plain string is escaped as it is)."""
    if isinstance(parts, str):
        return html.escape(parts)
    return "".join(html.escape(x) if isinstance(x, str) else inline(x, notation_)
                   for x in parts)


def _wrap(body: str, block: bool = True) -> str:
    display = ' display="block"' if block else ""
    return (f'<math xmlns="http://www.w3.org/1998/Math/MathML"{display}>'
            f"<mrow>{body}</mrow></math>")
