"""What grading reuses for one problem: its names and a few points on its verified motion.

Per problem, once: the :class:`~.vocabulary.Vocabulary`, the dimension of every symbol, and
:class:`Point` s -- random exact points ``(parameters, t, q, q')`` where the reference model is
regular, with the true accelerations (solved from the reference model by exact Gauss--Jordan,
:mod:`dualmech.exact.linalg`) and the reactions of every direct or multiplier model fitted at
those accelerations.  The models are evaluated by the same exact evaluator as the answers
(:mod:`.formula`: rational functions of the symbols and of ``sin``/``cos`` at rational points of
the unit circle), so an answer and the truth see the same value of every angle.  An answer is
decided by evaluating it at these points: a nonzero value is a certain counter-example, zeros
at every point bound the chance of a false "right" (Schwartz--Zippel, printed with the
verdict).

The points come in pairs that share the parameters, so "a constant factor" (free of the
state, possibly depending on the parameters) can be told apart from a state-dependent one.

Square roots of state expressions in the models (a rolling wheel's contact, ``sqrt(1 -
a_z^2)``) stay in that world: the true accelerations and reactions are then exact numbers of
``Q(sqrt d)`` at each point (:mod:`.formula`, :func:`~.formula.state_root`), solved by the
same Gauss--Jordan, and an answer is decided there as any other.  A problem whose models leave
that world (``Abs``, ``Piecewise``, roots whose radicands are squares or dependent) has no
exact points (:attr:`ProblemContext.method` is ``"slow"``): its answers are decided by
:func:`dualmech.verify.check.compare_models` (:mod:`.comparator_fallback`).  Real points in the declared ranges
(``points("mpmath")``) only show values to a student, never decide.

Example
-------
>>> from dualmech.problems import get
>>> ctx = ProblemContext.of(get("simple_pendulum"))
>>> ctx.method, len(ctx.points("exact")) >= 4
('exact', True)
"""
from __future__ import annotations

import random
import threading
import time
from dataclasses import dataclass, field
from fractions import Fraction

import mpmath
import sympy as sp

from dualmech.model.dimensions import TIME
from dualmech.model.equations import state_symbols, to_plain
from dualmech.exact.form import MP_DIGITS, SAMPLE_BITS
from dualmech.model.kinematics import t
from dualmech.exact import linalg as la
from dualmech.exact.surds import Surd
from dualmech.grade.audit import reduced
from dualmech.grade.formula import Env, Formula, NotExactHere, seeded_draw
from dualmech.grade.vocabulary import Vocabulary

__all__ = ["ProblemContext", "Point", "GradingUnavailable", "zero", "off_motion",
           "build_seconds"]

POINTS = 4          # exact points per answer (two pairs sharing parameters)
_ATTEMPTS = 40
_TRIG_TYPES = (sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc)


class GradingUnavailable(ValueError):
    """The problem cannot be graded this way (the message says why)."""


@dataclass
class Point:
    """One point on the motion: ``values`` (parameters, t, q, q', q'', reactions), ``atoms``
    (``u`` of each angle, exact points only), ``group`` (points sharing parameters)."""

    values: dict
    atoms: dict
    exact: bool
    group: int
    seed: str
    derived: dict = field(default_factory=dict)
    systems: dict = field(default_factory=dict)  # model name -> (A, b) values here
    draw: object = None
    angles: dict = field(default_factory=dict)   # (cos, sin) of every angle met here

    def env(self, changes: dict | None = None, need=()) -> Env:
        """An :class:`Env` at this point (with ``changes`` applied, e.g. other accelerations);
        ``need`` lists other models' coordinates to compute from the maps."""
        values = dict(self.values)
        if changes:
            values.update(changes)
        env = Env(values, self.exact, self.atoms, self.draw or seeded_draw(self.seed),
                  self.angles if self.exact else None)
        if need:
            with mpmath.workdps(MP_DIGITS):
                for sym in need:
                    values[sym] = self.derived[sym].evaluate(env)
        return env


_building = threading.local()


def build_seconds() -> float:
    """CPU seconds this thread has spent building per-problem caches (see :meth:`ProblemContext.memo`);
    a per-answer time limit leaves them out."""
    return getattr(_building, "seconds", 0.0)


