"""Mutation testing of the comparator: break a model on purpose and check the break is caught.

For every model of a problem the generator makes broken variants: drop one ingredient (a force,
a torque, a reaction, an energy term, a generalised force, the inertia term of a body), flip
the sign of one ingredient or of one unknown reaction, double one ingredient (e.g. one body's mass in its inertia term
only), double one mass or inertia parameter everywhere, swap two parameters of the same
dimension.  Each mutant
is compared with an unbroken model of the same problem -- its motion, and its reactions with
those of any other model that derives the same reactions -- and the comparator must report it
as disagreeing and name an equation (or the reaction that differs).  Mutants that are *identical* to the original model (a
dropped term that was zero, a swap of two parameters that enter symmetrically) cannot be caught
by any comparator; neither can one whose every equation is a constant (state-independent)
multiple of the original's -- e.g. doubling the car's mass, which scales out of its motion.
Both are detected exactly and reported apart, not counted.  Neither is a survivor that the
comparator, judging it against its own unbroken model, finds *equivalent*: the same motion,
the same reactions and the same value of every one of them -- e.g. the flipped or doubled
constraint of a multiplier that vanishes identically (``-N`` and ``2 N`` are ``N`` when
``N = 0``).  Such a mutant claims nothing false, so no comparator could catch it; it is
reported apart too.  Only a mutant that got past the full comparison is tested for this, so
no caught mutant is ever reclassified.

The sign of each *unknown* reaction is flipped too, one unknown at a time (``R -> -R`` in the
direct form's free-body diagram, ``lambda -> -lambda`` in a multiplier model).  Such a model
is the original with the unknown renamed, so its motion cannot change: only the recovered
reaction changes sign.  It is caught by the reactions comparison -- a reaction derived by a
second model (a direct form beside a multiplier form), or by the Kane referee dualmech derives
from the direct model's declarations (:mod:`dualmech.verify.referee`) -- and never by the
equations of motion.

The derivations are judged as :func:`~dualmech.verify.check.compare` judges them, referees
included.  A mutant edits a model's *equations* (its balances and projections); the referee
is derived from the model's unbroken *declarations*, so it catches the mutant as it catches a
balance or projection written wrong by hand.  The same mistake made in a declaration (a load
declared with the wrong sign) is shared with the referee, and only a second model written
independently catches it.  A survivor that changes only reactions which no second derivation
gives (a direct model without a referee, the problem's only model deriving them) is
*uncatchable* with the problem's derivations: reported apart, with the model that would catch
it, and not counted.  Where the reaction vanishes identically on the motion (``-N`` is ``N``
when ``N = 0``) the flipped model claims nothing false and is reported as *equivalent*.

Mutants that raise (``errored``) or on which the comparator gives no verdict
(``undetermined``) are reported apart too: neither is a catch.  The kill rate is over the
judged mutants only.

Example
-------
>>> from dualmech.problems import get
>>> report = mutation_report(get("simple_pendulum"), points=1)
>>> report.kill_rate, report.errored, report.undetermined
(1.0, [], [])
"""
from __future__ import annotations

import itertools
import random
from dataclasses import dataclass, field
from typing import Iterator

from dualmech.verify.check import claims_of
from dualmech.verify.referee import referees
from dualmech.verify.sampling import Context
from dualmech.verify.verdicts import judge
from dualmech.model.dimensions import INERTIA, MASS, reduce
from dualmech.model.equations import EquationSet, ModelError, to_plain
from dualmech.exact.form import ExactForm

__all__ = ["Mutant", "MutationReport", "mutants", "mutation_report"]


@dataclass(frozen=True)
class Mutant:
    """A deliberately broken copy of one model."""

    model: str
    description: str
    equations: EquationSet


