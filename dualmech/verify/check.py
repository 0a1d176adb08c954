"""``compare(problem)``: every derivation judged, reactions compared, printed answers checked.

Verdict first: equivalence, the reactions shared by two models and the printed answers are
all decided by evaluation (:mod:`~dualmech.verify.verdicts`,
:mod:`~dualmech.verify.published`).  What a person reads -- solved accelerations, reaction
formulas, residuals -- is computed when first read, within a display budget
(:mod:`~dualmech.verify.display`); past the budget the report shows the structured form and
says so.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import Sequence

import symengine as se
import sympy as sp

from dualmech.model._algebra import is_zero_held
from dualmech.model.equations import EquationSet, ModelError, Rows
from dualmech.sources import source_fields, source_name
from dualmech.verify.display import Budget, OverBudget, budget, dotted, solve_display, width, wrap
from dualmech.verify.explain import Mismatch, explain_model, explain_reaction
from dualmech.verify.published import PublishedVerdict, check_published
from dualmech.verify.referee import INDEPENDENCE, Referees, referees
from dualmech.verify.sampling import Context
from dualmech.verify.verdicts import Judgement, judge

__all__ = ["Comparison", "PairResult", "claims_of", "compare", "compare_models", "compare_reactions",
           "reaction_pairs", "recover_reactions", "solve_with_static", "METHOD_NAMES",
           "method_name"]

METHOD_NAMES = {
    "exact": "exact rational-point test",
    "mpmath": "high-precision numeric (mpmath)",
}


def method_name(method: str) -> str:
    """The human name of a verdict method (the evaluation module may add its own)."""
    from dualmech.exact import form as exact
    names = dict(METHOD_NAMES)
    names.update(getattr(exact, "METHOD_NAMES", {}))
    return names.get(method, method)


@dataclass
class PairResult:
    """Verdict on one model against another (``kind="motion"``), or on shared reactions."""

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
    decided: bool = True

    def __str__(self) -> str:
        return self.text()

    def text(self, notation: str = "dots") -> str:
        """The verdict line, then each mismatch in textbook notation (:meth:`Mismatch.text`)."""
        if self.kind in ("reactions", "referee reactions"):
            verdict = "the same" if self.equivalent else "DIFFERENT"
            if not self.decided:
                verdict = "not compared (the motion disagrees; fix it first)"
            head = (f"reactions {', '.join(self.reactions)} of {self.candidate} vs "
                    f"{self.reference}: {verdict}")
        else:
            verdict = "equivalent" if self.equivalent else "NOT equivalent"
            head = f"{self.candidate} vs {self.reference}: {verdict}"
        pts = f"{self.points} point" + ("" if self.points == 1 else "s")
        s = f"{head} ({method_name(self.method)}, {pts}"
        if self.method == "exact" and self.equivalent and not math.isnan(self.bound):
            s += (", P(false equal) < 1e-300" if self.bound == 0
                  else f", P(false equal) <= {self.bound:.1e}")
        s += f", {self.seconds:.2f} s)"
        return "\n".join([s] + [m.text(notation) for m in self.mismatches])

    def to_dict(self) -> dict:
        return {"kind": self.kind, "reference": self.reference, "candidate": self.candidate,
                "reactions": list(self.reactions), "equivalent": self.equivalent,
                "method": method_name(self.method), "points": self.points,
                "false_equal_bound": _json_float(self.bound), "seconds": self.seconds,
                "mismatches": [m.to_dict() for m in self.mismatches]}


def _json_float(x):
    x = float(x)
    return None if math.isnan(x) or math.isinf(x) else x


class Comparison:
    """Everything ``dualmech check`` reports for one problem; ``str()`` is the readable report.

    ``equivalent``, ``pairs``, ``published``, ``judgement`` and ``dimension_issues`` are the
    verdicts; ``accelerations`` and ``reactions`` are symbolic displays computed when first
    read (empty when past the display budget -- ``display_notes`` says why).
    ``dimension_audit`` holds the dimension audit's sentences with their terms as expressions
    (``dimension_issues`` is the same as plain text).  ``str()`` is :meth:`text` with dots.

    Examples
    --------
    >>> from dualmech import compare, get
    >>> c = compare(get("simple_pendulum"))
    >>> c.equivalent, sorted(c.reactions)
    (True, ['T'])
    >>> c.to_dict()["reactions"]["T"]
    "M*(a*theta'**2 + g*cos(theta))"
    """

    def __init__(self, problem, judgement: Judgement, pairs, published, dimension_issues,
                 seconds: float, points: int, limits: Budget | None = None):
        self.problem = problem
        self.judgement = judgement
        self.pairs = pairs
        self.published = published
        self.dimension_audit = [x if isinstance(x, tuple) else (str(x),)
                                for x in dimension_issues]
        self.seconds = seconds
        self.points = points
        self.limits = limits or Budget()
        self.display_notes: list[str] = []
        self._acc = self._reac = None
        self._static: dict = {}
        self.referees = Referees()
        self.referee_pairs: list = []

    @property
    def dimension_issues(self) -> list[str]:
        """The dimension audit's sentences as plain text, terms between backticks."""
        from dualmech.model.dimensions import quoted
        return [quoted(x) for x in self.dimension_audit]

    @property
    def reaction_directions(self) -> dict:
        return {r.name: r.direction for r in self.problem.reactions}

    @property
    def equivalent(self) -> bool:
        return self.judgement.equivalent and len(self.judgement.models) >= 2

    @property
    def method(self) -> str:
        return method_name(self.judgement.method)

    @property
    def reaction_derivations(self) -> dict:
        """``{declared reaction: [names of the models that derive it]}``."""
        out = {r.name: [] for r in self.problem.reactions}
        for name, m in self.judgement.models.items():
            if name in self.judgement.referees:
                continue
            for u in m.unknowns:
                if u.name in out:
                    out[u.name].append(name)
        return out

    @property
    def referee_derivations(self) -> dict:
        """``{declared reaction: [referees that derive it]}`` (a referee that withdrew, or
        leaves the reaction open, does not)."""
        out = {r.name: [] for r in self.problem.reactions}
        j = self.judgement
        for name in j.referees:
            if name in j.withdrawn or name not in j.models:
                continue
            for u in j.models[name].unknowns:
                if u.name in out and u.name not in j.undetermined.get(name, ()):
                    out[u.name].append(name)
        return out

    @property
    def not_cross_checked(self) -> list[str]:
        """Declared reactions that fewer than two derivations give: their value rests on one
        free-body diagram alone, so no comparison could have caught a wrong term in it."""
        refs = self.referee_derivations
        return [n for n, held in self.reaction_derivations.items()
                if len(held) + len(refs.get(n, ())) < 2]

    def reaction_count_text(self) -> str:
        """``"3"``, or ``"3 (1 not cross-checked)"`` -- the summary tables' cell."""
        n, k = len(self.problem.reactions), len(self.not_cross_checked)
        return f"{n} ({k} not cross-checked)" if k else str(n)

    @property
    def diagnosis(self):
        """What the disagreement is, named (:mod:`~dualmech.verify.diagnose`): computed when
        first read; ``None`` when the derivations agree."""
        if "_diagnosis" not in self.__dict__:
            from dualmech.verify.diagnose import diagnose
            self._diagnosis = None if self.judgement.equivalent or self.judgement.refusal \
                else diagnose(self.problem, self.judgement)
        return self._diagnosis

    @property
    def bound(self) -> float:
        return max((p.bound for p in self.pairs), default=0.0)

    @property
    def mismatches(self) -> list:
        return [m for p in self.pairs + self.referee_pairs for m in p.mismatches]

    @property
    def accelerations(self) -> dict:
        if self._acc is None:
            ref = self.problem.model(self.problem.reference)
            try:
                static, sol = solve_with_static(ref, self.limits)
                self._static = {q.func.__name__: v for q, v in static.items()}
                self._acc = {q.func.__name__: sol[a]
                             for q, a in zip(ref.coordinates, ref.accelerations) if a in sol}
            except (OverBudget, ModelError, ValueError, ZeroDivisionError) as exc:
                self._acc = {}
                self.display_notes.append(f"accelerations not solved symbolically ({exc}); "
                                          "the equations above are M q'' = f")
        return self._acc

    @property
    def static(self) -> dict:
        """``{coordinate: expression}`` of the coordinates fixed by static rows (a massless
        body's balance, no acceleration in it), solved for display; ``{}`` when none."""
        self.accelerations
        return self._static

    @property
    def reactions(self) -> dict:
        if self._reac is None:
            self._reac = {}
            if self.equivalent:
                try:
                    self._reac = recover_reactions(self.problem, self.limits)
                except (OverBudget, ModelError, ValueError, ZeroDivisionError) as exc:
                    self.display_notes.append(f"reactions not solved symbolically ({exc})")
        return self._reac

    def referee_lines(self) -> list[str]:
        """What the referee is, and why a direct model has none or it could not vote."""
        j, out = self.judgement, []
        for name, direct in j.referees.items():
            why = j.withdrawn.get(name)
            left = sorted(j.undetermined.get(name, ()))
            line = f"{name}: Kane method with auxiliary speeds, {INDEPENDENCE} (`{direct}`)"
            if why:
                line += f"; it does not vote: {why}"
            elif left:
                line += (f"; it leaves {', '.join(left)} open (statically indeterminate from "
                         "the declarations alone)")
            out.append(line)
        out += self.referees.notes
        return out

    def verdict_line(self) -> str:
        j = self.judgement
        if len(j.models) < 2:
            return "NOT CHECKED: the problem has a single derivation; nothing was compared"
        if self.equivalent:
            return f"all derivations agree ({self.method}, {self.seconds:.2f} s)"
        return "DISAGREEMENT: " + j.summary().replace("\n", "; ")

    def __str__(self) -> str:
        return self.text()

    def text(self, notation: str = "dots") -> str:
        """The readable report, every expression in textbook notation: letters as a worked
        solution writes them, rates as dots (``θ̈``) or, with ``notation="primes"``, primes
        (``θ′′``), powers as ``^`` and products as spaces -- no Python syntax."""
        from dualmech.model.notation import check_notation, plain, sentence, symbol_text
        check_notation(notation)
        pr = self.problem
        ref = pr.model(pr.reference)
        out = [f"{pr.name}: {pr.title}", f"  source: {source_name(pr.source)}",
               f"  coordinates: "
               + ", ".join(symbol_text(q.func.__name__, 0, notation) for q in ref.coordinates),
               f"  verdict: {self.verdict_line()}"]
        for p in self.pairs + self.referee_pairs:
            out.append("  " + p.text(notation).replace("\n", "\n  "))
        out += ["  " + line for line in self.referee_lines()]
        if self.diagnosis:
            out.append("  diagnosis:")
            out.append("    " + self.diagnosis.text(notation, width() - 4).replace("\n", "\n    "))
        if self.equivalent and self.accelerations:
            out.append("  accelerations:")
            for k, v in self.accelerations.items():
                out.append(f"    {symbol_text(k, 2, notation)} = {plain(v, notation)}")
            for k, v in self.static.items():
                name = symbol_text(k, 0, notation)
                out.append(f"    {name} = {plain(v, notation)}   (static row: no inertia in "
                           f"{name})")
        lonely = self.not_cross_checked
        if self.equivalent and self.reactions:
            out.append("  reactions (from the direct form):")
            dirs = self.reaction_directions
            for k, v in self.reactions.items():
                d = dirs.get(k, "")
                held = self.reaction_derivations.get(k, []) + \
                    self.referee_derivations.get(k, [])
                out.append(f"    {plain(sp.Symbol(k), notation)} = {plain(v, notation)}"
                           + (f"   [{d}]" if d else "")
                           + ("   (NOT CROSS-CHECKED)" if k in lonely else
                              f"   (cross-checked: {', '.join(held)} agree)"))
        if lonely:
            held = self.reaction_derivations
            out.append(wrap("  not cross-checked (one derivation only): " + ", ".join(
                f"{plain(sp.Symbol(n), notation)} ({', '.join(held[n]) or 'no model'})"
                for n in lonely)
                + "; a second derivation (a multiplier model or another free-body diagram) "
                "would catch a wrong term in it"))
        for note in self.display_notes:
            out.append(f"  ({note})")
        unchecked = getattr(self.problem, "dimensions_unchecked", "")
        if unchecked:
            out.append(wrap(f"  dimension audit: not run ({unchecked})"))
        elif self.dimension_audit:
            out.append("  dimension audit:")
            out.extend(f"    {sentence(x, notation)}" for x in self.dimension_audit)
        else:
            out.append("  dimension audit: every equation is consistent")
        if self.published:
            out.append("  published answers:")
            for v in self.published:
                out.append(f"    [{v.verdict.upper():7s}] {v.label}" +
                           (f" ({v.where})" if v.where else ""))
                if v.verdict != "correct":
                    why = v.text(notation) if hasattr(v, "text") else v.detail
                    out.append("              " + why.replace("\n", "\n              "))
        return "\n".join(out)

    def __repr__(self) -> str:
        return f"<Comparison {self.problem.name}: {self.verdict_line()}>"

    def _repr_html_(self) -> str:
        """Jupyter: verdict, accelerations, reactions and printed answers, typeset."""
        from dualmech.report.jupyter import comparison_html
        return comparison_html(self)

    def to_dict(self) -> dict:
        pr = self.problem
        ref = pr.model(pr.reference)
        return {
            "name": pr.name, "title": pr.title, **source_fields(pr.source),
            "coordinates": [q.func.__name__ for q in ref.coordinates],
            "parameters": [str(p.symbol) for p in pr.parameters],
            "equivalent": self.equivalent, "method": self.method,
            "verdict": self.verdict_line(),
            "odd": list(self.judgement.odd),
            "seconds": self.seconds,
            "eom": [dotted(e) for e in ref.equations],
            "accelerations": {k: dotted(v) for k, v in self.accelerations.items()},
            "static": {k: dotted(v) for k, v in self.static.items()},
            "reactions": {k: dotted(v) for k, v in self.reactions.items()},
            "reaction_directions": self.reaction_directions,
            "reaction_derivations": self.reaction_derivations,
            "referees": {name: {"of": direct, "independence": INDEPENDENCE,
                                "votes": name not in self.judgement.withdrawn,
                                "withdrawn": self.judgement.withdrawn.get(name, ""),
                                "open_reactions": sorted(self.judgement.undetermined.get(
                                    name, ()))}
                         for name, direct in self.judgement.referees.items()},
            "referee_notes": list(self.referees.notes),
            "referee_derivations": self.referee_derivations,
            "referee_pairs": [p.to_dict() for p in self.referee_pairs],
            "verdict_notes": list(self.judgement.notes),
            "reactions_not_cross_checked": self.not_cross_checked,
            "display_notes": list(self.display_notes),
            "published": [v.to_dict() for v in self.published],
            "mismatches": [m.to_dict() for m in self.mismatches],
            "models": {n: [dotted(e) for e in m.equations] for n, m in pr.models().items()},
            "pairs": [p.to_dict() for p in self.pairs],
            "diagnosis": self.diagnosis.to_dict() if self.diagnosis else None,
            "points": self.points,
            "false_equal_bound": _json_float(self.bound),
            "dimension_issues": list(self.dimension_issues),
            "dimensions_unchecked": getattr(self.problem, "dimensions_unchecked", "") or None,
            "machine": self._machine(),
        }

    def _machine(self) -> dict:
        """The expressions of :meth:`to_dict` in a form parsers read: ``theta_d``, ``theta_dd``
        for the rates (the grader's parser and sympy's ``parse_expr`` both take it)."""
        from dualmech.model.notation import machine
        pr = self.problem
        coords = pr.model(pr.reference).coordinates
        return {"notation": "q_d = dq/dt, q_dd = d2q/dt2; ** is a power",
                "eom": [machine(e, coords) for e in pr.model(pr.reference).equations],
                "accelerations": {k: machine(v, coords) for k, v in self.accelerations.items()},
                "reactions": {k: machine(v, coords) for k, v in self.reactions.items()}}


