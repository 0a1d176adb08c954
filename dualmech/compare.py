"""Decide whether two derivations describe the same motion, check printed answers, recover reactions.

Two equation sets are *equivalent* when they give the same accelerations wherever their mass
matrices are regular: one is an invertible combination of the other.  The test, at each random
point ``(parameters, t, q, q')`` (see :mod:`dualmech.exact`):

1. solve the reference system ``A_R [q''; lambda_R] = b_R`` for the accelerations ``q''``;
2. in the candidate ``[M_C  B_C] [q''; lambda_C] = b_C`` put those accelerations and remove the
   best reactions ``lambda_C`` (least squares over its independent columns); what is left of
   each equation is its *residual after the best combination*;
3. the candidate must also determine ``(q'', lambda_C)`` uniquely (full column rank).

Every residual exactly zero at ``k`` points proves equivalence up to the printed Schwartz--Zippel
bound; a nonzero residual is a certain counter-example, and is explained: which equation, its
residual symbolically when that is cheap, term by term at a concrete real state.

Example
-------
>>> import sympy as sp
>>> from dualmech import coordinate, t, EquationSet
>>> from dualmech.compare import compare_models
>>> th = coordinate("theta"); m, l, g = sp.symbols("m l g", positive=True)
>>> a = EquationSet("a", (th,), (m*l**2*th.diff(t, 2) + m*g*l*sp.sin(th),))
>>> b = EquationSet("b", (th,), (th.diff(t, 2) + g/l*sp.sin(th),))
>>> compare_models(a, b).equivalent
True
>>> bad = EquationSet("bad", (th,), (th.diff(t, 2) - g/l*sp.sin(th),))
>>> r = compare_models(a, bad); r.equivalent, r.mismatches[0].residual
(False, '-2*g*sin(theta(t))/l')
"""
from __future__ import annotations

import math
import random
import time
from dataclasses import dataclass, field
from typing import Sequence

import mpmath
import sympy as sp

from ._expr import as_expr
from .verify import linalg as la
from .dimensions import audit
from .equations import EquationSet, ModelError, _tidy, from_plain, state_symbols, to_plain
from .exact import MP_DIGITS, ExactForm, is_zero
from .kinematics import t

__all__ = ["compare", "compare_models", "compare_reactions", "reaction_pairs",
           "recover_reactions", "Comparison", "PairResult", "Mismatch", "METHOD_NAMES"]

METHOD_NAMES = {
    "exact": "exact rational-point test",
    "mpmath": "high-precision numeric (mpmath)",
}
_MAX_ATTEMPTS = 12


# ---------------------------------------------------------------------------------------
# results
@dataclass
class Mismatch:
    """Why a candidate equation set is not equivalent to the reference."""

    model: str
    equation: str
    reason: str
    residual: str = ""
    value: float = math.nan
    state: dict = field(default_factory=dict)
    terms: list = field(default_factory=list)

    def __str__(self) -> str:
        lines = [f"{self.model} [{self.equation}]: {self.reason}"]
        if self.residual:
            lines.append(f"    residual after the best combination: {self.residual}")
        if self.state:
            st = ", ".join(f"{k}={v:.6g}" for k, v in self.state.items())
            lines.append(f"    at {st}: residual {self.value:.6g}")
        for term, value in self.terms:
            lines.append(f"      {value:+.6g}  {term}")
        return "\n".join(lines)

    def to_dict(self) -> dict:
        return {"model": self.model, "equation": self.equation, "reason": self.reason,
                "residual": self.residual, "value": _json_float(self.value),
                "state": {k: _json_float(v) for k, v in self.state.items()},
                "terms": [[s, _json_float(v)] for s, v in self.terms]}


