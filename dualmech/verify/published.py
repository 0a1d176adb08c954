"""Checking a source's printed answers against the verified derivations, by evaluation only.

A printed answer is transcribed as a :class:`dualmech.model.problem.Published` entry.  At the same
kind of random rational points as the verdict, the accelerations come from the verified
derivations and the reactions from the models that determine them; then

* an *equation* is right when its left side is exactly zero there (it follows from the
  equations of motion: any combination of them is accepted);
* a *motion* set is right when every equation is, and together they determine every
  acceleration (``(e1, 2*e1)`` or ``0 = 0`` determine nothing: wrong, with that reason);
* an *expression* is right when it equals our own derivation there;
* a claim about a steady motion's stability (eigenvalues, a critical value) is judged on the
  linearised steady motion by :mod:`dualmech.verify.stability_claims`.

Nothing is solved symbolically to reach a verdict.  Why a wrong answer is wrong (the derived
equation it most resembles, what is left over, its dimensions) is worked out when the detail
is first read, within the display budget.
"""
from __future__ import annotations

import random

import mpmath
import symengine as se
import sympy as sp

from dualmech.model._expr import as_expr
from dualmech.model.dimensions import audit
from dualmech.model.equations import EquationSet, ModelError, state_symbols, to_plain, to_plain_se
from dualmech.exact.form import MP_DIGITS, is_zero
from dualmech.model.kinematics import t
from dualmech.exact.errors import Undecidable
from dualmech.verify.display import Budget, OverBudget, dotted, ops_within, solve_display, tidy
from dualmech.verify.stability_claims import STABILITY_KINDS, judge_stability_claims
from dualmech.verify.sampling import MAX_ATTEMPTS, Context, Sampler, System, shared_manifold, solve_model

__all__ = ["PublishedVerdict", "check_published", "closest_equation"]


class PublishedVerdict:
    """Verdict on one printed answer: ``verdict`` is ``"correct"``, ``"wrong"`` or
    ``"unchecked"``; ``detail`` (computed when first read) says why."""

    def __init__(self, label, where, verdict, detail, method):
        self.label, self.where, self.verdict, self.method = label, where, verdict, method
        self._detail = detail

    @property
    def parts(self) -> list[tuple]:
        """:attr:`detail` as sentences, each a tuple of text and sympy expressions (so a page
        can typeset the expressions); computed when first read."""
        if callable(self._detail):
            try:
                self._detail = self._detail()
            except Exception as exc:  # noqa: BLE001 - display must never break a verdict
                self._detail = f"differs from the derivation ({type(exc).__name__} while " \
                               "explaining)"
        if isinstance(self._detail, str):
            return [(self._detail,)] if self._detail else []
        return list(self._detail)

    @property
    def detail(self) -> str:
        """Why the answer is wrong, in plain text (primes for rates, Python's ``*`` and
        ``**``): the form ``check --json`` carries."""
        return "; ".join("".join(x if isinstance(x, str) else dotted(x) for x in sentence)
                         for sentence in self.parts)

    def text(self, notation: str = "dots") -> str:
        """Why the answer is wrong, in textbook text (``m l θ̇^2``; ``θ′`` with
        ``notation="primes"``): the form a report and ``dualmech check`` show."""
        from dualmech.model.notation import sentence
        return "; ".join(sentence(s, notation) for s in self.parts)

    def __repr__(self) -> str:
        return f"PublishedVerdict({self.label!r}, {self.verdict!r})"

    def to_dict(self) -> dict:
        from dualmech.verify.check import method_name   # (check imports this module)
        return {"label": self.label, "where": self.where, "verdict": self.verdict,
                "detail": self.detail, "method": method_name(self.method)}


