r"""What an answer costs to grade, estimated from its parsed tree before anything is computed.

Grading evaluates an answer exactly at sampled points: ``sin`` and ``cos`` of ``k*theta`` are
taken at a rational point of the unit circle raised to the power ``k`` (in ``O(log k)``
multiplications), so the size of the numbers grows with the *degree* of each term -- four per
unit of a multiple angle, times every power around it.  Feedback expands the answer
symbolically, so its cost grows with the *number of terms after expansion* (a multiple angle
``k`` becomes about ``k`` terms).  :func:`assess` computes, for every sub-expression,

* ``degree``: the degree of one term once multiple angles and powers are expanded;
* ``terms``: the number of terms after expansion (capped);
* ``nesting``: how deep transcendental functions (``sin cos tan ... exp log``) nest;

and :func:`check` refuses an answer over the :class:`~.parser.Limits` (``degree``) or with a
tower of exponentials, naming the smallest sub-expression that is over: ``too costly to grade:
`sin(1000*theta)` ...``.  :func:`explainable` says whether symbolic feedback may expand it.

Example
-------
>>> from dualmech.grade.parser import parse
>>> check(parse("m*g*sin(2*theta) = 0")[0].lhs)
>>> check(parse("sin(1000*theta) = 0")[0].lhs)  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
dualmech.grade.cost.TooCostly: too costly to grade: `sin(1000*theta)` has degree about 4000 ...
>>> costliest("(sin(999*theta)^5)^14 = 0")
'sin(999*theta)'
"""
from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

from dualmech.grade.parser import LIMITS, AnswerError, AnswerTooLarge, Limits, Node, parse, to_text

__all__ = ["Cost", "TooCostly", "assess", "check", "costliest", "explainable",
           "EXPLAIN_TERMS", "MAX_NESTING"]

#: Most terms symbolic feedback may expand an answer into.
EXPLAIN_TERMS = 400
#: Deepest nesting of transcendental functions graded (``exp(sin(cos(theta)))`` is 3).
MAX_NESTING = 3
_CAP = 10 ** 9
#: A constant power is computed only up to this many bits; past it it stands as ``_HUGE``.
_POWER_BITS = 256
_HUGE = Fraction(_CAP) ** 2
_TRIG = ("sin", "cos", "tan", "cot", "sec", "csc")


class TooCostly(AnswerTooLarge):
    """An answer whose grading would cost more than the limits allow (the message names the
    sub-expression and says what to change)."""


@dataclass(frozen=True)
class Cost:
    """Estimated cost of one sub-expression (see the module docstring)."""

    degree: int
    terms: int
    nesting: int
    exp_depth: int      # exponentials nested in exponentials (a tower when >= 2)


def _multiple(node: Node) -> int:
    """Largest |numerator| of a coefficient in a polynomial argument (``1000*theta`` -> 1000),
    1 when the argument is not such a polynomial."""
    coeffs = _coefficients(node)
    if not coeffs:
        return 1
    return max(1, max(abs(c.numerator) for c in coeffs))


def _coefficients(node: Node) -> list:
    op, a = node.op, node.args
    if op == "num":
        return []
    if op in ("name", "dot"):
        return [Fraction(1)]
    if op in ("group", "neg"):
        return _coefficients(a[0])
    if op == "add":
        return [c for x in a for c in _coefficients(x)]
    if op == "mul":
        const, inner = Fraction(1), []
        for x in a:
            v = _number(x)
            if v is not None:
                const *= v
            else:
                inner.append(_coefficients(x) or [Fraction(1)])
        if not inner:
            return []
        out = [const]
        for cs in inner:
            out = [o * c for o in out for c in cs][:64]
        return out
    return [Fraction(1)]


def _number(node: Node):
    """The value of a constant sub-expression built from numbers with ``+ - * / ^`` (bracketed,
    negated), else ``None``.  A power too large to compute (``10^20`` is computed; ``10^10^6``
    is not) stands as :data:`_HUGE` (or its inverse), beyond every limit, so a multiple written
    as a power is costed like the number it is."""
    op, a = node.op, node.args
    if op == "num":
        return a[0]
    if op == "add":
        out = Fraction(0)
        for x in a:
            v = _number(x)
            if v is None:
                return None
            out += v
        return out
    if op == "pow":
        return _power(_number(a[0]), _number(a[1]))
    if op in ("group", "neg"):
        v = _number(a[0])
        return None if v is None else (v if op == "group" else -v)
    if op == "inv":
        v = _number(a[0])
        return None if not v else 1 / v
    if op == "mul":
        out = Fraction(1)
        for x in a:
            v = _number(x)
            if v is None:
                return None
            out *= v
        return out
    return None


def _power(base, exponent):
    """``base ** exponent`` for an integer exponent, :data:`_HUGE` past :data:`_POWER_BITS`."""
    if base is None or exponent is None or exponent.denominator != 1:
        return None
    k = exponent.numerator
    if base == 0:
        return None if k < 0 else Fraction(int(k == 0))
    size = max(abs(base.numerator), base.denominator)
    if size > 1 and abs(k) * size.bit_length() > _POWER_BITS:
        big = _HUGE if (abs(base) > 1) == (k > 0) else 1 / _HUGE
        return -big if base < 0 and k % 2 else big
    return base ** k


