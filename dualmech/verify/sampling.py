"""Sampled values of every model of a problem, and what each model says at a point.

All derivations of a problem are brought to the reference model's coordinates and to plain
symbols; their matrices ``[A | b]`` (``A [q''; lambda] = b``) and any extra expressions (printed
answers) are compiled into ONE :class:`~dualmech.exact.form.ExactForm`, so a point is drawn and
evaluated once for everything that is decided there.  At a point, :func:`solve_model` says
what each model determines: its accelerations (or that it does not determine them, or
contradicts itself) and its reactions.
"""
from __future__ import annotations

import random
from dataclasses import dataclass, field
from typing import Iterator, Sequence

import symengine as se
import sympy as sp

from dualmech.model._algebra import Bridge, linear_coefficients, to_se, total_derivative
from dualmech.model._expr import as_expr
from dualmech.model.equations import EquationSet, ModelError, state_symbols
from dualmech.exact.form import ExactForm, is_zero
from dualmech.exact.errors import Undecidable
from dualmech.exact.sample_space import function_arguments_se
from dualmech.model.kinematics import t
from dualmech.exact import linalg as la

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
        self.problem = problem
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
            for e in list(m.equations) + [c.expression for c in m.constraints]:
                free |= e.free_symbols
        free -= {t} | set(u for m in models for u in m.unknowns)
        return cls(coords, sorted(free, key=str))

    def unknown_symbols(self, unknowns) -> tuple:
        """The symbols a point gets after solving: accelerations, then ``unknowns``."""
        return tuple(self.qdd) + tuple(unknowns)

    def name_of(self, sym) -> str:
        for q, s in zip(self.coordinates, self.states):
            if sym == s.q:
                return q.func.__name__
            if sym == s.qd:
                return q.func.__name__ + "'"
            if sym == s.qdd:
                return q.func.__name__ + "''"
        return str(sym)


class System:
    """One model in the reference coordinates: plain ``A`` (rows of lists) and ``b``.

    Static rows (no acceleration, no reaction: a massless body's balance) are replaced by
    their time derivative at the acceleration level; the rows themselves (and, for a
    position-level row, its first derivative) are kept in ``constraints``: they must vanish
    on the motion, and the sampler draws points on the manifold they define.  The constraints
    the model declares (``EquationSet.constraints``, position or velocity level) follow them
    in ``constraints`` (the last ``declared`` entries), with the index of their
    acceleration-level row in ``static``.

    A model derived in symengine keeps its matrices there (:meth:`flat_se`), and its sympy
    ``A``, ``b`` are built only when read.
    """

    def __init__(self, model: EquationSet, A: list | None, b: list | None,
                 static: list | None = None, constraints: list | None = None,
                 se_form: tuple | None = None):
        self.model = model
        self._A, self._b = A, b
        self.static = list(static or [])             # indices of the static rows
        self.constraints = list(constraints or [])   # per static row: [g, g'] or [g]
        self.declared = 0   # the last ones are declared constraints (row: their acceleration row)
        self._se = se_form                           # (A, b, names) in symengine
        self._inside: set | None = None

    @property
    def A(self) -> list:
        if self._A is None:
            A, b = self.model.plain_matrix()
            self._A, self._b = [list(A.row(i)) for i in range(A.rows)], list(b)
        return self._A

    @property
    def b(self) -> list:
        self.A  # noqa: B018
        return self._b

    @classmethod
    def of(cls, eqs: EquationSet, coords: Sequence) -> "System":
        eqs = reorder(eqs, coords)
        declared = _declared(eqs)
        fast = eqs.plain_matrix_se()
        if fast is not None:
            A, b, _ = fast
            if all(any(A[i, j] != 0 for j in range(A.cols)) for i in range(A.rows)):
                out = cls(eqs, None, None, [r for r, _ in declared],   # no static rows
                          [lv for _, lv in declared], se_form=fast)
                out.declared = len(declared)
                return out
        A, b = eqs.plain_matrix()
        rows = [list(A.row(i)) for i in range(A.rows)]
        rhs = list(b)
        static = [i for i, r in enumerate(rows) if all(x == 0 for x in r)]
        constraints = []
        if static:
            states = eqs.states
            unknown = [s.qdd for s in states] + list(eqs.unknowns)
            br = Bridge([rhs[i] for i in static],
                        unknown + [t] + [x for st in states for x in (st.q, st.qd)])
            qdds = {br.se(u) for u in unknown}
            for i in static:
                g = -rhs[i]
                levels = [g]
                d = total_derivative(br.se(g), states, t, br)
                if not (d.free_symbols & qdds):
                    levels.append(br.sp(d))
                    d = total_derivative(d, states, t, br)
                newA, newb, _ = linear_coefficients([br.sp(d)], unknown, br)
                rows[i], rhs[i] = list(newA.row(0)), newb[0]
                constraints.append(levels)
        out = cls(eqs, rows, rhs, static + [r for r, _ in declared],
                  constraints + [lv for _, lv in declared])
        out.declared = len(declared)
        return out

    def flat_se(self) -> list | None:
        """``flat()`` in symengine, for a model derived there (else ``None``)."""
        if self._se is None:
            return None
        A, b, _ = self._se
        return list(A) + list(b)

    @property
    def names(self) -> dict:
        return self._se[2] if self._se is not None else {}

    @property
    def size(self) -> int:
        if self._se is not None:
            A = self._se[0]
            return A.rows * (A.cols + 1)
        return len(self.A) * (len(self.A[0]) + 1) if self.A else 0

    @property
    def rows(self) -> int:
        return self._se[0].rows if self._se is not None else len(self.A)

    @property
    def cols(self) -> int:
        return self._se[0].cols if self._se is not None else len(self.A[0])

    def flat(self) -> list:
        return [x for row in self.A for x in row] + list(self.b)

    def unflatten(self, vals) -> tuple[list, list]:
        rows, cols = self.rows, self.cols
        A = [list(vals[i * cols:(i + 1) * cols]) for i in range(rows)]
        return A, list(vals[rows * cols: rows * cols + rows])

    def constraint_exprs(self) -> list:
        return [g for levels in self.constraints for g in levels]

    def inside_functions(self) -> set:
        """The symbols some function of this model takes as argument (they cannot be solved
        for on a manifold: their sines are sampled on the circle); computed once."""
        if self._inside is None:
            held = self.flat_se()
            inside = function_arguments_se(held) if held is not None else None
            if inside is None:   # the general route: every function's arguments
                inside = set()
                for e in (held if held is not None else self.flat()):
                    for f in e.atoms(se.Function if held is not None else sp.Function):
                        inside |= {sp.Symbol(x.name, real=True) for x in f.free_symbols}
            for e in self.constraint_exprs():
                for f in e.atoms(sp.Function):
                    inside |= f.free_symbols
            self._inside = inside
        return self._inside


