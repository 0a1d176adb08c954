"""Answers written from a problem's verified equations: correct forms and classic mistakes.

For tests, benchmarks and teachers (distractors for a quiz): :func:`correct_answers` writes the
verified equations in the answer syntax -- as derived, scaled and rearranged, combined, with a
trigonometric identity, one equation at a time, the direct form with its reactions, reactions
solved from the direct form, accelerations -- and :func:`wrong_answers` makes the mistakes
students make: a wrong sign, a missing Coriolis or centripetal term, ``l`` where ``l^2``
belongs, swapped masses, a dropped damper, a wrong reaction.  Each wrong answer carries the term
it broke, so the grader's diagnosis can be checked against it.

Example
-------
>>> from dualmech.grade import Grader
>>> ctx = Grader("simple_pendulum").context
>>> [s.text for s in correct_answers(ctx) if s.variant == "as derived"]
["M*a**2*theta'' + M*a*g*sin(theta)"]
>>> w = next(s for s in wrong_answers(ctx) if s.mistake == "sign")
>>> w.text, w.term
("M*a**2*theta'' - M*a*g*sin(theta)", M*a*g*sin(theta))
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp
from sympy.printing.str import StrPrinter

from dualmech.model.dimensions import DAMPING, LENGTH, TORSIONAL_DAMPING
from dualmech.grade.context import ProblemContext
from dualmech.grade.audit import reduced
from dualmech.grade.targets import unit_circle

__all__ = ["Sample", "write", "correct_answers", "wrong_answers", "names_mistake", "CannotWrite"]

_FUNCTIONS = (sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc, sp.exp, sp.log)
_MAX_TERMS = 40


class CannotWrite(ValueError):
    """The expression uses something the answer syntax has no notation for (``Abs``, ...)."""


@dataclass(frozen=True)
class Sample:
    """One answer: its ``text``, the ``quantity`` it answers, whether it is ``right``.

    Wrong samples name the ``mistake`` (``sign``, ``missing``, ``coefficient``, ``swap``,
    ``damping``, ``group`` -- several terms written as one group dropped --, ``factor sign``
    -- a sign flipped inside a factor --, ``like-term sign`` -- one of several terms with the
    same state part flipped) and the ``term`` concerned as the correct answer has it (for
    the signs, ``missing``, ``group`` and ``damping``) or as the wrong answer has it
    (``coefficient``, ``swap``, with ``correct`` the term it replaced); ``equation`` is its
    index in the answer.
    """

    text: str
    quantity: str | None
    right: bool
    variant: str
    mistake: str = ""
    term: object = None
    correct: object = None
    equation: int | None = None


class _Writer(StrPrinter):
    def __init__(self, names):
        super().__init__()
        self._names = names

    def _print_Symbol(self, expr):
        return self._names.get(expr, expr.name)

    def _print_Function(self, expr):
        if type(expr) in _FUNCTIONS or isinstance(expr, _FUNCTIONS):
            return super()._print_Function(expr)
        raise CannotWrite(f"no notation for {type(expr).__name__}")

    def emptyPrinter(self, expr):
        raise CannotWrite(f"no notation for {type(expr).__name__}")

    def _print_Abs(self, expr):
        raise CannotWrite("no notation for Abs")

    def _print_Piecewise(self, expr):
        raise CannotWrite("no notation for Piecewise")

    def _print_Exp1(self, expr):
        return "exp(1)"


def write(expr, ctx: ProblemContext) -> str:
    """``expr`` (plain symbols) in the answer syntax, e.g. ``m*l**2*theta'' + ...``."""
    return _Writer(ctx.names).doprint(expr)


def _rows(ctx):
    return [sp.expand(ctx.plain(e)) for e in ctx.reference.equations]


def _lines(ctx, exprs) -> str:
    return "\n".join(write(e, ctx) for e in exprs)


def correct_answers(ctx: ProblemContext) -> list[Sample]:
    """Right answers in several equivalent forms (see the module docstring)."""
    rows = _rows(ctx)
    n = len(rows)
    p = ctx.parameters[0] if ctx.parameters else sp.Integer(3)
    out = [Sample(_lines(ctx, rows), "eom", True, "as derived")]
    scaled = []
    for i, r in enumerate(rows):
        terms = sp.Add.make_args(r)
        lhs = (i + 2) * p * terms[0]
        rhs = -(i + 2) * p * sp.Add(*terms[1:])
        scaled.append(f"{write(lhs, ctx)} = {write(rhs, ctx)}")
    out.append(Sample("\n".join(scaled), "eom", True, "scaled and rearranged"))
    pair = _same_dimension(ctx, rows)
    if pair is not None:
        i, j = pair
        combined = list(rows)
        combined[i] = rows[i] + rows[j]
        out.append(Sample(_lines(ctx, combined), "eom", True, "combined"))
    trig = [sp.expand(r.xreplace({c: 1 - sp.sin(c.base.args[0]) ** 2
                                  for c in r.atoms(sp.Pow)
                                  if isinstance(c.base, sp.cos) and c.exp == 2}))
            for r in rows]
    if trig != rows:
        out.append(Sample(_lines(ctx, trig), "eom", True, "trigonometric identity"))
    if n >= 2:
        for i, r in enumerate(rows):
            out.append(Sample(write(r, ctx), "equation", True, f"equation {i + 1} alone",
                              equation=i))
    direct = _direct_model(ctx)
    if direct is not None:
        out.append(Sample(_lines(ctx, [sp.expand(ctx.plain(e)) for e in direct.equations]),
                          "eom", True, f"direct form ({direct.name})"))
    for u, form in _reaction_forms(ctx):
        out.append(Sample(write(form, ctx), u.name, True, f"reaction {u.name}"))
    if n == 1:
        s = ctx.states[0]
        r = rows[0]
        coeff = sp.diff(r, s.qdd)
        if not coeff.free_symbols & {s.qdd}:
            acc = sp.expand(-(r - coeff * s.qdd) / coeff)
            out.append(Sample(write(acc, ctx), s.name + "''", True, "acceleration"))
    return [s for s in out if _writable(s)]


def _same_dimension(ctx, rows):
    """Two rows of one dimension (their sum is then a meaningful equation), or None."""
    from dualmech.grade.audit import expected_dimension
    from dualmech.grade.formula import Formula
    dims = [expected_dimension(Formula.from_sympy(r), ctx.dims) for r in rows]
    for i in range(len(rows)):
        for j in range(i + 1, len(rows)):
            if dims[i] is not None and dims[i] == dims[j]:
                return i, j
    return None


def _writable(sample: Sample) -> bool:
    return "no notation" not in sample.text


def _direct_model(ctx):
    for name, m in ctx.models.items():
        if m.unknowns and m.is_square and name != ctx.problem.reference:
            return m
    return None


def _reaction_forms(ctx) -> list:
    """``(u, u solved from a direct row that has u as its only reaction)``, one per reaction."""
    out, done = [], set()
    react = set(ctx.reactions)
    for m in ctx.models.values():
        for e in m.equations:
            e = sp.expand(ctx.plain(e))
            here = e.free_symbols & react
            if len(here) != 1:
                continue
            (u,) = here
            coeff = sp.diff(e, u)
            if u in done or coeff.free_symbols & react or coeff == 0:
                continue
            # as a person writes it: sin^2 + cos^2 of one angle read as 1 (a row as the
            # derivation leaves it may carry them, wheel_on_pivot's spin and precession)
            form = sp.expand(unit_circle(-(e - coeff * u)) / unit_circle(coeff))
            if len(sp.Add.make_args(form)) >= 2:
                out.append((u, form))
                done.add(u)
    return out


def wrong_answers(ctx: ProblemContext) -> list[Sample]:
    """Classic mistakes, one per sample, each naming the term it broke."""
    rows = _rows(ctx)
    out = []
    qdd = set(ctx.qdd)
    qd = {s.qd for s in ctx.states}
    damping = {p for p in ctx.parameters
               if ctx.dims.get(p) in (reduced(DAMPING), reduced(TORSIONAL_DAMPING))}
    lengths = [p for p in ctx.parameters if ctx.dims.get(p) == reduced(LENGTH)]
    small = [i for i, r in enumerate(rows) if 2 <= len(sp.Add.make_args(r)) <= _MAX_TERMS]

    def pick(test):
        for i in small:
            for term in sp.Add.make_args(rows[i]):
                if test(term):
                    return i, term
        return None

    def replaced(i, old, new):
        return _lines(ctx, rows[:i] + [rows[i] - old + new] + rows[i + 1:])

    found = pick(lambda t: not t.free_symbols & qdd and t.free_symbols - set(ctx.parameters))
    if found:
        i, term = found
        out.append(Sample(replaced(i, term, -term), "eom", False, "sign error", "sign", term,
                          equation=i))
    found = pick(lambda t: t.free_symbols & qd and not t.free_symbols & (qdd | damping))
    if found:
        i, term = found
        out.append(Sample(replaced(i, term, 0), "eom", False, "velocity term dropped",
                          "missing", term, equation=i))
    for p in lengths:
        found = pick(lambda t: t.has(p))
        if found:
            i, term = found
            k = sp.degree(term, p) if term.is_polynomial(p) else 1
            new = term / p if k >= 2 else term * p
            out.append(Sample(replaced(i, term, new), "eom", False,
                              f"{p} for {p}**{k}" if k >= 2 else f"{p}**2 for {p}",
                              "coefficient", new, term, equation=i))
            break
    swap = _swap(ctx, rows, small)
    if swap:
        i, term, new = swap
        out.append(Sample(replaced(i, term, new), "eom", False, "parameters swapped", "swap",
                          new, term, equation=i))
    for i in small:
        damped = [t for t in sp.Add.make_args(rows[i]) if t.free_symbols & damping]
        if damped:
            out.append(Sample(replaced(i, sp.Add(*damped), 0), "eom", False,
                              "damping dropped", "damping", sp.Add(*damped), equation=i))
            break
    for u, form in _reaction_forms(ctx):
        terms = sp.Add.make_args(form)
        term = next((t for t in terms if t.free_symbols - set(ctx.parameters)), terms[0])
        out.append(Sample(write(form - 2 * term, ctx), u.name, False, f"reaction {u.name}",
                          "sign", term))
        break
    out += _written_mistakes(ctx)
    out += _mapped_mistakes(ctx)
    return [s for s in out if _writable(s)]


def _mapped_mistakes(ctx) -> list[Sample]:
    """A wrong sign in a row of a model written in other coordinates than the reference's
    (falling_container's ``y1, y2``): the answer is in those coordinates, and so must be the
    diagnosis."""
    from dualmech.grade.terms import state_symbols
    derived = set(ctx.derived_formulas())
    reference = {s.name for s in ctx.states}
    for name, m in ctx.problem.models().items():
        names = {q.func.__name__ for q in m.coordinates}
        if names <= reference or len(names) != len(reference):
            continue    # the same coordinates, or constrained ones (a multiplier model)
        for e in m.equations:
            row = sp.expand(m.to_plain(e))
            if not _exact(row):
                continue    # decided by the comparator (sqrt, ...): no term edits
            if not row.free_symbols & derived or row.free_symbols - derived - \
                    set(ctx.parameters) - set(ctx.reactions) - {sp.Symbol("t")} - \
                    state_symbols(ctx):
                continue
            for term in sp.Add.make_args(row):
                if term.free_symbols & derived and not any(
                        s.name.endswith("_ddot") for s in term.free_symbols):
                    return [Sample(write(row - 2 * term, ctx), "equation", False,
                                   f"sign error in {', '.join(sorted(names))}",
                                   "sign (own coordinates)", term)]
    return []


def _exact(expr) -> bool:
    from dualmech.grade.formula import Formula
    try:
        return Formula.from_sympy(expr).exact
    except TypeError:
        return False


def _written_mistakes(ctx) -> list[Sample]:
    """Mistakes in one row as a model writes it (its grouping of forces), one of each kind:
    a written group of several terms dropped (``m*L*(cos(phi)*phi'' - sin(phi)*phi'^2)``), a
    sign flipped inside a factor (``(A + B)*w1*w2`` for ``(A - B)*w1*w2``), and one of two
    written terms with the same state part flipped (``2*k*a^2*sin(theta)`` beside
    ``-m*g*l*sin(theta)``).  Each answer is that single equation."""
    from dualmech.grade.terms import state_symbols
    if ctx.method != "exact":   # how a person groups terms is read off exact term tables
        return []
    states = state_symbols(ctx)
    acc = set(ctx.qdd)
    found: dict = {}
    names = [ctx.reference.name] + [n for n in ctx.models if n != ctx.reference.name]
    written = [ctx.plain(e) for name in names
               for e in ctx.models.get(name, ctx.reference).equations]
    for row in written + _rows(ctx):
        args = sp.Add.make_args(row)
        if not 3 <= len(args) <= 12 or \
                len(sp.Add.make_args(sp.expand(row))) > _MAX_TERMS:
            continue
        for a in args:
            rest = row - a
            if not sp.expand(rest).free_symbols & acc or not a.free_symbols & states \
                    or not _natural(a, rest, row, ctx):
                continue
            inner = [f for f in sp.Mul.make_args(a) if f.is_Add]
            size = len(sp.Add.make_args(sp.expand(a)))
            if "group" not in found and inner and 2 <= size <= 4:
                found["group"] = Sample(write(rest, ctx), "equation", False,
                                        "group of terms dropped", "group", a)
            if "factor sign" not in found and len(inner) == 1 and \
                    len(inner[0].args) >= 2 and size >= 2:
                piece = inner[0].args[-1]
                others = sp.Mul(*[f for f in sp.Mul.make_args(a) if f is not inner[0]])
                new = sp.Mul(others, inner[0] - 2 * piece, evaluate=False)
                found["factor sign"] = Sample(
                    write(rest, ctx) + " + " + _grouped(new, ctx), "equation", False,
                    "sign inside a factor", "factor sign", sp.expand(others * piece))
            if "like-term sign" not in found and size == 1 and not a.free_symbols & acc:
                key = _state_part(a, states)
                if any(b != a and len(sp.Add.make_args(sp.expand(b))) == 1 and
                       _state_part(sp.expand(b), states) == key for b in args):
                    found["like-term sign"] = Sample(
                        write(rest - a, ctx), "equation", False, "one of like terms "
                        "flipped", "like-term sign", a)
        if len(found) == 3:
            return list(found.values())
    return list(found.values())


def _natural(a, rest, row, ctx) -> bool:
    """A written term as a person writes it: its expanded terms neither cancel nor merge
    with the rest of the row's, nor collapse by ``sin^2 + cos^2 = 1``."""
    from dualmech.grade.terms import term_table
    n = len(sp.Add.make_args(sp.expand(a)))
    if n + len(sp.Add.make_args(sp.expand(rest))) != len(sp.Add.make_args(sp.expand(row))):
        return False
    if n < 2:
        return True
    written, reduced_ = (term_table(a, ctx, mode=m) for m in ("written", "pythagoras"))
    return written is not None and reduced_ is not None and \
        len(written.terms) == len(reduced_.terms) == len(term_table(a, ctx).terms)


def _grouped(expr, ctx) -> str:
    """A product with a sum factor, written with the parentheses the student would type."""
    return "(" + write(expr, ctx) + ")" if not expr.is_Mul else \
        "*".join("(" + write(f, ctx) + ")" for f in expr.args)


def _state_part(term, states):
    return sp.Mul(*[f for f in sp.Mul.make_args(term) if f.free_symbols & states])


def names_mistake(ctx: ProblemContext, sample: Sample, edits: list) -> bool:
    """Whether ``edits`` (of a :class:`~.result.Grade`) are exactly the mistake ``sample``
    was made with: the right kind, the right term or terms, the right equation, nothing else.

    Terms are compared by their exact difference after expansion, so a term named as the
    student grouped it (``(A + B)*w1*w2`` where ``(A - B)*w1*w2`` belongs) counts the same as
    the expanded one (``B*w1*w2`` with the wrong sign).
    """
    if not edits or sample.right:
        return False
    multi = sample.quantity == "eom" and len(ctx.states) > 1
    want = sample.equation if multi else None
    if any(e.equation != want for e in edits):
        return False
    try:
        val = [(_read(ctx, e.term), _read(ctx, e.correct)) for e in edits]
    except Exception:  # an edit the parser cannot read back does not name anything
        return False
    kinds = {e.kind for e in edits}
    m, T = sample.mistake, sp.expand(sample.term)
    if m in ("missing", "group", "damping"):
        return kinds == {"missing"} and (len(edits) == 1 or m == "damping") and \
            _nil(sum(c for _, c in val) - T)
    if len(edits) != 1:
        return False
    have, right = val[0]
    if m in ("sign", "factor sign", "like-term sign", "sign (own coordinates)"):
        return edits[0].kind == "sign" and _nil(right - have - 2 * T)
    if m in ("coefficient", "swap"):
        return edits[0].kind in ("coefficient", "swap") and \
            _nil(right - have - (sample.correct - sample.term))
    return False


def _nil(expr) -> bool:
    """``expr`` is exactly zero after expansion, modulo ``sin^2 + cos^2 = 1`` (shown terms
    are reduced by that identity, :mod:`.tidy`)."""
    from dualmech.grade.terms import _normal
    return sp.expand(expr) == 0 or _normal(expr, "pythagoras") == 0


def _read(ctx, text: str):
    from dualmech.grade.formula import Formula
    from dualmech.grade.parser import parse
    if not text:
        return sp.Integer(0)
    return Formula.from_node(parse(text)[0].lhs, ctx.vocabulary).sympy()


def _swap(ctx, rows, small):
    """A term with one of two same-dimension parameters, that parameter replaced by the other."""
    params = list(ctx.parameters)
    for i in small:
        for term in sp.Add.make_args(rows[i]):
            for a in params:
                for b in params:
                    if a != b and ctx.dims.get(a) == ctx.dims.get(b) and term.has(a) and \
                            not term.has(b):
                        return i, term, term.xreplace({a: b})
    return None