def compare(problem, points: int = 8, seed: int = 0, limits: Budget | None = None) -> Comparison:
    """Judge every derivation of ``problem``, compare shared reactions, check printed answers.

    Never raises on a wrong model: a singular or contradictory derivation is a mismatch in
    the result.  Raises :class:`~dualmech.model.problem.ProblemError` for a declaration that cannot
    be used (with every mistake listed) and ``ValueError`` for ``points < 1``.

    >>> from dualmech.problems import get
    >>> c = compare(get("toy_car")); c.equivalent
    True
    """
    _check_points(points)
    _check_problem(problem)
    t0 = time.perf_counter()
    problem.validate()
    models = problem.models()
    ref = models[problem.reference]
    ctx = Context(ref.coordinates, problem.parameter_symbols, problem)
    mapped = {n: problem.in_reference_coordinates(m) for n, m in models.items()}
    refs = referees(problem)
    mapped.update(refs.models)
    claims = claims_of(problem)
    claims.update({r: claims[d] for r, d in refs.of.items() if d in claims})
    j = judge(mapped, context=ctx, points=points, seed=seed, reference=problem.reference,
              claims=claims, referees=refs.of)
    every = _pairs(j, problem.reference, ctx, seed)
    pairs = [p for p in every if not _refereed(p, j)]
    limits = limits or Budget()
    try:
        printed = problem.published()
    except (ValueError, TypeError, ArithmeticError, ModelError, KeyError) as exc:
        # the printed answers are built from a model that is wrong or singular here
        printed = None
        published = [PublishedVerdict(
            "printed answers", "", "unchecked",
            f"NOT CHECKED: `published()` failed ({type(exc).__name__}: {exc}); it builds "
            "them from the models, so fix the models first", "none")]
    if printed is None:
        pass
    elif j.equivalent:
        published = check_published(problem, points=points, seed=seed, context=ctx,
                                    limits=limits, claims=claims_of(problem),
                                    printed=printed)
    else:
        published = [PublishedVerdict(p.label, p.where, "unchecked",
                                      "the derivations disagree; fix them before judging "
                                      "printed answers", "none") for p in printed]
    issues = [] if getattr(problem, "dimensions_unchecked", "") else \
        list(problem.dimension_audit()) + _reaction_dimension_issues(problem)
    out = Comparison(problem, j, pairs, published, issues, time.perf_counter() - t0, points,
                     limits)
    out.referees = refs
    out.referee_pairs = [p for p in every if _refereed(p, j)]
    return out