def check_published(problem, points: int = 8, seed: int = 0, context: Context | None = None,
                    limits: Budget | None = None, claims: dict | None = None,
                    printed: list | None = None) -> list[PublishedVerdict]:
    """Verdict on every printed answer of ``problem`` (see :class:`dualmech.model.problem.Published`).

    ``limits`` is the display budget for explaining wrong answers (when first read);
    ``claims`` as for :func:`~dualmech.verify.verdicts.judge`; ``printed`` the answers when
    the caller has already built them (``problem.published()`` by default)."""
    limits = limits or Budget()
    pubs = problem.published() if printed is None else printed
    claims_about_stability = [p for p in pubs if p.kind in STABILITY_KINDS]
    if claims_about_stability:
        judged = {v.label: v for v in judge_stability_claims(problem, claims_about_stability)}
        rest = check_published(problem, points, seed, context, limits, claims,
                               [p for p in pubs if p.kind not in STABILITY_KINDS])
        judged.update({v.label: v for v in rest})
        return [judged[p.label] for p in pubs if p.label in judged]
    if not pubs:
        return []
    models = problem.models()
    ref = models[problem.reference]
    coords = ref.coordinates
    ctx = context or Context(coords, problem.parameter_symbols, problem)
    mapped = {nm: problem.in_reference_coordinates(m) for nm, m in models.items()}
    solvers = [problem.reference] + [nm for nm, m in mapped.items()
                                     if m.unknowns and nm != problem.reference]
    systems = [System.of(mapped[nm], coords) for nm in solvers]
    unknowns = list(dict.fromkeys(u for nm in solvers for u in mapped[nm].unknowns))
    n = len(coords)
    items = []
    symbols = tuple(ctx.unknown_symbols(unknowns))
    faulty: dict = {}     # a printed answer that cannot be evaluated: reported on it alone
    known = set(ctx.base) | set(ctx.qdd) | set(symbols)
    plain = _Plain(coords)
    for pub in pubs:
        try:
            if pub.kind == "expression" and pub.coordinates in (None, problem.reference):
                # printed - reference, each side converted once (they share their atoms)
                es = [plain.difference(p, r) for p, r in zip(pub.printed, pub.reference)]
            else:
                es = [plain(e) for e in _published_exprs(problem, pub)]
            motion = _motion_system(problem, pub, coords, unknowns) if pub.kind == "motion" \
                else None
        except (ValueError, TypeError, KeyError, ZeroDivisionError) as exc:
            faulty[pub.label] = f"could not be read: {type(exc).__name__}: {exc}"
            continue
        stray = sorted({str(x) for e in es for x in e.free_symbols} - {str(x) for x in known})
        if stray:
            faulty[pub.label] = (f"uses undeclared symbol(s) {', '.join(stray)}: declare them "
                                 "as parameters of the problem or write the answer with its "
                                 "symbols")
            continue
        items.append((pub, es, motion))
    claims = claims or {}
    every = [System.of(mapped[nm], coords) for nm in mapped if nm not in solvers]
    deps = shared_manifold(systems + every, [nm in claims for nm in solvers] +
                           [nm in claims for nm in mapped if nm not in solvers], ctx)
    # equations hold on the motion (its constraint manifold); expressions are identities of
    # the state, so with static rows they are also checked off the manifold
    groups = [(items, deps)]
    if deps:
        on = [it for it in items if it[0].kind != "expression"]
        off = [it for it in items if it[0].kind == "expression"]
        groups = [(on, deps), (off, [])]
    bad: dict = {}
    good, method = 0, "exact"
    with mpmath.workdps(MP_DIGITS):
        for group, dependents in groups:
            if not group:
                continue
            try:
                g, method = _evaluate(group, systems, solvers, mapped, ctx, symbols,
                                      dependents, claims, n, points, seed, bad)
                good = max(good, g)
                undecided = [it for it in group
                             if any(isinstance(x, str) and x.startswith("undecid")
                                    for x in bad.get(it[0].label, ()))]
                if len(group) == 1 or not undecided:
                    continue
                group = undecided   # maybe one answer made the whole group undecidable
                for it in group:
                    bad.pop(it[0].label, None)
            except (ValueError, TypeError, ZeroDivisionError):
                pass
            for item in group:      # one answer sank the group: find it, judge the others
                try:
                    g, method = _evaluate([item], systems, solvers, mapped, ctx, symbols,
                                          dependents, claims, n, points, seed, bad)
                    good = max(good, g)
                except (ValueError, TypeError, ZeroDivisionError) as exc:
                    faulty[item[0].label] = (f"could not be evaluated: "
                                             f"{type(exc).__name__}: {exc}")
    shared = _Explaining(problem, limits)     # what the explanations share, when read
    verdicts = [PublishedVerdict(pub.label, pub.where, "unchecked",
                                 "NOT CHECKED, the printed answer " + faulty[pub.label], "none")
                for pub in pubs if pub.label in faulty]
    for pub, es, motion in items:
        if pub.label in faulty:
            continue
        if isinstance(motion, str):
            verdicts.append(PublishedVerdict(pub.label, pub.where, "wrong", motion, method))
        elif pub.label not in bad:
            verdicts.append(PublishedVerdict(pub.label, pub.where, "correct",
                                             f"holds at {good} point"
                                             + ("" if good == 1 else "s"), method))
        elif all(isinstance(x, str) and x.startswith("undecid") for x in bad[pub.label]):
            verdicts.append(PublishedVerdict(pub.label, pub.where, "unchecked",
                                             "; ".join(sorted(bad[pub.label])), method))
        else:
            verdicts.append(PublishedVerdict(
                pub.label, pub.where, "wrong",
                lambda pub=pub, which=bad[pub.label]: _detail(problem, pub, which, limits,
                                                              shared),
                method))
    judged = {v.label: v for v in verdicts}
    return [judged[pub.label] for pub in pubs if pub.label in judged]