@dataclass
class MutationReport:
    """Outcome of :func:`mutation_report`."""

    problem: str
    killed: list = field(default_factory=list)      # (mutant description, equations named)
    survived: list = field(default_factory=list)    # mutant descriptions
    why: dict = field(default_factory=dict)         # survivor -> why it survived
    uncatchable: list = field(default_factory=list)  # no second derivation could catch it
    identical: list = field(default_factory=list)   # mutants equal to their original
    equivalent: list = field(default_factory=list)  # same motion and reactions as the original
    errored: list = field(default_factory=list)     # (mutant description, the error raised)
    undetermined: list = field(default_factory=list)  # (mutant description, why no verdict)

    @property
    def total(self) -> int:
        """Mutants with a verdict: caught or survived (errored, undetermined, identical,
        equivalent and uncatchable ones are reported apart and not counted)."""
        return len(self.killed) + len(self.survived)

    @property
    def kill_rate(self) -> float:
        """Caught over judged; ``nan`` when no mutant was judged (nothing to score)."""
        return len(self.killed) / self.total if self.total else float("nan")

    def to_dict(self) -> dict:
        """The report as JSON data (``kill_rate`` is ``None`` when nothing was judged)."""
        return {"problem": self.problem, "caught": len(self.killed), "judged": self.total,
                "kill_rate": self.kill_rate if self.total else None,
                "killed": [{"mutant": d, "named": list(n)} for d, n in self.killed],
                "survived": [{"mutant": d, "why": self.why.get(d, "")}
                             for d in self.survived],
                "uncatchable": [{"mutant": d, "why": self.why.get(d, "")}
                                for d in self.uncatchable],
                "identical": list(self.identical), "equivalent": list(self.equivalent),
                "errored": [{"mutant": d, "error": e} for d, e in self.errored],
                "undetermined": [{"mutant": d, "why": w} for d, w in self.undetermined]}

    def __str__(self) -> str:
        rate = f"{100 * self.kill_rate:.0f} %" if self.total else "no verdict"
        lines = [f"{self.problem}: {len(self.killed)}/{self.total} mutants caught "
                 f"({rate}), {len(self.identical)} identical to the original, "
                 f"{len(self.equivalent)} equivalent (same motion and reactions), "
                 + (f"{len(self.uncatchable)} uncatchable by these derivations, "
                    if self.uncatchable else "")
                 + f"{len(self.errored)} errored, {len(self.undetermined)} undetermined "
                 "(none of those counted)"]
        for d in self.survived:
            lines.append(f"  SURVIVED: {d}")
            if d in self.why:
                lines.append(f"    {self.why[d]}")
        for d in self.uncatchable:
            lines.append(f"  UNCATCHABLE: {d}")
            lines.append(f"    {self.why[d]}")
        for d, why in self.errored:
            lines.append(f"  ERRORED: {d}: {why}")
        for d, why in self.undetermined:
            lines.append(f"  UNDETERMINED: {d}: {why}")
        for d in self.equivalent:
            lines.append(f"  EQUIVALENT: {d}")
        return "\n".join(lines)


def mutants(problem) -> Iterator[Mutant]:
    """Every broken variant of every model of ``problem``."""
    params = list(problem.parameters)
    for name, m in problem.models().items():
        free = set().union(*(e.free_symbols for e in m.equations))
        for key in m.ingredients():
            yield Mutant(name, f"{name}: drop `{key}`", m.without(key))
            if not key.startswith("reaction "):
                yield Mutant(name, f"{name}: flip the sign of `{key}`", m.flipped(key))
                yield Mutant(name, f"{name}: double `{key}`", m._edit(key, 2, f"{name} x2 {key}"))
        for u in m.unknowns:
            yield Mutant(name, f"{name}: flip the sign of unknown `{u}`",
                         m.substitute({u: -u}))
        heavy = {reduce(MASS), reduce(INERTIA)}
        for p in params:
            if p.symbol in free and reduce(p.dimension) in heavy:
                yield Mutant(name, f"{name}: double `{p.symbol}`",
                             m.substitute({p.symbol: 2 * p.symbol}))
        for p, r in itertools.combinations(params, 2):
            if (p.symbol in free or r.symbol in free) and \
                    reduce(p.dimension) == reduce(r.dimension):
                yield Mutant(name, f"{name}: swap `{p.symbol}` and `{r.symbol}`",
                             m.substitute({p.symbol: r.symbol, r.symbol: p.symbol}))


