"""Answers the fast exact evaluator cannot decide, decided by the library's comparator.

An answer with ``sqrt``, ``exp``, ``log``, a fractional power or an angle such as
``theta/2`` -- or any answer to a problem whose models have them -- is turned into an
:class:`~dualmech.model.equations.EquationSet` and judged by :func:`dualmech.verify.check.compare_models`
(and :func:`~dualmech.verify.check.compare_reactions` for the reactions it uses), whose verdict
names its own method (exact with square roots, or rigorous interval arithmetic, which is
evidence rather than proof).  A single equation, a reaction or an acceleration becomes one more
equation beside a model that determines the accelerations (and the reactions): the set is
equivalent to that model exactly when the answer holds on the motion.
"""
from __future__ import annotations

import sympy as sp

from dualmech.verify.check import compare_models, compare_reactions, method_name
from dualmech.model.equations import EquationSet, ModelError, from_plain
from dualmech.verify.sampling import Context
from dualmech.grade.context import GradingUnavailable, ProblemContext
from dualmech.grade.judge import Verdict
from dualmech.grade.parser import AnswerError

__all__ = ["slow_equations", "slow_expression"]

_POINTS = 4


_NONLINEAR = ("the answer uses an acceleration or a reaction non-linearly (inside a function, "
              "a root, a power or a denominator); write it so that they appear linearly "
              "(as in an equation of motion), or without them.")


def _candidate(name, coordinates, equations, unknowns) -> EquationSet:
    try:
        return EquationSet(name, coordinates, equations, unknowns)
    except ModelError:
        raise AnswerError(_NONLINEAR) from None


def _function_form(ctx: ProblemContext, formula) -> sp.Expr:
    expr = formula.sympy()
    derived = ctx.derived_formulas()
    if expr.free_symbols & set(derived):
        expr = expr.xreplace({s: f.sympy() for s, f in derived.items()})
    return from_plain(expr, ctx.coordinates)


def _model_with(ctx: ProblemContext, reactions) -> EquationSet:
    """The reference, or a square model in the reference coordinates with ``reactions``."""
    if set(reactions) <= set(ctx.reference.unknowns):
        return ctx.reference
    for m in ctx.models.values():
        if set(reactions) <= set(m.unknowns) and m.is_square:
            return m
    raise GradingUnavailable(f"no model of `{ctx.problem.name}` determines "
                             f"{', '.join(map(str, reactions))}.")


def _sampling(problem, reference: EquationSet, candidate: EquationSet) -> Context:
    """The comparator's sampling context with the problem's declared ranges and domains, so
    that exact points lie where the problem lives (the right branch of every root)."""
    c = Context.for_models(reference, candidate)
    return Context(c.coordinates, c.parameters, problem=problem)


def _decide(reference: EquationSet, candidate: EquationSet, used,
            problem=None) -> tuple[bool, str]:
    try:
        context = _sampling(problem, reference, candidate) if problem is not None else None
        r = compare_models(reference, candidate, points=_POINTS, explain=False,
                           context=context)
        ok, method = r.equivalent, r.method
        if ok and used:
            rr = compare_reactions(reference, reference, candidate, used, points=_POINTS,
                                   explain=False, context=context)
            ok = rr.equivalent
    except ModelError as exc:
        raise GradingUnavailable(f"the comparator cannot judge this answer: {exc}") from None
    return ok, _method_words(method)


def _method_words(method: str) -> str:
    try:
        return method_name(method)
    except Exception:  # an older or newer comparator: its own word for the method
        return str(method)


def slow_equations(ctx: ProblemContext, formulas: list, single: bool, dims: list) -> Verdict:
    """A set (or, ``single``, one equation) decided by the comparator."""
    eqs = [_function_form(ctx, f) for f in formulas]
    used = [r for r in ctx.reactions if any(r in f.symbols for f in formulas)]
    model = _model_with(ctx, used)
    if single:
        candidate = _candidate("answer", model.coordinates, model.equations + tuple(eqs),
                               model.unknowns)
        ok, method = _decide(model, candidate, [], ctx.problem)
        summary = "the equation follows from the equations of motion" if ok else \
            "the equation does not follow from the equations of motion"
    else:
        candidate = _candidate("answer", ctx.coordinates, tuple(eqs), tuple(used))
        ok, method = _decide(model, candidate, used, ctx.problem)
        summary = "equivalent to the equations of motion" if ok else \
            "not equivalent to the equations of motion"
    status = "right" if ok and not dims else "wrong"
    return Verdict(status, summary, dimension_issues=dims, method="slow", method_text=method)


def slow_expression(ctx: ProblemContext, comps: list, refs: list, dims: list,
                    description: str) -> Verdict:
    """``answer - reference = 0`` for each component, beside a model that determines them."""
    eqs = [_function_form(ctx, c) - from_plain(r.sympy(), ctx.coordinates)
           for c, r in zip(comps, refs)]
    used = [u for u in ctx.reactions if any(u in r.symbols for r in refs)]
    model = _model_with(ctx, used)
    candidate = _candidate("answer", model.coordinates, model.equations + tuple(eqs),
                           model.unknowns)
    ok, method = _decide(model, candidate, [], ctx.problem)
    status = "right" if ok and not dims else "wrong"
    summary = description if ok else f"{description}: it differs from the right value on the motion"
    return Verdict(status, summary, dimension_issues=dims, method="slow", method_text=method)
