"""Checking a source's printed answers against the verified derivations.

A printed answer is transcribed as a :class:`dualmech.problem.Published` entry.  An
*equation* is right when it follows from the equations of motion -- any combination of them is
accepted -- so it must vanish on the motion: at random rational points ``(parameters, t, q,
q')`` the accelerations come from the reference model and the reactions from the direct
model(s), and the printed left side must evaluate to exactly zero.  An *expression* (a reaction,
a momentum, an inertia) must equal our own derivation at every such point.  A wrong answer is
explained: the derived equation it most resembles and what is left over, its value on the
motion, and any dimensional inconsistency.
"""
from __future__ import annotations

import random
from dataclasses import dataclass

import mpmath
import sympy as sp

from ._expr import as_expr
from .compare import (METHOD_NAMES, _MAX_ATTEMPTS, _Context, _fit_reactions, _flatten,
                      _high_precision, _plain_system, _regular_points)
from .dimensions import audit
from .equations import ModelError, _tidy, to_plain
from .exact import ExactForm, is_zero
from .kinematics import t

__all__ = ["PublishedVerdict", "check_published", "closest_equation"]


@dataclass
class PublishedVerdict:
    """Verdict on one printed answer of the source."""

    label: str
    where: str
    verdict: str
    detail: str
    method: str

    def to_dict(self) -> dict:
        return {"label": self.label, "where": self.where, "verdict": self.verdict,
                "detail": self.detail, "method": METHOD_NAMES.get(self.method, self.method)}



@_high_precision
def check_published(problem, points: int = 8, seed: int = 0,
                    context: _Context | None = None) -> list[PublishedVerdict]:
    """Verdict on every printed answer of ``problem`` (see :class:`dualmech.problem.Published`)."""
    pubs = problem.published()
    if not pubs:
        return []
    models = problem.models()
    ref = models[problem.reference]
    coords = ref.coordinates
    ctx = context or _Context(coords, problem.parameter_symbols, problem)
    directs = [problem.in_reference_coordinates(m) for m in models.values() if m.unknowns]
    unknowns = []
    for m in directs:
        unknowns += [u for u in m.unknowns if u not in unknowns]
    Ar, br = _plain_system(ref, coords)
    systems = [_plain_system(m, coords) for m in directs]
    items = []  # (pub, [plain expressions])
    for pub in pubs:
        items.append((pub, [to_plain(e, coords) for e in _published_exprs(problem, pub)]))
    exprs = _flatten(Ar, br)
    for A, b in systems:
        exprs += _flatten(A, b)
    sizes = [len(e) for _, e in items]
    for _, es in items:
        exprs += es
    symbols = ctx.base + ctx.qdd + tuple(unknowns)
    form = ExactForm.build(exprs, symbols)
    rng = random.Random(seed + 1)
    bad: dict = {}
    good = 0
    n = len(coords)
    zero = 0 if form.method == "exact" else mpmath.mpf(0)
    fill = {s: zero for s in ctx.qdd + tuple(unknowns)}   # not yet known: first pass
    off = sum(len(A) * (len(A[0]) + 1) for A, _ in [(Ar, br)] + systems)
    for point, _, parts, x in _regular_points(form, ctx, rng, [(Ar, br)] + systems,
                                              _MAX_ATTEMPTS * points, fill):
        for s, v in zip(ctx.qdd, x[:n]):
            point[s] = v
        for (Av, bv), m in zip(parts[1:], directs):
            lam = _fit_reactions(Av, bv, x[:n], n)[1]
            for u, v in zip(m.unknowns, lam):
                point[u] = v
        try:
            vals = form.evaluate(point)
        except (ZeroDivisionError, ValueError):
            continue
        good += 1
        pos = off
        for (pub, _), size in zip(items, sizes):
            for j, v in enumerate(vals[pos:pos + size]):
                if not is_zero(v, 1):
                    bad.setdefault(pub.label, set()).add(j)
            pos += size
        if good == points:
            break
    verdicts = []
    dims = problem.dimensions()
    for pub, es in items:
        if pub.label not in bad:
            verdicts.append(PublishedVerdict(pub.label, pub.where, "correct",
                                             f"holds at {good} points", form.method))
            continue
        details = []
        for j in sorted(bad[pub.label]):
            details.append(_published_detail(problem, pub, j, dims))
        verdicts.append(PublishedVerdict(pub.label, pub.where, "wrong", "\n".join(details),
                                         form.method))
    return verdicts


