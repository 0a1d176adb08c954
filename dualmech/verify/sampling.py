"""Sampled values of every model of a problem, and what each model says at a point.

All derivations of a problem are brought to the reference model's coordinates and to plain
symbols; their matrices ``[A | b]`` (``A [q''; lambda] = b``) and any extra expressions (printed
answers) are compiled into ONE :class:`~dualmech.exact.ExactForm`, so a point is drawn and
evaluated once for everything that is decided there.  At a point, :func:`solve_model` says
what each model determines: its accelerations (or that it does not determine them, or
contradicts itself) and its reactions.
"""
from __future__ import annotations

import random
from dataclasses import dataclass, field
from typing import Iterator, Sequence

from ..equations import EquationSet, state_symbols
from ..exact import ExactForm, is_zero
from ..kinematics import t
from . import linalg as la

__all__ = ["Context", "System", "Solution", "solve_model", "same_values", "Sampler",
           "MAX_ATTEMPTS"]

#: Points drawn per point wanted before giving up (divisions by zero, singular states).
MAX_ATTEMPTS = 12


class Context:
    """Symbols of one problem (or of bare equation sets) and their working ranges.

    ``base`` are the symbols a point gives values to: parameters, ``t``, ``q``, ``q'``;
    ``floats`` their working ranges (for display and simulation, never for verdicts);
    ``domains`` the domains of validity a problem declares (``Coordinate.domain``).
    """

    def __init__(self, coordinates, parameters=(), problem=None):
        self.coordinates = tuple(coordinates)
        self.states = [state_symbols(q) for q in self.coordinates]
        self.parameters = tuple(parameters)
        self.base = tuple(self.parameters) + (t,) + tuple(s.q for s in self.states) + \
            tuple(s.qd for s in self.states)
        self.qdd = tuple(s.qdd for s in self.states)
        self.floats: dict = {t: (0.0, 10.0)}
        self.domains: dict = {}
        if problem is not None:
            for p in problem.parameters:
                self.floats[p.symbol] = tuple(float(x) for x in p.range)
            for q, s in zip(self.coordinates, self.states):
                c = problem.coordinate_info(q)
                self.floats[s.q] = tuple(float(x) for x in c.range)
                self.floats[s.qd] = tuple(float(x) for x in c.rate_range)
                dom = getattr(c, "domain", None)
                if dom is not None:
                    self.domains[s.q] = tuple(dom)
        for s in self.parameters:
            self.floats.setdefault(s, (0.5, 2.0))
        for s in self.states:
            self.floats.setdefault(s.q, (-1.0, 1.0))
            self.floats.setdefault(s.qd, (-1.0, 1.0))

    @classmethod
    def for_models(cls, *models: EquationSet) -> "Context":
        coords = models[0].coordinates
        free = set()
        for m in models:
            for e in m.equations:
                free |= e.free_symbols
        free -= {t} | set(u for m in models for u in m.unknowns)
        return cls(coords, sorted(free, key=str))

    def name_of(self, sym) -> str:
        for q, s in zip(self.coordinates, self.states):
            if sym == s.q:
                return q.func.__name__
            if sym == s.qd:
                return q.func.__name__ + "'"
            if sym == s.qdd:
                return q.func.__name__ + "''"
        return str(sym)


@dataclass
class System:
    """One model in the reference coordinates: plain ``A`` (rows of lists) and ``b``."""

    model: EquationSet
    A: list
    b: list

    @classmethod
    def of(cls, eqs: EquationSet, coords: Sequence) -> "System":
        eqs = reorder(eqs, coords)
        A, b = eqs.plain_matrix()
        return cls(eqs, [list(A.row(i)) for i in range(A.rows)], list(b))

    @property
    def size(self) -> int:
        return len(self.A) * (len(self.A[0]) + 1) if self.A else 0

    def flat(self) -> list:
        return [x for row in self.A for x in row] + list(self.b)

    def unflatten(self, vals) -> tuple[list, list]:
        rows, cols = len(self.A), len(self.A[0])
        A = [list(vals[i * cols:(i + 1) * cols]) for i in range(rows)]
        return A, list(vals[rows * cols: rows * cols + rows])


