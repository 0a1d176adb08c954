r"""Judging energies, Lagrangians and generalised forces against a problem's Lagrange model.

* ``T`` is compared with ``q'^T M q' / 2`` at the points (or, where the kinetic pieces are not
  of that form -- moving constraints -- by its Lagrange terms, identically in ``q''``).
* ``V`` is right up to a constant: its gradient must be the potential pieces (plus, optionally,
  the drives written as a time-dependent potential, and the steady loads the problem declares as
  generalised forces -- ``M g x`` in ``V`` or ``F`` in ``Q``, either way).
* ``L`` is right when ``d/dt dL/dq' - dL/dq = c (kinetic + potential pieces [+ drives])`` for
  every ``q, q', q''`` with ``c`` a nonzero constant (it may depend on the parameters), so
  ``c L + dF(q, t)/dt`` is right; ``c`` is found from an acceleration coefficient and checked
  to be the same at two states with the same parameters.
* ``Q_j`` is right when it is minus the sum of the pieces of a consistent choice of
  ingredients: every drive, any dampers (or leave them to a dissipation function), any
  conservative loads (or leave them to ``V``); the verdict says which choice it matched.

See :mod:`dualmech.grade.energies` for how ingredients are sorted.
"""
from __future__ import annotations

from itertools import combinations

import sympy as sp

from dualmech.grade.answers import Quantity
from dualmech.grade.context import GradingUnavailable, ProblemContext, off_motion, zero
from dualmech.grade.energies import LagrangeParts, euler_lagrange
from dualmech.grade.feedback import best_edit, concrete_state
from dualmech.grade.terms import term_table
from dualmech.grade.audit import dimension_issues, reduced
from dualmech.grade.notation import for_student, in_their_words
from dualmech.grade.formula import Formula
from dualmech.grade.roots import MAX_ROOTS
from dualmech.grade.judge import Deadline, Verdict, audited, factor_edit, method_for
from dualmech.grade.kinds import naming_energy
from dualmech.grade.result import DIMENSIONS_ONLY
from dualmech.grade.parser import AnswerError
from dualmech.model.dimensions import ENERGY

__all__ = ["judge_kinetic", "judge_potential", "judge_lagrangian", "judge_force"]

_MAX_SUBSETS = 512


def _exact(ctx, formulas) -> str:
    method = method_for(ctx, formulas)
    if method != "exact":
        raise GradingUnavailable("energies, Lagrangians and generalised forces with a root "
                                 "of a symbol, exp, log, other fractional powers or roots of "
                                 f"more than {MAX_ROOTS} different primes are not graded; "
                                 "write them with powers, sines and cosines (square roots of "
                                 "numbers, as sqrt(3)/2, are fine).")
    return method


def _check_symbols(ctx, f: Formula, quantity: Quantity, velocities: bool = True):
    bad = f.symbols & quantity.forbid
    if not velocities:
        bad |= f.symbols & {s.qd for s in ctx.states}
    if bad:
        shown = ", ".join(sorted(ctx.names.get(s, str(s)) for s in bad))
        raise AnswerError(f"{quantity.description} cannot contain {shown}.")
    if ctx.derived_formulas() and f.symbols & set(ctx.derived_formulas()):
        raise AnswerError(f"write {quantity.description} in the coordinates "
                          f"{', '.join(s.name for s in ctx.states)}.")


def _energy_dims(ctx, f: Formula) -> list:
    mine = in_their_words(ctx, f.text)
    return [mine(s) for s in audited(ctx, f.tree, ctx.dims, ctx.names, reduced(ENERGY))]