def _refereed(pair: PairResult, j: Judgement) -> bool:
    """A line of a referee (kept apart from the teacher's models' lines)."""
    return pair.kind == "referee reactions" or pair.candidate in j.referees


def _check_problem(problem) -> None:
    """A string (a catalogue name) or anything else that is not a problem: a TypeError that
    shows the fix.  ``compare`` does not look names up itself: the catalogue sits above the
    verifier in the pipeline, and a name may also be a file or ``module:Class``."""
    from dualmech.model.problem import Problem
    if isinstance(problem, str):
        raise TypeError(f"`problem` must be a Problem, got the string {problem[:60]!r}; "
                        f"look it up first: compare(dualmech.problems.get({problem[:60]!r})).")
    if not isinstance(problem, Problem):
        raise TypeError(f"`problem` must be a Problem (dualmech.model.problem.Problem), got "
                        f"{type(problem).__name__}.")


def claims_of(problem) -> dict:
    """Models written in fewer coordinates than the reference, and the reference coordinates
    (indices) each speaks for: those its coordinate map uses."""
    ref = problem.model(problem.reference).coordinates
    maps = problem.coordinate_maps()
    out = {}
    for name, m in problem.models().items():
        if set(m.coordinates) == set(ref) or name not in maps:
            continue
        used = set()
        for v in maps[name].values():
            used |= sp.sympify(v, strict=True).atoms(sp.core.function.AppliedUndef)
        idx = [i for i, q in enumerate(ref) if q in used]
        if len(idx) < len(ref):
            out[name] = idx
    return out


