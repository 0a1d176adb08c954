"""The student's own coordinates: ``...; where x = 2*l*cos(theta) - l0``.

A map names new coordinates as expressions of the problem's reference coordinates, the
parameters and time, read by the answer grammar (:func:`.parser.split_where`).  The answer may
then use ``x``, ``x'`` and ``x''``; they are replaced by the map and its first and second time
derivatives (the chain rule on the map, differentiated symbolically -- the map is bounded by
the parser's limits) before the answer is decided as usual.  A map must be invertible where the
problem lives: at every sampled exact point the Jacobian of the new coordinates together with
the reference coordinates the answer still uses, with respect to the reference coordinates,
has full rank (decided exactly); otherwise the answer is refused with the reason.

Example
-------
>>> from dualmech.grade import grade
>>> grade("simple_pendulum", "a*s'' + g*a*sin(s/a) = 0; where s = a*theta").right
True
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from ..equations import state_symbols
from ..kinematics import coordinate, t
from ..verify import linalg as la
from .context import ProblemContext
from .formula import Formula
from .parser import LIMITS, AnswerError, Equation, Limits
from .vocabulary import Vocabulary

__all__ = ["StudentMap", "student_map"]


@dataclass
class StudentMap:
    """The student's coordinates: their ``vocabulary`` and ``rules`` (plain symbols of the new
    coordinates and their rates -> expressions in the reference coordinates)."""

    vocabulary: Vocabulary
    rules: dict
    names: list

    def rewrite(self, formula: Formula, ctx: ProblemContext) -> Formula:
        """``formula`` in the reference coordinates; refused when the map leaves the world the
        exact evaluator handles (the answer's own limits already bound its size)."""
        used = set(self.rules) & formula.symbols
        if not used:
            return formula
        self.check(ctx, formula.symbols)
        out = Formula.from_sympy(formula.sympy().xreplace(self.rules))
        out.text = formula.text
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