def reorder(eqs: EquationSet, coords) -> EquationSet:
    """``eqs`` with its coordinates in the order ``coords`` (same set)."""
    if tuple(eqs.coordinates) == tuple(coords):
        return eqs
    return EquationSet(eqs.name, tuple(coords), eqs.equations, eqs.unknowns, eqs.labels,
                       eqs.contributions, eqs.description)


@dataclass
class Solution:
    """What one model determines at one point.

    ``status``: ``"ok"`` (accelerations determined), ``"undetermined"`` (its equations do not
    fix every acceleration) or ``"inconsistent"`` (they contradict each other).  ``lam`` maps
    each reaction to its value, ``None`` where the equations leave it undetermined.
    """

    status: str
    qdd: list = field(default_factory=list)
    lam: dict = field(default_factory=dict)
    rank: int = 0

    @property
    def undetermined_reactions(self) -> list:
        return [u for u, v in self.lam.items() if v is None]


def solve_model(A: list, b: list, n: int, unknowns: Sequence) -> Solution:
    """Solve ``A [q''; lambda] = b`` at a point exactly (Gauss--Jordan on ``[B M | b]``).

    The reaction columns go first, so the accelerations are determined exactly when every
    acceleration column is a pivot; a pivot in the last column means the equations contradict
    each other.
    """
    m = len(A[0]) if A else n
    k = m - n
    order = list(range(n, m)) + list(range(n))
    aug = [[row[j] for j in order] + [bi] for row, bi in zip(A, b)]
    R, piv = la.rref(aug)
    rank = len([p for p in piv if p < m])
    if m in piv:
        return Solution("inconsistent", rank=rank)
    row_of = {p: i for i, p in enumerate(piv)}
    if any(k + j not in row_of for j in range(n)):
        return Solution("undetermined", rank=rank)
    qdd = [R[row_of[k + j]][m] for j in range(n)]
    free = [c for c in range(k) if c not in row_of]
    lam = {}
    for c, u in enumerate(unknowns):
        if c not in row_of or any(R[row_of[c]][f] != 0 for f in free):
            lam[u] = None
        else:
            lam[u] = R[row_of[c]][m]
    return Solution("ok", qdd, lam, rank)


def same_values(a: Sequence, b: Sequence) -> bool:
    """Exactly equal (Fractions), or equal within the fallback's own error bound."""
    for x, y in zip(a, b):
        if not is_zero(x - y, max(abs(x), abs(y))):
            return False
    return True


class Sampler:
    """Draws points and evaluates every system (and extra expressions) there, all at once."""

    def __init__(self, systems: Sequence[System], ctx: Context, extra: Sequence = (),
                 extra_symbols: Sequence = ()):
        self.systems = list(systems)
        self.ctx = ctx
        exprs = []
        for s in self.systems:
            exprs += s.flat()
        self.offset_extra = len(exprs)
        exprs += list(extra)
        self.symbols = tuple(ctx.base) + tuple(extra_symbols)
        self.form = ExactForm.build(exprs, self.symbols, **_domains(ctx))

    @property
    def method(self) -> str:
        return self.form.method

    def points(self, rng: random.Random, limit: int, fill: dict | None = None) -> Iterator:
        """Yield ``(point, values, parts)``; ``parts`` is each system's ``(A, b)`` there."""
        for _ in range(limit):
            point = self.form.sample(rng, self.ctx.floats)
            if fill:
                point.update(fill)
            try:
                vals = self.form.evaluate(point)
            except (ZeroDivisionError, ValueError, OverflowError):
                continue
            parts, off = [], 0
            for s in self.systems:
                parts.append(s.unflatten(vals[off:off + s.size]))
                off += s.size
            yield point, vals, parts


def _domains(ctx: Context) -> dict:
    """``domains=`` for ExactForm.build when the problem declares any (older forms lack it)."""
    if not ctx.domains:
        return {}
    import inspect
    if "domains" in inspect.signature(ExactForm.build).parameters:
        return {"domains": dict(ctx.domains)}
    return {}
