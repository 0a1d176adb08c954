"""Explaining a disagreement: which equation of the faulty derivation, which term, how much.

The verdict (:mod:`dualmech.verify.verdicts`) gives a certain counter-example point.  Here the
faulty model's equations are evaluated there with the accelerations of the models it is checked
against (and its own best-fitting reactions): an equation that does not hold is wrong.  For a
person, each wrong equation is then shown term by term at a real state inside the working
ranges, and -- lazily, within a display budget -- as a symbolic residual.  A derivation
written in other coordinates than the reference is shown in its own (state, terms, residual),
through the problem's coordinate map (:mod:`dualmech.verify.coordinates`).
"""
from __future__ import annotations

import math
import random

import mpmath
import sympy as sp

from dualmech.model.equations import from_plain
from dualmech.exact.form import is_zero
from dualmech.model.kinematics import t
from dualmech.exact import linalg as la
from dualmech.exact.mp_program import mp_function
from dualmech.verify.coordinates import OwnCoordinates
from dualmech.verify.display import Budget, OverBudget, dotted, solve_display, tidy
from dualmech.verify.sampling import Context, System, solve_model

__all__ = ["Mismatch", "explain_model", "explain_reaction", "residuals_at"]

_MAX_TERMS = 40


class Mismatch:
    """Why one equation (or a whole derivation) is wrong; ``str()`` is the readable form
    (:meth:`text` in textbook notation).

    ``residual`` (the symbolic residual after the best combination) is computed when first
    read, within the display budget; ``value``, ``state`` and ``terms`` show the equation at a
    real state, term by term.  ``residual`` and ``terms`` are plain text (``theta'**2``, what
    JSON carries); the expressions themselves stay behind them for :meth:`text`.
    """

    def __init__(self, model: str, equation: str, reason: str, residual=None,
                 value: float = math.nan, state: dict | None = None, terms: list | None = None):
        self.model, self.equation, self.reason = model, equation, reason
        self._residual = residual
        self.value = value
        self.state = dict(state or {})
        self._terms = list(terms or [])
        #: +1, or -1 for a row written "applied minus mass times acceleration" (the text
        #: shows every row as "mass times acceleration minus applied = 0"); the data
        #: (value, terms, residual) stay as the model wrote the row
        self.sign = 1
        #: the terms as :meth:`text` shows them: each ingredient simplified (None: terms)
        self.shown_terms: list | None = None
        #: whether the state lies outside the declared working ranges
        self.outside = False

    def _resolved(self):
        """The residual: an expression, a text saying why there is none, or ``""``."""
        if callable(self._residual):
            try:
                self._residual = self._residual()
            except OverBudget as exc:
                self._residual = f"(not simplified: {exc}; see the values below)"
            except Exception as exc:  # noqa: BLE001 - display must never break a verdict
                self._residual = (f"(not solved symbolically: {type(exc).__name__}; see the "
                                  "values below)")
        return self._residual if self._residual is not None else ""

    @property
    def residual(self) -> str:
        r = self._resolved()
        return r if isinstance(r, str) else dotted(r)

    @property
    def terms(self) -> list:
        """``[(term as plain text, value)]`` of the equation at :attr:`state`."""
        return [(x if isinstance(x, str) else dotted(x), v) for x, v in self._terms]

    def __str__(self) -> str:
        return self.text()

    def text(self, notation: str = "dots") -> str:
        """The readable form in textbook notation: ``θ̈``, powers as ``^`` (``θ′′`` with
        ``notation="primes"``)."""
        from dualmech.model.notation import plain, symbol_text
        from dualmech.verify.display import wrap
        k = self.sign
        show = lambda x: x if isinstance(x, str) else plain(k * x, notation)  # noqa: E731
        lines = [f"{self.model} [{self.equation}]: {self.reason}"]
        if k == -1:
            lines.append("    (row shown with its sign reversed to read: mass times "
                         "acceleration minus applied = 0)")
        residual = self._resolved()
        if isinstance(residual, str) and residual.startswith("("):   # why there is none
            lines += ["    residual after the best combination:", f"      {residual}"]
        elif not isinstance(residual, str) or residual:
            lines.append(f"    residual after the best combination: {show(residual)}")
        if self.state:
            moving = [n for n in self.state if n == "t" or n.endswith("'")
                      or n + "'" in self.state]
            fixed = [n for n in self.state if n not in moving]
            if fixed and moving:
                lines.append("    with " + ", ".join(
                    f"{_state_name(n, notation, symbol_text)}={self.state[n]:.6g}"
                    for n in fixed))
            st = ", ".join(f"{_state_name(n, notation, symbol_text)}={self.state[n]:.6g}"
                           for n in (moving or fixed))
            where = " (outside the declared ranges)" if self.outside else ""
            lines.append(f"    at {st}{where}: residual {k * self.value:.6g}")
        terms = self.shown_terms if self.shown_terms is not None else self._terms
        for term, value in terms:
            lines.append(f"      {k * value:+.6g}  {show(term)}")
        from dualmech.verify.display import width
        return "\n".join(wrap(line, width() - 4, "    ") for line in lines)

    def to_dict(self) -> dict:
        return {"model": self.model, "equation": self.equation, "reason": self.reason,
                "residual": self.residual, "value": _json_float(self.value),
                "state": {k: _json_float(v) for k, v in self.state.items()},
                "terms": [[s, _json_float(v)] for s, v in self.terms]}