def _reaction_dimension_issues(problem) -> list[str]:
    """A declared reaction whose dimension does not fit the equations it appears in.

    In each equation the reaction's coefficient times its declared dimension must have the
    dimension of the rest of the equation; decided from the structure, without solving.
    """
    from dualmech.model.dimensions import dimension_reader, format_dimension, reduce
    dims = problem.dimensions()
    declared = problem.reaction_info()
    out, seen = [], set()
    for mname, m in problem.models().items():
        if not m.unknowns:
            continue
        held = m.plain_matrix_se()   # in symengine, as the derivation left it
        if held is not None:
            A, b, names = held
            us = [se.Symbol(st.qdd.name) for st in m.states] + \
                [se.Symbol(u.name) for u in m.unknowns]
            rows = [sum((A[i, k] * us[k] for k in range(A.cols)), se.Integer(0)) - b[i]
                    for i in range(A.rows)]
        else:
            A, _ = m.matrix()
            us, rows, names = list(m.unknowns), list(m.equations), None
        dimension_of = dimension_reader(dims, names, held=held is not None)
        for j, u in enumerate(m.unknowns):
            info = declared.get(u.name)
            if info is None or u.name in seen:
                continue
            for i, e in enumerate(rows):
                coeff = A[i, m.n + j]
                if coeff == 0:
                    continue
                if held is not None:
                    rest = (e - coeff * us[m.n + j]).expand()
                else:
                    rest = sp.expand(e - coeff * u)
                if rest == 0:
                    continue
                try:
                    dc = dimension_of(coeff)
                    dr = dimension_of(rest)
                except (ValueError, KeyError, TypeError):
                    continue
                need = tuple(sorted(dict(dr).items()))
                have = dict(dc)
                for name, e_ in reduce(info.dimension):
                    have[name] = have.get(name, 0) + e_
                have = tuple(sorted((k, v) for k, v in have.items() if v != 0))
                if have != need:
                    want = dict(dr)
                    for name, e_ in dc:
                        want[name] = want.get(name, 0) - e_
                    want = tuple(sorted((k, v) for k, v in want.items() if v != 0))
                    out.append(f"reaction {u.name}: declared {format_dimension(info.dimension)}"
                               f", but in `{mname}` [{m.labels[i]}] it must be "
                               f"{format_dimension(want)}")
                    seen.add(u.name)
                break
    return out


