"""The student's own coordinates: ``...; where x = 2*l*cos(theta) - l0``.

A map names new coordinates as expressions of the problem's reference coordinates, the
parameters and time, read by the answer grammar (:func:`.parser.split_where`).  The answer may
then use ``x``, ``x'`` and ``x''``; they are replaced by the map and its first and second time
derivatives (the chain rule on the map, differentiated symbolically -- the map is bounded by
the parser's limits) before the answer is decided as usual.  A map must be invertible where the
problem lives: at every sampled exact point the Jacobian of the new coordinates together with
the reference coordinates the answer still uses, with respect to the reference coordinates,
has full rank (decided exactly); otherwise the answer is refused with the reason.

A wrong answer is diagnosed in the student's coordinates when the map can be inverted in
closed form -- an affine map (``s = a*theta``, ``y = x2 - x1``, coefficients free of the
state): the correct equations are rewritten in the student's coordinates
(:meth:`StudentMap.targets`) and the smallest edit is sought among them, so that the named term
is one the student could have written (``-g*a*sin(s/a)``, not ``-a*g*sin(theta)``).

Example
-------
>>> from dualmech.grade import grade
>>> grade("simple_pendulum", "a*s'' + g*a*sin(s/a) = 0; where s = a*theta").right
True
"""
from __future__ import annotations

from dataclasses import dataclass, field

import mpmath
import sympy as sp

from dualmech.model.equations import state_symbols, to_plain
from dualmech.exact.form import MP_DIGITS
from dualmech.model.kinematics import coordinate, t
from dualmech.exact import linalg as la
from dualmech.model.dimensions import TIME
from dualmech.grade.audit import expected_dimension, reduced
from dualmech.grade.context import ProblemContext, _dsub
from dualmech.grade.formula import Formula
from dualmech.grade.parser import LIMITS, AnswerError, Equation, Limits
from dualmech.grade.terms import equation_targets, term_table
from dualmech.grade.vocabulary import Vocabulary

__all__ = ["StudentMap", "StudentView", "student_map"]


#: Largest integer multiple of a student's coordinate that the inverse of their map may
#: put into the correct equations (``theta = 8*s`` gives ``sin(8*s)``).
_MAX_MULTIPLE = 8