def _state_name(name: str, notation: str, symbol_text) -> str:
    """``theta''`` (a state's plain name) as the textbook writes it: ``θ̈``."""
    base = name.rstrip("'")
    if not base or not base.isidentifier():
        return name
    return symbol_text(base, len(name) - len(base), notation)


def _json_float(x):
    try:
        x = float(x)
    except (TypeError, ValueError):
        return None
    return None if math.isnan(x) or math.isinf(x) else x


def residuals_at(A: list, b: list, qdd: list, n: int) -> tuple[list, list]:
    """Residual of each equation with accelerations ``qdd`` and the best-fitting reactions."""
    M = [row[:n] for row in A]
    B = [row[n:] for row in A]
    r = [bi - mi for bi, mi in zip(b, la.matvec(M, qdd))]
    res, lam, _ = la.residual_after_least_squares(B, r)
    return res, lam


def explain_model(name: str, judgement, against: tuple, ctx: Context,
                  seed: int = 0, limits: Budget | None = None,
                  problem=None) -> list[Mismatch]:
    """Mismatches of model ``name``: its equations that fail with the others' accelerations.

    A model that ``problem`` (default: ``ctx.problem``, when the context keeps one) declares
    in other coordinates than the reference is explained in its own: state, terms and
    residual through the declared coordinate map (:mod:`dualmech.verify.coordinates`).
    """
    model = judgement.models[name]
    sols = judgement.solutions
    fault = [f for f in judgement.faults if f.model == name]
    if fault and fault[0].kind != "differs":
        return [Mismatch(name, "all", fault[0].detail)]
    ref = next((a for a in against if a in sols and sols[a].status == "ok"), None)
    if ref is None:
        return [Mismatch(name, "all", "differs from the other derivations")]
    n = len(model.coordinates)
    A, b = judgement.parts[name]
    with mpmath.workdps(40):
        res, _ = residuals_at(A, b, sols[ref].qdd, n)
        scale = max((abs(v) for v in b), default=1)
        wrong = [i for i, v in enumerate(res) if not is_zero(v, scale)]
    if not wrong:
        return [Mismatch(name, "all", f"its accelerations differ from those of `{ref}`")]
    real = _real_states(judgement, name, ref, ctx, seed)
    reference_model = judgement.models[ref]
    problem = problem if problem is not None else getattr(ctx, "problem", None)
    own = OwnCoordinates.of(problem, name, model)
    reason = f"does not hold with the accelerations of `{ref}`"
    out = []
    for i in wrong:
        values = _best(real, i)
        mm = _in_own_coordinates(name, own, model, i, values, reference_model, ctx, limits)
        if isinstance(mm, Mismatch):
            mm.reason = reason
            out.append(mm)
            continue
        note = f" (shown in the reference coordinates, not in {own.names}: {mm})" if mm else ""
        value, terms, state = _terms(model, i, values, _shown(ctx.base, ctx))
        mm = Mismatch(
            name, model.labels[i], reason + note,
            residual=lambda i=i: _symbolic_residual(model, reference_model, i, limits),
            value=value, state=state, terms=terms)
        _readable(mm, model, i, values, real)
        out.append(mm)
    return out


def _readable(mm: Mismatch, model, i: int, values, real) -> None:
    """The display side of a row's mismatch: its sign convention, its ingredients each
    simplified, whether its state is outside the working ranges."""
    if values is None:
        return
    mm.outside = any(v is values and not inside for v, _, inside in real)
    mm.sign = _row_sign(model, i, values)
    mm.shown_terms = _ingredient_terms(model, i, values)