@dataclass
class PairResult:
    """Verdict on one candidate model against the reference model."""

    reference: str
    candidate: str
    equivalent: bool
    method: str
    points: int
    bound: float
    seconds: float
    mismatches: list = field(default_factory=list)
    kind: str = "motion"
    reactions: tuple = ()

    def __str__(self) -> str:
        if self.kind == "reactions":
            verdict = "the same" if self.equivalent else "DIFFERENT"
            head = f"reactions {', '.join(self.reactions)} of {self.candidate} vs {self.reference}: {verdict}"
        else:
            verdict = "equivalent" if self.equivalent else "NOT equivalent"
            head = f"{self.candidate} vs {self.reference}: {verdict}"
        s = (f"{head} "
             f"({METHOD_NAMES[self.method]}, {self.points} points")
        if self.method == "exact":
            s += f", P(false equal) <= {self.bound:.1e}"
        s += f", {self.seconds:.2f} s)"
        return "\n".join([s] + [str(m) for m in self.mismatches])

    def to_dict(self) -> dict:
        return {"kind": self.kind, "reference": self.reference, "candidate": self.candidate,
                "reactions": list(self.reactions), "equivalent": self.equivalent, "method": METHOD_NAMES[self.method],
                "points": self.points, "false_equal_bound": _json_float(self.bound),
                "seconds": self.seconds, "mismatches": [m.to_dict() for m in self.mismatches]}


@dataclass
class Comparison:
    """Everything ``dualmech check`` reports for one problem; ``str()`` is the readable report."""

    problem: object
    pairs: list
    published: list
    accelerations: dict
    reactions: dict
    reaction_directions: dict
    dimension_issues: list
    seconds: float
    points: int

    @property
    def equivalent(self) -> bool:
        return all(p.equivalent for p in self.pairs)

    @property
    def method(self) -> str:
        methods = {p.method for p in self.pairs}
        return METHOD_NAMES["mpmath"] if "mpmath" in methods else METHOD_NAMES["exact"]

    @property
    def bound(self) -> float:
        return max((p.bound for p in self.pairs), default=0.0)

    @property
    def mismatches(self) -> list:
        return [m for p in self.pairs for m in p.mismatches]

    def __str__(self) -> str:
        pr = self.problem
        ref = pr.model(pr.reference)
        out = [f"{pr.name}: {pr.title}", f"  source: {pr.source}",
               f"  coordinates: {', '.join(q.func.__name__ for q in ref.coordinates)}",
               f"  verdict: {'all derivations agree' if self.equivalent else 'DISAGREEMENT'}"
               f" ({self.method}, {self.seconds:.2f} s)"]
        for p in self.pairs:
            out.append("  " + str(p).replace("\n", "\n  "))
        if self.accelerations:
            out.append("  accelerations:")
            for k, v in self.accelerations.items():
                out.append(f"    {k}'' = {v}")
        if self.reactions:
            out.append("  reactions (from the direct form):")
            for k, v in self.reactions.items():
                d = self.reaction_directions.get(k, "")
                out.append(f"    {k} = {v}" + (f"   [{d}]" if d else ""))
        if self.dimension_issues:
            out.append("  dimension audit:")
            out.extend(f"    {i}" for i in self.dimension_issues)
        else:
            out.append("  dimension audit: every equation is consistent")
        if self.published:
            out.append("  published answers:")
            for v in self.published:
                out.append(f"    [{v.verdict.upper():7s}] {v.label}" +
                           (f" ({v.where})" if v.where else ""))
                if v.verdict != "correct":
                    out.append("              " + v.detail.replace("\n", "\n              "))
        return "\n".join(out)

    def to_dict(self) -> dict:
        pr = self.problem
        ref = pr.model(pr.reference)
        return {
            "name": pr.name, "title": pr.title, "source": pr.source,
            "coordinates": [q.func.__name__ for q in ref.coordinates],
            "parameters": [str(p.symbol) for p in pr.parameters],
            "equivalent": self.equivalent, "method": self.method,
            "seconds": self.seconds,
            "eom": [str(e) for e in ref.equations],
            "accelerations": {k: str(v) for k, v in self.accelerations.items()},
            "reactions": {k: str(v) for k, v in self.reactions.items()},
            "reaction_directions": dict(self.reaction_directions),
            "published": [v.to_dict() for v in self.published],
            "mismatches": [m.to_dict() for m in self.mismatches],
            "models": {n: [str(e) for e in m.equations] for n, m in pr.models().items()},
            "pairs": [p.to_dict() for p in self.pairs],
            "points": self.points,
            "false_equal_bound": _json_float(self.bound),
            "dimension_issues": list(self.dimension_issues),
        }


