"""Expressions as tables of terms, and the correct forms a wrong answer is compared with.

A term is ``coefficient x state part``: the coefficient is free of the state (parameters,
numbers, trigonometric functions of parameters), the state part a product of coordinates,
rates, accelerations, reactions, trigonometric functions of them and time.  Tables are built in
three :data:`MODES` -- as written, with multiple and compound angles expanded, and modulo
``sin^2 + cos^2 = 1`` -- so that the smallest edit can be sought in the form the student wrote.
Coefficients are compared exactly, by value at one of the context's random points.
"""
from __future__ import annotations

import random
from dataclasses import dataclass, field
from fractions import Fraction

import sympy as sp

from dualmech.model.kinematics import t
from dualmech.grade.context import GradingUnavailable, ProblemContext, zero
from dualmech.grade.formula import Env, Formula, seeded_draw

__all__ = ["TermTable", "term_table", "equation_targets", "expression_tables",
           "coefficient_env", "state_symbols", "MODES", "answer_coordinates"]

_MAX_TERMS = 60


@dataclass
class TermTable:
    """``terms[key] = (coefficient, value, written)``: expanded terms by state part;
    ``value`` is the coefficient at the context's first point (exact); ``written`` the like
    terms as the answer wrote them."""

    label: str
    expr: object
    terms: dict
    #: keys whose written terms cancel (``P*x1/a - P*x1/a``), with those written terms
    hidden: dict = field(default_factory=dict)
    #: the mode the table was built in
    mode: str = "trig"
    _groups: list | None = None
    #: state parts the answer writes as a term of their own (filled by :meth:`groups`)
    alone: dict = field(default_factory=dict)

    def groups(self, ctx: ProblemContext, parts: list | None = None) -> list:
        """``[(written term, {key: value})]`` of the written terms (``parts``, default the
        top-level terms of :attr:`expr`) that expand to two or more state parts: the groups
        a person writes (``m*L*(cos(phi)*phi'' - sin(phi)*phi'^2)``)."""
        if self._groups is None:
            out = []
            for p in parts if parts is not None else sp.Add.make_args(self.expr):
                self._add_group(out, p, ctx)
                if parts is not None and p.is_Mul:   # a term inside the student's factor
                    sums = [f for f in p.args if f.is_Add]
                    if len(sums) == 1 and len(sums[0].args) <= 8:
                        others = sp.Mul(*[f for f in p.args if f is not sums[0]])
                        for piece in sums[0].args:
                            self._add_group(out, sp.Mul(others, piece), ctx)
            self._groups = out
        return self._groups

    def _add_group(self, out, p, ctx) -> None:
        if len(sp.Add.make_args(sp.expand(p))) < 2:
            tab = term_table(p, ctx, mode=self.mode)
            if tab is not None and len(tab.terms) == 1:
                self.alone.update(tab.terms)   # a written term on one state part
            return
        tab = term_table(p, ctx, mode=self.mode)
        if tab is not None and len(tab.terms) >= 2 and not tab.hidden:
            out.append((p, {k: v[1] for k, v in tab.terms.items()}))


def state_symbols(ctx: ProblemContext) -> set:
    """Symbols of the state: coordinates, rates, accelerations, reactions, time."""
    out = {t} | set(ctx.reactions)
    for s in ctx.states:
        out |= {s.q, s.qd, s.qdd}
    out |= set(ctx.derived_formulas())
    return out


def _normal_trig(expr):
    """tan, cot, sec, csc as sin and cos; multiple and compound angles expanded."""
    if expr.has(sp.tan, sp.cot, sp.sec, sp.csc):
        expr = expr.rewrite(sp.cos, sp.sin) if expr.has(sp.sec, sp.csc, sp.cot) else expr
        expr = expr.replace(lambda e: isinstance(e, sp.tan),
                            lambda e: sp.sin(e.args[0]) / sp.cos(e.args[0]))
    rules = {}
    for f in expr.atoms(sp.sin, sp.cos):
        if not f.args[0].is_Symbol:
            rules[f] = sp.expand_trig(f)
    return expr.xreplace(rules) if rules else expr