def _row_sign(model, i: int, values) -> int:
    """-1 for a row written "applied minus mass times acceleration" (a balance ``sum F -
    m a``), +1 for "mass times acceleration minus applied" (Lagrange's rows): decided by the
    sign of the row's largest acceleration coefficient at the state."""
    label = model.labels[i]
    if label.startswith("Lagrange, "):
        return 1
    if label.startswith("sum F") or label.startswith("sum tau"):
        return -1
    A, _ = model.plain_matrix()
    n = len(model.coordinates)
    subs = {k: sp.Float(str(v), 30) for k, v in values.items()}
    try:
        coeffs = [float(A[i, j].xreplace(subs).evalf(30)) for j in range(n)]
    except (TypeError, ValueError):
        return 1
    big = max(coeffs, key=abs, default=0.0)
    return -1 if big < 0 else 1


def _ingredient_terms(model, i: int, values) -> list | None:
    """``[(term, value)]`` of row ``i``: each ingredient (a load, an inertia, a potential)
    simplified as a teacher writes it (``sin^2 + cos^2 = 1`` applied) and split into its
    terms; ``None`` when the model keeps no ingredients."""
    if not model.contributions or i >= len(model.contributions):
        return None
    coords = model.coordinates
    subs = {k: sp.Float(str(v), 30) for k, v in values.items()}
    out = []
    try:
        for part in model.contributions[i].values():
            plain = model.to_plain(part)
            if plain == 0:
                continue
            try:
                short = tidy(plain)
            except OverBudget:
                short = plain
            short = sp.expand(short) if not isinstance(short, sp.Mul) and \
                len(sp.Add.make_args(sp.expand(short))) <= 6 else short
            for term in sp.Add.make_args(short):
                value = float(term.xreplace(subs).evalf(30))
                out.append((from_plain(term, coords), value))
    except (TypeError, ValueError, ZeroDivisionError):
        return None
    return out if len(out) <= _MAX_TERMS else None


def _in_own_coordinates(name, own, model, i, values, reference, ctx, limits):
    """Row ``i`` of ``model`` (in the reference coordinates) explained in the own coordinates
    of ``own``: a :class:`Mismatch`, or why not (a short text), or ``None`` for a model
    written in the reference coordinates."""
    if own is None:
        return None
    row = own.row(model, i)
    if row is None:
        return "its rows could not be matched to the rows as written"
    try:
        at = own.state(values) if values is not None else None
    except (TypeError, ValueError, ZeroDivisionError, KeyError):
        return "the coordinate map could not be evaluated at the state"
    shown = [k for k in ctx.base if k in ctx.parameters or k == t]
    shown += [s.q for s in own.own_states] + [s.qd for s in own.own_states]
    shown += [sym for s in own.uncovered for sym in (s.q, s.qd)]
    value, terms, state = _terms(own.model, row, at, _shown(shown, ctx, own))
    return Mismatch(name, own.model.labels[row], "",
                    residual=lambda: _own_residual(own, row, reference, values, limits),
                    value=value, state=state, terms=terms)


def _shown(symbols, ctx, own=None) -> list:
    """``(name, symbol)`` of the state symbols to show (own coordinates' names first)."""
    names = {}
    if own is not None:
        for s in own.own_states:
            names.update({s.q: s.name, s.qd: s.name + "'", s.qdd: s.name + "''"})
    return [(names.get(k) or ctx.name_of(k), k) for k in symbols]