def _identical(original: EquationSet, mutant: EquationSet, parameters, seed: int = 0) -> bool:
    """Exactly: is every mutant equation a state-independent multiple of the original one?

    Such a mutant (a dropped term that was zero; a mass that scales out of every equation; a
    swap of parameters that enter symmetrically) is the same motion by construction.  Tested
    at pairs of random points that share the parameter values but differ in everything else.
    """
    coords = original.coordinates
    exprs = []
    for a, b in zip(mutant.equations, original.equations):
        exprs += [to_plain(a, coords), to_plain(b, coords)]
    symbols = sorted(set().union(*(e.free_symbols for e in exprs)), key=str)
    form = ExactForm.build(exprs, symbols)
    params = set(parameters)
    rng = random.Random(seed)
    checked = 0
    for _ in range(30):
        p1 = form.sample(rng)
        p2 = form.sample(rng)
        for key in p1:
            key_syms = key.free_symbols if hasattr(key, "free_symbols") else {key}
            if key_syms <= params:
                p2[key] = p1[key]
        try:
            v1, v2 = form.evaluate(p1), form.evaluate(p2)
        except ZeroDivisionError:
            continue
        for i in range(0, len(v1), 2):
            # mutant_i * original_i(other point) == mutant_i(other) * original_i: same ratio
            if v1[i] * v2[i + 1] != v2[i] * v1[i + 1]:
                return False
            if (v1[i] == 0) != (v1[i + 1] == 0):
                return False
        checked += 1
        if checked == 3:
            return True
    return checked > 0   # no point could be evaluated: nothing shows they are the same


def mutation_report(problem, points: int = 3, seed: int = 0) -> MutationReport:
    """Generate every mutant of ``problem`` and check that the comparator catches it.

    Each mutant replaces its original among ALL the problem's derivations, which are judged
    together exactly as :func:`dualmech.verify.check.compare` judges them; the mutant is caught when
    the verdict is "disagree" and names the mutant's derivation among the faulty ones (the
    odd one out, or a suspect of a tie) or a reaction it gives differently.
    """
    if isinstance(points, bool) or not isinstance(points, int) or not 1 <= points <= 1000:
        raise ValueError(f"`points` must be an integer from 1 to 1000 (random points per "
                         f"verdict), got {points!r}.")
    report = MutationReport(problem.name)
    models = {n: problem.in_reference_coordinates(m) for n, m in problem.models().items()}
    if len(models) < 2:
        raise ValueError(f"`{problem.name}` has a single derivation ({', '.join(models)}): a "
                         "mutant can only be caught against a second, independent one; add a "
                         "second model before scoring mutants.")
    ref_model = problem.model(problem.reference)
    ctx = Context(ref_model.coordinates, problem.parameter_symbols, problem)
    claims = claims_of(problem)
    refs = referees(problem)   # judged as `check` judges: the referee votes, with reactions
    models.update(refs.models)
    claims.update({r: claims[d] for r, d in refs.of.items() if d in claims})
    unbroken = judge(models, context=ctx, points=points, seed=seed,
                     reference=problem.reference, claims=claims, referees=refs.of)
    if not unbroken.equivalent:
        # a mutant that happens to repair the disagreement would pass for a gap in the checks
        raise ValueError(f"`{problem.name}`'s derivations disagree before any mutant is made "
                         f"(`dualmech check {problem.name}` shows where): mutants can only be "
                         "scored against derivations that agree; fix them first.")
    for mut in mutants(problem):
        original = problem.models()[mut.model]
        if _identical(original, mut.equations, problem.parameter_symbols, seed):
            report.identical.append(mut.description)
            continue
        try:
            candidate = _in_ref(problem, mut.equations, original)
            trial = dict(models)
            trial[mut.model] = candidate
            j = judge(trial, context=ctx, points=points, seed=seed,
                      reference=problem.reference, claims=claims, referees=refs.of)
        except (ModelError, ValueError, TypeError, ArithmeticError) as exc:
            # raising is not catching: the comparator gave no verdict on this mutant
            report.errored.append((mut.description, f"{type(exc).__name__}: {exc}"))
            continue
        if j.refusal or (j.points == 0 and all(f.kind == "undetermined" for f in j.faults)
                         and set(j.odd) == set(trial)):
            report.undetermined.append((mut.description, j.refusal or "no derivation "
                                        "determines the motion at any sampled state"))
            continue
        named = []
        if not j.equivalent and mut.model in j.odd:
            named = [f"{f.model}: {f.kind}" for f in j.faults if f.model == mut.model]
            named += [f"reaction {r.name}" for r in j.reaction_faults
                      if mut.model in r.suspects]
        if named:
            report.killed.append((mut.description, named))
            continue
        alone = _against_original(models[mut.model], candidate, ctx, points, seed,
                                  claims.get(mut.model))
        if _equivalent(alone, models[mut.model], candidate):
            report.equivalent.append(mut.description)
            continue
        why, gap = _why_survived(alone, candidate, mut.model in refs.of.values())
        (report.survived if gap else report.uncatchable).append(mut.description)
        report.why[mut.description] = why
    return report