def _exponent(node: Node) -> int:
    v = _number(node)
    if v is None:
        return 1
    return max(1, min(_CAP, abs(v.numerator)))


def assess(node: Node, visit=None) -> Cost:
    """The :class:`Cost` of ``node``; ``visit(node, cost)`` is called for every sub-expression,
    innermost first."""
    op, a = node.op, node.args
    if op == "num":
        out = Cost(0, 1, 0, 0)
    elif op in ("name", "dot"):
        out = Cost(1, 1, 0, 0)
    elif op in ("group", "neg"):
        out = assess(a[0], visit)
    elif op == "inv":
        c = assess(a[0], visit)
        out = Cost(c.degree, c.terms, c.nesting, c.exp_depth)
    elif op in ("add", "vec"):
        cs = [assess(x, visit) for x in a]
        out = Cost(max(c.degree for c in cs), min(_CAP, sum(c.terms for c in cs)),
                   max(c.nesting for c in cs), max(c.exp_depth for c in cs))
    elif op == "mul":
        cs = [assess(x, visit) for x in a]
        terms = 1
        for c in cs:
            terms = min(_CAP, terms * c.terms)
        out = Cost(min(_CAP, sum(c.degree for c in cs)), terms, max(c.nesting for c in cs),
                   max(c.exp_depth for c in cs))
    elif op == "pow":
        c, _ = assess(a[0], visit), assess(a[1], visit)
        k = _exponent(a[1])
        terms = c.terms ** k if c.terms > 1 and k * c.terms.bit_length() < 64 else \
            (c.terms if c.terms <= 1 else _CAP)
        out = Cost(min(_CAP, c.degree * k), min(_CAP, terms), c.nesting, c.exp_depth)
    elif op == "func":
        name, arg = a
        c = assess(arg, visit)
        constant = c.degree == 0
        if name in _TRIG:
            k = _multiple(arg)
            out = Cost(min(_CAP, 4 * k), min(_CAP, k + 1), c.nesting + (not constant),
                       c.exp_depth)
        elif name == "sqrt":
            out = Cost(c.degree, 1, c.nesting, c.exp_depth)
        else:   # exp, log
            depth = c.exp_depth + (name == "exp" and not constant)
            out = Cost(c.degree, 1, c.nesting + (not constant), depth)
    else:
        out = Cost(1, 1, 0, 0)
    if visit is not None:
        visit(node, out)
    return out


def _over(cost: Cost, limits: Limits) -> str:
    """Why ``cost`` is over the limits, in words ("" when it is not)."""
    if cost.exp_depth >= 2:
        return ("is a tower of exponentials (an exponential inside an exponential); no "
                "equation of motion has one: check the answer")
    if cost.nesting > MAX_NESTING:
        return (f"nests {cost.nesting} transcendental functions (at most {MAX_NESTING} are "
                "graded); check the answer")
    if cost.degree > limits.degree:
        shown = f"about {cost.degree}" if cost.degree < _CAP else "beyond 10^9"
        return (f"has degree {shown} once its multiple angles and powers are expanded "
                f"(at most {limits.degree} are graded); write it with smaller multiples of "
                "angles and lower powers")
    return ""


def check(node: Node, limits: Limits = LIMITS) -> None:
    """Raise :class:`TooCostly` when ``node`` costs more than ``limits`` allow, naming the
    smallest sub-expression that does."""
    culprit = _culprit(node, limits)
    if culprit is not None:
        sub, why = culprit
        raise TooCostly(f"too costly to grade: `{_text(sub)}` {why}.")


def _culprit(node: Node, limits: Limits):
    found: list = []

    def visit(n, c):
        if not found:
            why = _over(c, limits)
            if why:
                found.append((n, why))
    assess(node, visit)
    return found[0] if found else None


def costliest(answer: str, limits: Limits = LIMITS) -> str:
    """The sub-expression of ``answer`` (text) that makes it costly: the smallest one over the
    limits, else the one of largest degree; ``""`` when the answer does not parse."""
    try:
        eqs = parse(answer, limits)
    except AnswerError:
        return ""
    seen: list = []
    for e in eqs:
        for side in (e.lhs, e.rhs):
            if side is None:
                continue
            culprit = _culprit(side, limits)
            if culprit is not None:
                return _text(culprit[0])
            assess(side, lambda n, c: seen.append((n, c)) if n.op not in ("num", "name",
                                                                             "dot") else None)
    if not seen:
        return ""
    top = max((c.exp_depth, c.nesting, c.degree) for _, c in seen)
    # the smallest sub-expression carrying at least half of the largest degree
    near = [(n.size, i) for i, (n, c) in enumerate(seen)
            if (c.exp_depth, c.nesting) == top[:2] and 2 * c.degree >= top[2]]
    return _text(seen[min(near)[1]][0])


def explainable(node: Node) -> bool:
    """Whether symbolic feedback may expand ``node``: at most :data:`EXPLAIN_TERMS` terms."""
    return assess(node).terms <= EXPLAIN_TERMS


def _text(node: Node) -> str:
    """``node`` as compact text, the way a student writes it: ``sin(1001*theta/2)``."""
    s = to_text(node)
    return s[:200] + ("..." if len(s) > 200 else "")