def _real_states(judgement, name, ref, ctx: Context, seed: int, want: int = 8) -> list:
    """Real states where ``ref`` is regular, with the residual of each equation of ``name``
    there: ``[(values, residuals)]``.  Half inside the working ranges, half with the state in
    wider ones (angles over a full turn, the rest three times as wide), so that an
    equation wrong only outside the working range is still shown where it is wrong.
    Parameters always stay inside their declared ranges."""
    models = judgement.models
    coords = models[ref].coordinates
    systems = [System.of(models[ref], coords), System.of(models[name], coords)]
    exprs = systems[0].flat() + systems[1].flat()
    fn = mp_function(ctx.base, exprs)
    rng = random.Random(seed + 7)
    n = len(coords)
    trig = set()
    for e in exprs:
        for f in e.atoms(sp.sin, sp.cos, sp.tan):
            trig |= f.free_symbols
    angles = {s.q for s in ctx.states if s.q in trig}   # coordinates inside sin/cos
    out = []
    with mpmath.workdps(30):
        for attempt in range(6 * want):
            wide = len(out) >= want // 2 or attempt >= 3 * want
            point = {}
            for s in ctx.base:
                lo, hi = ctx.floats.get(s, (0.5, 2.0))
                if wide and s not in ctx.parameters:   # parameters stay physical
                    mid, half = (lo + hi) / 2, 1.5 * (hi - lo)
                    lo, hi = (-3.14, 3.14) if s in angles else (mid - half, mid + half)
                    if s == t:
                        lo = max(lo, 0.0)               # time runs forward
                point[s] = mpmath.mpf(rng.uniform(lo, hi))
            try:
                vals = fn(*[point[s] for s in ctx.base])
            except (ZeroDivisionError, ValueError, TypeError):
                continue
            Ar, br = systems[0].unflatten(vals)
            sol = solve_model(Ar, br, n, models[ref].unknowns)
            if sol.status != "ok":
                continue
            Ac, bc = systems[1].unflatten(vals[systems[0].size:])
            res, lam = residuals_at(Ac, bc, sol.qdd, n)
            scale = 1 + max((abs(v) for v in bc), default=0)
            values = dict(point)
            values.update({s: v for s, v in zip(ctx.qdd, sol.qdd)})
            values.update({u: v for u, v in zip(models[name].unknowns, lam)})
            out.append((values, [abs(r) / scale for r in res], not wide))
            if len(out) == want:
                break
    return out


def _best(states: list, i: int):
    """The state where equation ``i`` is most visibly wrong (``None`` without states):
    inside the working ranges whenever one there shows it."""
    if not states:
        return None
    inside = [s for s in states if s[2]]
    if inside:
        top = max(inside, key=lambda vr: vr[1][i])
        if top[1][i] > 1e-12:
            return top[0]
    return max(states, key=lambda vr: vr[1][i])[0]


def _terms(model, i, values, shown):
    """Equation ``i`` of ``model`` at ``values``, term by term; ``shown`` the
    ``(name, symbol)`` of the state to print."""
    if values is None:
        return math.nan, [], {}
    coords = model.coordinates
    eq = model.to_plain(model.equations[i])
    state = {name: float(values[k]) for name, k in shown if k in values}
    subs = {k: sp.Float(str(v), 30) for k, v in values.items()}
    terms = []
    try:
        expanded = sp.expand(eq) if sp.count_ops(eq) < 400 else eq
        parts = sp.Add.make_args(expanded)
        if len(parts) <= _MAX_TERMS:
            for term in parts:
                terms.append((from_plain(term, coords),
                              float(term.xreplace(subs).evalf(30))))
        total = float(eq.xreplace(subs).evalf(30))
    except (TypeError, ValueError, ZeroDivisionError):
        return math.nan, [], state
    return total, terms, state


def _symbolic_residual(candidate, reference, i, limits):
    """Equation ``i`` of ``candidate`` on the motion of ``reference`` (display only)."""
    eq = candidate.equations[i]
    if any(eq.has(u) for u in candidate.unknowns):
        return ""   # its reactions are fitted numerically; the values below show the residual
    sol = solve_display(reference, limits)
    rules = {}
    rules.update({a: sol[a] for a in reference.accelerations})
    return tidy(eq.xreplace(rules), limits)


def _own_residual(own, row, reference, values, limits):
    """Own equation ``row`` on the motion of ``reference``, in the own coordinates
    (display only); says so when the coordinate map is not inverted within the budget."""
    eq = own.model.equations[row]
    if any(eq.has(u) for u in own.model.unknowns):
        return ""   # its reactions are fitted numerically; the values below show the residual
    inverse = own.inverse(values, limits) if values is not None else None
    if inverse is None:
        return (f"(not written in {own.names}: the coordinate map was not inverted within "
                "the display budget; see the values below)")
    sol = solve_display(reference, limits)
    accelerations = {a: sol[a] for a in reference.accelerations}
    return tidy(own.residual(row, accelerations, inverse), limits)