class ProblemContext:
    """Names, dimensions and sampled points of one problem (see the module docstring)."""

    _cache: dict = {}
    _lock = threading.Lock()

    def __init__(self, problem, seed: int = 0):
        self.problem = problem
        self.seed = seed
        ref = problem.model(problem.reference)
        self.reference = ref
        self.coordinates = tuple(ref.coordinates)
        self.states = [state_symbols(q) for q in self.coordinates]
        self.parameters = tuple(problem.parameter_symbols)
        self.models = {}
        for name, m in problem.models().items():
            try:
                self.models[name] = problem.in_reference_coordinates(m)
            except Exception:  # a model in other coordinates without a map: not used here
                continue
        reactions: list = []
        for m in self.models.values():
            reactions += [u for u in m.unknowns if u not in reactions]
        self.reactions = tuple(reactions)
        self.qdd = tuple(s.qdd for s in self.states)
        self.base = self.parameters + (t,) + tuple(s.q for s in self.states) + \
            tuple(s.qd for s in self.states)
        self._extra = self._extra_coordinates()
        self.vocabulary = Vocabulary.build(self.coordinates, self.parameters, self.reactions,
                                           extra_coordinates=[q for q, _ in self._extra],
                                           aliases=getattr(problem, "aliases", None))
        self.dims = self._dimensions()
        self.names = {}
        for q in list(self.coordinates) + [q for q, _ in self._extra]:
            s = state_symbols(q)
            self.names[s.qd] = s.name + "'"
            self.names[s.qdd] = s.name + "''"
        self._points: dict = {}
        #: what the answer's equations must follow from, in words
        self.subject = "the equations of motion"
        self.store: dict = {}  # lazily built helpers of other modules (feedback, Lagrange)
        #: the catalogue name this context was built for by name (its problem at its default
        #: size), else None; only such a context is kept on disk (:mod:`.stored`)
        self.named: str | None = None
        #: keys of :attr:`store` already kept on disk
        self.stored: frozenset = frozenset()

    def memo(self, key, build):
        """``store[key]``, built once by ``build()``; its time is per-problem, not per-answer."""
        if key in self.store:
            return self.store[key]
        depth = getattr(_building, "depth", 0)
        _building.depth = depth + 1
        t0 = time.thread_time()
        try:
            value = build()
        finally:
            _building.depth = depth
            if depth == 0:
                _building.seconds = build_seconds() + time.thread_time() - t0
        self.store[key] = value
        return value

    @classmethod
    def of(cls, problem, seed: int = 0) -> "ProblemContext":
        """The cached context of ``problem`` (one per problem name, class and seed)."""
        key = (problem.name, type(problem).__qualname__, seed, id(problem))
        with cls._lock:
            ctx = cls._cache.get(key)
            if ctx is None:
                ctx = cls._cache[key] = cls(problem, seed)
        return ctx

    # -- names and dimensions ---------------------------------------------------------
    def _extra_coordinates(self) -> list:
        """``[(q, expression in the reference coordinates)]`` of other models' coordinates."""
        out, seen = [], set(self.coordinates)
        try:
            maps = self.problem.coordinate_maps()
        except Exception:
            maps = {}
        for mapping in maps.values():
            for q, expr in mapping.items():
                if q not in seen:
                    seen.add(q)
                    out.append((q, sp.sympify(expr, strict=True)))
        return out

    def _dimensions(self) -> dict:
        dims = {}
        declared = self.problem.dimensions()
        T = reduced(TIME)
        for q in list(self.coordinates) + [q for q, _ in self._extra]:
            s = state_symbols(q)
            d = reduced(declared[q]) if q in declared else ()
            dims[s.q] = d
            dims[s.qd] = _dsub(d, T, 1)
            dims[s.qdd] = _dsub(d, T, 2)
        for p in self.problem.parameters:
            dims[p.symbol] = reduced(p.dimension)
        for x in getattr(self.problem, "input_symbols", ()):   # a given input F(t)
            if x in declared:
                dims[x] = reduced(declared[x])
        info = self.problem.reaction_info()
        for u in self.reactions:
            if u.name in info:
                dims[u] = reduced(info[u.name].dimension)
        dims[t] = T
        return dims

    def plain(self, expr):
        """``expr`` in plain state symbols of the reference coordinates."""
        return to_plain(expr, self.coordinates)

    def derived_formulas(self) -> dict:
        """Plain symbols of the other models' coordinates -> formulas in the reference ones."""
        def build():
            out = {}
            for q, expr in self._extra:
                s = state_symbols(q)
                for sym, e in ((s.q, expr), (s.qd, expr.diff(t)), (s.qdd, expr.diff(t, 2))):
                    out[sym] = Formula.from_sympy(self.plain(e))
            return out
        return self.memo("derived", build)

    # -- points on the motion --------------------------------------------------------------
    @property
    def method(self) -> str:
        """``exact`` when every model of the problem evaluates exactly (rational functions of
        the symbols and of sines and cosines of angles, and independent square roots of
        expressions in them), else ``slow`` (answers are then decided by
        :func:`dualmech.verify.check.compare_models`)."""
        if not self._formulas()[1] or self.static_rows():
            return "slow"
        return "exact" if self.memo("roots exact", self._roots_exact) else "slow"

    def _roots_exact(self) -> bool:
        """Whether the models' square roots of expressions (if any) stay exact at the
        points: their radicands independent there (:class:`~.formula.NotExactHere`)."""
        systems, _ = self._formulas()
        if not any(f.state_roots for _, fa, fb in systems for row in fa + [fb] for f in row):
            return True
        try:
            self.points("exact")
        except NotExactHere:
            return False
        return True

    def points(self, method: str) -> list[Point]:
        """The sampled points: ``exact`` (for verdicts) or ``mpmath`` (real states in the
        declared ranges, for showing values); built once."""
        if method not in self._points:
            with self._lock:
                if method not in self._points:
                    self._points[method] = self.memo(("points", method),
                                                     lambda: self._sample(method))
        return self._points[method]

    def _formulas(self):
        """``([(model, A formulas, b formulas)], all exact)`` of the reference and of every
        model with reactions, in plain symbols."""
        def build():
            out, exact = [], True
            models = [self.reference] + [m for n, m in self.models.items()
                                         if m.unknowns and n != self.problem.reference]
            for m in models:
                A, b = m.matrix()
                try:
                    fa = [[Formula.from_sympy(self.plain(A[i, j])) for j in range(A.cols)]
                          for i in range(A.rows)]
                    fb = [Formula.from_sympy(self.plain(b[i])) for i in range(b.rows)]
                except TypeError:   # Abs, Piecewise, ...: only compare_models decides these
                    if m is self.reference:
                        return [], False
                    continue
                exact = exact and all(f.exact for row in fa for f in row) and \
                    all(f.exact for f in fb)
                out.append((m, fa, fb))
            return out, exact
        return self.memo("formulas", build)

    def _sample(self, method: str) -> list[Point]:
        systems, exact = self._formulas()
        if method == "exact" and not exact:
            raise GradingUnavailable(f"`{self.problem.name}` has no exact points")
        if not systems:
            raise GradingUnavailable(f"the reference model of `{self.problem.name}` cannot be "
                                     "evaluated by the grader.")
        mp = method != "exact"
        rng = random.Random(f"{self.problem.name}:{self.seed}:{method}")
        ranges = self._ranges()
        points: list[Point] = []
        count = POINTS if not mp else 2
        for i in range(count):
            group = i // 2
            if i % 2 == 0:
                params = {p: self._draw(rng, ranges[p], mp) for p in self.parameters}
            for _ in range(_ATTEMPTS):
                values = dict(params)
                for s in (t,) + self.base[len(self.parameters) + 1:]:
                    values[s] = self._draw(rng, ranges.get(s, (-1.0, 1.0)), mp)
                seed = f"{self.problem.name}:{self.seed}:{method}:{i}"
                gseed = f"{self.problem.name}:{self.seed}:{method}:group{group}"
                point = Point(values, {}, not mp, group, seed, self.derived_formulas())
                point.draw = _GroupedDraw(seed, gseed, self.parameters)
                if self._on_motion(point, systems):
                    points.append(point)
                    break
        if len(points) < count:
            raise GradingUnavailable(
                f"the reference model `{self.problem.reference}` of `{self.problem.name}` does "
                "not determine the accelerations at random states (its mass matrix is singular "
                "there, e.g. a coordinate without inertia); answers to it cannot be graded "
                "against the accelerations.")
        return points

    @staticmethod
    def _draw(rng, rng_range, mp):
        if not mp:
            half = 1 << (SAMPLE_BITS - 1)
            return Fraction(rng.randrange(-half, half))
        with mpmath.workdps(MP_DIGITS):
            return mpmath.mpf(rng.uniform(*rng_range))

    def _on_motion(self, point: "Point", systems) -> bool:
        """Fill ``point`` with the true accelerations and reactions; False where singular."""
        env = point.env()
        try:
            with mpmath.workdps(MP_DIGITS):
                parts = [([[f.evaluate(env) for f in row] for row in fa],
                          [f.evaluate(env) for f in fb]) for _, fa, fb in systems]
        except NotExactHere:
            raise
        except (ZeroDivisionError, ValueError):
            return False
        with mpmath.workdps(MP_DIGITS):
            x = la.solve_square(*parts[0])
        if x is None:
            return False
        n = len(self.coordinates)
        ref = systems[0][0]
        point.values.update(zip(self.qdd, x[:n]))
        point.values.update(zip(ref.unknowns, x[n:]))
        for (m, _, _), (Av, bv) in zip(systems[1:], parts[1:]):
            with mpmath.workdps(MP_DIGITS):
                r = [bi - sum((a * v for a, v in zip(row[:n], x[:n])), 0)
                     for bi, row in zip(bv, Av)]
                res, lam, undetermined = la.residual_after_least_squares(
                    [row[n:] for row in Av], r)
            if undetermined or any(not zero(v, r) for v in res):
                continue  # this model does not give its reactions here; others may
            for u, v in zip(m.unknowns, lam):
                point.values.setdefault(u, v)
        point.systems = {m.name: part for (m, _, _), part in zip(systems, parts)}
        return True

    def static_rows(self) -> bool:
        """Whether the reference model has static rows (no acceleration in a row, as a
        massless bar): its accelerations are not determined at free states, so answers are
        decided by the comparator, which samples the constraint manifold with the unknowns
        [accelerations of the dynamic coordinates, the static coordinates]."""
        def build():
            A, _ = self.reference.matrix()
            n = len(self.coordinates)
            return any(all(A[i, j] == 0 for j in range(min(n, A.cols))) for i in range(A.rows))
        return self.memo("static rows", build)

    def ranges(self) -> dict:
        """Working ranges (floats) of the parameters, ``t``, coordinates and rates."""
        return self._ranges()

    def _ranges(self) -> dict:
        floats = {t: (0.0, 10.0)}
        for p in self.problem.parameters:
            floats[p.symbol] = tuple(float(v) for v in p.range)
        for x in getattr(self.problem, "input_symbols", ()):
            floats[x] = (0.5, 2.0)   # a given input F(t): any value at a point, as the verdict
            # draws it (dualmech.verify.sampling.Context)
        for q, s in zip(self.coordinates, self.states):
            c = self.problem.coordinate_info(q)
            floats[s.q] = tuple(float(v) for v in c.range)
            floats[s.qd] = tuple(float(v) for v in c.rate_range)
        return floats

    def false_right_bound(self, degree: int, method: str) -> float:
        """Bound on the chance that a wrong answer of ``degree`` vanished at every point."""
        if method != "exact":
            return float("nan")
        systems, _ = self._formulas()
        d_ref = max((f.degree for _, fa, fb in systems for row in fa + [fb] for f in row),
                    default=1)
        n = len(self.coordinates) + len(self.reference.unknowns)
        D = max(degree, 1) * max(1, 2 * n * d_ref)
        return min(1.0, D / 2.0 ** SAMPLE_BITS) ** POINTS