def _evaluate(items, systems, solvers, mapped, ctx, symbols, dependents, claims, n, points,
              seed, bad) -> tuple[int, str]:
    """Evaluate the printed ``items`` at random points of the motion; record failures in
    ``bad``; return the number of points used and the method."""
    extra = []
    for pub, es, motion in items:
        extra += es
        if isinstance(motion, System):
            extra += [x for row in motion.A for x in row]
    try:
        sampler = Sampler(systems, ctx, extra=extra, extra_symbols=symbols,
                          dependents=dependents)
    except Undecidable as exc:
        for pub, _, _ in items:
            bad.setdefault(pub.label, set()).add(f"undecidable: {exc.expr}: {exc.why}")
        return 0, "refused"
    form = sampler.form
    rng = random.Random(seed + 1)
    zero = 0 if form.method == "exact" else mpmath.mpf(0)
    good = 0
    for point, _, parts, _ in sampler.points(rng, MAX_ATTEMPTS * points,
                                             fill={s: zero for s in symbols}):
        sols = [solve_model(A, b, n, mapped[nm].unknowns, claims.get(nm))
                for nm, (A, b) in zip(solvers, parts)]
        if sols[0].status != "ok":
            continue
        point.update(dict(zip(ctx.qdd, sols[0].qdd)))
        for sol in sols[1:]:
            for u, v in sol.lam.items():
                if v is not None:
                    point[u] = v
        try:
            vals = form.evaluate(point)
        except (ZeroDivisionError, ValueError, OverflowError):
            continue
        good += 1
        pos = sampler.offset_extra
        for pub, es, motion in items:
            for j, v in enumerate(vals[pos:pos + len(es)]):
                if not is_zero(v, 1):
                    certain = getattr(form, "certain", lambda _p: True)(point)
                    bad.setdefault(pub.label, set()).add(
                        j if certain else "undecided: differs only in an unconfirmed case")
            pos += len(es)
            if isinstance(motion, System):
                cols = len(motion.A[0])
                J = [list(vals[pos + r * cols: pos + (r + 1) * cols])
                     for r in range(len(motion.A))]
                pos += len(motion.A) * cols
                if solve_model(J, [0] * len(J), n, motion.model.unknowns).status != "ok":
                    bad.setdefault(pub.label, set()).add("determines")
        if good == points:
            break
    return good, form.method