def explain_reaction(reaction: str, suspect: str, against: tuple, judgement, ctx: Context,
                     seed: int = 0, limits: Budget | None = None) -> Mismatch:
    """Why reaction ``reaction`` of model ``suspect`` differs from the value of ``against``.

    At a real state inside the working ranges (where both models determine the motion and
    the two values differ) both values are shown; the suspect's equations are then evaluated
    with the other model's reactions and the common accelerations: the equation that no
    longer holds is shown term by term, and (lazily, within the display budget) as a symbolic
    residual -- the term by which the two derivations differ.

    >>> import sympy as sp
    >>> from dualmech import coordinate, t, EquationSet
    >>> from dualmech.verify.verdicts import judge
    >>> x = coordinate("x"); m, g = sp.symbols("m g", positive=True)
    >>> N = sp.Symbol("N", real=True)
    >>> a = EquationSet("a", (x,), (m*x.diff(t, 2), N - m*g), (N,), ("along x", "up"))
    >>> b = EquationSet("b", (x,), (m*x.diff(t, 2), N - 2*m*g), (N,), ("along x", "up"))
    >>> ctx = Context.for_models(a, b)
    >>> mm = explain_reaction("N", "b", ("a",), judge({"a": a, "b": b}, context=ctx), ctx)
    >>> mm.equation, [term for term, _ in mm.terms], mm.residual
    ('reaction N', ['N', '-2*g*m'], '-g*m')
    """
    models = judgement.models
    label = f"reaction {reaction}"
    holds = lambda nm: any(u.name == reaction for u in models[nm].unknowns)  # noqa: E731
    other = next((a for a in against if a in models and holds(a)), None)
    if other is None or not holds(suspect):
        return Mismatch(suspect, label, f"{reaction} differs from the other derivations")
    coords = models[other].coordinates
    n = len(coords)
    systems = [System.of(models[other], coords), System.of(models[suspect], coords)]
    fn = mp_function(ctx.base, systems[0].flat() + systems[1].flat())
    rng = random.Random(seed + 11)
    found = None
    with mpmath.workdps(30):
        for _ in range(64):
            point = {s: mpmath.mpf(rng.uniform(*ctx.floats.get(s, (0.5, 2.0))))
                     for s in ctx.base}
            try:
                vals = fn(*[point[s] for s in ctx.base])
            except (ZeroDivisionError, ValueError, TypeError):
                continue
            A1, b1 = systems[0].unflatten(vals[:systems[0].size])
            A2, b2 = systems[1].unflatten(vals[systems[0].size:])
            s1 = solve_model(A1, b1, n, models[other].unknowns)
            s2 = solve_model(A2, b2, n, models[suspect].unknowns)
            if s1.status != "ok" or s2.status != "ok":
                continue
            v1 = next((v for u, v in s1.lam.items() if str(u) == reaction), None)
            v2 = next((v for u, v in s2.lam.items() if str(u) == reaction), None)
            if v1 is None or v2 is None or is_zero(v1 - v2, 1 + abs(v1)):
                continue
            found = (point, s1, s2, v1, v2, A2, b2)
            break
        if found is None:
            return Mismatch(suspect, label, f"{reaction} differs from the value `{other}` "
                            "gives (no real state in the working ranges shows it)")
        point, s1, s2, v1, v2, A2, b2 = found
        theirs = {str(u): v for u, v in s1.lam.items() if v is not None}
        lam = [theirs.get(str(u), s2.lam.get(u)) for u in models[suspect].unknowns]
        x = list(s1.qdd) + [v if v is not None else 0 for v in lam]
        res = [bi - sum(aij * xj for aij, xj in zip(row, x)) for row, bi in zip(A2, b2)]
        scale = 1 + max((abs(v) for v in b2), default=0)
        row = max(range(len(res)), key=lambda i: abs(res[i]))
        if is_zero(res[row], scale):
            row = None
    values = dict(point)
    values.update({q: v for q, v in zip(ctx.qdd, s1.qdd)})
    values.update({u: v for u, v in zip(models[suspect].unknowns, lam)})
    reason = (f"{reaction} = {float(v2):.6g} here, but `{other}` gives {float(v1):.6g}")
    model = models[suspect]
    if row is None:
        return Mismatch(suspect, label, reason)
    value, terms, state = _terms(model, row, values, _shown(ctx.base, ctx))
    reason += (f"; with `{other}`'s reactions its equation [{model.labels[row]}] is off by "
               f"{value:.6g}")
    return Mismatch(suspect, label, reason, value=value, state=state, terms=terms,
                    residual=lambda: _reaction_residual(model, models[other], row, limits))


def _reaction_residual(suspect, other, row, limits):
    """Equation ``row`` of ``suspect`` with the accelerations and reactions of ``other``
    substituted, simplified (display only): the term the two derivations differ by."""
    sol = solve_display(other, limits)
    rules = {a: sol[a] for a in other.accelerations}
    rules.update({u: sol[u] for u in other.unknowns if u in suspect.unknowns})
    return tidy(suspect.equations[row].xreplace(rules), limits)
