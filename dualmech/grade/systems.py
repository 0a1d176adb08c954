"""Equations with constraint rows graded as a system: a DAE in the student's own coordinates.

A student may answer in the coordinates of one of the problem's constrained models -- the
pendulum's bob at ``(x, y)`` with the rod's pull ``S`` -- and write the system the way the
model is: dynamic rows with the multiplier or reaction, plus the constraint itself, at position
level (``x^2 + y^2 = l^2``), velocity level (``x*x' + y*y' = 0``) or acceleration level (a
dynamic-looking row without reactions).  Judged in the reference coordinates (where ``x`` and
``y`` are ``l sin(theta)``, ``-l cos(theta)``) a constraint row holds identically and would
"say nothing"; judged here it is what it is: a constraint of the student's coordinates, true on
the motion, that the system needs.

Completeness is then counted in the student's coordinates (:func:`determines_system`): the
unknowns are the accelerations of *every* coordinate of the group and the reactions used; a
dynamic row contributes its coefficients of those unknowns, a position-level constraint
``g(q) = 0`` its gradient ``dg/dq`` (the coefficients of ``q''`` in ``g'' = 0``), a
velocity-level one ``a(q) q' + b = 0`` its coefficients ``a`` (those of ``q''`` in its time
derivative).  The system is complete when that matrix has full column rank at the sampled
points of the motion; otherwise the undetermined unknowns are named, and a missing constraint
is said to be missing.

Example
-------
>>> from dualmech import grade
>>> print(grade("pendulum_particle",
...             "m*x'' = -S*x/l; m*y'' = -S*y/l + m*g; x^2 + y^2 = l^2").summary)
... # doctest: +NORMALIZE_WHITESPACE
equivalent to the equations of motion: every equation follows from them and together they
determine the accelerations of x, y and the reaction S, with the constraint of equation 3
(position level)
>>> print(grade("pendulum_particle", "m*x'' = -S*x/l; m*y'' = -S*y/l + m*g").summary)
... # doctest: +NORMALIZE_WHITESPACE
every equation is right, but 2 equations cannot determine 3 unknowns (the accelerations of
x, y and the reaction S): S undetermined; the constraint that ties x, y (at position,
velocity or acceleration level) is missing
"""
from __future__ import annotations

import random
from fractions import Fraction

import sympy as sp

from dualmech.exact import linalg as la
from dualmech.grade.context import ProblemContext
from dualmech.grade.formula import Formula
from dualmech.model.equations import state_symbols

__all__ = ["constrained_group", "constraint_rows", "determines_system"]


def _owners(ctx: ProblemContext) -> dict:
    """Every plain state symbol (``q``, ``q'``, ``q''`` of every model) -> its ``q``."""
    def build():
        out = {}
        for m in ctx.problem.models().values():
            for q in m.coordinates:
                s = state_symbols(q)
                out.update({s.q: s.q, s.qd: s.q, s.qdd: s.q})
        return out
    return ctx.memo("grade.systems.owners", build)


def _groups(ctx: ProblemContext) -> list:
    """The coordinates of each model with more coordinates than the reference has: the
    models whose coordinates are tied by constraints, smallest first."""
    def build():
        n = len(ctx.coordinates)
        seen, out = set(), []
        for m in ctx.problem.models().values():
            group = tuple(state_symbols(q).q for q in m.coordinates)
            if len(group) > n and group not in seen:
                seen.add(group)
                out.append(group)
        return sorted(out, key=len)
    return ctx.memo("grade.systems.groups", build)


def constrained_group(ctx: ProblemContext, formulas: list) -> tuple | None:
    """The constrained model's coordinates the answer is written in (plain ``q`` symbols), or
    ``None`` when it uses only the reference coordinates (or no single constrained model's)."""
    owners = _owners(ctx)
    used = {owners[s] for f in formulas for s in f.symbols if s in owners}
    reference = {s.q for s in ctx.states}
    if not used or used <= reference:
        return None
    return next((g for g in _groups(ctx) if used <= set(g)), None)


def _rates(group) -> tuple:
    """The plain rate symbols ``q'`` of the group's coordinates."""
    return tuple(state_symbols_of(q)[1] for q in group)


def state_symbols_of(q) -> tuple:
    """``(q, q', q'')`` plain symbols of a plain coordinate symbol (named ``x``, ``x_dot``,
    ``x_ddot`` by :func:`~dualmech.model.equations.state_symbols`)."""
    return q, sp.Symbol(f"{q.name}_dot", real=True), sp.Symbol(f"{q.name}_ddot", real=True)