class _Plain:
    """Printed expressions in plain state symbols: in symengine when they convert (the
    sampler takes them there), else in sympy.

    One walk over the sympy tree, each distinct subexpression converted once for all the
    printed answers of a problem (they share most of theirs: ``sin(theta)``, ``m R``,
    ``theta'``); what the walk does not know is left to :func:`~dualmech.model.equations.to_plain_se`.
    """

    _FUNCTIONS: dict = {}   # sympy function -> symengine's (made on first use)

    def __init__(self, coords):
        if not _Plain._FUNCTIONS:
            _Plain._FUNCTIONS.update({sp.sin: se.sin, sp.cos: se.cos, sp.tan: se.tan,
                                      sp.exp: se.exp, sp.log: se.log})
        self.coords = tuple(coords)
        self.memo: dict = {}
        for q in self.coords:
            s = state_symbols(q)
            self.memo[q] = se.Symbol(s.q.name)
            self.memo[sp.Derivative(q, t)] = se.Symbol(s.qd.name)
            self.memo[sp.Derivative(q, (t, 2))] = se.Symbol(s.qdd.name)

    def __call__(self, expr):
        try:
            return self._node(as_expr(expr))
        except Exception:  # noqa: BLE001 - what symengine does not take stays in sympy
            return to_plain(expr, self.coords)

    def difference(self, a, b):
        """``a - b`` in plain state symbols."""
        try:
            return self._node(as_expr(a)) - self._node(as_expr(b))
        except Exception:  # noqa: BLE001 - what symengine does not take stays in sympy
            return to_plain(as_expr(a) - as_expr(b), self.coords)

    def _node(self, e):
        out = self.memo.get(e)
        if out is not None:
            return out
        if e.is_Symbol:
            out = se.Symbol(e.name)
        elif e.is_Integer:
            out = se.Integer(int(e))
        elif e.is_Rational:
            out = se.Rational(int(e.p), int(e.q))
        elif e.is_Add:
            out = se.Add(*[self._node(a) for a in e.args])
        elif e.is_Mul:
            out = se.Mul(*[self._node(a) for a in e.args])
        elif e.is_Pow:
            out = se.Pow(self._node(e.base), self._node(e.exp))
        elif type(e) in self._FUNCTIONS:
            out = self._FUNCTIONS[type(e)](*[self._node(a) for a in e.args])
        else:
            out = to_plain_se(e, self.coords)
        self.memo[e] = out
        return out


def _motion_system(problem, pub, coords, unknowns):
    """The printed set as a :class:`System` (static rows at the acceleration level), or the
    reason it cannot be equations of motion."""
    es = _published_exprs(problem, pub)
    used = tuple(u for u in unknowns if any(e.has(u) for e in es))
    try:
        eqs = EquationSet(f"printed {pub.label}", tuple(coords), tuple(es), used)
        return System.of(eqs, coords)
    except ModelError as exc:
        return f"the printed set cannot be equations of motion: {exc}"


def _published_exprs(problem, pub) -> list:
    """Printed (equation kinds) or printed - reference (expression kind), reference coordinates."""
    if pub.kind in ("equation", "motion"):
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


class _Explaining:
    """What explaining the wrong printed answers of one problem shares, each part built when
    first needed: the declared dimensions, the reference model's rows as term tables, the
    symbols of the reactions.  One per :func:`check_published` call, so nothing outlives the
    models it was built from."""

    def __init__(self, problem, limits: Budget):
        self.problem, self.limits = problem, limits
        self._dims = None
        self.tables: dict = {}    # expression -> its expanded terms (see _terms)

    @property
    def dims(self) -> dict:
        if self._dims is None:
            self._dims = self.problem.dimensions()
        return self._dims

    @property
    def ref(self):
        return self.problem.model(self.problem.reference)

    @property
    def unknowns(self) -> set:
        return {u for m in self.problem.models().values() for u in m.unknowns}