def _edits(ctx, f: Formula, target, deadline):
    """The smallest edit from ``f`` to ``target`` (one correct form, or a list of them: the
    conventions an energy may follow, the first preferred on a tie)."""
    targets = [x for x in (target if isinstance(target, list) else [target]) if x is not None]
    if not targets or f.expanded_size() > 400:
        return None
    deadline.check()
    rights = [_drop_constants(x, ctx) for x in targets]

    def tables(mode):
        tabs = [term_table(r, ctx, "the right answer", mode) for r in rights]
        return [tab for tab in tabs if tab is not None and tab.terms]
    expr = _drop_constants(f.sympy(), ctx)
    with naming_energy():   # the terms of an energy, named as such, kept apart as written
        parts = [p for p in (_as_written(w, ctx) for w in f.written_terms()) if p != 0]
        best = best_edit(expr, tables, ctx, scale=False, parts=parts)
        if best is not None and len(best.edits) <= 1:
            return best
        factor = factor_edit(expr, tables("trig"), ctx)
        if factor is not None and len(parts) == 1 and factor.edits[0].kind == "factor":
            return _one_coefficient(expr, factor, ctx)
        found = [d for d in (best, factor) if d is not None]
        return min(found, key=lambda d: len(d.edits)) if found else None


def _one_coefficient(expr, factor, ctx):
    """An energy written as one term, a constant times the right one: that term's
    coefficient is wrong (``m (R - r)^2 th'^2/2`` where ``3 m (R - r)^2 th'^2/4`` belongs),
    one edit -- not one per term of its expansion."""
    from dualmech.grade.feedback import Diagnosis
    from dualmech.grade.kinds import category
    from dualmech.grade.result import Edit
    from dualmech.grade.audit import display
    right = expr / factor.scale
    edit = Edit("coefficient", None, display(expr, ctx.names), display(right, ctx.names),
                category(expr, ctx))
    return Diagnosis(factor.label, 1, [edit], 1)


def _edits_any(ctx, f: Formula, forms: list, deadline):
    """The smallest edit to any of several correct forms."""
    if f.expanded_size() > 400:
        return None
    deadline.check()

    def tables(mode):
        out = []
        for form in forms:
            tab = term_table(sp.expand(form), ctx, "the right answer", mode)
            if tab is not None and tab.terms:
                out.append(tab)
        return out
    expr = f.sympy()
    return best_edit(expr, tables, ctx, scale=False) or factor_edit(expr, tables("trig"), ctx)


def _as_written(term, ctx):
    """A written term of an energy as written, unless it holds a constant (which never
    matters in ``V`` or ``L``): then without it, expanded."""
    dropped = _drop_constants(term, ctx)
    return term if sp.expand(term - dropped) == 0 else dropped


def _drop_constants(expr, ctx):
    states = {s.q for s in ctx.states} | {s.qd for s in ctx.states} | {sp.Symbol("t", real=True)}
    return sp.Add(*[a for a in sp.Add.make_args(sp.expand(expr)) if a.free_symbols & states])


def _wrong(ctx, f, truth, summary, dims, method, deadline, target=None, extra=()):
    d = _edits(ctx, f, target, deadline)
    details = list(extra)
    state = {}
    if d is not None:
        edits = for_student(ctx, d.edits, f.text)   # their names, rates and LaTeX
    else:
        edits = []
        if truth is not None:
            state, a, b = concrete_state(ctx, f, truth)
            details.append(f"no small edit explains it: at the state below the answer is "
                           f"{a:.6g}, the right value {b:.6g}")
    return Verdict("wrong", summary, details, edits, dims, state=state, method=method,
                   degree=f.degree)


