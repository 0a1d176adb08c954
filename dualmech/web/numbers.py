"""Per-student numbers: each student's parameter values, and grading exactly with them.

A student's numbers are drawn once, from the ranges the problem declares for its parameters
(:class:`~dualmech.model.problem.Parameter`), as short decimals (three significant digits)
and kept as text; the grader reads them as exact rationals (``"2.35"`` is ``47/20``).  An
answer is then graded at points on the motion whose parameters *are* the student's values
(only the time, the coordinates and the rates are drawn at random): an answer is right when
it agrees with the equations of motion of the student's own system, whether it is written
with the numbers (``0.75*theta'' + 9.81*sin(theta) = 0``) or with the names (``a*theta'' +
g*sin(theta) = 0``), and the verdict is exact (rational arithmetic, no rounding).

:class:`Personal` is what the web app sends to the grading pool in place of a problem name:
a small picklable, hashable value whose :meth:`Personal.grader` builds, in the worker, a
:class:`~dualmech.grade.api.Grader` whose context samples at those values.

Example
-------
>>> import random
>>> from fractions import Fraction
>>> short_decimal(random.Random(1), (0.1, 3.0))
'0.49'
>>> exact_values({"a": "0.75", "g": "9.81"}) == {"a": Fraction(3, 4), "g": Fraction(981, 100)}
True
"""
from __future__ import annotations

import math
import random
from dataclasses import dataclass
from decimal import Decimal
from fractions import Fraction

__all__ = ["short_decimal", "draw_numbers", "shared_ranges", "exact_values", "Personal", "DIGITS"]

#: Significant digits of a drawn value.
DIGITS = 3


def short_decimal(rng: random.Random, rng_range: tuple, digits: int = DIGITS) -> str:
    """A value inside ``rng_range`` (low, high) with ``digits`` significant digits, as text.

    Drawn uniformly, then rounded; a rounded value that left the range is drawn again (at
    most a few times; the midpoint rounded inwards otherwise).
    """
    lo, hi = (float(v) for v in rng_range)
    for _ in range(20):
        x = rng.uniform(lo, hi)
        text = _rounded(x, digits)
        if lo <= float(text) <= hi and float(text) != 0.0:
            return text
    return _rounded((lo + hi) / 2, digits + 3)


def _rounded(x: float, digits: int) -> str:
    if x == 0:
        return "0"
    exponent = math.floor(math.log10(abs(x))) - digits + 1
    q = Decimal(1).scaleb(exponent)
    text = format(Decimal(repr(x)).quantize(q), "f")
    return text.rstrip("0").rstrip(".") if "." in text else text


def draw_numbers(ranges: dict[str, tuple], seed: str) -> dict[str, str]:
    """``{parameter name: short decimal}``, one inside each ``ranges[name]`` (low, high),
    drawn by a generator seeded with ``seed`` (the same seed, the same numbers).

    >>> n = draw_numbers({"a": (0.1, 3.0), "g": (9.0, 10.0)}, "s1")
    >>> sorted(n), 9.0 <= float(n["g"]) <= 10.0, n == draw_numbers({"a": (0.1, 3.0),
    ...                                                              "g": (9.0, 10.0)}, "s1")
    (['a', 'g'], True, True)
    """
    rng = random.Random(seed)
    return {name: short_decimal(rng, ranges[name]) for name in sorted(ranges)}


def shared_ranges(parameter_lists) -> dict[str, tuple]:
    """One range per parameter name over several problems' ``Parameter`` declarations: where
    problems share a name (``g``), the overlap of their ranges, so that a student has one
    value of it in every question; ``ValueError`` when the ranges do not overlap.

    >>> from dualmech.problems import get
    >>> shared_ranges([get("simple_pendulum").parameters, get("toy_car").parameters])["g"]
    (1.0, 20.0)
    """
    out: dict = {}
    for params in parameter_lists:
        for p in params:
            name, (lo, hi) = str(p.symbol), (float(v) for v in p.range)
            if name in out:
                lo, hi = max(lo, out[name][0]), min(hi, out[name][1])
                if lo >= hi:
                    raise ValueError(f"the problems declare ranges of `{name}` that do not "
                                     "overlap; put them in separate assignments.")
            out[name] = (lo, hi)
    return out


def exact_values(numbers: dict[str, str]) -> dict[str, Fraction]:
    """The exact rationals of a student's numbers (decimal text, read by ``Fraction``)."""
    return {name: Fraction(text) for name, text in numbers.items()}


@dataclass(frozen=True)
class Personal:
    """A problem served at one student's numbers: the pool's spec (``name``, the served spec
    the workers load) and the numbers as ``((parameter, decimal text), ...)``.

    ``str()`` is the problem's spec, so a grade that fails before grading names the problem.
    """

    spec: str
    numbers: tuple

    @classmethod
    def of(cls, spec: str, numbers: dict[str, str]) -> "Personal":
        return cls(spec, tuple(sorted(numbers.items())))

    def __str__(self) -> str:
        return self.spec

    def grader(self, limits):
        """The grader of this problem whose points have the student's parameter values."""
        key = (self, limits)
        found = _GRADERS.get(key)
        if found is None:
            found = _personal_grader()(self.spec, limits=limits)
            found._ctx = _personal_context()(found.problem, exact_values(dict(self.numbers)))
            _GRADERS[key] = found
            while len(_GRADERS) > _KEPT:
                _GRADERS.pop(next(iter(_GRADERS)))
        return found