def _json_float(x):
    x = float(x)
    return None if math.isnan(x) or math.isinf(x) else x


# ---------------------------------------------------------------------------------------
# sampling context
class _Context:
    """Symbols and real ranges of one problem (or of two bare equation sets)."""

    def __init__(self, coordinates, parameters=(), problem=None, extra_free=()):
        self.coordinates = tuple(coordinates)
        self.states = [state_symbols(q) for q in self.coordinates]
        self.parameters = tuple(parameters)
        self.base = tuple(self.parameters) + (t,) + tuple(s.q for s in self.states) + \
            tuple(s.qd for s in self.states)
        self.qdd = tuple(s.qdd for s in self.states)
        self.floats: dict = {t: (0.0, 10.0)}
        if problem is not None:
            for p in problem.parameters:
                self.floats[p.symbol] = tuple(float(x) for x in p.range)
            for q, s in zip(self.coordinates, self.states):
                c = problem.coordinate_info(q)
                self.floats[s.q] = tuple(float(x) for x in c.range)
                self.floats[s.qd] = tuple(float(x) for x in c.rate_range)
        for s in self.parameters:
            self.floats.setdefault(s, (0.5, 2.0))
        for s in self.states:
            self.floats.setdefault(s.q, (-1.0, 1.0))
            self.floats.setdefault(s.qd, (-1.0, 1.0))

    @classmethod
    def for_models(cls, *models: EquationSet) -> "_Context":
        coords = models[0].coordinates
        free = set()
        for m in models:
            for e in m.equations:
                free |= e.free_symbols
        free -= {t} | set(u for m in models for u in m.unknowns)
        return cls(coords, sorted(free, key=str))

    def name_of(self, sym) -> str:
        for q, s in zip(self.coordinates, self.states):
            if sym == s.q:
                return q.func.__name__
            if sym == s.qd:
                return q.func.__name__ + "'"
        return str(sym)


def _plain_system(eqs: EquationSet, coords) -> tuple[list, list]:
    A, b = eqs.matrix()
    A = [[to_plain(A[i, j], coords) for j in range(A.cols)] for i in range(A.rows)]
    b = [to_plain(b[i], coords) for i in range(b.rows)]
    return A, b


def _flatten(A, b) -> list:
    return [x for row in A for x in row] + list(b)


def _unflatten(vals, rows, cols) -> tuple[list, list]:
    A = [list(vals[i * cols:(i + 1) * cols]) for i in range(rows)]
    b = list(vals[rows * cols: rows * cols + rows])
    return A, b


def _regular_points(form, ctx, rng, systems, limit, fill=None):
    """Random points where the first of ``systems`` (the reference) is regular.

    ``systems`` are the ``(A, b)`` whose entries ``form`` evaluates first, in order; ``fill``
    gives values of extra symbols to set before evaluating.  Yields ``(point, values, parts,
    x)``: the sampled point, every value, each system's ``(A, b)`` at the point and the
    reference solution ``x``.  Points where an expression divides by zero or the reference is
    singular are skipped; at most ``limit`` points are drawn.
    """
    for _ in range(limit):
        point = form.sample(rng, ctx.floats)
        if fill:
            point.update(fill)
        try:
            vals = form.evaluate(point)
        except (ZeroDivisionError, ValueError):
            continue
        parts, off = [], 0
        for A, _b in systems:
            parts.append(_unflatten(vals[off:], len(A), len(A[0])))
            off += len(A) * (len(A[0]) + 1)
        x = la.solve_square(*parts[0])
        if x is not None:
            yield point, vals, parts, x