@dataclass
class StudentMap:
    """The student's coordinates: their ``vocabulary`` and ``rules`` (plain symbols of the new
    coordinates and their rates -> expressions in the reference coordinates)."""

    vocabulary: Vocabulary
    rules: dict
    names: list
    _cache: dict = field(default_factory=dict, repr=False)

    def rewrite(self, formula: Formula, ctx: ProblemContext) -> Formula:
        """``formula`` in the reference coordinates; refused when the map leaves the world the
        exact evaluator handles (the answer's own limits already bound its size)."""
        used = set(self.rules) & formula.symbols
        if not used:
            return formula
        self.check(ctx, formula.symbols)
        out = Formula.from_sympy(formula.sympy().xreplace(self.rules))
        out.text = formula.text
        out.student = (formula, self)
        return out

    def check(self, ctx: ProblemContext, symbols: set) -> None:
        """Refuse a map whose Jacobian is singular at a sampled point (not invertible)."""
        reference = [s for s in ctx.states if {s.q, s.qd, s.qdd} & symbols]
        rows = []
        for name in self.names:
            expr = self.rules[state_symbols(coordinate(name)).q]
            rows.append((name, [Formula.from_sympy(sp.diff(expr, s.q)) for s in ctx.states]))
        for s in reference:
            rows.append((s.name, [Formula.from_sympy(sp.Integer(int(o is s)))
                                  for o in ctx.states]))
        if len(rows) > len(ctx.states):
            raise AnswerError(f"the answer uses {len(rows)} coordinates "
                              f"({', '.join(n for n, _ in rows)}) for a problem with "
                              f"{len(ctx.states)}; write it in {len(ctx.states)} independent "
                              "coordinates.")
        method = ctx.method
        for p in ctx.points(method):
            env = p.env()
            try:
                J = [[f.evaluate(env) for f in row] for _, row in rows]
            except ZeroDivisionError:
                raise AnswerError("the map's derivative divides by zero at a state of the "
                                  "motion; check the map.") from None
            except (TypeError, ValueError):
                raise AnswerError("the map cannot be evaluated exactly at the problem's "
                                  "states; write it with polynomials, sin and cos of the "
                                  "coordinates (multiple angles up to the answer limits).") \
                    from None
            if la.rank(J) < len(rows):
                names = ", ".join(n for n, _ in rows)
                raise AnswerError(f"the coordinates {names} do not determine the problem's "
                                  "coordinates: the map's Jacobian is singular at a state of "
                                  "the motion, so it is not invertible there; choose "
                                  "coordinates that are independent.")


    # -- diagnosis in the student's coordinates -------------------------------------------
    def view(self, ctx: ProblemContext) -> "StudentView":
        """``ctx`` seen with the student's coordinates as mapped ones (cached)."""
        if "view" not in self._cache:
            derived = {sym: Formula.from_sympy(expr) for sym, expr in self.rules.items()}
            self._cache["view"] = StudentView(ctx, derived)
        return self._cache["view"]

    def inverse(self, ctx: ProblemContext, symbols: set) -> dict | None:
        """Rules giving the reference coordinates the answer (with ``symbols``) does not use,
        and their rates, in the student's coordinates -- when the map is affine in them with
        state-free coefficients (then the inverse is exact and unique); else None."""
        key = ("inverse", frozenset(symbols))
        if key in self._cache:
            return self._cache[key]
        self._cache[key] = out = self._inverse(ctx, symbols)
        return out

    def _inverse(self, ctx, symbols) -> dict | None:
        new = [state_symbols(coordinate(n)) for n in self.names]
        unknown = [s for s in ctx.states if not {s.q, s.qd, s.qdd} & symbols]
        if len(unknown) != len(new) or len(new) > 4:
            return None
        states = set()
        for s in ctx.states:
            states |= {s.q, s.qd, s.qdd}
        maps = sp.Matrix([self.rules[s.q] for s in new])
        J = maps.jacobian([s.q for s in unknown])
        if J.free_symbols & states:
            return None
        try:
            b = maps - J * sp.Matrix([s.q for s in unknown])
            if sp.expand(b).free_symbols & {s.q for s in unknown}:
                return None
            if J.det() == 0:
                return None
            solved = J.LUsolve(sp.Matrix([s.q for s in new]) - b)
        except (ValueError, ZeroDivisionError, sp.PolynomialError):
            return None
        # the correct equations' angles become multiples of the student's coordinates
        # (theta = 150*s): past a small multiple, expanding them would cost more than the
        # answer itself was allowed to; such answers are diagnosed in the problem's
        # coordinates instead
        if any(abs(r.p) > _MAX_MULTIPLE for e in solved for r in sp.expand(e).atoms(sp.Rational)):
            return None
        functions = [coordinate(n) for n in self.names]
        timed_rule = {s.q: f for s, f in zip(new, functions)}
        timed_rule.update({st.q: q for st, q in zip(ctx.states, ctx.coordinates)})
        every = list(ctx.coordinates) + functions
        out = {}
        for s, expr in zip(unknown, solved):
            timed = sp.expand(expr).xreplace(timed_rule)
            out[s.q] = sp.expand(expr)
            out[s.qd] = to_plain(timed.diff(t), every)
            out[s.qdd] = to_plain(timed.diff(t, 2), every)
        return out

    def targets(self, ctx: ProblemContext, symbols: set, mode: str) -> list | None:
        """The correct equations (:func:`.terms.equation_targets`) in the student's
        coordinates, as term tables of :meth:`view`; None when the map has no closed-form
        inverse."""
        inverse = self.inverse(ctx, symbols)
        if inverse is None:
            return None
        key = ("targets", frozenset(symbols), mode)
        if key not in self._cache:
            view = self.view(ctx)
            out = []
            for tab in equation_targets(ctx, mode):
                moved = term_table(sp.expand(tab.expr.xreplace(inverse)), view, tab.label, mode)
                if moved is not None and moved.terms:
                    out.append(moved)
            self._cache[key] = out
        return self._cache[key]

    def state(self, ctx: ProblemContext, state: dict, symbols: set) -> dict:
        """The concrete state of :func:`.feedback.concrete_state` (at the context's first
        real point, in the reference coordinates) in the coordinates the answer uses: the
        reference coordinates the map replaces give way to the student's, by the map."""
        inverse = self.inverse(ctx, symbols)
        if inverse is None:
            return state
        gone = {st.name for st in ctx.states if st.q in inverse}
        out = {k: v for k, v in state.items() if k.rstrip("'") not in gone}
        env = ctx.points("mpmath")[0].env()
        with mpmath.workdps(MP_DIGITS):
            for name in self.names:
                s = state_symbols(coordinate(name))
                for sym, key in ((s.q, name), (s.qd, name + "'")):
                    v = Formula.from_sympy(self.rules[sym]).evaluate(env)
                    out[key] = float(mpmath.re(v))
        return out