#: more random points than any verdict needs (the false-equal bound is already < 1e-100 at 8)
MAX_POINTS = 1000


def _check_points(points) -> None:
    if isinstance(points, bool) or not isinstance(points, int) or points < 1:
        raise ValueError(f"`points` must be a positive integer (random points per verdict), "
                         f"got {points!r}.")
    if points > MAX_POINTS:  # (the CLI caps --points the same way)
        raise ValueError(f"`points` = {points} is more than a verdict needs; use at most "
                         f"{MAX_POINTS} (8 already bound a false 'equal' below 1e-100).")


def _pairs(j: Judgement, reference: str, ctx: Context, seed: int) -> list[PairResult]:
    """Per-model pair lines (each model against the reference) and shared-reaction lines."""
    names = list(j.models)
    if j.refusal:
        return [PairResult(reference, nm, False, j.method, j.points, 0.0, j.seconds,
                           [Mismatch(nm, "all", j.refusal)] if i == 0 else [])
                for i, nm in enumerate(n for n in names if n != reference)]
    explained = {}
    for nm in j.odd:
        if j.fault_of(nm):
            against = tuple(a for a in (j.majority or names) if a != nm)
            explained[nm] = explain_model(nm, j, against, ctx, seed)
    out, ref_shown = [], False
    bound = j.bound
    for nm in names:
        if nm == reference:
            continue
        motion_faults = lambda x: [f for f in j.fault_of(x) if f.kind != "reactions"]  # noqa
        both_ok = not motion_faults(nm) and not motion_faults(reference)
        same = j.equivalent or frozenset((nm, reference)) in j.agreeing
        ok = both_ok and same
        mism = list(explained.get(nm, []))
        if reference in explained and not ref_shown:
            mism += explained[reference]
            ref_shown = True
        out.append(PairResult(reference, nm, ok, j.method, j.points, bound if ok else 0.0,
                              j.seconds, mism))
    # one line per group of models sharing reactions, then each referee against its model
    groups: dict = {}
    for nm, m in j.models.items():
        if nm in j.referees:
            continue
        for u in m.unknowns:
            groups.setdefault(str(u), []).append(nm)
    lines: dict = {}
    for u, holders in groups.items():
        if len(holders) >= 2:
            lines.setdefault(tuple(holders), []).append(u)
    for ref, direct in j.referees.items():
        if ref in j.withdrawn or ref not in j.models:
            continue
        shared = [str(u) for u in j.models[ref].unknowns
                  if str(u) not in j.undetermined.get(ref, ())]
        if shared:
            lines.setdefault((direct, ref), []).extend(shared)
    motion_ok = not [f for f in j.faults if f.kind != "reactions"]
    explained_r: set = set()
    for holders, shared in lines.items():
        kind = "referee reactions" if holders[-1] in j.referees else "reactions"
        bad = [r for r in j.reaction_faults if r.name in shared
               and set(holders) & set(r.suspects)]
        mism = []
        for r in bad:
            if r.name in explained_r:
                continue
            explained_r.add(r.name)
            others = ", ".join(r.agreeing) if r.agreeing else None
            for suspect in r.suspects:
                rest = tuple(x for x in r.agreeing + r.suspects if x != suspect)
                mm = explain_reaction(r.name, suspect, rest, j, ctx, seed)
                if others:
                    mm.reason += f" ({others} agree)"
                mism.append(mm)
        ok = motion_ok and not bad
        out.append(PairResult(holders[0], ", ".join(holders[1:]), ok, j.method, j.points,
                              bound if ok else 0.0, j.seconds, mism, kind,
                              tuple(shared), decided=motion_ok))
    return out