def _high_precision(fn):
    """Run ``fn`` at the fallback's working precision, so mpmath arithmetic done on sampled
    values (residuals, eliminations) keeps MP_DIGITS digits; exact Fractions are unaffected."""
    import functools

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        with mpmath.workdps(MP_DIGITS):
            return fn(*args, **kwargs)
    return wrapper


# ---------------------------------------------------------------------------------------
# pairs
@_high_precision
def compare_models(reference: EquationSet, candidate: EquationSet, *, points: int = 8,
                   seed: int = 0, context: _Context | None = None,
                   explain: bool = True) -> PairResult:
    """Is ``candidate`` the same motion as ``reference``?  Both must use the same coordinates.

    ``reference`` must be square and regular at generic points (it decides the accelerations).
    """
    if set(candidate.coordinates) != set(reference.coordinates):
        raise ModelError(f"`{candidate.name}` uses coordinates {list(candidate.coordinates)} but "
                         f"`{reference.name}` uses {list(reference.coordinates)}; rewrite one "
                         "with EquationSet.change_coordinates first.")
    if not reference.is_square:
        raise ModelError(f"reference `{reference.name}` has {len(reference.equations)} equations "
                         f"for {reference.n} accelerations and {len(reference.unknowns)} "
                         "reactions; the reference must be square.")
    t0 = time.perf_counter()
    ctx = context or _Context.for_models(reference, candidate)
    coords = reference.coordinates
    candidate = _reorder(candidate, coords)
    Ar, br = _plain_system(reference, coords)
    Ac, bc = _plain_system(candidate, coords)
    form = ExactForm.build(_flatten(Ar, br) + _flatten(Ac, bc), ctx.base)
    n = len(coords)
    rng = random.Random(seed)
    good, mismatches = 0, []
    for _, _, parts, x in _regular_points(form, ctx, rng, [(Ar, br), (Ac, bc)],
                                          _MAX_ATTEMPTS * points):
        good += 1
        Acv, bcv = parts[1]
        found = _point_mismatch(Acv, bcv, x[:n], n)
        if found:
            mismatches = _explain(reference, candidate, ctx, found, rng) if explain else \
                [Mismatch(candidate.name, candidate.labels[i] if isinstance(i, int) else i, r)
                 for i, r in found]
            break
        if good == points:
            break
    if good == 0:
        raise ModelError(f"the mass matrix of `{reference.name}` is singular at every sampled "
                         "point: check that every coordinate has inertia and the reactions are "
                         "independent.")
    bound = form.false_equal_bound(good, _degree_factor(Ar, Ac, form.degree)) \
        if not mismatches else 0.0
    return PairResult(reference.name, candidate.name, not mismatches, form.method, good, bound,
                      time.perf_counter() - t0, mismatches)


def _degree_factor(Ar, Ac, e) -> int:
    """Extra degree for solving the systems: see exact.py; a generous upper bound."""
    kr = len(Ar) * (len(Ar[0]) + 1)
    kc = len(Ac) * (len(Ac[0]) + 1)
    return 4 * (len(Ar) * kr + len(Ac) * kc) * e


def _reorder(eqs: EquationSet, coords) -> EquationSet:
    if tuple(eqs.coordinates) == tuple(coords):
        return eqs
    return EquationSet(eqs.name, tuple(coords), eqs.equations, eqs.unknowns, eqs.labels,
                       eqs.contributions, eqs.description)


def _fit_reactions(A, b, qdd, n):
    """Put the accelerations ``qdd`` into ``A [q''; lambda] = b`` and fit the reactions.

    Returns ``(residual per equation, lambda, undetermined columns, r = b - M qdd)``.
    """
    M = [row[:n] for row in A]
    B = [row[n:] for row in A]
    r = [bi - mi for bi, mi in zip(b, la.matvec(M, qdd))]
    res, lam, undetermined = la.residual_after_least_squares(B, r)
    return res, lam, undetermined, r


