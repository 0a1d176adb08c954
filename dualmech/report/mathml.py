"""Equations as MathML (presentation markup): browsers render it with no script.

Coordinates are printed as plain letters with dots for their rates (``theta'`` as a theta
with a dot above, ``theta''`` with two), Greek names as Greek letters and trailing digits as
subscripts, so an equation reads like the worked solution (:func:`dualmech.model.notation.mathml`).
Dimensions in a sentence's text (``has dimension M L^2 T^-2``) are typeset too: upright base
letters with their exponents as superscripts (:func:`dimension`, :func:`text_html`).

Example
-------
>>> import sympy as sp
>>> from dualmech import coordinate, t
>>> th = coordinate("theta")
>>> "<mi>&#952;&#775;</mi>" in equation(th.diff(t)**2 + sp.sin(th), 0)
True
>>> page = text_html("term x has dimension M L T^-2")
>>> '<msup><mi mathvariant="normal">T</mi><mrow><mo>&#8722;</mo><mn>2</mn></mrow></msup>' in page
True
"""
from __future__ import annotations

import html
import re

from dualmech.model import notation

__all__ = ["expression", "equation", "inline", "sentence", "dimension", "text_html"]

#: the base dimensions as :func:`dualmech.model.dimensions.format_dimension` writes them, in its order
_BASES = ("M", "L", "T", "current", "temperature", "amount_of_substance", "luminous_intensity")
_TOKEN = rf"(?:{'|'.join(_BASES)})(?:\^-?\d+(?:/\d+)?)?"
#: a dimension where the library's sentences write one: after "dimension", "has", "be",
#: "declared" -- so a product ``M L`` inside a printed formula is never taken for one
_IN_TEXT = re.compile(rf"\b(dimension|has|be|declared) ({_TOKEN}(?: {_TOKEN})*)(?=$|[\s;,.)])")


def expression(expr, notation_: str = "dots") -> str:
    """``<math>`` markup of ``expr`` (display style, block)."""
    return _wrap(notation.mathml(expr, notation_))


def inline(expr, notation_: str = "dots") -> str:
    """``<math>`` markup of ``expr`` to sit inside a sentence."""
    return _wrap(notation.mathml(expr, notation_), block=False)


def equation(lhs, rhs=0, notation_: str = "dots", block: bool = True) -> str:
    """``<math>`` markup of ``lhs = rhs`` (``block=False``: inside a sentence)."""
    return _wrap(f"{notation.mathml(lhs, notation_)}<mo>=</mo>"
                 f"{notation.mathml(rhs, notation_)}", block=block)


def sentence(parts, notation_: str = "dots") -> str:
    """A sentence -- text and expressions -- as HTML: the text escaped, each expression
    typeset inline (a plain string is escaped as it is)."""
    if isinstance(parts, str):
        return text_html(parts)
    return "".join(text_html(x) if isinstance(x, str) else inline(x, notation_)
                   for x in parts)


def dimension(text: str) -> str | None:
    """``M L^2 T^-2`` as inline ``<math>``: upright base letters, each exponent a
    superscript (``<msup>``); ``None`` when ``text`` is not a dimension in that form."""
    tokens = text.split(" ")
    order, body = -1, []
    for tok in tokens:
        base, _, exp = tok.partition("^")
        if base not in _BASES or _BASES.index(base) <= order or \
                not re.fullmatch(r"(-?\d+(/\d+)?)?", exp) or (tok.endswith("^")):
            return None
        order = _BASES.index(base)
        letter = f'<mi mathvariant="normal">{html.escape(base)}</mi>'
        if exp:
            sign, num = ("<mo>&#8722;</mo>", exp[1:]) if exp.startswith("-") else ("", exp)
            top, _, bottom = num.partition("/")
            power = f"<mn>{top}</mn>" + (f"<mo>/</mo><mn>{bottom}</mn>" if bottom else "")
            letter = f"<msup>{letter}<mrow>{sign}{power}</mrow></msup>"
        body.append(letter)
    return _wrap('<mspace width="0.2em"/>'.join(body), block=False)


def text_html(text: str) -> str:
    """Prose as HTML: escaped, each dimension the library wrote in it typeset
    (:func:`dimension`)."""
    out, at = [], 0
    for m in _IN_TEXT.finditer(text):
        typeset = dimension(m.group(2))
        if typeset is None:
            continue
        out += [html.escape(text[at:m.start(2)]), typeset]
        at = m.end(2)
    return "".join(out) + html.escape(text[at:])


def _wrap(body: str, block: bool = True) -> str:
    display = ' display="block"' if block else ""
    return (f'<math xmlns="http://www.w3.org/1998/Math/MathML"{display}>'
            f"<mrow>{body}</mrow></math>")