def _published_exprs(problem, pub) -> list:
    """Printed (equation kind) or printed - reference (expression kind), in reference coordinates."""
    if pub.kind == "equation":
        exprs = list(pub.printed)
    else:
        exprs = [p - r for p, r in zip(pub.printed, pub.reference)]
    if pub.coordinates and pub.coordinates != problem.reference:
        mapping = problem.coordinate_maps().get(pub.coordinates)
        if mapping is None:
            raise ModelError(f"published `{pub.label}` uses the coordinates of "
                             f"`{pub.coordinates}`, which has no entry in coordinate_maps().")
        rules = {}
        for q, e in mapping.items():
            rules[q.diff(t, 2)] = as_expr(e).diff(t, 2)
            rules[q.diff(t)] = as_expr(e).diff(t)
        exprs = [e.xreplace(rules).xreplace(dict(mapping)) for e in exprs]
    return exprs


def _published_detail(problem, pub, j, dims) -> str:
    """Say what is wrong with component ``j`` of a printed answer."""
    what = f"equation {j + 1}" if pub.kind == "equation" else f"component {j + 1}"
    if len(pub.printed) == 1:
        what = "the printed answer"
    lines = []
    issues = audit(pub.printed[j], dims) if pub.kind == "equation" else \
        audit(pub.printed[j] - pub.reference[j], dims)
    if issues:
        lines.append(f"{what} is dimensionally inconsistent: " + "; ".join(map(str, issues)))
    expr = _published_exprs(problem, pub)[j]
    if pub.kind == "equation":
        ref = problem.model(problem.reference)
        near = closest_equation(expr, ref.equations, ref.labels, problem.parameter_symbols)
        if near is not None:
            label, alpha, rest = near
            lines.append(f"{what} is closest to ({alpha}) x [{problem.reference}: {label}]; "
                         f"printed minus that = {rest}")
    diff = _on_shell(problem, expr)
    if diff is not None and (not lines or len(str(diff)) < 160):
        if pub.kind == "equation":
            lines.append(f"{what} does not follow from the equations of motion: on the "
                         f"motion its left side equals {diff}, not 0")
        else:
            lines.append(f"{what}: printed minus derived = {diff}")
    elif not lines:
        lines.append(f"{what} differs from the derivation")
    return "; ".join(lines)


def closest_equation(expr, equations, labels, parameters, max_terms: int = 40):
    """The derived equation that ``expr`` most resembles, up to a constant factor.

    Tries every ratio ``alpha`` of a term of ``expr`` to a term of a derived equation (ratios
    free of the state) and keeps the smallest ``expr - alpha * equation``.  Returns
    ``(label, alpha, remainder)`` or ``None`` when nothing matches or the input is large.
    """
    E = sp.expand(expr)
    terms_e = sp.Add.make_args(E)
    if len(terms_e) > max_terms:
        return None
    allowed = set(parameters)
    best = None
    for label, R in zip(labels, equations):
        R = sp.expand(R)
        terms_r = sp.Add.make_args(R)
        if len(terms_r) > max_terms:
            continue
        ratios = []
        for a in terms_e:
            for b in terms_r:
                r = sp.cancel(a / b)
                if r.free_symbols <= allowed and r not in ratios and r != 0:
                    ratios.append(r)
        for alpha in ratios[:60]:
            rest = sp.expand(E - alpha * R)
            size = len(sp.Add.make_args(rest)) if rest != 0 else 0
            if best is None or size < best[0]:
                best = (size, label, alpha, rest)
    if best is None or best[0] >= len(terms_e):
        return None
    return best[1], best[2], sp.factor_terms(best[3])


def _on_shell(problem, expr):
    """``expr`` with accelerations and reactions replaced by their solved forms, simplified."""
    ref = problem.model(problem.reference)
    rules = {}
    try:
        rules.update(ref.accelerations_solved())
    except ModelError:
        return None
    for m in problem.models().values():
        m = problem.in_reference_coordinates(m) if m.unknowns else m
        if m.unknowns and m.is_square:
            for u, v in m.reactions_solved().items():
                rules.setdefault(u, v)
    expr = as_expr(expr).xreplace(rules)
    if sp.count_ops(expr) > 2000:
        return None
    return _tidy(expr)
