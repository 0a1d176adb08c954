"""The heavy part of :func:`dualmech.model.stability.linearize_about` for equations held in
symengine: substitute the parameters, find the constraint rows, differentiate and evaluate
at the steady state there, and bring back to sympy only the small results (numbers and
polynomials in the swept parameter).

A row is a constraint when it may be one (:func:`~dualmech.model.stability.constraint_candidates`:
a declared constraint's row, or any row of a model with multipliers), holds no reaction, its acceleration coefficients ``a(q)`` hold
no rate, and its rest is ``-(da/dt) . q'``; that identity, and whether the form ``a . dq`` is
closed (holonomic), are recognised by evaluating at :data:`PROBES` random rational states at
:data:`BITS` bits (a structural recognition, not a verdict: a row taken for a constraint is
still solved as an equation of the model).
"""
from __future__ import annotations

import random

import symengine as se
import sympy as sp

from dualmech.model._algebra import to_sp

__all__ = ["at_steady"]

#: random states at which a constraint's identities are evaluated
PROBES = 2
#: working precision of those evaluations (bits)
BITS = 256


def at_steady(eqs, subs: dict, x0: dict, w) -> tuple:
    """``(A0, b0, R, cons)``: ``A`` and ``b`` at the steady state ``x0``, ``R = d(A w - b)/d(q,
    q')`` there, and ``cons = [(label, a(x0), d(a . q')/dq at x0, holonomic)]``."""
    A, b, names = eqs.plain_matrix_se()
    names = dict(names)
    n = eqs.n
    qs = [se.Symbol(s.q.name) for s in eqs.states]
    qds = [se.Symbol(s.qd.name) for s in eqs.states]
    values = {}
    for k, v in subs.items():
        values[se.Symbol(k.name)] = se.sympify(v)
    point = {}
    for k, v in x0.items():
        point[se.Symbol(k.name)] = se.sympify(v)
        for sym in sp.sympify(v).free_symbols:
            names.setdefault(sym.name, sym)
    for sym in w:
        names[sym.name] = sym
    rows = [[A[i, j].subs(values) for j in range(A.cols)] for i in range(A.rows)]
    rest = [b[i, 0].subs(values) for i in range(b.rows)]
    memo: dict = {}

    def back(e):
        return to_sp(e.subs(point), names, memo)

    cons = []
    rng = random.Random(20071955)
    probes = [_probe(rng, qs, qds, rows, rest) for _ in range(PROBES)]
    from dualmech.model.stability import constraint_candidates
    for i in constraint_candidates(eqs):
        row = rows[i]
        a = row[:n]
        if any(x != 0 for x in row[n:]) or all(x == 0 for x in a) or \
                any(x.has(*qds) for x in a):
            continue
        rate = sum((a[j].diff(qs[k]) * qds[k] * qds[j] for j in range(n) for k in range(n)
                    if a[j] != 0), se.Integer(0))
        if not all(_vanishes(rest[i] + rate, p) for p in probes):
            continue
        closed = all(_vanishes(a[j].diff(qs[k]) - a[k].diff(qs[j]), p) for p in probes
                     for j in range(n) for k in range(j + 1, n))
        c = sum((aj * qd for aj, qd in zip(a, qds)), se.Integer(0))
        cons.append((eqs.labels[i], [back(x) for x in a], [back(c.diff(q)) for q in qs],
                     closed))
    ws = [se.Symbol(x.name) for x in w]
    R = sp.zeros(len(rows), 2 * n)
    for k, var in enumerate(qs + qds):
        for i, row in enumerate(rows):
            entry = sum((row[j].diff(var) * ws[j] for j in range(len(row)) if row[j] != 0),
                        se.Integer(0)) - rest[i].diff(var)
            R[i, k] = back(entry)
    A0 = sp.Matrix(len(rows), len(rows[0]), [back(x) for row in rows for x in row])
    b0 = sp.Matrix(len(rest), 1, [back(x) for x in rest])
    return A0, b0, R, cons


def _probe(rng, qs, qds, rows, rest) -> dict:
    """A random state (and random values of any other free symbol), as MPFR numbers."""
    free = set(qs) | set(qds)
    for e in rest:
        free |= e.free_symbols
    out = {}
    for sym in sorted(free, key=str):
        out[sym] = se.RealMPFR(str(sp.Rational(rng.randint(-97, 97), rng.randint(50, 150))
                                   .evalf(40)), BITS)
    return out


def _vanishes(expr, probe: dict) -> bool:
    """``expr`` is zero at ``probe`` to the working precision (relative to its terms)."""
    if expr == 0:
        return True
    value = expr.subs(probe)
    try:
        number = complex(value.n(BITS))
    except (RuntimeError, TypeError, ValueError):
        return False
    terms = expr.args if isinstance(expr, se.Add) else (expr,)
    scale = 1.0
    for term in terms:
        try:
            scale = max(scale, abs(complex(term.subs(probe).n(BITS))))
        except (RuntimeError, TypeError, ValueError):
            return False
    return abs(number) <= 1e-40 * scale