def compare_models(reference: EquationSet, candidate: EquationSet, *, points: int = 8,
                   seed: int = 0, context: Context | None = None,
                   explain: bool = True) -> PairResult:
    """Is ``candidate`` the same motion as ``reference``?  Both must use the same coordinates.

    >>> import sympy as sp
    >>> from dualmech import coordinate, t, EquationSet
    >>> th = coordinate("theta"); m, l, g = sp.symbols("m l g", positive=True)
    >>> a = EquationSet("a", (th,), (m*l**2*th.diff(t, 2) + m*g*l*sp.sin(th),))
    >>> b = EquationSet("b", (th,), (th.diff(t, 2) + g/l*sp.sin(th),))
    >>> compare_models(a, b).equivalent
    True
    >>> bad = EquationSet("bad", (th,), (th.diff(t, 2) - g/l*sp.sin(th),))
    >>> r = compare_models(a, bad); r.equivalent, r.mismatches[0].residual
    (False, '-2*g*sin(theta)/l')
    """
    _check_points(points)
    if set(candidate.coordinates) != set(reference.coordinates):
        raise ModelError(f"`{candidate.name}` uses coordinates {list(candidate.coordinates)} but "
                         f"`{reference.name}` uses {list(reference.coordinates)}; rewrite one "
                         "with EquationSet.change_coordinates first.")
    rname, cname = reference.name, candidate.name
    if cname == rname:
        cname = f"{cname} (candidate)"
    ctx = context or Context.for_models(reference, candidate)
    j = judge({rname: reference, cname: candidate}, context=ctx, points=points, seed=seed,
              reference=rname)
    mism = []
    if not j.equivalent and explain:
        mism = explain_model(cname, j, (rname,), ctx, seed) if j.fault_of(cname) or \
            not j.fault_of(rname) else explain_model(rname, j, (cname,), ctx, seed)
    elif not j.equivalent:
        mism = [Mismatch(candidate.name, f.model, f.detail or f.kind) for f in j.faults] or \
            [Mismatch(candidate.name, f"reaction {r.name}",
                      f"{r.name} differs from the value `{rname}` gives")
             for r in j.reaction_faults]
    for m in mism:
        if m.model == cname:
            m.model = candidate.name
    motion_ok = not j.faults
    return PairResult(rname, candidate.name, motion_ok, j.method, j.points,
                      j.bound if motion_ok else 0.0, j.seconds, mism)