def _pythagoras(expr):
    """Canonical form modulo ``sin^2 + cos^2 = 1``: even powers of cos become powers of sin."""
    rules = {}
    for p in expr.atoms(sp.Pow):
        if isinstance(p.base, sp.cos) and p.exp.is_Integer and p.exp >= 2:
            n = int(p.exp)
            rules[p] = sp.cos(p.base.args[0]) ** (n % 2) * \
                (1 - sp.sin(p.base.args[0]) ** 2) ** (n // 2)
    return sp.expand(expr.xreplace(rules)) if rules else expr


#: Ways to expand before comparing terms: as written (products expanded, trigonometric
#: functions untouched), multiple and compound angles expanded, and modulo sin^2 + cos^2 = 1.
MODES = ("written", "trig", "pythagoras")


def _normal(expr, mode: str):
    if mode == "written":
        return sp.expand(expr)
    e = sp.expand(_normal_trig(expr))
    return _pythagoras(e) if mode == "pythagoras" else e


def term_table(expr, ctx: ProblemContext, label: str = "", mode: str = "trig",
               parts: list | None = None):
    """The :class:`TermTable` of ``expr`` (None when it has too many terms).

    ``mode`` is one of :data:`MODES`.  ``parts`` (the answer's own top-level terms) keeps like
    terms the student wrote apart: ``terms[key] = (coefficient, value, [(coefficient, value)
    of each written term])``.
    """
    pieces = parts if parts is not None else [expr]
    states = state_symbols(ctx)
    env = coefficient_env(ctx)
    terms: dict = {}
    count = 0
    for piece in pieces:
        args = sp.Add.make_args(_normal(piece, mode))
        count += len(args)
        if count > _MAX_TERMS:
            return None
        local: dict = {}
        for term in args:
            if term == 0:
                continue
            coeff, key = [], []
            for f in sp.Mul.make_args(term):
                if f.free_symbols & states:
                    c, f = _canonical_factor(f, states)
                    coeff.append(c)
                    key.append(f)
                else:
                    coeff.append(f)
            k = sp.Mul(*key)
            local[k] = local.get(k, 0) + sp.Mul(*coeff)
        for k, c in local.items():
            terms.setdefault(k, []).append(c)
    out, hidden = {}, {}
    for k, cs in terms.items():
        try:
            vals = [Formula.from_sympy(c).evaluate(env) for c in cs]
        except (TypeError, ZeroDivisionError, KeyError):
            return None
        v = sum(vals, 0)
        written = [(c, x) for c, x in zip(cs, vals) if not zero(x, [1])]
        if not zero(v, [1]):
            out[k] = (sp.Add(*cs), v, written)
        elif len(written) >= 2:
            hidden[k] = (sp.Integer(0), 0, written)
    return TermTable(label, expr, out, hidden, mode)


def _canonical_factor(f, states):
    """``(c, g)`` with ``f = c*g``: a power of a sum of state terms (``1/(4*l**2 - (l0 +
    x)**2)``, ``sqrt(...)``) made canonical, so that the same factor written with another
    scale or sign (``2*l**2 - ...``, ``-(x**2 + ...)``) is the same state part; the scale goes
    to the coefficient.  A sum under an integer power is made monic in the state symbols (its
    leading coefficient, a parameter expression, leaves it); under any other power only its
    positive numeric content leaves it (no sign, so that no root of a negative number is
    taken)."""
    base, exp = f.as_base_exp()
    if not base.is_Add:
        return sp.Integer(1), f
    content, prim = base.as_content_primitive()
    if exp.is_Integer:
        syms = sorted(base.free_symbols & states, key=str)
        try:
            lead = sp.Poly(prim, *syms).LC()
        except sp.PolynomialError:
            lead = sp.Integer(1)
        if lead.free_symbols & states or lead == 0:
            lead = sp.Integer(1)
        content = content * lead
        prim = sp.expand(prim / lead)
    if content == 1:
        return sp.Integer(1), f
    return content ** exp, prim ** exp


def coefficient_env(ctx: ProblemContext):
    """Where coefficients (free of the state) are compared: the parameters of the context's
    first point, or -- a problem whose static rows leave no free states -- parameters drawn
    for this alone (deterministic per problem)."""
    def build():
        try:
            return ctx.points(ctx.method)[0].env()
        except GradingUnavailable:
            rng = random.Random(f"{ctx.problem.name}:coefficients")
            values = {p: Fraction(rng.randrange(2, 1 << 20), rng.randrange(1, 1 << 10))
                      for p in ctx.parameters}
            return Env(values, True, draw=seeded_draw(f"{ctx.problem.name}:coefficients"))
    return ctx.memo("coefficient_env", build)


def equation_targets(ctx: ProblemContext, mode: str = "trig",
                     coordinates: tuple | None = None) -> list[TermTable]:
    """Correct equations to compare a wrong one with (cached per context and mode): the
    reference model's rows first, then every other model's, then simple eliminations.

    ``coordinates`` (names, as :func:`answer_coordinates` gives them) asks for the rows of
    the models written in those coordinates instead, in those coordinates (falling_container's
    ``y1, y2``), so that an answer in them is diagnosed in them."""
    def build():
        out = []
        if coordinates is None:
            names = [ctx.reference.name] + [n for n in ctx.models if n != ctx.reference.name]
            rows = [(name, m.labels, [ctx.plain(e) for e in m.equations]) for name, m in
                    ((n, ctx.models.get(n, ctx.reference)) for n in names)]
        else:
            rows = []
            for name, m in ctx.problem.models().items():
                if tuple(q.func.__name__ for q in m.coordinates) == coordinates:
                    rows.append((name, m.labels, [m.to_plain(e) for e in m.equations]))
        vanish = _vanishing_reactions(ctx)
        for name, labels, equations in rows:
            for label, e in zip(labels, equations):
                # a reaction that is zero on the motion is no term of its row
                forms = [e, e.xreplace(vanish)] if vanish and e.free_symbols & set(vanish) \
                    else [e]
                for form in forms:
                    tab = term_table(form, ctx, f"{name}: {label}", mode)
                    if tab is not None and tab.terms:
                        out.append(tab)
        return out + _eliminations(ctx, out, mode)
    return ctx.memo(("equation_targets", mode, coordinates), build)


def _vanishing_reactions(ctx: ProblemContext) -> dict:
    """``{reaction: 0}`` for the reactions that are zero at every exact point of the motion
    (block_in_pipe's massless pipe cannot push its block: ``N = 0``)."""
    def build():
        try:
            points = ctx.points("exact")
        except GradingUnavailable:
            return {}
        return {r: sp.S.Zero for r in ctx.reactions
                if points and all(p.values.get(r, 1) == 0 for p in points)}
    return ctx.memo("vanishing_reactions", build)


def answer_coordinates(ctx: ProblemContext, symbols: set) -> tuple | None:
    """The coordinates (names) of a model the answer is written in, when it uses another
    model's coordinates and none of the reference's; None for the reference coordinates."""
    reference = set()
    for s in ctx.states:
        reference |= {s.q, s.qd, s.qdd}
    derived = set(ctx.derived_formulas())
    if not symbols & derived or symbols & reference:
        return None
    for m in ctx.problem.models().values():
        names = tuple(q.func.__name__ for q in m.coordinates)
        own = set()
        for q in m.coordinates:
            own |= {sym for sym in derived | reference if sym.name in
                    (q.func.__name__, q.func.__name__ + "_dot", q.func.__name__ + "_ddot")}
        if symbols & (derived | reference) <= own:
            return names
    return None


def _eliminations(ctx, rows: list, mode: str) -> list:
    """Row pairs of one model whose difference (by a constant factor) removes a reaction."""
    out = []
    react = set(ctx.reactions)
    by_model: dict = {}
    for tab in rows:
        by_model.setdefault(tab.label.split(":")[0], []).append(tab)
    for tabs in by_model.values():
        for i, a in enumerate(tabs):
            ka = [k for k in a.terms if k.free_symbols & react]
            if len(ka) != 1:
                continue
            for b in tabs[i + 1:]:
                kb = [k for k in b.terms if k.free_symbols & react]
                if kb != ka:
                    continue
                ratio = a.terms[ka[0]][0] / b.terms[kb[0]][0]
                expr = sp.expand(a.expr - ratio * b.expr)
                label = f"{a.label} minus ({ratio}) x {b.label.split(': ')[1]}"
                tab = term_table(expr, ctx, label, mode)
                if tab is not None and tab.terms and not any(
                        k.free_symbols & react for k in tab.terms):
                    out.append(tab)
    return out


def expression_tables(ctx: ProblemContext, key, forms: list, mode: str) -> list:
    """Term tables of correct forms of a quantity (cached under ``key`` per mode)."""
    def build():
        tabs = [term_table(f, ctx, str(key), mode) for f in forms]
        return [tb for tb in tabs if tb is not None and tb.terms]
    return ctx.memo(("expression_tables", key, mode), build)