class _GroupedDraw:
    """Angles of parameters only (``sin(alpha)``) are shared by the points of a pair."""

    __slots__ = ("point", "group", "parameters")

    def __init__(self, seed: str, group_seed: str, parameters):
        self.point, self.group = seeded_draw(seed), seeded_draw(group_seed)
        self.parameters = frozenset(parameters)

    def __call__(self, mono):
        return self.group(mono) if all(s in self.parameters for s, _ in mono) \
            else self.point(mono)


def _dsub(d, T, k):
    out = dict(d)
    for name, e in T:
        out[name] = out.get(name, 0) - k * e
    return tuple(sorted((n, e) for n, e in out.items() if e != 0))


def zero(v, scale_values=()) -> bool:
    """Exactly zero (Fractions, and exact square-root numbers -- a
    :class:`~dualmech.exact.surds.Surd` is zero exactly when every coordinate is), or zero to
    half the working precision relative to the largest of ``scale_values`` (mpmath numbers)."""
    if isinstance(v, (Fraction, int, Surd)):
        return v == 0
    scale = max((abs(s) for s in scale_values), default=1)
    with mpmath.workdps(MP_DIGITS):
        return abs(v) <= mpmath.mpf(10) ** (-(MP_DIGITS // 2)) * (1 + scale)


_zero = zero


def off_motion(point: Point, ctx: "ProblemContext", changes: dict | None = None) -> Env:
    """An :class:`Env` at ``point`` with random accelerations (not the true ones): for
    identities that must hold for every ``q''`` (Lagrange terms)."""
    rng = random.Random(point.seed + "|off-motion")
    acc = {}
    for s in ctx.qdd:
        v = Fraction(rng.randrange(-(1 << 40), 1 << 40))
        if not point.exact:
            with mpmath.workdps(MP_DIGITS):
                v = mpmath.mpf(v.numerator) / (1 << 20)
        acc[s] = v
    acc.update(changes or {})
    return point.env(acc)


