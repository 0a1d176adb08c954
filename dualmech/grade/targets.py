"""Correct forms of a quantity to explain a wrong answer against (display aids, never verdicts).

A reaction or an acceleration asked on its own is compared, term by term, with forms a person
writes: solved from single rows of the problem's models (keeping the other accelerations, as
``F = m (x'' + s'')``), those forms rewritten in other accelerations by the rows that hold no
reaction (``F = m x''/3``), and -- when none of these is close -- the form solved from the
whole system.  Every form is an identity on the motion of the verified models; the verdict
itself is decided elsewhere, by evaluation (:mod:`.judge`).

Example
-------
>>> import sympy as sp
>>> a, l = sp.symbols("a l")
>>> unit_circle(l*sp.sin(a)**2 + l*sp.cos(a)**2)
l
"""
from __future__ import annotations

import sympy as sp

from dualmech.grade.answers import Quantity
from dualmech.model.kinematics import t

__all__ = ["expression_targets", "unit_circle"]


def expression_targets(ctx, quantity: Quantity, stage: int = 0) -> list:
    """Per component, correct forms (sympy) to compare a wrong answer with (cached).  Stage
    0: the reference itself, or a reaction/acceleration solved from single rows; stage 1:
    solved from the whole system (symbolic, slower)."""
    def build():
        out = []
        for ref in quantity.reference:
            forms = [ref] if stage == 0 else []
            if ref.is_Symbol and ref in ctx.reactions:
                forms = _solved_rows(ctx, ref) if stage == 0 else _recovered(ctx, ref)
                if stage == 0:
                    forms += _in_other_accelerations(ctx, forms)
            elif ref.is_Symbol and ref in ctx.qdd:
                forms = _solved_rows(ctx, ref) if stage == 0 else _accelerations(ctx, ref)
            out.append(forms)
        return out
    return ctx.memo(("targets", quantity.name, stage), build)


def unit_circle(expr):
    """``expr`` expanded with ``sin(a)^2 + cos(a)^2`` read as 1 wherever both squares of one
    angle appear (``-l*sin(phi)^2 - l*cos(phi)^2`` is ``-l``): a polynomial substitution,
    far cheaper than ``trigsimp``.

    >>> import sympy as sp
    >>> a, l = sp.symbols("a l")
    >>> unit_circle(-l*sp.sin(a)**2 - l*sp.cos(a)**2 + sp.sin(a))
    -l + sin(a)
    """
    expr = sp.expand(expr)
    kinds: dict = {}
    for p in expr.atoms(sp.Pow):
        if p.exp == 2 and isinstance(p.base, (sp.sin, sp.cos)):
            kinds.setdefault(p.base.args[0], set()).add(type(p.base))
    rules = {sp.sin(a)**2: 1 - sp.cos(a)**2 for a, k in kinds.items() if len(k) == 2}
    return sp.expand(expr.xreplace(rules)) if rules else expr


def _solved_rows(ctx, unknown) -> list:
    """``unknown`` solved from each row that has it as its only reaction/acceleration of its
    kind (so the form may keep other accelerations: a reaction ``m (g + l theta'')``); then
    from each row with one other such unknown, that one put in from a row of its own (a
    string's tension through the pulley it passes: ``T2 = T1 + m x''/2``, ``T1`` from the
    first mass)."""
    kind = set(ctx.reactions) if unknown in ctx.reactions else set(ctx.qdd)
    rows = [sp.expand(ctx.plain(e)) for m in ctx.models.values() for e in m.equations]
    out = [f for e in rows if unknown in e.free_symbols and
           not (e.free_symbols & kind) - {unknown} for f in _solve_row(e, unknown, kind)]
    for e in rows:
        others = (e.free_symbols & kind) - {unknown}
        if len(out) >= 6 or unknown not in e.free_symbols or len(others) != 1:
            continue
        (other,) = others
        for r in rows:
            if other in r.free_symbols and not (r.free_symbols & kind) - {other}:
                for value in _solve_row(r, other, kind):
                    out += _solve_row(sp.expand(e.xreplace({other: value})), unknown, kind)
                    break
                break
    return out[:6]


def _in_other_accelerations(ctx, forms: list, limit: int = 6) -> list:
    """``forms`` (a reaction solved from single rows) rewritten in other accelerations by the
    rows that hold no reaction (``s'' = -2 x''/3`` of a Lagrange row turns ``F = -m s''/2``
    into ``F = m x''/3``): the forms a student writes in the one acceleration they solved
    for.  Appended after the rows' own forms, so those win a tie.  Only for a few
    coordinates (a display aid: larger problems keep the rows' own forms)."""
    qdd = set(ctx.qdd)
    if len(qdd) > 4:
        return []
    rows = [sp.expand(ctx.plain(e)) for m in ctx.models.values() if not m.unknowns
            for e in m.equations]
    rows = [e for e in rows if len(e.free_symbols & qdd) >= 2 and sp.count_ops(e) <= 200]
    out: list = []
    for form in forms:
        for a in sorted(form.free_symbols & qdd, key=str):
            for e in rows:
                if a not in e.free_symbols:
                    continue
                for value in _solve_row(e, a, {a}):
                    new = sp.expand(form.xreplace({a: value}))
                    if new != 0 and all(sp.expand(new - f) != 0 for f in forms + out):
                        out.append(new)
                if len(out) >= limit:
                    return out
    return out


def _solve_row(e, unknown, kind) -> list:
    """``[unknown]`` solved from the row ``e`` (linear in it), or ``[]``."""
    coeff = sp.diff(e, unknown)
    if coeff == 0 or coeff.free_symbols & kind:
        return []
    # sin^2 + cos^2 of one angle read as 1, as a person writes the form
    return [sp.expand(unit_circle(-(e - coeff * unknown)) / unit_circle(coeff))]


def _recovered(ctx, u) -> list:
    from dualmech.verify.check import recover_reactions

    def build():
        try:
            return recover_reactions(ctx.problem)
        except Exception:  # a display aid only: no form, no edit
            return {}
    rec = ctx.memo("recovered", build)
    return [ctx.plain(rec[u.name])] if u.name in rec else []


def _accelerations(ctx, a) -> list:
    if len(ctx.states) > 3:
        return []

    def build():
        try:
            return ctx.reference.accelerations_solved()
        except Exception:  # a display aid only
            return {}
    sol = ctx.memo("accelerations", build)
    if not sol:
        return []
    for q, s in zip(ctx.coordinates, ctx.states):
        if s.qdd == a:
            return [ctx.plain(sol[q.diff(t, 2)])]
    return []