def _against_original(original: EquationSet, candidate: EquationSet, ctx, points, seed,
                      claim=None):
    """The mutant judged against its own unbroken model alone (``None`` if that raises)."""
    renamed = EquationSet("original", original.coordinates, original.equations,
                          original.unknowns, original.labels)
    claims = {"original": claim, "mutant": claim} if claim is not None else None
    try:
        return judge({"original": renamed, "mutant": candidate}, context=ctx, points=points,
                     seed=seed, claims=claims)
    except (ModelError, ValueError, TypeError, ArithmeticError):
        return None


def _equivalent(j, original: EquationSet, candidate: EquationSet) -> bool:
    """Exactly: does the mutant give the motion and every reaction of its original?

    It must derive the same reactions (a dropped one is a loss, not an equivalence), and the
    comparator must reach a verdict at sampled states: then the two agree in everything a
    comparison of derivations can see, and the mutant claims nothing false.
    """
    if j is None or j.refusal or j.points == 0:
        return False
    if {u.name for u in candidate.unknowns} != {u.name for u in original.unknowns}:
        return False
    return j.equivalent


#: a survivor the problem's derivations cannot catch, whatever the comparator does
_UNCATCHABLE = ("it leaves the motion unchanged and changes only the reaction(s) {names}, "
                "which no second derivation gives ({referee}); a model that derives {names} "
                "independently (a Lagrangian with the contact freed and closed by a "
                "multiplier named {names}) would catch it")


def _why_survived(j, candidate: EquationSet, refereed: bool) -> tuple[str, bool]:
    """Why a mutant got through, and whether that is a gap in the checks (``True``) or a
    mistake no comparator could catch with the problem's derivations (``False``): it changes
    only reactions that no second derivation gives (no referee derives them)."""
    gap = "the comparator did not notice it: a gap in the checks"
    if not candidate.unknowns or j is None:
        return gap, True
    if not j.faults and j.reaction_faults and not refereed:
        names = ", ".join(r.name for r in j.reaction_faults)
        return _UNCATCHABLE.format(names=names, referee="this model has no Kane referee: "
                                   "`dualmech check` says why"), False
    return gap, True


def _in_ref(problem, mutant: EquationSet, original: EquationSet) -> EquationSet:
    renamed = EquationSet(original.name, mutant.coordinates, mutant.equations, mutant.unknowns,
                          mutant.labels, mutant.contributions, mutant.description)
    return problem.in_reference_coordinates(renamed)