class StudentView:
    """A :class:`ProblemContext` that also knows the student's coordinates (their plain
    symbols map to formulas in the reference ones, like a declared model's coordinates), so
    that term tables, categories and notation treat them as the state.  Everything else is the
    problem's context."""

    def __init__(self, ctx: ProblemContext, derived: dict):
        self._ctx = ctx
        self._derived = {**ctx.derived_formulas(), **derived}
        self.store = {}
        self.names = dict(ctx.names)
        self.dims = dict(ctx.dims)
        T = reduced(TIME)
        for sym, f in derived.items():
            if sym.name.endswith("_dot"):
                continue
            base = sym.name
            rates = {x.name: x for x in derived}
            qd, qdd = rates.get(base + "_dot"), rates.get(base + "_ddot")
            if qd is None or qdd is None:
                continue
            self.names[qd], self.names[qdd] = base + "'", base + "''"
            d = expected_dimension(f, ctx.dims)
            if d is not None:      # a map of inconsistent dimensions: its terms say so
                self.dims[sym], self.dims[qd], self.dims[qdd] = d, _dsub(d, T, 1), \
                    _dsub(d, T, 2)

    def __getattr__(self, name):
        return getattr(self._ctx, name)

    def derived_formulas(self) -> dict:
        return self._derived

    def memo(self, key, build):
        if key == "coefficient_env":
            return self._ctx.memo(key, build)
        if key not in self.store:
            self.store[key] = build()
        return self.store[key]


def student_map(ctx: ProblemContext, maps: list[Equation], vocabulary: Vocabulary,
                limits: Limits = LIMITS) -> StudentMap:
    """Read the ``where`` clauses ``maps`` against the problem of ``ctx``."""
    reference = {s.q for s in ctx.states}
    rates = set()
    for s in ctx.states:
        rates |= {s.qd, s.qdd}
    new_q, rules, names = [], {}, []
    for m in maps:
        name = m.lhs.args[0]
        ref = vocabulary.lookup(name)
        if ref is not None and (ref.kind != "coordinate" or ref.symbol in reference):
            raise AnswerError(f"`{name}` already means a {ref.kind} of the problem; give your "
                              "coordinate another name.")
        if name in names:
            raise AnswerError(f"`{name}` is defined twice after `where`.")
        f = Formula.from_node(m.rhs, vocabulary, limits, m.text)
        bad = f.symbols - reference - set(ctx.parameters) - {t}
        if bad & rates:
            raise AnswerError(f"the map of `{name}` must use the coordinates themselves, not "
                              "their rates.")
        if bad:
            shown = ", ".join(sorted(str(b) for b in bad))
            raise AnswerError(f"the map of `{name}` may use only the problem's coordinates "
                              f"({', '.join(s.name for s in ctx.states)}), parameters and t; "
                              f"it uses {shown}.")
        if f.tree[0] == "vec":
            raise AnswerError(f"the map of `{name}` must be a scalar.")
        q = coordinate(name)
        s = state_symbols(q)
        expr = f.sympy()
        timed = expr.xreplace({st.q: qq for st, qq in zip(ctx.states, ctx.coordinates)})
        rules[s.q] = expr
        rules[s.qd] = ctx.plain(timed.diff(t))
        rules[s.qdd] = ctx.plain(timed.diff(t, 2))
        new_q.append(q)
        names.append(name)
    voc = Vocabulary.build(ctx.coordinates, ctx.parameters, ctx.reactions,
                           extra_coordinates=new_q,
                           aliases=getattr(ctx.problem, "aliases", None))
    return StudentMap(voc, rules, names)