# -- T ------------------------------------------------------------------------------------------
def judge_kinetic(ctx: ProblemContext, f: Formula, quantity: Quantity,
                  deadline: Deadline) -> Verdict:
    _check_symbols(ctx, f, quantity)
    parts = LagrangeParts.of(ctx)
    dims = _energy_dims(ctx, f)
    T = parts.kinetic_energy()
    if T is not None:
        ref = Formula.from_sympy(T)
        method = _exact(ctx, [f, ref])
        ok = all(zero(f.evaluate(e) - ref.evaluate(e), [ref.evaluate(e)])
                 for e in (p.env() for p in ctx.points(method)))
        if ok:
            return Verdict("wrong" if dims else "right", "the kinetic energy" +
                           (", but dimensionally inconsistent" if dims else ""),
                           dimension_issues=dims, method=method, degree=f.degree,
                           credit=DIMENSIONS_ONLY if dims else None)
        return _wrong(ctx, f, ref, "this is not the kinetic energy", dims, method, deadline, T)
    kin = parts.total(parts.keys("kinetic"))
    ok, method = _same_lagrange_terms(ctx, f, kin)
    if not ok:   # the edit is named against the problem's own T
        return _wrong(ctx, f, None, "its Lagrange terms differ from those of the kinetic "
                      "energy", dims, method, deadline, parts.declared_kinetic_energy())
    summary = ("its Lagrange terms are those of the kinetic energy (the problem's T has "
               "terms from moving constraints, so T is judged by its equations)")
    return Verdict("wrong" if dims else "right", summary, dimension_issues=dims, method=method,
                   degree=f.degree)


def _same_lagrange_terms(ctx, f, pieces) -> tuple[bool, str]:
    el = [Formula.from_sympy(e) for e in euler_lagrange(f.sympy(), ctx.states)]
    ref = [Formula.from_sympy(e) for e in pieces]
    method = _exact(ctx, el + ref)
    for p in ctx.points(method):
        env = off_motion(p, ctx)
        for a, b in zip(el, ref):
            if not zero(a.evaluate(env) - b.evaluate(env), [b.evaluate(env)]):
                return False, method
    return True, method


# -- V ------------------------------------------------------------------------------------------
def judge_potential(ctx: ProblemContext, f: Formula, quantity: Quantity,
                    deadline: Deadline) -> Verdict:
    _check_symbols(ctx, f, quantity, velocities=False)
    parts = LagrangeParts.of(ctx)
    dims = _energy_dims(ctx, f)
    grad = [Formula.from_sympy(sp.diff(f.sympy(), s.q)) for s in ctx.states]
    pot, drives = parts.keys("potential"), parts.keys("drive", "load")
    method = _exact(ctx, grad + [x for k in pot + drives for x in parts.formulas[k]])
    envs = [p.env() for p in ctx.points(method)]
    mine = [[g.evaluate(e) for g in grad] for e in envs]
    for chosen in _subsets(drives):
        deadline.check()
        keys = pot + list(chosen)
        if all(zero(mine[i][j] - sum((parts.formulas[k][j].evaluate(e) for k in keys), 0),
                    [mine[i][j]])
               for i, e in enumerate(envs) for j in range(len(ctx.states))):
            note = f" (with {', '.join(chosen)} as a potential)" if chosen else ""
            if dims:
                return Verdict("wrong", "the potential energy, but dimensionally inconsistent",
                               dimension_issues=dims, method=method, degree=f.degree,
                               credit=DIMENSIONS_ONLY)
            return Verdict("right", f"the potential energy, up to a constant{note}",
                           method=method, degree=f.degree)
    # diagnosed against each convention, the one the answer's symbols show first: a load or
    # drive counted in V when the student wrote its parameters, left out when not
    used = {k: bool(_own_parameters(parts, k, pot, ctx) & f.symbols) for k in drives}
    chosen = sorted(_subsets(drives), key=lambda c: sum((k in c) != used[k] for k in drives))
    forms = [parts.potential(pot + list(c)) for c in chosen[:8]]
    return _wrong(ctx, f, None, "this is not the potential energy: its gradient differs",
                  dims, method, deadline, forms)


def _parameters(parts, key, ctx) -> set:
    """The parameters in the pieces of the ingredient ``key``."""
    free = set().union(*(sp.sympify(v).free_symbols for v in parts.pieces[key]))
    return free & set(ctx.parameters)