def compare_reactions(reference: EquationSet, first: EquationSet, second: EquationSet,
                      names: Sequence, *, points: int = 8, seed: int = 0,
                      context: Context | None = None, explain: bool = True) -> PairResult:
    """Do ``first`` and ``second`` give the same values of the reactions ``names``?"""
    models = {reference.name: reference}
    models.setdefault(first.name, first)
    models.setdefault(second.name, second)
    ctx = context or Context.for_models(*models.values())
    j = judge(models, context=ctx, points=points, seed=seed, reference=reference.name)
    wanted = {str(u) for u in names}
    bad = [r for r in j.reaction_faults if r.name in wanted]
    undetermined = [f for f in j.faults if f.kind == "reactions"]
    mism = [explain_reaction(r.name, second.name, (first.name,), j, ctx, seed) if explain
            else Mismatch(second.name, f"reaction {r.name}",
                          f"{r.name} differs from the value `{first.name}` gives") for r in bad]
    mism += [Mismatch(f.model, "reactions", f.detail) for f in undetermined]
    ok = not bad and not undetermined
    return PairResult(first.name, second.name, ok, j.method, j.points,
                      j.bound if ok else 0.0, j.seconds, mism, "reactions",
                      tuple(str(u) for u in names))


def reaction_pairs(problem, models: dict | None = None, *, points: int = 8, seed: int = 0,
                   context: Context | None = None, explain: bool = True) -> list[PairResult]:
    """Compare the reactions of every two models that declare a reaction of the same name."""
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


