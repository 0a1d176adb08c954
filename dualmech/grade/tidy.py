"""Expressions shown to a person reduced as a person would write them, under a small budget.

``1/(m*sin(a)^2 + m*cos(a)^2)`` is shown ``1/m``; ``g*l*m + k*l*m`` as ``l*m*(g + k)``.  Only
the shown text changes, never a verdict: a form is taken when it is *identically* the same
expression (``sin^2 + cos^2 = 1``, cancelling, pulling common factors out) and shorter by
sympy's operation count; an expression too large for the budget is shown as it is.

Example
-------
>>> import sympy as sp
>>> m, a = sp.symbols("m alpha", positive=True)
>>> tidy(1/(m*sp.sin(a)**2 + m*sp.cos(a)**2))
1/m
"""
from __future__ import annotations

import sympy as sp

__all__ = ["tidy", "BUDGET"]

#: Expressions with more operations than this are shown as they are (reducing costs time).
BUDGET = 40


def tidy(expr, budget: int = BUDGET):
    """``expr`` in the shortest of a few identical forms (the expression itself on a tie)."""
    if not isinstance(expr, sp.Basic) or expr.is_Atom:
        return expr
    ops = sp.count_ops(expr)
    if ops > budget or not (expr.has(sp.Add) or expr.has(sp.sin, sp.cos)):
        return expr
    best, size = expr, ops
    for form in _forms(expr):
        n = sp.count_ops(form)
        if n < size:
            best, size = form, n
    return best


def _forms(expr):
    """Identical forms: each Pythagorean direction, cancelled; common factors pulled out."""
    yield sp.factor_terms(expr)
    trig = expr.atoms(sp.sin, sp.cos)
    for f, g in ((sp.cos, sp.sin), (sp.sin, sp.cos)):
        rules = {}
        for p in expr.atoms(sp.Pow):
            if isinstance(p.base, f) and p.exp.is_Integer and p.exp >= 2:
                n, x = int(p.exp), p.base.args[0]
                rules[p] = f(x) ** (n % 2) * (1 - g(x) ** 2) ** (n // 2)
        if rules:
            e = sp.cancel(sp.expand(expr.xreplace(rules)))
            yield e
            yield sp.factor_terms(e)
    if expr.has(sp.Pow) and not trig:
        yield sp.factor_terms(sp.cancel(expr))