def _own_parameters(parts, key, others, ctx) -> set:
    """The parameters of ``key`` that the ingredients ``others`` do not have (``mu`` of a
    friction ``-mu m g cos(alpha)`` beside gravity's ``m g sin(alpha)``): what shows that an
    answer counts ``key``; all of its parameters when it has none of its own."""
    mine = _parameters(parts, key, ctx)
    shared = set().union(*(_parameters(parts, k, ctx) for k in others)) if others else set()
    return (mine - shared) or mine


def _subsets(keys):
    n = 0
    for r in range(len(keys) + 1):
        for c in combinations(keys, r):
            n += 1
            if n > _MAX_SUBSETS:
                return
            yield c


# -- L ------------------------------------------------------------------------------------------
def judge_lagrangian(ctx: ProblemContext, f: Formula, quantity: Quantity,
                     deadline: Deadline) -> Verdict:
    _check_symbols(ctx, f, quantity)
    parts = LagrangeParts.of(ctx)
    dims = _energy_dims(ctx, f)
    el = [Formula.from_sympy(e) for e in euler_lagrange(f.sympy(), ctx.states)]
    kin, pot, drives = (parts.keys("kinetic"), parts.keys("potential"),
                        parts.keys("drive", "load"))
    pieces = [x for k in kin + pot + drives for x in parts.formulas[k]]
    method = _exact(ctx, el + pieces)
    points = ctx.points(method)
    n = len(ctx.states)
    rows = []  # per point: (mine, core, {drive: values}, c)
    for p in points:
        deadline.check()
        env = off_motion(p, ctx)
        mine = [g.evaluate(env) for g in el]
        core = [sum((parts.formulas[k][j].evaluate(env) for k in kin + pot), 0) for j in range(n)]
        dv = {k: [parts.formulas[k][j].evaluate(env) for j in range(n)] for k in drives}
        c = _factor(ctx, p, el, kin, parts)
        rows.append((mine, core, dv, c))
    if any(r[3] is None for r in rows):
        return _lagrangian_wrong(ctx, f, parts, dims, method, deadline,
                                 "this Lagrangian gives no accelerations (it has no kinetic "
                                 "energy, or the wrong one)")
    same_c = all(zero(rows[a][3] - rows[b][3], [rows[a][3]])
                 for a in range(len(points)) for b in range(a + 1, len(points))
                 if points[a].group == points[b].group)
    if same_c:
        for chosen in _subsets(drives):
            if all(zero(m[j] - c * (core[j] + sum((dv[k][j] for k in chosen), 0)), [m[j]])
                   for m, core, dv, c in rows for j in range(n)):
                note = f" (with {', '.join(chosen)} in L as a potential)" if chosen else ""
                if dims:
                    return Verdict("wrong", "the Lagrangian gives the right equations but is "
                                   "dimensionally inconsistent", dimension_issues=dims,
                                   method=method, degree=f.degree, credit=DIMENSIONS_ONLY)
                return Verdict("right", f"the Lagrangian: it gives the same Lagrange "
                               f"equations{note}", method=method, degree=f.degree)
    return _lagrangian_wrong(ctx, f, parts, dims, method, deadline,
                             "this Lagrangian gives different equations of motion")


def _factor(ctx, point, el, kin, parts):
    """``c`` with ``EL(L) = c EL(L_ref)``, from the first acceleration coefficient (or None)."""
    base = off_motion(point, ctx)
    n = len(ctx.states)
    for k, s in enumerate(ctx.states):
        bumped = off_motion(point, ctx, {s.qdd: base.values[s.qdd] + 1})
        for j in range(n):
            ref = sum((parts.formulas[key][j].evaluate(bumped) -
                       parts.formulas[key][j].evaluate(base) for key in kin), 0)
            if not zero(ref, [1]):
                mine = el[j].evaluate(bumped) - el[j].evaluate(base)
                return None if zero(mine, [ref]) else mine / ref
    return None