def _detail(problem, pub, which, limits: Budget, shared: _Explaining | None = None
            ) -> list[tuple]:
    """Say what is wrong with a printed answer (display work, within budget): sentences of
    text and expressions.  A difference is shown only between quantities of one dimension."""
    shared = shared or _Explaining(problem, limits)
    dims = shared.dims
    lines = []
    if "determines" in which:
        k, n = len(pub.printed), len(shared.ref.coordinates)
        if k == 1 and n == 1:
            why = "its one equation does not involve the acceleration"
        elif k == 1:
            why = f"one equation is too few for the {n} coordinates"
        else:
            why = (f"its {k} equations are dependent or too few for the "
                   + (f"{n} coordinates" if n != 1 else "coordinate"))
        lines.append((f"the printed set does not determine every acceleration: {why}",))
    exprs = _published_exprs(problem, pub)
    for j in sorted(x for x in which if isinstance(x, int)):
        what = f"equation {j + 1}" if pub.kind != "expression" else f"component {j + 1}"
        if len(pub.printed) == 1:
            what = "the printed answer"
        issues = audit(pub.printed[j], dims) if pub.kind != "expression" else \
            audit(pub.printed[j] - pub.reference[j], dims)
        if issues:
            said: tuple = (f"{what} is dimensionally inconsistent: ",)
            for i, issue in enumerate(issues):
                said += (("; ",) if i else ()) + issue.sentence()
            lines.append(said)
        shell = None
        if pub.kind != "expression":
            ref = shared.ref
            near = closest_equation(exprs[j], ref.equations, ref.labels,
                                    problem.parameter_symbols, memo=shared.tables)
            if near is not None:
                label, alpha, rest = near
                # the derived row named in words (never its internal label), typeset
                from dualmech.model.notation import equation_words   # (display only: imported when read)
                row = equation_words(label, problem.reference, ref.coordinates)
                lines.append((f"{what} is closest to ",)
                             + ((alpha, " \u00d7 ") if alpha != 1 else ()) + row
                             + (("; printed minus that = ", rest) if not issues else ()))
                # the derived row vanishes on the motion: a remainder free of accelerations
                # and reactions is the printed side's value there, with no solve
                shell = rest
        if issues and pub.kind == "expression":
            lines.append((f"{what} and the derivation have different dimensions, so their "
                          "difference is not shown",))
            continue
        if issues:
            lines.append((f"{what} does not follow from the equations of motion (its terms "
                          "differ in dimension, so its value on the motion is not shown)",))
            continue
        diff = _on_shell(problem, exprs[j], limits, shell, shared)
        if diff is not None and len(dotted(diff)) < 200:
            if pub.kind != "expression":
                lines.append((f"{what} does not follow from the equations of motion: on the "
                              "motion its left side equals ", diff, ", not 0"))
            else:
                lines.append((f"{what}: printed minus derived = ", diff))
        elif not lines or pub.kind == "expression":
            lines.append((f"{what} differs from the derivation",))
    return lines


def closest_equation(expr, equations, labels, parameters, max_terms: int = 40,
                     memo: dict | None = None):
    """The derived equation that ``expr`` most resembles, up to a constant factor.

    Tries every ratio ``alpha`` of a term of ``expr`` to a term of a derived equation (ratios
    free of the state) and keeps the smallest ``expr - alpha * equation``.  Returns
    ``(label, alpha, remainder)`` or ``None`` when nothing matches or the input is large.
    Terms are compared as tables of ``{monomial: coefficient}`` with each monomial a table
    of ``{base: exponent}``, so ratios and trial remainders are dictionary arithmetic and
    only the best remainder is ever built as an expression.  ``memo`` (a dict the caller
    keeps) shares the expanded terms of the equations between calls.

    Example
    -------
    >>> import sympy as sp
    >>> x, k, c = sp.symbols("x k c")
    >>> closest_equation(2*k*x + 2*c + 1, [k*x + c, x**2], ["first", "second"], [k, c])
    ('first', 2, 1)
    """
    memo = {} if memo is None else memo
    _, terms_e = _terms(expr, memo)
    if len(terms_e) > max_terms:
        return None
    table_e = {key: k for k, key, _, _ in terms_e}
    allowed = set(parameters)
    free: dict = {}    # base or exponent -> whether it is free of the state

    def constant(x) -> bool:
        hit = free.get(x)
        if hit is None:
            hit = free[x] = x.free_symbols <= allowed
        return hit

    best = None
    for label, R in zip(labels, equations):
        _, terms_r = _terms(R, memo)
        if len(terms_r) > max_terms:
            continue
        ratios, seen = [], set()
        for ka, _, pa, _ in terms_e:
            for kb, _, pb, _ in terms_r:
                # a / b, monomials: the quotient's exponents are the differences
                powers = dict(pa)
                for base, x in pb.items():
                    left = powers.get(base, 0) - x
                    if left == 0:
                        powers.pop(base, None)
                    else:
                        powers[base] = left
                if not all(constant(base) and constant(x) for base, x in powers.items()):
                    continue
                r = (ka / kb, frozenset(powers.items()))
                if r not in seen:
                    seen.add(r)
                    ratios.append((ka / kb, powers))
        for k_alpha, p_alpha in ratios[:60]:
            rest = dict(table_e)
            for c, _, mono, _ in terms_r:
                key = _times(mono, p_alpha)
                rest[key] = rest.get(key, 0) - k_alpha * c
            size = sum(1 for v in rest.values() if v != 0)
            if best is None or size < best[0]:
                best = (size, label, (k_alpha, p_alpha), terms_r)
    if best is None or best[0] >= len(terms_e):
        return None
    size, label, (k_alpha, p_alpha), terms_r = best
    # expr - alpha * equation, expanded: the winning table, each term built once
    rest = dict(table_e)
    monomials = {key: m for _, key, _, m in terms_e}
    for c, _, mono, _ in terms_r:
        key = _times(mono, p_alpha)
        rest[key] = rest.get(key, 0) - k_alpha * c
    remainder = sp.Add(*(c * (monomials[key] if key in monomials else
                              sp.Mul(*(b**x for b, x in key)))
                         for key, c in rest.items() if c != 0))
    alpha = sp.Mul(k_alpha, *(b**x for b, x in p_alpha.items()))
    return label, alpha, sp.factor_terms(remainder)


