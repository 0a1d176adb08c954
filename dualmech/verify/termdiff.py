"""Two expressions as tables of terms, and the smallest edit from one to the other.

The core both the grader's feedback and the verifier's explanations need, in its simplest
form: an expression is expanded into terms ``coefficient x state part`` (the coefficient free
of the state, the state part a product of coordinates, rates, accelerations, reactions,
virtual displacements, trigonometric functions of them and time), with ``sin^2 + cos^2 = 1``
applied one way (even powers of ``cos`` written through ``sin``), so that two forms of one
quantity written differently give the same table.  Coefficients are compared exactly (their
difference cancels to zero).  The edit is a list of :class:`TermEdit`: a term **missing**,
one **extra**, a wrong **sign**, a wrong **coefficient**.

Example
-------
>>> import sympy as sp
>>> m, l, x, th = sp.symbols("m l x theta")
>>> have = m*l*x*sp.cos(th)**2 - m*l**2*th
>>> right = m*l*x + m*l**2*th - m*l*x*sp.sin(th)**2
>>> [str(e) for e in term_edits(have, right, {x, th})]
['sign: -l**2*m*theta where l**2*m*theta belongs']
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from dualmech.model._expr import as_expr

__all__ = ["TermEdit", "term_table", "term_edits", "canonical"]

#: more terms than this on either side: not an edit a person makes, no table is built
MAX_TERMS = 60


@dataclass(frozen=True)
class TermEdit:
    """One term to change: ``have`` (as written, ``None`` when missing) into ``right``
    (``None`` when it is extra)."""

    kind: str             # "missing", "extra", "sign", "coefficient"
    have: sp.Expr | None
    right: sp.Expr | None

    def __str__(self) -> str:
        if self.kind == "missing":
            return f"missing: {self.right}"
        if self.kind == "extra":
            return f"extra: {self.have}"
        return f"{self.kind}: {self.have} where {self.right} belongs"


def canonical(expr) -> sp.Expr:
    """``expr`` expanded, multiple angles expanded and every ``cos^n`` (n >= 2) written as
    ``cos^(n mod 2) (1 - sin^2)^(n div 2)``: one form per quantity modulo sin^2 + cos^2 = 1."""
    expr = sp.expand(as_expr(expr))
    rules = {f: sp.expand_trig(f) for f in expr.atoms(sp.sin, sp.cos) if not f.args[0].is_Atom}
    if rules:
        expr = sp.expand(expr.xreplace(rules))
    rules = {}
    for p in expr.atoms(sp.Pow):
        if isinstance(p.base, sp.cos) and p.exp.is_Integer and p.exp >= 2:
            n = int(p.exp)
            rules[p] = sp.cos(p.base.args[0]) ** (n % 2) * \
                (1 - sp.sin(p.base.args[0]) ** 2) ** (n // 2)
    return sp.expand(expr.xreplace(rules)) if rules else expr


def term_table(expr, states) -> dict | None:
    """``{state part: coefficient}`` of :func:`canonical` ``(expr)`` (``None`` past
    :data:`MAX_TERMS` terms); ``states`` the symbols that make a factor a state part."""
    states = set(states)
    args = sp.Add.make_args(canonical(expr))
    if len(args) > MAX_TERMS:
        return None
    out: dict = {}
    for term in args:
        if term == 0:
            continue
        coeff, key = [], []
        for f in sp.Mul.make_args(term):
            (key if f.free_symbols & states else coeff).append(f)
        k = sp.Mul(*key)
        out[k] = out.get(k, 0) + sp.Mul(*coeff)
    return {k: c for k, c in out.items() if sp.cancel(c) != 0}


def _same(a, b) -> bool:
    return sp.cancel(sp.expand(a - b)) == 0


def term_edits(have, right, states, ignore_constant: bool = False) -> list[TermEdit] | None:
    """The term edits that turn ``have`` into ``right`` (empty when they are the same;
    ``None`` when either has too many terms).  ``ignore_constant`` drops the state-free
    term (a potential is defined up to a constant)."""
    a, b = term_table(have, states), term_table(right, states)
    if a is None or b is None:
        return None
    if ignore_constant:
        a.pop(sp.Integer(1), None)
        b.pop(sp.Integer(1), None)
    edits = []
    for k in list(a) + [k for k in b if k not in a]:
        ca, cb = a.get(k), b.get(k)
        if ca is not None and cb is not None and _same(ca, cb):
            continue
        if ca is None:
            edits.append(TermEdit("missing", None, cb * k))
        elif cb is None:
            edits.append(TermEdit("extra", ca * k, None))
        elif _same(ca, -cb):
            edits.append(TermEdit("sign", ca * k, cb * k))
        else:
            edits.append(TermEdit("coefficient", ca * k, cb * k))
    return edits