def _lagrangian_wrong(ctx, f, parts, dims, method, deadline, summary):
    T, V = parts.kinetic_energy() or parts.declared_kinetic_energy(), parts.potential_energy()
    target = (T - V) if T is not None and V is not None else None
    return _wrong(ctx, f, None, summary, dims, method, deadline, target,
                  extra=[] if target is not None else
                  ["(the problem's kinetic or potential energy could not be written out, so "
                   "no term-by-term edit is given)"])


# -- Q ------------------------------------------------------------------------------------------
def judge_force(ctx: ProblemContext, comps: list, quantity: Quantity,
                deadline: Deadline) -> Verdict:
    """``comps``: the answer's generalised forces (one, for ``Q_q``; all, for ``Q``)."""
    for f in comps:
        _check_symbols(ctx, f, quantity)
    parts = LagrangeParts.of(ctx)
    js = [quantity.coordinate] if quantity.coordinate is not None else list(range(len(ctx.states)))
    if len(comps) != len(js):
        raise AnswerError(f"{quantity.name} has {len(js)} component{'s' if len(js) > 1 else ''}"
                          f"; the answer has {len(comps)} (write Q as "
                          f"[{', '.join('Q_' + ctx.states[j].name for j in js)}]).")
    dims = []
    for f, j in zip(comps, js):
        expected = reduced(ENERGY)
        expected = tuple(sorted(_sub(expected, ctx.dims[ctx.states[j].q]).items()))
        dims += map(in_their_words(ctx, f.text),
                    audited(ctx, f.tree, ctx.dims, ctx.names, expected))
    drives, optional = parts.keys("drive"), parts.keys("velocity", "potential", "load")
    method = _exact(ctx, comps + [x for k in drives + optional for x in parts.formulas[k]])
    envs = [p.env() for p in ctx.points(method)]
    mine = [[f.evaluate(e) for f in comps] for e in envs]
    vals = {k: [[parts.formulas[k][j].evaluate(e) for j in js] for e in envs]
            for k in drives + optional}
    for chosen in _subsets(optional):
        deadline.check()
        keys = drives + list(chosen)
        if all(zero(mine[i][a] + sum((vals[k][i][a] for k in keys), 0), [mine[i][a]])
               for i in range(len(envs)) for a in range(len(js))):
            left = [k for k in optional if k not in chosen]
            note = f"; counted here: {', '.join(keys) or 'nothing'}" + (
                f"; left to V or R: {', '.join(left)}" if left else "")
            if dims:
                return Verdict("wrong", "the generalised force, but dimensionally inconsistent",
                               dimension_issues=dims, method=method, degree=comps[0].degree,
                               credit=DIMENSIONS_ONLY)
            return Verdict("right", f"{quantity.description}{note}", method=method,
                           degree=max(c.degree for c in comps))
    # the declared loads (a push F(t), a steady weight) are counted in Q by the problem's own
    # Lagrange model, so a wrong factor on one is named against them first
    loads = parts.keys("load")
    conventions = [drives + loads, drives + loads + parts.keys("velocity")] if loads else []
    conventions += [drives, drives + parts.keys("velocity")]
    edits, details = [], []
    for a, (f, j) in enumerate(zip(comps, js)):
        forms = [-sp.Add(*[parts.pieces[k][j] for k in keys]) for keys in conventions]
        d = _edits_any(ctx, f, forms, deadline)
        if d is not None:
            edits += [e.__class__(e.kind, a if len(js) > 1 else None, e.term, e.correct,
                                  e.category, e.detail, "component")
                      for e in for_student(ctx, d.edits, f.text)]
    if not edits:
        details.append("compared with the generalised forces of the drives "
                       f"({', '.join(drives) or 'none'}), with and without the dampers; "
                       "conservative loads may be counted in V instead")
    return Verdict("wrong", f"{quantity.description}: not the virtual work of the loads",
                   details, edits, dims, method=method, degree=max(c.degree for c in comps))


def _sub(a, b) -> dict:
    out = dict(a)
    for name, e in b:
        out[name] = out.get(name, 0) - e
    return {k: v for k, v in out.items() if v != 0}
