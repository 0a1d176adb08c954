r"""Grade one typed answer: :func:`grade` and the reusable :class:`Grader`.

Example
-------
>>> g = grade("simple_pendulum", "a*theta'' + g*sin(theta) = 0")
>>> g.status, g.summary
('right', 'equivalent to the equations of motion: every equation follows from them and together they determine the accelerations')
>>> print(grade("simple_pendulum", "a*theta'' - g*sin(theta) = 0"))  # doctest: +ELLIPSIS
WRONG: the equation does not follow from the equations of motion
  smallest edit that makes it right:
    - the term `-g*sin(theta)` has the wrong sign: it is `g*sin(theta)` (a gravity term)
  the equation is closest to ...
"""
from __future__ import annotations

import time

import sympy as sp

from dualmech.grade.answers import Quantity, catalogue, find_quantity, linearised_context
from dualmech.grade.context import GradingUnavailable, ProblemContext, build_seconds
from dualmech.grade.formula import Formula, difference
from dualmech.grade.cost import costliest
from dualmech.grade.judge import AnswerTimeout, Deadline, judge_equations, judge_expression
from dualmech.grade.judge_energy import judge_force, judge_kinetic, judge_lagrangian, judge_potential
from dualmech.grade.maps import student_map
from dualmech.grade.parser import LIMITS, AnswerError, Limits, parse, split_where
from dualmech.grade.result import Grade, check_feedback, score_of
from dualmech.grade.small_angles import other_form
from dualmech.grade.vocabulary import UnknownName, Vocabulary

__all__ = ["grade", "Grader"]

_METHODS = {"exact": "exact rational-point test", "slow": "library comparator"}


