"""Deciding an answer exactly: equation sets, single equations and expressions.

Every verdict comes from evaluating the answer at the context's points on the verified motion
(:mod:`.context`): an equation is right when it vanishes there with the true accelerations and
reactions put in; a set must also determine every acceleration (and every reaction it uses) --
the rank of its coefficients, computed exactly; an expression must equal the problem's own
quantity there.  Feedback (:mod:`.feedback`) only explains a verdict already reached.

Example
-------
>>> from dualmech.problems import get
>>> from dualmech.grade.context import ProblemContext
>>> from dualmech.grade.answers import find_quantity
>>> from dualmech.grade.formula import Formula
>>> from dualmech.grade.parser import parse
>>> ctx = ProblemContext.of(get("simple_pendulum"))
>>> f = Formula.from_node(parse("a*theta'' + g*sin(theta)")[0].lhs, ctx.vocabulary)
>>> judge_equations(ctx, [f], find_quantity(ctx, "eom"), Deadline(5)).status
'right'
"""
from __future__ import annotations

import random
import time
from fractions import Fraction
from dataclasses import dataclass, field, replace

import mpmath
import sympy as sp

from dualmech.exact.form import MP_DIGITS
from dualmech.exact import linalg as la
from dualmech.grade.answers import Quantity
from dualmech.grade.context import GradingUnavailable, Point, ProblemContext, build_seconds, zero
from dualmech.grade.feedback import Diagnosis, best_edit, concrete_state, differing_kinds
from dualmech.grade.notation import for_student, in_their_words
from dualmech.grade.terms import answer_coordinates, equation_targets, expression_tables, term_table
from dualmech.grade.audit import dimension_issues, display, expected_dimension, label_words
from dualmech.exact.surds import Surd
from dualmech.grade.formula import Formula, NotExactHere
from dualmech.grade.parser import AnswerError
from dualmech.grade.result import DIMENSIONS_ONLY, Edit
from dualmech.grade.systems import constrained_group, constraint_rows, determines_system
from dualmech.grade.targets import expression_targets

__all__ = ["Verdict", "Deadline", "AnswerTimeout", "judge_equations", "judge_expression",
           "says_nothing", "check_real", "audited", "roots_stay_exact",
           "method_for", "values_at"]

_MAX_FEEDBACK_TERMS = 400


class AnswerTimeout(AnswerError):
    """Grading one answer took longer than its time limit."""


class Deadline:
    """A time limit for one answer; :meth:`check` raises :class:`AnswerTimeout` past it.

    The limit is on the CPU time of the grading thread (``time.thread_time``), so a busy
    machine does not make an ordinary answer "too slow"; the wall clock and memory are
    bounded by the worker process of :mod:`.sandbox`, which the operating system stops."""

    def __init__(self, seconds: float):
        self.seconds = seconds
        self.start = time.thread_time()
        self.built = build_seconds()

    def elapsed(self) -> float:
        """CPU seconds spent on this answer, leaving out per-problem caches built meanwhile."""
        return time.thread_time() - self.start - (build_seconds() - self.built)

    def check(self) -> None:
        if self.elapsed() > self.seconds:
            raise AnswerTimeout(f"grading this answer took longer than {self.seconds:g} s; "
                                "simplify it and try again.")


@dataclass
class Verdict:
    """What a judge decided, before it becomes a :class:`~.result.Grade`."""

    status: str
    summary: str
    details: list = field(default_factory=list)
    edits: list = field(default_factory=list)
    dimension_issues: list = field(default_factory=list)
    matches: str = ""
    state: dict = field(default_factory=dict)
    method: str = "exact"
    degree: int = 1
    method_text: str = ""
    parts: int = 1                    # equations (or components) in the answer
    wrong_parts: tuple | None = None  # which of them are wrong (None: not known, all)
    credit: float | None = None       # a score set by the judge itself (see result.score_of)


def audited(ctx: ProblemContext, tree, dims: dict, names: dict, expected=None) -> list[str]:
    """:func:`~.audit.dimension_issues` of an answer, or none when the problem declares that
    its equations hold no dimensions to audit (``dimensions_unchecked``: a geometry fixed at
    numbers, whose lengths are then plain numbers in a right answer too)."""
    if getattr(ctx.problem, "dimensions_unchecked", ""):
        return []
    return dimension_issues(tree, dims, names, expected)