def _terms(expr, memo: dict) -> tuple:
    """``(expanded expr, [(coefficient, key, {base: exponent}, monomial) per term])``, kept
    in ``memo`` under the expression itself (equal expressions, equal terms: never stale)."""
    hit = memo.get(expr)
    if hit is None:
        E = sp.expand(expr)
        terms = []
        for term in sp.Add.make_args(E):
            k, m = term.as_coeff_Mul()
            powers = {b: x for b, x in m.as_powers_dict().items() if b != 1 and x != 0}
            terms.append((k, frozenset(powers.items()), powers, m))
        hit = memo[expr] = (E, terms)
    return hit


def _times(powers: dict, other: dict) -> frozenset:
    """The key of the product of two monomials given as ``{base: exponent}``."""
    out = dict(powers)
    for base, x in other.items():
        y = out.get(base, 0) + x
        if y == 0:
            out.pop(base, None)
        else:
            out[base] = y
    return frozenset(out.items())


def _on_shell(problem, expr, limits: Budget, same_on_motion=None,
              shared: _Explaining | None = None):
    """``expr`` on the motion (accelerations and reactions substituted), for display.

    ``same_on_motion`` is an expression known to equal ``expr`` on the motion (``expr``
    minus a multiple of a derived row); when it is free of accelerations and reactions it is
    shown instead, and nothing is solved.  A model is solved for its reactions only when
    ``expr`` holds one of them that no model before it gave."""
    shared = shared or _Explaining(problem, limits)
    expr = as_expr(expr)
    ref = shared.ref
    unknowns = shared.unknowns
    if same_on_motion is not None:
        other = as_expr(same_on_motion)
        if not any(other.has(a) for a in ref.accelerations) and \
                not (other.free_symbols & unknowns):
            expr = other
    if not any(expr.has(a) for a in ref.accelerations) and not (expr.free_symbols & unknowns):
        try:
            return tidy(expr, limits)
        except OverBudget:
            return None
    try:
        rules = dict((a, v) for a, v in solve_display(ref, limits).items())
        wanted = expr.free_symbols & unknowns
        for m in problem.models().values():
            if not (set(m.unknowns) & wanted) - set(rules):
                continue    # none of its reactions is in expr, or an earlier model gave them
            m = problem.in_reference_coordinates(m)
            try:
                sol = solve_display(m, limits)
            except (OverBudget, ModelError, ValueError):
                continue
            for u in m.unknowns:
                if u in sol:
                    rules.setdefault(u, sol[u])
        out = as_expr(expr).xreplace(rules)
        if not ops_within(out, 2000):
            return None
        return tidy(out, limits)
    except (OverBudget, ModelError, ValueError, ZeroDivisionError):
        return None