def _personal_context():
    """The :class:`~dualmech.grade.context.ProblemContext` subclass sampling at fixed
    parameter values (made on first use: the grader is imported only in a worker)."""
    global _PersonalContext
    if _PersonalContext is not None:
        return _PersonalContext
    from dualmech.grade.context import POINTS, GradingUnavailable, Point, ProblemContext, \
        _GroupedDraw
    from dualmech.model.kinematics import t

    class PersonalContext(ProblemContext):
        """A problem's grading context whose points all carry the given parameter values."""

        def __init__(self, problem, values: dict):
            super().__init__(problem, 0)
            by_name = {str(p): p for p in self.parameters}
            unknown = sorted(set(values) - set(by_name))
            if unknown or len(values) != len(by_name):
                raise GradingUnavailable(
                    f"the numbers name {', '.join(sorted(values))}; `{problem.name}` has the "
                    f"parameters {', '.join(sorted(by_name))}.")
            self.fixed = {by_name[k]: v for k, v in values.items()}

        def _dimensions(self) -> dict:
            # a number in an answer stands for a value in SI units, which the dimension
            # check would call dimensionless: every symbol is taken as dimensionless too
            return {sym: () for sym in super()._dimensions()}

        def _sample(self, method: str) -> list:
            systems, exact = self._formulas()
            if method == "exact" and not exact:
                raise GradingUnavailable(f"`{self.problem.name}` has no exact points")
            mp = method != "exact"
            rng = random.Random(f"{self.problem.name}:personal:{method}")
            ranges = self._ranges()
            params = {p: (v if not mp else _mpf(v)) for p, v in self.fixed.items()}
            points: list = []
            count = POINTS if not mp else 2
            for i in range(count):
                for _ in range(40):
                    values = dict(params)
                    for s in (t,) + self.base[len(self.parameters) + 1:]:
                        values[s] = self._draw(rng, ranges.get(s, (-1.0, 1.0)), mp)
                    seed = f"{self.problem.name}:personal:{method}:{i}"
                    point = Point(values, {}, not mp, 0, seed, self.derived_formulas())
                    point.draw = _GroupedDraw(seed, f"{seed}:group", self.parameters)
                    if self._on_motion(point, systems):
                        points.append(point)
                        break
            if len(points) < count:
                raise GradingUnavailable(
                    f"`{self.problem.name}` does not determine its accelerations at these "
                    "numbers (its mass matrix is singular there); ask the teacher for others.")
            return points

    _PersonalContext = PersonalContext
    return PersonalContext


def _personal_grader():
    """The :class:`~dualmech.grade.api.Grader` subclass of a student's numbers (made on first
    use): as the grader, and each edit that names no kind of term is named the way the grader
    names it at the problem's own points (:func:`dualmech.grade.feedback.category`, which
    needs the parameters' dimensions: a gravity term, a spring term), from its correct term,
    else its written one."""
    global _PersonalGrader
    if _PersonalGrader is not None:
        return _PersonalGrader
    from dataclasses import replace

    from dualmech.grade.api import Grader

    class PersonalGrader(Grader):
        def grade(self, answer, quantity=None, about=None, feedback="full"):
            g = super().grade(answer, quantity, about, "full")
            if not any(not e.category for e in g.edits):
                return g.at_level(feedback)
            named = [replace(e, category=_category(e, self.problem, self.limits))
                     if not e.category else e for e in g.edits]
            return replace(g, edits=named).at_level(feedback)

    _PersonalGrader = PersonalGrader
    return PersonalGrader


def _category(edit, problem, limits) -> str:
    """The kind of term ``edit`` corrects, at the problem's own context ("" if unknown)."""
    from dualmech.grade.context import ProblemContext
    from dualmech.grade.feedback import category
    from dualmech.grade.formula import Formula
    from dualmech.grade.parser import parse
    ctx = ProblemContext.of(problem)
    for text in (edit.correct, edit.term):
        if not text:
            continue
        try:
            eqs = parse(text, limits)
            if len(eqs) != 1 or eqs[0].rhs is not None:
                continue
            found = category(Formula.from_node(eqs[0].lhs, ctx.vocabulary, limits,
                                               text).sympy(), ctx)
        except Exception:   # noqa: BLE001 - a name is a courtesy; the verdict stands without
            continue
        if found:
            return found
    return ""


_PersonalGrader = None


def _mpf(v: Fraction):
    import mpmath

    from dualmech.exact.form import MP_DIGITS
    with mpmath.workdps(MP_DIGITS):
        return mpmath.mpf(v.numerator) / v.denominator


_PersonalContext = None
#: Personal graders kept warm in one worker (a class's worth).
_KEPT = 256
_GRADERS: dict = {}