class Grader:
    """Grades answers to one problem; the problem's models and points are built once.

    ``problem`` is a :class:`~dualmech.model.problem.Problem` or a catalogue name.

    Examples
    --------
    >>> from dualmech import Grader
    >>> grader = Grader("simple_pendulum")
    >>> grader.grade("a*theta'' + g*sin(theta) = 0").right
    True
    >>> grader.grade("a*theta'' - g*sin(theta) = 0").right
    False
    """

    _cache: dict = {}

    def __init__(self, problem, seed: int = 0, limits: Limits = LIMITS):
        self._ctx = None
        self._named = None   # the catalogue name the problem was built from, if any
        if isinstance(problem, str):
            from dualmech import problems as catalogue_
            from dualmech.grade import stored_contexts as stored
            name = problem
            self._ctx = stored.load(name, seed)   # a context kept by an earlier run
            if self._ctx is not None:
                problem = self._ctx.problem
            else:
                try:
                    problem = catalogue_.get(name)
                except KeyError as exc:
                    raise AnswerError(exc.args[0] if exc.args else str(exc)) from None
                self._named = name if catalogue_.is_name(name) else None
        self.problem = problem
        self.seed = seed
        self.limits = limits

    @classmethod
    def of(cls, name: str, seed: int = 0, limits: Limits = LIMITS) -> "Grader":
        """The cached grader of catalogue problem ``name``."""
        key = (name, seed, limits)
        if key not in cls._cache:
            cls._cache[key] = cls(name, seed, limits)
        return cls._cache[key]

    @property
    def context(self) -> ProblemContext:
        if self._ctx is None:
            ctx = ProblemContext.of(self.problem, self.seed)
            if self._named is not None:
                ctx.named = self._named   # built from the bare name: may be kept (.stored)
            self._ctx = ctx
        return self._ctx

    def quantities(self) -> dict[str, str]:
        """``{name: description}`` of everything an answer to this problem may be."""
        return {n: q.description for n, q in catalogue(self.context).items()}

    def grade(self, answer: str, quantity: str | None = None, about: str | None = None,
              feedback: str = "full") -> Grade:
        """Grade ``answer`` (text) as ``quantity`` (default: equations of motion, or one
        equation when a single one is given for several coordinates); never raises for a bad
        answer -- the :class:`~.result.Grade` says what is wrong, as much as ``feedback``
        allows (:data:`~dualmech.grade.result.FEEDBACK_LEVELS`: ``verdict``, ``locate``,
        ``hint``, ``full``)."""
        check_feedback(feedback)
        return self._graded(answer, quantity, about).at_level(feedback)

    def _graded(self, answer, quantity, about) -> Grade:
        t0, built = time.thread_time(), build_seconds()
        qname = quantity or "auto"
        shown = answer if isinstance(answer, str) else repr(answer)
        try:
            verdict, qname, kind, ctx = self._grade(answer, quantity, about)
        except AnswerTimeout:
            return Grade(self.problem.name, qname, "", shown[:1000], "invalid",
                         _too_costly(answer, f"{self.limits.seconds:g} s", self.limits),
                         seconds=_since(t0, built))
        except (AnswerError, UnknownName, GradingUnavailable) as exc:
            return Grade(self.problem.name, qname, "", shown[:1000], "invalid", str(exc),
                         seconds=_since(t0, built))
        except (MemoryError, RecursionError, OverflowError) as exc:
            what = "memory" if isinstance(exc, MemoryError) else "nesting or number size"
            return Grade(self.problem.name, qname, "", shown[:1000], "invalid",
                         _too_costly(answer, f"the {what} allowed", self.limits),
                         seconds=_since(t0, built))
        except TypeError as exc:
            if "zoo" not in str(exc) and "nan" not in str(exc):
                return _internal(self.problem.name, qname, shown, exc, _since(t0, built))
            return Grade(self.problem.name, qname, "", shown[:1000], "invalid",
                         "the answer is infinite or undefined (e.g. `tan(pi/2)`, `1/0`); "
                         "write it so that it is defined on the motion.",
                         seconds=_since(t0, built))
        except ZeroDivisionError:
            return Grade(self.problem.name, qname, "", shown[:1000], "invalid",
                         "the answer divides by zero where it is evaluated on the motion (a "
                         "denominator such as `tan(pi/2)`, `1/cos(pi/2)` or `1/(x - x)` "
                         "vanishes); write it so that it is defined on the motion.",
                         seconds=_since(t0, built))
        except Exception as exc:  # a bug here must not stop a batch; it is reported as such
            return Grade(self.problem.name, qname, "", shown[:1000], "invalid",
                         f"could not grade this answer: internal error "
                         f"({type(exc).__name__}: {exc}); please report it",
                         seconds=_since(t0, built))
        bound = ctx.false_right_bound(verdict.degree, verdict.method) if verdict.status == \
            "right" else float("nan")
        method = verdict.method_text or _METHODS[verdict.method]
        if verdict.status == "right" and verdict.method == "exact":
            method += f", {len(ctx.points('exact'))} points, P(wrong answer passes) <= {bound:.1e}"
        score = score_of(verdict.status, verdict.parts, verdict.wrong_parts, verdict.edits,
                         verdict.credit)
        return Grade(self.problem.name, qname, kind, shown, verdict.status, verdict.summary,
                     verdict.details, verdict.edits, verdict.dimension_issues, verdict.matches,
                     verdict.state, method, bound, _since(t0, built), score=score)

    def _grade(self, answer, quantity, about):
        deadline = Deadline(self.limits.seconds)
        ctx = self.context
        answer, maps = split_where(answer, self.limits)
        eqs = parse(answer, self.limits)
        n = len(ctx.states)
        if quantity is None:
            q = find_quantity(ctx, "eom" if len(eqs) > 1 or n == 1 else "equation")
        else:
            q = find_quantity(ctx, quantity)
        asked = q.name
        if q.name == "linearised":
            ctx = linearised_context(ctx, about)
            q = find_quantity(ctx, "eom" if len(eqs) > 1 or n == 1 else "equation")
        voc = self._vocabulary(ctx, q)
        own = student_map(ctx, maps, voc, self.limits) if maps else None
        if own is not None:
            voc = own.vocabulary
        if q.kind in ("equations", "equation"):
            if any(side is not None and _unwrap(side).op == "vec"
                   for e in eqs for side in (e.lhs, e.rhs)):
                raise AnswerError("an equation cannot be a vector; write one equation per "
                                  "component, on separate lines.")
            formulas = [difference(Formula.from_node(e.lhs, voc, self.limits, e.text),
                                   Formula.from_node(e.rhs, voc, self.limits)
                                   if e.rhs is not None else None) for e in eqs]
            if own is not None:
                formulas = [own.rewrite(f, ctx) for f in formulas]
            v = judge_equations(ctx, formulas, q, deadline, single=q.kind == "equation")
            if v.status == "wrong" and own is None:
                said = other_form(self.context, formulas, q.kind, asked, about, deadline)
                if said:
                    v.details.insert(0, said)
            return v, asked, q.kind, ctx
        f = _expression(eqs, q, voc, self.limits)
        if own is not None:
            f = own.rewrite(f, ctx)
        if q.kind == "expression":
            return judge_expression(ctx, f, q, deadline, _components(ctx, f, q)), q.name, \
                q.kind, ctx
        if q.kind == "force":
            comps = [Formula(c) for c in f.tree[1]] if f.tree[0] == "vec" else [f]
            return judge_force(ctx, comps, q, deadline), q.name, q.kind, ctx
        if f.tree[0] == "vec":
            raise AnswerError(f"{q.description} is a scalar, not a vector.")
        judge = {"kinetic": judge_kinetic, "potential": judge_potential,
                 "lagrangian": judge_lagrangian}[q.kind]
        return judge(ctx, f, q, deadline), q.name, q.kind, ctx

    def _vocabulary(self, ctx, q: Quantity) -> Vocabulary:
        if not q.basis:
            return ctx.vocabulary
        key = ("vocabulary", q.basis)
        if key not in ctx.store:
            ctx.store[key] = Vocabulary.build(ctx.coordinates, ctx.parameters, ctx.reactions,
                                              q.basis, [q for q, _ in ctx._extra_coordinates()],
                                              getattr(ctx.problem, "aliases", None))
        return ctx.store[key]


