r"""The small-angle form where the nonlinear equations are asked, and the other way round.

A classic slip is to answer with the equations linearised about the equilibrium (``sin
theta`` written ``theta``) when the full equations of motion are asked, or to hand in the
full nonlinear equations when their linearisation is asked.  Such an answer is wrong, but the
edit that explains it is not a term or two: every nonlinear term changes.  :func:`other_form`
grades a wrong answer against the other form and, when it is right there, says so in words.

The linearisation is taken about the point the question names (``about``; default every
coordinate zero) and only when that point is an equilibrium of the reference model (its
equations vanish there at rest, read off structurally): a model pushed by a constant force
(``m g sin(alpha)`` on an incline) or a time-dependent drive has no such linear form, and
nothing is said.

Example
-------
>>> from dualmech.grade import grade
>>> g = grade("simple_pendulum", "a*theta'' + g*theta = 0")
>>> g.status, g.details[0]
('wrong', 'this is the small-angle form: the equations linearised about theta=0; the full nonlinear equations of motion are asked')
"""
from __future__ import annotations

import sympy as sp

from dualmech.grade.answers import find_quantity, linearised_context
from dualmech.grade.context import GradingUnavailable, ProblemContext
from dualmech.grade.judge import AnswerTimeout, Deadline, judge_equations
from dualmech.grade.parser import AnswerError
from dualmech.model.equations import ModelError
from dualmech.model.kinematics import t

__all__ = ["other_form"]


def other_form(ctx: ProblemContext, formulas: list, kind: str, asked: str,
               about: str | None, deadline: Deadline) -> str:
    """A sentence when ``formulas`` (a wrong answer of ``kind`` ``equations``/``equation``)
    are right as the other form -- linearised when ``asked`` is not ``linearised``, the full
    equations when it is; ``""`` otherwise.  ``ctx`` is the full problem's context."""
    name = "eom" if kind == "equations" else "equation"
    try:
        lctx = _linear(ctx, about)
        if lctx is None:
            return ""
        if asked == "linearised":
            other, words = ctx, ("these are the full nonlinear equations of motion; they "
                                 f"are asked linearised about {_point(lctx)}")
        else:
            other, words = lctx, ("this is the small-angle form: the equations linearised "
                                  f"about {_point(lctx)}; the full nonlinear equations of "
                                  "motion are asked")
        v = judge_equations(other, formulas, find_quantity(other, name), deadline,
                            single=kind == "equation")
    except (AnswerError, GradingUnavailable, ModelError, AnswerTimeout, KeyError,
            TypeError, ValueError, ZeroDivisionError):
        return ""
    return words if v.status == "right" else ""


def _linear(ctx: ProblemContext, about: str | None):
    """The linearised context about ``about``, or None when that point is no equilibrium."""
    lctx = linearised_context(ctx, about)
    point = getattr(lctx.problem, "about_point", None)
    if point is None or not _at_rest(ctx, point):
        return None
    return lctx


def _at_rest(ctx: ProblemContext, point: dict) -> bool:
    """Whether the reference equations vanish, structurally, at ``point`` with every rate and
    acceleration zero (a constant push or a time-dependent drive: no)."""
    still = {}
    for q in ctx.coordinates:
        still[q.diff(t, 2)] = 0
        still[q.diff(t)] = 0
    for q in ctx.coordinates:
        still[q] = point.get(q, 0)
    for e in ctx.reference.equations:
        value = sp.expand(sp.sympify(e).subs(still))
        if value != 0:
            return False
    return True


def _point(lctx) -> str:
    return getattr(lctx.problem, "about_text", "the equilibrium")