def _point_mismatch(Acv, bcv, qdd, n) -> list:
    """Residual problems of the candidate at one point: ``[(equation index or 'all', reason)]``."""
    res, _, undetermined, r = _fit_reactions(Acv, bcv, qdd, n)
    scale = max((abs(v) for v in r), default=1)
    out = [(i, "does not hold with the reference accelerations")
           for i, v in enumerate(res) if not is_zero(v, scale)]
    if not out and undetermined:
        out.append(("reactions", "reactions not determined by the equations: unknowns "
                                  f"{undetermined} (by position) depend on the others"))
    if not out and la.rank(Acv) < len(Acv[0]):
        out.append(("all", f"the equations do not determine the accelerations "
                           f"(rank {la.rank(Acv)} < {len(Acv[0])})"))
    return out


def _explain(reference, candidate, ctx, found, rng) -> list:
    """Turn point residuals into readable mismatches: symbolic residual, real state, terms."""
    coords = reference.coordinates
    state, qdd_vals, lam_vals = _real_state(reference, candidate, ctx, rng)
    out = []
    for i, reason in found:
        if not isinstance(i, int):
            if i == "reactions":
                reason = reason.split(": unknowns")[0] + ": " + ", ".join(
                    str(candidate.unknowns[j]) for j in _undetermined(candidate, ctx, rng))
            out.append(Mismatch(candidate.name, i, reason))
            continue
        eq = to_plain(candidate.equations[i], coords)
        symbolic = _symbolic_residual(reference, candidate, i)
        values = dict(state)
        values.update(qdd_vals)
        values.update(lam_vals)
        terms, total = [], math.nan
        try:
            for term in sp.Add.make_args(sp.expand(eq) if sp.count_ops(eq) < 300 else eq):
                terms.append((str(from_plain(term, coords)), float(_num(term, values))))
            total = float(_num(eq, values))
        except (TypeError, ValueError, ZeroDivisionError):
            pass
        out.append(Mismatch(candidate.name, candidate.labels[i], reason,
                            residual=str(from_plain(symbolic, coords)) if symbolic is not None else "",
                            value=total, state={ctx.name_of(k): float(v) for k, v in state.items()},
                            terms=terms))
    return out


def _undetermined(candidate, ctx, rng) -> list[int]:
    """Indices of the candidate's unknowns that its equations cannot determine."""
    coords = candidate.coordinates
    B = [[to_plain(e, coords) for e in row] for row in candidate.reaction_matrix().tolist()]
    form = ExactForm.build([x for row in B for x in row], ctx.base)
    for _ in range(_MAX_ATTEMPTS):
        try:
            vals = form.evaluate(form.sample(rng, ctx.floats))
        except (ZeroDivisionError, ValueError):
            continue
        rows = [vals[i * len(B[0]):(i + 1) * len(B[0])] for i in range(len(B))]
        piv = la.rref(rows)[1]
        return [j for j in range(len(B[0])) if j not in piv]
    return []


def _num(expr, values):
    with mpmath.workdps(30):
        return as_expr(expr).xreplace({k: sp.Float(str(v), 30) for k, v in values.items()}).evalf(30)


def _real_state(reference, candidate, ctx, rng):
    """A real state inside the declared ranges where the reference is regular."""
    coords = reference.coordinates
    Ar, br = _plain_system(reference, coords)
    form = ExactForm.build(_flatten(Ar, br), ctx.base, force_mp=True)
    for point, _, _, x in _regular_points(form, ctx, rng, [(Ar, br)], 50):
        n = len(coords)
        qdd = {s.qdd: x[j] for j, s in enumerate(ctx.states)}
        lam = {u: x[n + j] for j, u in enumerate(reference.unknowns)}
        # the candidate's own reactions, best fit
        Ac, bc = _plain_system(candidate, coords)
        cform = ExactForm.build(_flatten(Ac, bc), ctx.base, force_mp=True)
        cvals = cform.evaluate(point)
        Acv, bcv = _unflatten(cvals, len(Ac), len(Ac[0]))
        lam_c = _fit_reactions(Acv, bcv, x[:n], n)[1]
        lam.update({u: v for u, v in zip(candidate.unknowns, lam_c)})
        return {k: point[k] for k in ctx.base}, qdd, lam
    return {}, {}, {}