def method_for(ctx: ProblemContext, formulas) -> str:
    """``exact`` when the problem and every formula evaluate exactly (the fast evaluator),
    else ``slow`` (the library's comparator decides, :mod:`.comparator_fallback`).  Formulas
    with square roots of expressions are exact where their radicands and the models' are
    independent at the points (:func:`roots_stay_exact`)."""
    if ctx.method != "exact" or not all(f.exact for f in formulas):
        return "slow"
    return "exact" if roots_stay_exact(ctx, formulas) else "slow"


def roots_stay_exact(ctx: ProblemContext, formulas) -> bool:
    """False when a square root of an expression in ``formulas`` cannot be kept exact at
    the context's points (a radicand negative, a rational square, or dependent on another
    root met there, the models' included: :class:`~.formula.NotExactHere`); the values and
    their sum are computed once here, so the judges meet no such root later."""
    if not any(f.state_roots for f in formulas):
        return True
    need = need_for(ctx, formulas)
    try:
        for p in ctx.points("exact"):
            env = p.env(need=need)
            total = sum((v for v in env.values.values() if isinstance(v, Surd)), Fraction(0))
            for f in formulas:
                v = f.evaluate(env)
                for x in (v if isinstance(v, list) else [v]):
                    total = total + x
    except (NotExactHere, ValueError):
        return False
    except (ZeroDivisionError, KeyError, TypeError):
        return True     # the judge says what is wrong with the answer
    return True


def need_for(ctx: ProblemContext, formulas) -> tuple:
    derived = ctx.derived_formulas()
    used = set().union(*(f.symbols for f in formulas)) if formulas else set()
    return tuple(s for s in derived if s in used)


def values_at(ctx, formulas, method, deadline, need=()) -> list:
    """``[point][formula]`` values on the motion (``ZeroDivisionError`` -> AnswerError)."""
    out = []
    for p in ctx.points(method):
        deadline.check()
        env = p.env(need=need)
        try:
            out.append([(f.evaluate(env), env) for f in formulas])
        except ZeroDivisionError:
            raise AnswerError("the answer divides by zero: a denominator vanishes "
                              "identically.") from None
        except KeyError as exc:   # a reaction no model of the problem determines
            raise AnswerError(f"`{exc.args[0]}` is not determined by the problem's models, "
                              "so an answer cannot use it.") from None
    return out


def says_nothing(ctx: ProblemContext, formulas: list, method: str, need=(),
                 deadline: Deadline | None = None) -> list[int]:
    """Indices of the ``formulas`` that vanish for any motion: at random states with random
    accelerations and reactions (no point of the motion is needed: a formula that says
    something about the system is nonzero somewhere off it).

    Exact formulas are decided exactly at rational points (Schwartz--Zippel, as the
    verdicts); others at real points in the declared ranges at high precision, relative to
    the size of their terms.  A formula that cannot be evaluated there is left to the verdict.
    """
    exact = method == "exact"
    ranges = ctx.ranges()
    symbols = list(ctx.base) + list(ctx.qdd) + list(ctx.reactions)
    envs = []
    for i in range(2):
        rng = random.Random(f"{ctx.problem.name}:{ctx.seed}:says-nothing:{i}")
        values = {}
        for s in symbols:
            if exact:
                values[s] = Fraction(rng.randrange(-(1 << 61), 1 << 61))
            else:
                lo, hi = ranges.get(s, (-1.0, 1.0))
                with mpmath.workdps(MP_DIGITS):
                    values[s] = mpmath.mpf(rng.uniform(lo, hi))
        seed = f"{ctx.problem.name}:{ctx.seed}:says-nothing:{i}"
        envs.append(Point(values, {}, exact, i, seed, ctx.derived_formulas()))
    out = []
    for i, f in enumerate(formulas):
        empty = True
        for p in envs:
            if deadline is not None:
                deadline.check()
            try:
                with mpmath.workdps(MP_DIGITS):
                    env = p.env(need=need)
                    v = f.evaluate(env)
                    scale = f.term_values(env) if not exact else ()
                    ok = zero(v, scale) if not isinstance(v, list) else False
            except (ZeroDivisionError, TypeError, ValueError, KeyError, OverflowError):
                ok = False
            if not ok:
                empty = False
                break
        if empty:
            out.append(i)
    return out


