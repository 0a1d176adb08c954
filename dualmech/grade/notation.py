"""Feedback as the student wrote the answer: their notation for rates (primes, dots, ``_d``,
``\\dot{}``), the aliases they used (``l`` for the source's ``a``), and every term as MathML for
web pages (:func:`dualmech.model.notation.mathml`).

Example
-------
>>> from dualmech.grade import grade
>>> r = grade("toy_car", "R*thetaddot + R*phidot^2*sin(theta)*cos(theta) - g*sin(theta)*cos(phi)")
>>> r.edits[0].term, r.edits[0].term_html.startswith("<math")
('-g*sin(theta)*cos(phi)', True)
"""
from __future__ import annotations

import re
from dataclasses import replace

import sympy as sp

from dualmech.model.kinematics import t
from dualmech.grade.audit import notation_of, restyle
from dualmech.grade.context import ProblemContext
from dualmech.grade.echo import is_latex, letters, spelling, to_latex
from dualmech.grade.formula import Formula

__all__ = ["for_student", "coordinate_names", "in_their_words"]


def coordinate_names(ctx: ProblemContext) -> list[str]:
    """Names of every coordinate an answer may use (the reference's and the maps')."""
    return [name for name, _ in _coordinate_states(ctx)]


def _coordinate_states(ctx: ProblemContext) -> list:
    """``[(name, (q, q', q'') plain symbols)]`` of the reference and the mapped coordinates."""
    def build():
        out = [(s.name, (s.q, s.qd, s.qdd)) for s in ctx.states]
        derived = {sym.name: sym for sym in ctx.derived_formulas()}
        for name, sym in derived.items():
            if not name.endswith("_dot") and not name.endswith("_ddot"):
                out.append((name, (sym, derived.get(name + "_dot"),
                                   derived.get(name + "_ddot"))))
        return out
    return ctx.memo("coordinate_states", build)


def for_student(ctx: ProblemContext, edits: list, text: str = "", where: str = "") -> list:
    """``edits`` in the notation of the answer ``text`` (``thetadot`` if the student wrote
    dots, ...), named ``where`` (``the theta equation``), with each term as MathML."""
    mine = in_their_words(ctx, text)
    out = []
    for e in edits:
        out.append(replace(e, term=mine(e.term), correct=mine(e.correct),
                           detail=mine(e.detail),
                           where=where or e.where,
                           term_html=_mathml(ctx, e.term), correct_html=_mathml(ctx, e.correct)))
    return out


def in_their_words(ctx: ProblemContext, text: str):
    """A function turning feedback text (terms written ``theta'``, ``^``, the problem's own
    symbols) into the notation of the answer ``text``: its way of writing rates and the
    aliases it used.

    >>> from dualmech.grade.context import ProblemContext
    >>> from dualmech.problems import get
    >>> ctx = ProblemContext.of(get("simple_pendulum"))
    >>> in_their_words(ctx, "l*thetaddot + g*sin(theta) = 0")("`a*theta''` has L")
    '`l*thetaddot` has L'
    """
    coords = coordinate_names(ctx)
    style = notation_of(text, coords) if text else "primes"
    used = _aliases_used(ctx, text)
    rates = {sym: (name, order) for name, syms in _coordinate_states(ctx)
             for order, sym in enumerate(syms) if order and sym is not None}
    typed = spelling(text or "", rates)
    for target, alias in used.items():
        typed.names[target] = typed.name(alias)

    def plain(s):
        s = restyle(s, coords, style)
        for target, alias in used.items():
            s = re.sub(r"(?<![A-Za-z0-9_'])" + re.escape(target) + r"(?![A-Za-z0-9_])",
                       alias, s)
        return letters(s, typed)

    def latex(s):
        try:
            return to_latex(_read(ctx, s), typed)
        except Exception:   # a display aid only: text the parser cannot read stays as it is
            return plain(s)

    if not is_latex(text):
        return plain

    def mine(s):
        if not s:
            return s
        if "`" in s:
            return re.sub(r"`([^`]*)`", lambda m: f"`{latex(m.group(1))}`", s)
        return latex(s)
    return mine


def _read(ctx: ProblemContext, text: str):
    """A term the feedback wrote (``theta'``, ``^``), read back by the answer parser."""
    from dualmech.grade.parser import parse
    return Formula.from_node(parse(text)[0].lhs, ctx.vocabulary).sympy()


def _aliases_used(ctx: ProblemContext, text: str) -> dict:
    """``{symbol: alias}`` of the problem's declared aliases the answer uses instead of the
    symbol's own name (``l`` for ``a``)."""
    out = {}
    for alias, target in (getattr(ctx.problem, "aliases", None) or {}).items():
        word = r"(?<![A-Za-z0-9_])%s(?![A-Za-z0-9_])"
        if ctx.vocabulary.table.get(alias) is not None and \
                re.search(word % re.escape(alias), text) and \
                not re.search(word % re.escape(str(target)), text):
            out[str(target)] = alias
    return out


def _mathml(ctx: ProblemContext, text: str) -> str:
    """MathML of a term the feedback wrote (read back by the answer parser), or ''."""
    if not text:
        return ""
    from dualmech.model import notation
    from dualmech.grade.parser import parse
    try:
        expr = Formula.from_node(parse(text)[0].lhs, ctx.vocabulary).sympy()
    except Exception:   # a display aid only: a term the parser cannot read has no MathML
        return ""
    body = notation.mathml(expr.xreplace(_functions(ctx)))
    return (f'<math xmlns="http://www.w3.org/1998/Math/MathML" display="block">'
            f"<mrow>{body}</mrow></math>")


def _functions(ctx: ProblemContext) -> dict:
    """Plain state symbols -> ``q(t)`` and its derivatives (for typesetting with dots)."""
    def build():
        rules = {}
        for name, syms in _coordinate_states(ctx):
            q = sp.Function(name)(t)
            for order, sym in enumerate(syms):
                if sym is not None:
                    rules[sym] = q.diff(t, order) if order else q
        return rules
    return ctx.memo("functions", build)