def constraint_rows(ctx: ProblemContext, formulas: list, group: tuple) -> dict:
    """``{index: "position" | "velocity" | "acceleration"}`` of the rows that constrain
    ``group``'s coordinates: no reaction, no acceleration of another coordinate, and not
    identically zero when the group's coordinates, rates and accelerations are free (a
    tautology such as ``x = x`` constrains nothing).  Rows of reactions are dynamic rows."""
    others = {state_symbols_of(q)[2] for q in _owners(ctx).values()} | set(ctx.qdd)
    mine = {state_symbols_of(q)[2] for q in group}
    rates = set(_rates(group))
    out = {}
    for i, f in enumerate(formulas):
        if f.symbols & set(ctx.reactions) or f.symbols & (others - mine) \
                or not f.symbols & (set(group) | rates | mine):
            continue
        if _genuine(ctx, f, group, i):
            out[i] = "acceleration" if f.symbols & mine else \
                "velocity" if f.symbols & rates else "position"
    return out


def _genuine(ctx: ProblemContext, f: Formula, group: tuple, i: int) -> bool:
    """Nonzero at a random point where the group's coordinates and rates are independent."""
    rng = random.Random(f"{ctx.problem.name}:{ctx.seed}:constraint:{i}")
    values = {s: Fraction(rng.randrange(1, 1 << 40), rng.randrange(1, 1 << 20))
              for s in ctx.parameters}
    for q in group:
        for s in state_symbols_of(q):
            values[s] = Fraction(rng.randrange(-(1 << 40), 1 << 40), rng.randrange(1, 1 << 20))
    for s in ctx.base:
        values.setdefault(s, Fraction(rng.randrange(-(1 << 40), 1 << 40), 1 << 20))
    try:
        return f.sympy().subs(values) != 0
    except (TypeError, ValueError, ZeroDivisionError):
        return True


def determines_system(ctx: ProblemContext, formulas: list, points: list, need, group: tuple,
                      rows: dict) -> tuple:
    """``(complete, summary)`` of a right system in the coordinates ``group`` with the
    constraint ``rows`` (see the module docstring)."""
    qdd = [state_symbols_of(q)[2] for q in group]
    used = [r for r in ctx.reactions if any(r in f.symbols for f in formulas)]
    cols = qdd + used
    k = len(formulas)
    derived = ctx.derived_formulas()
    mine = {s for q in group for s in state_symbols_of(q)}
    need = tuple(need) + tuple(s for s in derived if s in mine and s not in need)
    for p in (points[0], points[-1]):
        J = _jacobian(formulas, p, cols, need, group, rows)
        if la.rank(J) == len(cols):
            continue
        piv = la.rref(J)[1]
        missing = [cols[c] for c in range(len(cols)) if c not in piv]
        what = " or ".join(ctx.names.get(s, str(s)) for s in missing)
        summary = (f"every equation is right, but {k} equation{'s' if k > 1 else ''} cannot "
                   f"determine {len(cols)} unknowns ({_unknowns(ctx, group, used)}): {what} "
                   "undetermined")
        if not rows:
            names = ", ".join(ctx.names.get(q, str(q)) for q in group)
            summary += (f"; the constraint that ties {names} (at position, velocity or "
                        "acceleration level) is missing")
        return False, summary, (len(cols) - len(missing)) / len(cols)
    which = ", ".join(f"equation {i + 1} ({level} level)" for i, level in sorted(rows.items()))
    summary = (f"equivalent to {ctx.subject}: every equation follows from them and together "
               f"they determine {_unknowns(ctx, group, used)}")
    if rows:
        summary += f", with the constraint{'s' if len(rows) > 1 else ''} of {which}"
    return True, summary, 1.0


def _unknowns(ctx, group, used) -> str:
    names = ", ".join(ctx.names.get(q, str(q)) for q in group)
    out = f"the accelerations of {names}"
    if used:
        r = ", ".join(ctx.names.get(u, str(u)) for u in used)
        out += f" and the reaction{'s' if len(used) > 1 else ''} {r}"
    return out


def _jacobian(formulas, point, cols, need, group, rows) -> list:
    env = point.env(need=need)
    held = {s: env.values[s] for s in need}
    gradient = {i: level for i, level in rows.items() if level != "acceleration"}
    base = [None if i in gradient else f.evaluate(env) for i, f in enumerate(formulas)]
    J = [[0] * len(cols) for _ in formulas]
    for c, u in enumerate(cols):
        e2 = point.env({**held, u: env.values[u] + 1})
        for i, f in enumerate(formulas):
            if i not in gradient:
                J[i][c] = f.evaluate(e2) - base[i]
    for i, level in gradient.items():
        expr = formulas[i].sympy()
        for c, q in enumerate(group):
            by = state_symbols_of(q)[0 if level == "position" else 1]
            J[i][c] = Formula.from_sympy(expr.diff(by)).evaluate(env)
    return J