def reorder(eqs: EquationSet, coords) -> EquationSet:
    """``eqs`` with its coordinates in the order ``coords`` (same set)."""
    if tuple(eqs.coordinates) == tuple(coords):
        return eqs
    return EquationSet(eqs.name, tuple(coords), eqs.equations, eqs.unknowns, eqs.labels,
                       eqs.contributions, eqs.description, eqs.constraints)


def _declared(eqs: EquationSet) -> list:
    """``[(row, levels)]`` of the constraints ``eqs`` declares, in plain symbols: ``row`` the
    index of the acceleration-level row, ``levels`` ``[g, g']`` (position) or ``[g]``
    (velocity).  A constraint whose row is not among the equations is left out."""
    out = []
    for c in eqs.constraints:
        if c.label not in eqs.labels:
            continue
        g = c.plain(eqs.coordinates)
        levels = [g]
        if c.level == "position":
            levels.append(sp.diff(g, t) + sum(sp.diff(g, s.q) * s.qd for s in eqs.states))
        out.append((eqs.labels.index(c.label), levels))
    return out


@dataclass
class Solution:
    """What one model determines at one point.

    ``status``: ``"ok"`` (accelerations determined), ``"undetermined"`` (its equations do not
    fix every acceleration), ``"inconsistent"`` (they contradict each other) or
    ``"undecided"`` (interval values too wide to tell at this point).  ``lam`` maps
    each reaction to its value, ``None`` where the equations leave it undetermined.
    """

    status: str
    qdd: list = field(default_factory=list)
    lam: dict = field(default_factory=dict)
    rank: int = 0

    @property
    def undetermined_reactions(self) -> list:
        return [u for u, v in self.lam.items() if v is None]