def check_real(ctx: ProblemContext, formulas: list, need=()) -> None:
    """Raise :class:`AnswerError` when a formula is not a finite real number on the motion
    (``log(-1)``, ``sqrt(-1)``, ``cot(0)``): such an answer is not graded as typed."""
    try:
        points = ctx.points("mpmath")
    except GradingUnavailable:
        return
    for p in points:
        with mpmath.workdps(MP_DIGITS):
            try:
                env = p.env(need=need)
                values = [f.evaluate(env) for f in formulas]
            except ZeroDivisionError:
                raise AnswerError("the answer divides by zero on the motion (e.g. `cot(0)`, "
                                  "`1/sin(0)`, `1/(x - x)`); write it so that it is "
                                  "defined.") from None
            except (TypeError, ValueError, KeyError):
                return      # left to the verdict
            for v in values:
                for x in (v if isinstance(v, list) else [v]):
                    if isinstance(x, mpmath.mpc) and abs(x.imag) > 10 ** (-(MP_DIGITS // 2)) \
                            * (1 + abs(x.real)):
                        raise AnswerError("the answer is not a real number on the motion (the "
                                          "logarithm or a square root of a negative number?); "
                                          "check the signs inside `log` and `sqrt`.")
                    if isinstance(x, (mpmath.mpf, mpmath.mpc)) and not mpmath.isfinite(x):
                        raise AnswerError("the answer is infinite or undefined on the motion "
                                          "(e.g. `log(0)`, `cot(0)`, `tan(pi/2)`); write it so "
                                          "that it is defined.")


def _is_zero(f: Formula, v, env) -> bool:
    if isinstance(v, list):
        return all(zero(x) for x in v)
    return zero(v)


# -- equations ----------------------------------------------------------------------------------
def judge_equations(ctx: ProblemContext, formulas: list, quantity: Quantity,
                    deadline: Deadline, single: bool = False) -> Verdict:
    """A set of equations (``single``: one equation that must follow from the motion)."""
    k = len(formulas)
    name = (lambda i: f"equation {i + 1}") if k > 1 else (lambda i: "the equation")
    dims = []
    for i, f in enumerate(formulas):
        written, smap = f.student or (f, None)
        seen = smap.view(ctx) if smap is not None else ctx
        mine = in_their_words(seen, f.text)
        for issue in audited(ctx, written.tree, seen.dims, seen.names):
            dims.append(mine(f"{name(i)}: {issue}" if k > 1 else issue))
    unknowns = set(ctx.qdd) | set(ctx.reactions) | {
        s for s in ctx.derived_formulas() if s.name.endswith("_ddot")}
    for i, f in enumerate(formulas):
        d = f.unknown_degree(unknowns)
        if d is None or d > 1:
            return Verdict("wrong", f"{name(i)} is not linear in the accelerations"
                           f"{' and reactions' if ctx.reactions else ''}; equations of motion "
                           "are (no acceleration squared, inside a function or in a "
                           "denominator).", dimension_issues=dims)
        if f.tree[0] == "vec":
            raise AnswerError("an equation cannot be a vector; write one equation per "
                              "component, on separate lines.")
    method = method_for(ctx, formulas)
    if method == "slow":
        check_real(ctx, formulas, need_for(ctx, formulas))
    group = None if single else constrained_group(ctx, formulas)
    constraints = constraint_rows(ctx, formulas, group) if group else {}
    empty = [i for i in says_nothing(ctx, formulas, method, need_for(ctx, formulas), deadline)
             if i not in constraints]
    if empty:
        which = ", ".join(name(i) for i in empty)
        many = len(empty) > 1
        return Verdict("wrong", f"{which} hold{'' if many else 's'} for any motion (every state, "
                       "acceleration and force): "
                       f"{'they say' if many else 'it says'} nothing about this system; an "
                       "equation of motion must involve the accelerations on the motion",
                       dimension_issues=dims, method="exact" if method == "exact" else "slow")
    if method == "slow":
        from dualmech.grade.comparator_fallback import slow_equations
        v = slow_equations(ctx, formulas, single or quantity.coordinate is not None, dims)
        try:
            wrong = _off_at_real_points(ctx, formulas, [None] * k) if v.status == "wrong" \
                else []
        except GradingUnavailable:      # (before ValueError: it is one)
            # no free real states (a static row ties the coordinates): each equation of a
            # wrong set is asked on its own whether it follows from the motion
            wrong = [0] if k == 1 else [
                i for i, f in enumerate(formulas)
                if slow_equations(ctx, [f], True, []).status != "right"]
        except (TypeError, ValueError, ZeroDivisionError):
            wrong = list(range(k))
        try:
            if wrong:
                fb = _wrong_equations(ctx, formulas, wrong, dims, method, 1, name, deadline,
                                      need_for(ctx, formulas))
                v.edits, v.details, v.state = fb.edits, fb.details, fb.state
        except GradingUnavailable:   # no free points (a static row): no explanation
            v.details = ["(no explanation: this problem's static rows leave no free states "
                         "to show it at)"]
        return v
    need = need_for(ctx, formulas)
    table = values_at(ctx, formulas, method, deadline, need)
    wrong = [i for i, f in enumerate(formulas)
             if any(not _is_zero(f, row[i][0], row[i][1]) for row in table)]
    degree = max(f.degree for f in formulas)
    if wrong:
        return _wrong_equations(ctx, formulas, wrong, dims, method, degree, name, deadline, need)
    if dims:
        return Verdict("wrong", f"the answer follows from {ctx.subject} but is "
                       "dimensionally inconsistent", dimension_issues=dims, method=method,
                       degree=degree)
    points = ctx.points(method)
    match, coords = describe_match(ctx, formulas[0], points[0], need) if k == 1 else ("", [])
    if quantity.coordinate is not None:
        j = quantity.coordinate
        qname = ctx.states[j].name
        if coords != [j]:
            what = f"it matches {match}" if match else "it is a combination of equations"
            return Verdict("wrong", f"the equation follows from {ctx.subject}, but "
                           f"it is not the equation of {qname}: {what}", matches=match,
                           method=method, degree=degree)
        return Verdict("right", f"the equation of {qname}: {match}", matches=match,
                       method=method, degree=degree)
    if single:
        return Verdict("right", f"the equation follows from {ctx.subject}; it "
                       f"matches {match}", matches=match, method=method, degree=degree)
    if group is not None:
        complete, summary, credit = determines_system(ctx, formulas, points, need, group,
                                                      constraints)
        return Verdict("right" if complete else "wrong", summary, method=method,
                       degree=degree, parts=k, wrong_parts=() if not complete else None,
                       credit=None if complete else credit)
    return _determines(ctx, formulas, points, need, method, degree, deadline)


def _determines(ctx, formulas, points, need, method, degree, deadline) -> Verdict:
    """Right when the (correct) equations determine every acceleration and used reaction."""
    n, k = len(ctx.states), len(formulas)
    used = [r for r in ctx.reactions if any(r in f.symbols for f in formulas)]
    cols = list(ctx.qdd) + used
    for p in (points[0], points[-1]):
        deadline.check()
        J = _jacobian(formulas, p, cols, need)
        rank = la.rank(J)
        if rank == len(cols):
            continue
        piv = la.rref(J)[1]
        missing = [cols[c] for c in range(len(cols)) if c not in piv]
        what = ", ".join(ctx.names.get(s, str(s)) for s in missing)
        if k < len(cols):
            summary = (f"every equation is right, but {k} equation{'s' if k > 1 else ''} "
                       f"cannot determine {len(cols)} unknowns ({n} accelerations"
                       f"{f' and {len(used)} reactions' if used else ''}): {what} "
                       "undetermined")
        else:
            summary = (f"every equation is right, but together they do not determine the "
                       f"accelerations: {what} undetermined (an equation is a combination of "
                       "the others)")
        found = len(cols) - len(missing)
        return Verdict("wrong", summary, method=method, degree=degree, parts=k,
                       wrong_parts=(), credit=found / len(cols))
    extra = f" and the reactions {', '.join(map(str, used))}" if used else ""
    return Verdict("right", f"equivalent to {ctx.subject}: every equation follows "
                   f"from them and together they determine the accelerations{extra}",
                   method=method, degree=degree)


def _jacobian(formulas, point, cols, need) -> list:
    env = point.env(need=need)
    base = [f.evaluate(env) for f in formulas]
    J = [[None] * len(cols) for _ in formulas]
    for c, u in enumerate(cols):
        e2 = point.env({u: env.values[u] + 1}, need=need)
        for i, f in enumerate(formulas):
            J[i][c] = f.evaluate(e2) - base[i]
    return J


def describe_match(ctx, f: Formula, point, need) -> tuple[str, list]:
    """Which derived equation(s) a correct equation is a combination of, in words, and the
    coordinates whose Lagrange equations it combines (or whose acceleration alone it has)."""
    used = [r for r in ctx.reactions if r in f.symbols]
    ref_name = ctx.reference.name
    for name in [ref_name] + [m for m in point.systems if m != ref_name]:
        model = ctx.models.get(name, ctx.reference if name == ref_name else None)
        if model is None or not set(used) <= set(model.unknowns):
            continue
        A, _ = point.systems[name]
        cols = list(ctx.qdd) + list(model.unknowns)
        J = _jacobian([f], point, cols, need)[0]
        aug = [[A[i][c] for i in range(len(A))] + [J[c]] for c in range(len(cols))]
        R, piv = la.rref(aug)
        if len(A) in piv:
            continue
        y = [0] * len(A)
        for row, c in enumerate(piv):
            y[c] = R[row][len(A)]
        rows = [i for i, v in enumerate(y) if not zero(v, [1])]
        labels = [model.labels[i] for i in rows]
        coords = _lagrange_coordinates(ctx, labels) if name == ref_name else []
        only = [j for j, s in enumerate(ctx.states) if not zero(J[j], [1])]
        if len(only) == 1 and not used:
            coords = coords or only
        return _words(name, labels), coords
    return "", []


def _lagrange_coordinates(ctx, labels) -> list:
    names = [s.name for s in ctx.states]
    out = []
    for lb in labels:
        if lb.startswith("Lagrange, ") and lb[10:] in names:
            out.append(names.index(lb[10:]))
        else:
            return []
    return out


def _words(model: str, labels: list) -> str:
    """Rows of a model in words a student reads (no model or label names)."""
    def one(lb):
        if lb.startswith("Lagrange, "):
            return f"the equation of {lb[10:]}"
        return label_words(lb)
    if len(labels) == 1:
        return one(labels[0])
    return "a combination of " + " and ".join(one(lb) for lb in labels)


def _wrong_equations(ctx, formulas, wrong, dims, method, degree, name, deadline, need):
    edits, details, state = [], [], {}
    k = len(formulas)
    for i in wrong:
        deadline.check()
        d = None
        own = answer_coordinates(ctx, formulas[i].symbols)
        mine, seen = formulas[i], ctx
        written, smap = formulas[i].student or (None, None)
        if written is not None and smap.inverse(ctx, written.symbols) is not None:
            # the student's own coordinates (``where s = a*theta``): diagnosed in them
            mine, seen = written, smap.view(ctx)

            def targets(mode, smap=smap, symbols=written.symbols):
                return smap.targets(ctx, symbols, mode)
        else:
            def targets(mode, own=own):
                return equation_targets(ctx, mode, own)
        if mine.expanded_size() <= _MAX_FEEDBACK_TERMS:
            d = best_edit(mine.sympy(), targets, seen,
                          equation=i if k > 1 else None, parts=mine.written_terms())
        if d is not None:
            target = _target_words(d, ctx, in_their_words(seen, formulas[i].text))
            if seen is not ctx:
                target += f", written in {', '.join(smap.names)}"
            where = _equation_name(d) if k > 1 else ""
            edits += for_student(seen, d.edits, formulas[i].text,
                                 f"{name(i)} ({where})" if where else "")
            details.append(f"{name(i)} is closest to {target}")
        elif not state:
            try:
                state, value, _ = concrete_state(ctx, formulas[i], None, need, own)
                if written is not None:
                    state = smap.state(ctx, state, written.symbols)
                mine = in_their_words(seen, formulas[i].text)
                state = {mine(key): v for key, v in state.items()}
                kinds = _kinds_words(ctx, formulas[i], targets, seen, need) \
                    if seen is ctx and mine_size(formulas[i]) else ""
                details.append(f"no small edit explains {name(i)}{kinds}: on the motion, at "
                               f"the state below, its two sides differ by {value:.6g} (they "
                               "must be equal)" if not kinds else
                               f"no small edit explains {name(i)}; {kinds}, {value:.6g} in "
                               "all between its two sides (they must be equal)")
            except (GradingUnavailable, TypeError, ValueError, ZeroDivisionError):
                details.append(f"no small edit explains {name(i)}")
    which = ", ".join(str(i + 1) for i in wrong)
    if k == 1:
        summary = f"the equation does not follow from {ctx.subject}"
    else:
        summary = (f"equation{'s' if len(wrong) > 1 else ''} {which} "
                   f"do{'es' if len(wrong) == 1 else ''} not follow from {ctx.subject}")
    return Verdict("wrong", summary, details, edits, dims, state=state, method=method,
                   degree=degree, parts=k, wrong_parts=tuple(wrong))


def mine_size(f: Formula) -> bool:
    """Whether a formula is small enough to be compared term by term."""
    return f.expanded_size() <= _MAX_FEEDBACK_TERMS


def _kinds_words(ctx, f: Formula, targets, seen, need) -> str:
    """``compared with the phi equation, its gravity and Coriolis terms differ: on the motion,
    at the state below, by 1.2 and -0.4`` -- the kinds of the terms in which a wrong equation differs
    from the correct row it is closest to (at the scale of most of its terms), with what each
    kind adds to the difference at the state shown; "" when no term of it is right."""
    found = differing_kinds(f.sympy(), targets, seen, f.written_terms())
    if not found:
        return ""
    label, kinds = found
    env = ctx.points("mpmath")[0].env(need=need)
    values = []
    with mpmath.workdps(MP_DIGITS):
        for kind, diff in kinds.items():
            try:
                v = float(mpmath.re(Formula.from_sympy(diff).evaluate(env)))
            except (TypeError, ValueError, ZeroDivisionError, KeyError):
                return ""
            values.append((-abs(v), kind, v))
    values.sort()
    names = ["other" if kind == "another term" else kind.split(" ", 1)[1].removesuffix(" term")
             for _, kind, _ in values]
    words = names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]
    by = " and ".join(f"{v:.4g}" for _, _, v in values)
    terms = "term" if len(names) == 1 else "terms"
    return (f"compared with {_row_words(label.partition(': ')[2])}, its {words} {terms} "
            f"differ: on the motion, at the state below, by {by}")


def _equation_name(d) -> str:
    """``the theta equation`` when the closest target is a coordinate's Lagrange row."""
    _, _, label = d.label.partition(": ")
    if label.startswith("Lagrange, "):
        return f"the {label[10:]} equation"
    return ""


def _target_words(d, ctx, echo=None) -> str:
    """The closest correct equation in words: ``the theta equation``, ``the force
    balance on m2 along y``, times a factor if the answer is scaled (written as the student
    writes, by ``echo``)."""
    _, _, label = d.label.partition(": ")
    factor = display(d.scale, ctx.names)
    scale = "" if d.scale == 1 else f", times {echo(factor) if echo else factor}"
    return f"{_row_words(label)}{scale}"


def _row_words(label: str) -> str:
    """A row's label in words; a combination the student made as ``a combination of the
    theta equation and the phi equation``."""
    if label.startswith("combination of "):
        first, _, second = label[len("combination of "):].partition(" and ")
        return f"a combination of {label_words(first)} and {label_words(second)}"
    return label_words(label)


# -- expressions --------------------------------------------------------------------------------
def judge_expression(ctx: ProblemContext, answer: Formula, quantity: Quantity,
                     deadline: Deadline, components: list | None = None) -> Verdict:
    """A scalar or vector quantity compared with the problem's own on the motion."""
    bad = answer.symbols & quantity.forbid
    if bad:
        shown = ", ".join(sorted(ctx.names.get(s, str(s)) for s in bad))
        raise AnswerError(f"{quantity.name} must be written without {shown}: give it in terms "
                          "of the coordinates, their rates, time and the parameters.")
    refs = reference_formulas(ctx, quantity)
    comps = components if components is not None else [answer]
    if len(comps) != len(refs):
        raise AnswerError(f"{quantity.name} has {len(refs)} component"
                          f"{'s' if len(refs) > 1 else ''}; the answer has {len(comps)}"
                          + (f" (write it as [{', '.join(['...'] * len(refs))}])"
                             if len(refs) > 1 else "."))
    dims = []
    for j, (c, r) in enumerate(zip(comps, refs)):
        expected = expected_dimension(r, ctx.dims)
        mine = in_their_words(ctx, c.text)
        for issue in map(mine, audited(ctx, c.tree, ctx.dims, ctx.names, expected)):
            dims.append(f"component {j + 1}: {issue}" if len(refs) > 1 else issue)
    method = method_for(ctx, comps + refs)
    if method == "slow":
        check_real(ctx, comps, need_for(ctx, comps))
        from dualmech.grade.comparator_fallback import slow_expression
        v = slow_expression(ctx, comps, refs, dims, quantity.description)
        if v.status == "wrong":
            try:
                try:
                    bad = _off_at_real_points(ctx, comps, refs)
                except (GradingUnavailable, TypeError, ValueError, ZeroDivisionError):
                    bad = list(range(len(comps)))
                fb = _expression_feedback(ctx, comps, refs, quantity, bad, deadline,
                                          need_for(ctx, comps + refs))
                v.edits, v.details, v.state = fb
            except GradingUnavailable:   # no free points (a static row): no explanation
                pass
        return v
    minus = ("c", Fraction(-1))
    diffs = [Formula(("add", (c.tree, ("mul", (minus, r.tree))))) for c, r in zip(comps, refs)]
    need = need_for(ctx, comps + refs)
    table = values_at(ctx, diffs, method, deadline, need)
    bad_j = []
    for j in range(len(diffs)):
        vals = [row[j][0] for row in table]
        envs = [row[j][1] for row in table]
        if quantity.up_to_constant:
            points = ctx.points(method)
            ok = all(zero(vals[a] - vals[b], [vals[a], vals[b]])
                     for a in range(len(points)) for b in range(a + 1, len(points))
                     if points[a].group == points[b].group)
        else:
            ok = all(_is_zero(diffs[j], v, e) for v, e in zip(vals, envs))
        if not ok:
            bad_j.append(j)
    degree = max(c.degree for c in comps)
    if not bad_j:
        if dims:
            return Verdict("wrong", "the value is right but the answer is dimensionally "
                           "inconsistent", dimension_issues=dims, method=method, degree=degree,
                           credit=DIMENSIONS_ONLY)
        note = " (up to a constant)" if quantity.up_to_constant else ""
        return Verdict("right", f"{quantity.description}{note}", method=method, degree=degree)
    edits, details, state = _expression_feedback(ctx, comps, refs, quantity, bad_j, deadline,
                                                 need)
    which = ("components " + ", ".join(str(j + 1) for j in bad_j)) if len(refs) > 1 else "it"
    return Verdict("wrong", f"{quantity.description}: {which} differ"
                   f"{'s' if which == 'it' else ''} from the right value on the motion",
                   details, edits, dims, state=state, method=method, degree=degree,
                   parts=len(refs), wrong_parts=tuple(bad_j))


def _expression_feedback(ctx, comps, refs, quantity, bad_j, deadline, need):
    """``(edits, details, state)`` for the wrong components ``bad_j`` of an expression."""
    edits, details, state = [], [], {}
    for j in bad_j:
        deadline.check()
        d = None
        where = j if len(refs) > 1 else None
        if comps[j].expanded_size() <= _MAX_FEEDBACK_TERMS:
            expr, parts = comps[j].sympy(), comps[j].written_terms()
            several = len(sp.Add.make_args(sp.expand(expr))) > 1
            for stage in (0, 1):
                forms = expression_targets(ctx, quantity, stage)[j]
                if not forms:
                    continue
                key = (quantity.name, j, stage)
                tables = lambda mode, key=key, forms=forms: \
                    expression_tables(ctx, key, forms, mode)  # noqa: E731
                d = _fewest_edits(expr, tables, ctx, where, parts, several)
                if d is not None:
                    break
        if d is not None:
            mine = for_student(ctx, d.edits, comps[j].text)
            edits += [replace(e, part="component") if where is not None else e for e in mine]
        elif not state:
            what = f"component {j + 1}" if len(refs) > 1 else "it"
            try:
                state, a, b = concrete_state(ctx, comps[j], refs[j], need)
                mine = in_their_words(ctx, comps[j].text)
                state = {mine(key): v for key, v in state.items()}
                details.append(f"no small edit explains {what}: at the state below the "
                               f"answer is {a:.6g}, the right value {b:.6g}")
            except (GradingUnavailable, TypeError, ValueError, ZeroDivisionError):
                details.append(f"no small edit explains {what}")
    return edits, details, state


def _off_at_real_points(ctx, formulas, refs) -> list[int]:
    """Indices whose value differs from its reference (None: from zero) at the real display
    points -- only to choose what to explain after the comparator's verdict."""
    import mpmath
    from dualmech.exact.form import MP_DIGITS
    points = ctx.points("mpmath")       # GradingUnavailable: the caller decides
    out = []
    with mpmath.workdps(MP_DIGITS):
        for i, (f, r) in enumerate(zip(formulas, refs)):
            for p in points:
                try:
                    env = p.env(need=need_for(ctx, [f]))
                    a = f.evaluate(env)
                    b = r.evaluate(env) if r is not None else 0
                    scale = max(abs(a), abs(b), 1)
                except (TypeError, ValueError, ZeroDivisionError, KeyError):
                    continue
                if abs(a - b) > mpmath.mpf(10) ** -20 * scale:
                    out.append(i)
                    break
    return out


def _fewest_edits(expr, tables, ctx, where, parts, several: bool):
    """The diagnosis of a wrong expression with the fewest edits: the whole answer times a
    factor (tried first when it has several terms), term edits, or two symbols swapped --
    on a tie in that order (``m g cos - m (R - r) th'^2`` has one wrong sign, not ``R`` and
    ``r`` swapped)."""
    found = []
    if several:
        found.append(factor_edit(expr, tables("trig"), ctx, equation=where, swaps=False))
    found.append(best_edit(expr, tables, ctx, scale=False, equation=where, parts=parts))
    found.append(factor_edit(expr, tables("trig"), ctx, equation=where))
    found = [d for d in found if d is not None]
    return min(found, key=lambda d: len(d.edits)) if found else None


def _monomial(c) -> bool:
    """Whether ``c`` is a number times powers of symbols (a factor a person can name)."""
    num, den = sp.fraction(sp.factor_terms(c))
    return not any(isinstance(f, sp.Add) or (isinstance(f, sp.Pow) and isinstance(f.base, sp.Add))
                   for part in (num, den) for f in sp.Mul.make_args(part))


def factor_edit(expr, targets, ctx, equation=None, swaps: bool = True):
    """A diagnosis when the answer is a constant multiple of a target (a number times
    parameters: ``(2 g m - F)/(F + 2 g m)`` is no factor), possibly after two symbols of one
    dimension are swapped (``R`` missing and the angles swapped; not with ``swaps=False``)."""
    from dualmech.grade.feedback import swap_pairs
    for rule, text in [({}, "")] + (swap_pairs(ctx) if swaps else []):
        mine = term_table(expr.xreplace(rule) if rule else expr, ctx)
        if mine is None:
            continue
        for tab in targets:
            if set(mine.terms) != set(tab.terms):
                continue
            # a list, not a set: exact square-root values (Surd) are compared, not hashed
            ratios = [mine.terms[k][1] / tab.terms[k][1] for k in mine.terms]
            if any(r != ratios[0] for r in ratios[1:]):
                continue
            k0 = next(iter(mine.terms))
            c = sp.cancel(mine.terms[k0][0] / tab.terms[k0][0])
            if not _monomial(c):
                continue
            edits = []
            if text:
                edits.append(Edit("swap", equation, display(expr, ctx.names),
                                  display(sp.expand(expr.xreplace(rule) / c), ctx.names), "",
                                  text))
            if c != 1:
                edits.append(Edit("factor", equation, "", "", "", display(c, ctx.names)))
            if edits:
                return Diagnosis(tab.label, c, edits, len(edits))
    return None


def reference_formulas(ctx, quantity: Quantity) -> list:
    return ctx.memo(("reference", quantity.name),
                    lambda: [Formula.from_sympy(e) for e in quantity.reference])