def _symbolic_residual(reference: EquationSet, candidate: EquationSet, i: int):
    """``e_i - y . (reference equations)`` with ``y`` cancelling every acceleration and reaction.

    Only for reaction-free candidate equations of small models (it needs a symbolic solve).
    """
    if candidate.unknowns and any(candidate.equations[i].has(u) for u in candidate.unknowns):
        return None
    A_R, b_R = reference.matrix()
    if A_R.rows > 6 or sp.count_ops(A_R) > 3000:
        return None
    coords = reference.coordinates
    Mrow = candidate.mass_matrix()[i, :]
    target = sp.Matrix([list(Mrow) + [0] * len(reference.unknowns)]).T
    try:
        A_p = A_R.applyfunc(lambda e: to_plain(e, coords))
        y = A_p.T.LUsolve(target.applyfunc(lambda e: to_plain(e, coords)))
        b_i = to_plain(candidate.forcing()[i], coords)
        residual = -b_i + (y.T * b_R.applyfunc(lambda e: to_plain(e, coords)))[0, 0]
        return _tidy(residual)
    except (ValueError, ZeroDivisionError, sp.matrices.exceptions.NonInvertibleMatrixError):
        return None


# ---------------------------------------------------------------------------------------
# problems
def compare(problem, points: int = 8, seed: int = 0) -> Comparison:
    """Cross-check every derivation of ``problem`` against its reference; check published answers.

    Returns a :class:`Comparison`; ``str()`` of it is the report a teacher reads.
    """
    t0 = time.perf_counter()
    problem.validate()
    models = problem.models()
    ref = models[problem.reference]
    ctx = _Context(ref.coordinates, problem.parameter_symbols, problem)
    pairs = []
    for name, m in models.items():
        if name == problem.reference:
            continue
        cand = problem.in_reference_coordinates(m)
        pairs.append(compare_models(ref, cand, points=points, seed=seed, context=ctx))
    pairs += reaction_pairs(problem, points=points, seed=seed, context=ctx)
    accelerations = _accelerations(ref)
    reactions = recover_reactions(problem)
    from .published import PublishedVerdict, check_published  # (imports this module)
    published = check_published(problem, points=points, seed=seed, context=ctx) \
        if all(p.equivalent for p in pairs) else \
        [PublishedVerdict(p.label, p.where, "unchecked",
                          "the derivations disagree; fix them before judging printed answers",
                          "none") for p in problem.published()]
    issues = list(problem.dimension_issues())
    declared = problem.reaction_info()
    dims = problem.dimensions()
    for name, expr in reactions.items():
        if name in declared:
            for issue in audit(expr, dims, declared[name].dimension):
                issues.append(f"reaction {name}: {issue}")
    return Comparison(problem, pairs, published, accelerations, reactions,
                      {r.name: r.direction for r in problem.reactions},
                      issues, time.perf_counter() - t0, points)