def solve_model(A: list, b: list, n: int, unknowns: Sequence,
                claimed: Sequence[int] | None = None) -> Solution:
    """Solve ``A [q''; lambda] = b`` at a point exactly (Gauss--Jordan on ``[B M' M | b]``).

    The reaction columns go first, then the accelerations the model does not claim (a model
    written in fewer coordinates than the reference says nothing about the others), then
    the claimed ones: those are determined exactly when each is a pivot column.  A pivot in
    the last column means the equations contradict each other.  Unclaimed accelerations
    that the equations do not fix are ``None`` in ``qdd``.
    """
    m = len(A[0]) if A else n
    if len(A) == m and (claimed is None or sorted(claimed) == list(range(n))):
        x = la.solve_regular(A, b)   # the common case: square and regular
        if x is not None:
            return Solution("ok", x[:n], dict(zip(unknowns, x[n:])), m)
    claimed = list(range(n)) if claimed is None else list(claimed)
    unclaimed = [j for j in range(n) if j not in claimed]
    order = list(range(n, m)) + unclaimed + claimed
    aug = [[row[j] for j in order] + [bi] for row, bi in zip(A, b)]
    R, piv, ambiguous = la.rref_info(aug)
    rank = len([p for p in piv if p < m])
    if ambiguous:   # interval values that cannot tell a pivot from zero: no claim here
        return Solution("undecided", rank=rank)
    if m in piv:
        return Solution("inconsistent", rank=rank)
    row_of = {p: i for i, p in enumerate(piv)}
    position = {col: i for i, col in enumerate(order)}
    free = [c for c in range(m) if c not in row_of]

    def value(col):
        c = position[col]
        if c not in row_of or any(R[row_of[c]][f] != 0 for f in free if f != c):
            return None
        return R[row_of[c]][m]

    qdd = [value(j) for j in range(n)]
    if any(qdd[j] is None for j in claimed):
        return Solution("undetermined", rank=rank)
    lam = {u: value(n + c) for c, u in enumerate(unknowns)}
    return Solution("ok", qdd, lam, rank)


def same_values(a: Sequence, b: Sequence) -> bool:
    """Exactly equal (Fractions), or equal within the fallback's own error bound."""
    for x, y in zip(a, b):
        if x is None or y is None:
            continue
        if not is_zero(x - y, max(abs(x), abs(y))):
            return False
    return True


def shared_manifold(systems: Sequence[System], partial: Sequence[bool], ctx: Context) -> list:
    """The dependents of the reference's constraint manifold (``systems[0]``), when every
    model that speaks for all coordinates has static rows too; else none.

    A static row in one model where another has inertia is that model's fault, not a
    constraint of the motion: without a shared manifold, points are drawn freely and such a
    row is reported where it does not hold.
    """
    if any(s.declared for s in systems):
        return _declared_manifold(systems, ctx)
    full = [s for s, p in zip(systems, partial) if not p]
    if not systems[0].constraints or not all(s.constraints for s in full):
        return []
    return manifold(systems[:1], ctx)


def _declared_manifold(systems: Sequence[System], ctx: Context) -> list:
    """The manifold of the constraints declared (or held as static rows) by the models, when
    some model declares constraints: each model's own is a candidate, and the one on which
    the most models' constraints hold wins (ties: the first, the reference); a model whose
    constraints differ (the geometric contact point's velocity where the material point's
    was meant) is then the one whose constraints fail.  Free points when no candidate can be
    sampled exactly (the acceleration-level rows are compared there, as before)."""
    candidates, seen = [], []
    for s in systems:
        if not s.constraints:
            continue
        try:
            deps = manifold([s] + [o for o in systems if o is not s], ctx)
        except ModelError:
            continue
        key = [(sym, sp.expand(e)) for sym, e in deps]
        if key not in seen:
            seen.append(key)
            candidates.append(deps)
    if len(candidates) <= 1:
        return candidates[0] if candidates else []
    return max(candidates, key=lambda deps: _satisfied(deps, systems, ctx))


def _satisfied(deps: list, systems: Sequence[System], ctx: Context, tries: int = 6) -> int:
    """How many of ``systems`` have every constraint zero at a point of ``deps``' manifold."""
    cons = [s.constraint_exprs() for s in systems]
    exprs = [e for _, e in deps] + [e for c in cons for e in c]
    try:
        form = ExactForm.build(exprs, ctx.base, **_domains(ctx))
    except (ValueError, ModelError, Undecidable):
        return 0
    rng = random.Random(len(deps))
    for _ in range(tries):
        point = form.sample(rng, ctx.floats)
        try:
            vals = form.evaluate(point)
            for i, (sym, _) in enumerate(deps):
                point[sym] = vals[i]
                vals = form.evaluate(point)
        except (ZeroDivisionError, ValueError, OverflowError):
            continue
        count, off = 0, len(deps)
        for c in cons:
            count += all(is_zero(v, 1) for v in vals[off:off + len(c)])
            off += len(c)
        return count
    return 0