def _internal(problem, qname, shown, exc, seconds) -> Grade:
    return Grade(problem, qname, "", shown[:1000], "invalid",
                 f"could not grade this answer: internal error ({type(exc).__name__}: {exc}); "
                 "please report it", seconds=seconds)


def _too_costly(answer, ceiling: str, limits: Limits) -> str:
    culprit = costliest(answer, limits) if isinstance(answer, str) else ""
    what = f"`{culprit}`" if culprit else "this answer"
    return (f"too costly to grade: {what} needs more than {ceiling} to evaluate; simplify "
            "it (smaller multiples of angles, lower powers, fewer nested functions) and "
            "submit again.")


def _unwrap(node):
    while node.op == "group":
        node = node.args[0]
    return node


def _since(t0: float, built: float) -> float:
    """CPU seconds on this answer, leaving out the problem's one-time loading meanwhile."""
    return time.thread_time() - t0 - (build_seconds() - built)


def _expression(eqs, q: Quantity, voc, limits) -> Formula:
    """The one expression of an answer; ``X = expr`` is accepted when ``X`` is a name."""
    if len(eqs) != 1:
        raise AnswerError(f"{q.description} is one expression; the answer has {len(eqs)} "
                          "parts (separate vector components with commas: [a, b, c]).")
    e = eqs[0]
    if e.rhs is None:
        return Formula.from_node(e.lhs, voc, limits, e.text)
    if e.lhs.op != "name":
        raise AnswerError(f"give {q.description} as an expression, or as `{q.name} = ...` "
                          "with a single name on the left.")
    return Formula.from_node(e.rhs, voc, limits, e.text)


def _components(ctx, f: Formula, q: Quantity) -> list | None:
    """Components of a vector answer: a ``[a, b, c]`` literal, or coefficients of the basis."""
    if f.tree[0] == "vec":
        return [Formula(c) for c in f.tree[1]]
    if not q.basis:
        return None
    basis = [sp.Symbol(b, commutative=True) for b in q.basis]
    if not f.symbols & set(basis):
        if len(q.reference) > 1:
            raise AnswerError(f"{q.name} is a vector: write it with "
                              f"{', '.join(q.basis)} or as [{', '.join(['...'] * len(basis))}].")
        return None
    d = f.unknown_degree(set(basis))
    if d is None or d > 1:
        raise AnswerError(f"{q.name}: each term must carry exactly one of {', '.join(q.basis)}.")
    expr = sp.expand(f.sympy())
    rest = expr.xreplace({b: 0 for b in basis})
    if rest != 0:
        raise AnswerError(f"{q.name} is a vector; the terms without {', '.join(q.basis)} "
                          "add a scalar to it.")
    return [Formula.from_sympy(sp.diff(expr, b)) for b in basis]


def grade(problem, answer: str, quantity: str | None = None, *, about: str | None = None,
          limits: Limits = LIMITS, feedback: str = "full") -> Grade:
    """Grade ``answer`` to ``problem`` (a Problem or a catalogue name); see :class:`Grader`.

    ``feedback`` is how much a wrong answer is told (:meth:`Grade.at_level
    <dualmech.grade.result.Grade.at_level>`): ``"verdict"``, ``"locate"``, ``"hint"`` or
    ``"full"`` (the default).

    An unknown problem name gives an ``invalid`` grade that lists the known ones.

    Bounds: in this process an answer is bounded by its size, depth and exponents
    (:class:`~dualmech.grade.parser.Limits`) and by the cost model (:mod:`~dualmech.grade.cost`)
    before anything is computed, but not by a clock or a memory ceiling.  For answers from
    people you do not trust, grade in :class:`~dualmech.grade.sandbox.GradingPool` (what the
    ``dualmech grade`` command and the web page always do): its workers run under a
    wall-clock and memory ceiling the operating system enforces.

    Examples
    --------
    >>> from dualmech import grade
    >>> result = grade("simple_pendulum", "theta'' = -g/a*sin(theta)")
    >>> result.right
    True
    >>> grade("no_such_problem", "x = 0").status
    'invalid'
    """
    check_feedback(feedback)
    try:
        grader = Grader.of(problem, limits=limits) if isinstance(problem, str) else \
            Grader(problem, limits=limits)
    except AnswerError as exc:
        return Grade(str(problem), quantity or "auto", "", answer if isinstance(answer, str)
                     else repr(answer), "invalid", str(exc), feedback=feedback)
    return grader.grade(answer, quantity, about, feedback)