def reaction_pairs(problem, models: dict | None = None, *, points: int = 8, seed: int = 0,
                   context: _Context | None = None, explain: bool = True) -> list[PairResult]:
    """Compare the reactions of every two models that declare a reaction of the same name.

    The direct form gives reactions from free-body diagrams; a Lagrangian with multipliers
    (constraints written as distances with unit gradient along the contact force) gives them
    independently.  Comparing the two catches errors that leave the motion untouched -- the
    weight of a body that only presses on the ground, the sign of a contact force.
    """
    models = models if models is not None else problem.models()
    ref = problem.model(problem.reference)
    with_unknowns = [(n, problem.in_reference_coordinates(m)) for n, m in models.items()
                     if m.unknowns]
    out = []
    for i, (na, a) in enumerate(with_unknowns):
        for nb, b in with_unknowns[i + 1:]:
            shared = [u for u in a.unknowns if u in b.unknowns]
            if shared:
                out.append(compare_reactions(ref, a, b, shared, points=points, seed=seed,
                                             context=context, explain=explain))
    return out


@_high_precision
def compare_reactions(reference: EquationSet, first: EquationSet, second: EquationSet,
                      names: Sequence, *, points: int = 8, seed: int = 0,
                      context: _Context | None = None, explain: bool = True) -> PairResult:
    """Do ``first`` and ``second`` give the same values of the reactions ``names``?

    Accelerations come from ``reference``; each model's reactions are then its best fit
    (exact least squares), which is its unique solution when the model is consistent.
    """
    t0 = time.perf_counter()
    coords = reference.coordinates
    ctx = context or _Context.for_models(reference, first, second)
    systems = [_plain_system(m, coords) for m in (reference, _reorder(first, coords),
                                                   _reorder(second, coords))]
    exprs = []
    for A, b in systems:
        exprs += _flatten(A, b)
    form = ExactForm.build(exprs, ctx.base)
    n = len(coords)
    rng = random.Random(seed + 2)
    good, bad = 0, []
    for _, _, parts, x in _regular_points(form, ctx, rng, systems, _MAX_ATTEMPTS * points):
        good += 1
        lams = []
        for (Av, bv), m in zip(parts[1:], (first, second)):
            lams.append(dict(zip(m.unknowns, _fit_reactions(Av, bv, x[:n], n)[1])))
        bad = [u for u in names if not is_zero(lams[0][u] - lams[1][u], abs(lams[0][u]))]
        if bad or good == points:
            break
    mismatches = []
    for u in bad:
        residual = ""
        try:
            if not explain:
                raise ValueError("no explanation asked for")
            first, second = _drop_zero_rows(first), _drop_zero_rows(second)
            if first.is_square and second.is_square:
                d = _tidy(first.reactions_solved()[u] - second.reactions_solved()[u])
                residual = str(d)
        except (ModelError, ValueError, ZeroDivisionError):
            pass
        mismatches.append(Mismatch(second.name, f"reaction {u}",
                                   f"{u} differs from the value `{first.name}` gives",
                                   residual=residual))
    bound = form.false_equal_bound(good, _degree_factor(systems[1][0], systems[2][0],
                                                        form.degree)) if not bad else 0.0
    return PairResult(first.name, second.name, not bad, form.method, good, bound,
                      time.perf_counter() - t0, mismatches, "reactions",
                      tuple(str(u) for u in names))


def _drop_zero_rows(m: EquationSet) -> EquationSet:
    keep = [i for i, e in enumerate(m.equations) if sp.expand(e) != 0]
    if len(keep) == len(m.equations):
        return m
    return EquationSet(m.name, m.coordinates, [m.equations[i] for i in keep], m.unknowns,
                       [m.labels[i] for i in keep])


def _accelerations(ref: EquationSet) -> dict:
    try:
        sol = ref.accelerations_solved()
    except ModelError:
        return {}
    return {q.func.__name__: sol[a] for q, a in zip(ref.coordinates, ref.accelerations)}


def recover_reactions(problem) -> dict:
    """Symbolic reactions ``{name: expression in q, q', t}`` from the direct model(s)."""
    out = {}
    for m in problem.models().values():
        if not m.unknowns or all(u.name in out for u in m.unknowns):
            continue
        m = problem.in_reference_coordinates(m)
        if not m.is_square:
            continue
        for u, expr in m.reactions_solved().items():
            out.setdefault(u.name, expr)
    return out