def manifold(systems: Sequence[System], ctx: Context) -> list:
    """Dependent variables ``[(symbol, expression)]`` that put a point on the motion's
    constraint manifold, from the static rows of the first system that has any.

    Each position-level static row ``g(q, t) = 0`` is solved for a coordinate in which it is
    linear (and which no function takes as argument), its derivative ``g' = 0`` for that
    coordinate's rate; a velocity-level row for a rate.  Raises :class:`ModelError` when a
    static row cannot be solved that way (the comparator cannot sample its manifold exactly).
    """
    source = next((s for s in systems if s.constraints), None)
    if source is None:
        return []
    inside = set()
    for s in systems:
        inside |= s.inside_functions()
    taken: set = set()
    deps = []
    qs = [st.q for st in ctx.states]
    qds = [st.qd for st in ctx.states]
    for levels in source.constraints:
        g = levels[0]
        candidates = qds if len(levels) == 1 else qs
        chosen = _linear_in(g, candidates, taken, inside)
        if chosen is None:
            raise ModelError(
                f"model `{source.model.name}` has the static equation {g} = 0, which is not "
                "linear in any coordinate or rate that no function takes as argument; the "
                "comparator cannot sample its constraint manifold exactly.")
        sym, expr = chosen
        taken.add(sym)
        deps.append((sym, expr))
        if len(levels) > 1:
            rate = qds[qs.index(sym)]
            solved = _linear_in(levels[1], [rate], taken, set())
            if solved is None:
                raise ModelError(f"the rate form of the static equation {g} = 0 of "
                                 f"`{source.model.name}` does not fix {rate}.")
            taken.add(rate)
            deps.append(solved)
    return deps


def _linear_in(g, candidates, taken, inside):
    for s in candidates:
        if s in taken or s in inside or not g.has(s):
            continue
        c = sp.diff(g, s)
        if c.has(s) or c == 0:
            continue
        return s, -g.xreplace({s: 0}) / c
    return None


class Sampler:
    """Draws points and evaluates every system (and extra expressions) there, all at once.

    With ``dependents`` (see :func:`manifold`) each point is moved onto the constraint
    manifold first: the dependent variables are evaluated, in order, from the others.
    """

    def __init__(self, systems: Sequence[System], ctx: Context, extra: Sequence = (),
                 extra_symbols: Sequence = (), dependents: Sequence = ()):
        self.systems = list(systems)
        self.ctx = ctx
        self.dependents = list(dependents)
        exprs = [e for _, e in self.dependents]
        self.offset = len(exprs)
        fast = [s.flat_se() for s in self.systems]
        cons = [e for s in self.systems for e in s.constraint_exprs()]
        held = None
        if all(f is not None for f in fast):
            held = _in_symengine(exprs + cons + list(extra))
        if held is not None:
            # every model derived in symengine: the manifold, the constraints and the extras
            # join them there (see world_se)
            k = len(exprs)
            exprs = held[:k]
            for f in fast:
                exprs += f
            cons, extra = held[k:k + len(cons)], held[k + len(cons):]
        else:
            for s in self.systems:
                exprs += s.flat()
        self.offset_constraints = len(exprs)
        exprs += cons
        self.offset_extra = len(exprs)
        exprs += list(extra)
        self.symbols = tuple(ctx.base) + tuple(extra_symbols)
        self.form = ExactForm.build(exprs, self.symbols, **_domains(ctx))

    @property
    def method(self) -> str:
        return self.form.method

    def points(self, rng: random.Random, limit: int, fill: dict | None = None) -> Iterator:
        """Yield ``(point, values, parts, residues)``: each system's ``(A, b)`` at the point
        and the values of its static rows there (zero for a model consistent with the
        manifold)."""
        for _ in range(limit):
            point = self.form.sample(rng, self.ctx.floats)
            if fill:
                point.update(fill)
            try:
                vals = self.form.evaluate(point)
                for i, (sym, _) in enumerate(self.dependents):
                    point[sym] = vals[i]
                    vals = self.form.evaluate(point)
            except (ZeroDivisionError, ValueError, OverflowError):
                continue
            parts, residues, off = [], [], self.offset
            coff = self.offset_constraints
            for s in self.systems:
                parts.append(s.unflatten(vals[off:off + s.size]))
                off += s.size
                k = len(s.constraint_exprs())
                residues.append(list(vals[coff:coff + k]))
                coff += k
            yield point, vals, parts, residues


def _in_symengine(exprs) -> list | None:
    """``exprs`` converted to symengine, or ``None`` if one does not convert."""
    try:
        return [e if isinstance(e, se.Basic) else to_se(as_expr(e)) for e in exprs]
    except Exception:  # noqa: BLE001 - then everything stays in sympy
        return None


def _domains(ctx: Context) -> dict:
    """``domains=`` for ExactForm.build when the problem declares any (older forms lack it)."""
    if not ctx.domains:
        return {}
    import inspect
    if "domains" in inspect.signature(ExactForm.build).parameters:
        return {"domains": dict(ctx.domains)}
    return {}