def recover_reactions(problem, limits: Budget | None = None) -> dict:
    """Symbolic reactions ``{name: expression in q, q', t}`` from the direct model(s) (display;
    raises :class:`~dualmech.verify.display.OverBudget` past the budget)."""
    out = {}
    for m in problem.models().values():
        if not m.unknowns or all(u.name in out for u in m.unknowns):
            continue
        m = _drop_zero_rows(problem.in_reference_coordinates(m))
        if not m.is_square:
            continue
        _, sol = solve_with_static(m, limits)
        for u in m.unknowns:
            out.setdefault(u.name, sol[u])
    return out


def solve_with_static(eqs: EquationSet, limits: Budget | None = None) -> tuple[dict, dict]:
    """``(static, solution)`` of a square ``eqs`` for display.

    ``solution`` maps accelerations and reactions to expressions (as
    :func:`~dualmech.verify.display.solve_display`).  When the system is singular because
    some rows hold no acceleration and no reaction (the balance of a massless body) and some
    coordinates have no inertia, those static rows are solved for those coordinates first
    (``static``: ``{q(t): expression}``), substituted into the other rows, and the rest is
    solved; the static coordinates' accelerations are then not in ``solution``.

    >>> from dualmech.problems import get
    >>> static, sol = solve_with_static(get("copying_machine").model("lagrange"))
    >>> static
    {theta(t): L*k2*y(t)/(L**2*k2 + a**2*k1)}
    """
    try:
        return {}, solve_display(eqs, limits)
    except (ValueError, ZeroDivisionError) as exc:
        singular = exc
    A, _ = eqs.matrix()
    n = len(eqs.coordinates)
    static_rows = [i for i in range(A.rows) if all(A[i, j] == 0 for j in range(A.cols))]
    massless = [q for j, q in enumerate(eqs.coordinates)
                if all(A[i, j] == 0 for i in range(A.rows))]
    if not static_rows or len(static_rows) != len(massless) or len(massless) == n:
        raise singular
    plain = {q: sp.Symbol(f"_{q.func.__name__}_static") for q in massless}
    rows = [eqs.equations[i].xreplace(plain) for i in static_rows]
    if any(r.has(sp.Derivative) for r in rows):
        raise singular
    with budget((limits or Budget()).remaining()):
        found = sp.solve(rows, list(plain.values()), dict=True)
    if len(found) != 1 or set(found[0]) != set(plain.values()):
        raise ValueError(f"the static rows do not fix {[q.func.__name__ for q in massless]} "
                         "uniquely; not solved symbolically")
    static = {q: sp.factor(found[0][plain[q]]) for q in massless}
    keep = [i for i in range(len(eqs.equations)) if i not in static_rows]
    reduced = EquationSet(eqs.name, [q for q in eqs.coordinates if q not in static],
                          [eqs.equations[i].subs(static).doit() for i in keep], eqs.unknowns,
                          [eqs.labels[i] for i in keep])
    return static, solve_display(reduced, limits)


def _drop_zero_rows(m: EquationSet) -> EquationSet:
    rows = m.equations
    held = m.plain_matrix_se()
    if isinstance(rows, Rows) and held is not None:
        # held in symengine: a row clearly nonzero at a random point (100 bits) is kept
        # without expanding it (expanding a bicycle's rows takes seconds); the others are
        # expanded there, never through the sympy form
        keep = [i for i, e in enumerate(rows.se) if _nonzero_row(held, i, e)]
    elif isinstance(rows, Rows):
        keep = [i for i, e in enumerate(rows.se) if se.expand(e) != 0]
    else:
        keep = [i for i, e in enumerate(rows) if sp.expand(e) != 0]
    if len(keep) == len(m.equations):
        return m
    return EquationSet(m.name, m.coordinates, [m.equations[i] for i in keep], m.unknowns,
                       [m.labels[i] for i in keep])



def _nonzero_row(held, i: int, row) -> bool:
    """Whether row ``i`` (``A[i, :]``, ``b[i]`` of ``held``) is not identically zero: whether
    some entry is not (see :func:`~dualmech.model._algebra.is_zero_held`)."""
    A, b, _ = held
    entries = [x for x in list(A.row(i)) + [b[i]] if x != 0]
    if not entries:
        return False
    return any(not is_zero_held(x, f"zero rows {i}") for x in entries)
