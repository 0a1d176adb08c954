"""Speed against accuracy: work-precision diagrams per problem, formulation and integrator.

:func:`work_precision` integrates every formulation of a problem
(:func:`~dualmech.numeric.formulations.formulations`: the Lagrangian ODE, the direct forms,
the maximal-coordinate DAEs) with every integrator over a sweep of tolerances (the
symplectic midpoint rule over a sweep of step sizes) and measures, against a high-accuracy
reference (the reference model with DOP853 at ``rtol = 1e-13``):

* **final error** and **path error**: the largest state error at the last sample and over
  all samples, each component divided by the width of its declared range (dimensionless);
* **reaction error**: the largest reaction error over the path divided by the largest
  reaction (dimensionless);
* **constraint drift**: the largest ``|g|`` of a DAE form (unit of the constraint);
* **energy drift**: the largest ``|E(t) - E(0)|`` where the model conserves energy (N m);

against two measures of work: the CPU seconds of the integration (the median of
``repeats`` runs, 5 by default; the spread is kept in the data) and the states the generated
code evaluated (right-hand sides, finite-difference Jacobian columns, DAE residuals).  Each
formulation is labelled with the backend its generated code ran on (compiled C or NumPy):
compare CPU times within one backend.  The DAE forms are the index-1 system unstabilised,
with Baumgarte's gains swept (:data:`~dualmech.numeric.dae.BAUMGARTE_GAINS`), projected after
every accepted step, and the index-3 and GGL forms solved by IDA.  The reference's own error
is estimated by running it again at ``1e-12``: no error below that is resolved.
:meth:`WorkPrecision.write` saves the data as CSV and JSON and the diagram as PNG and SVG: one
row per measure, CPU time on the left and evaluations on the right, log scales, each point
marked with its tolerance's exponent (``-6`` for 1e-6; the midpoint rule's with its step
count), a legend for the integrators (colours) and one for the formulations (line styles);
curves that coincide exactly (two forms that are the same ODE) are drawn once and named in
the legend, whatever backend ran them; a point that did not finish within its budget is an
``x`` at the top of its panel, at the work it spent.  The figure for a lesson -- one panel,
one line per integrator at its best formulation, the scene's parameters and initial state
stated -- is :func:`~dualmech.numeric.studies.wplesson.lesson_chart`, written beside it.

Example
-------
One model, one method, one tolerance, to keep the example fast (``dualmech chart`` sweeps
them all):

>>> import tempfile
>>> from dualmech.problems import get
>>> wp = work_precision(get("simple_pendulum"), duration=1.0, tolerances=(1e-6,), steps=(),
...                     methods=("DOP853",), models=("lagrange",), progress=False)
>>> [(r.formulation, r.method, r.success) for r in wp.runs]
[('lagrange', 'DOP853', True)]
>>> with tempfile.TemporaryDirectory() as out:
...     sorted(p.name for p in wp.write(Path(out)))  # doctest: +NORMALIZE_WHITESPACE
['simple_pendulum_workprecision.csv', 'simple_pendulum_workprecision.json',
 'simple_pendulum_workprecision.png', 'simple_pendulum_workprecision.svg',
 'simple_pendulum_workprecision_lesson.png', 'simple_pendulum_workprecision_lesson.svg']
"""
from __future__ import annotations

import csv
import json
import math
import sys
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Mapping, Sequence

import numpy as np

from dualmech.model.equations import ModelError
from dualmech.numeric.contacts import scene_span
from dualmech.numeric.dae import BAUMGARTE_GAINS, DAE_SOLVED, STABILISATIONS
from dualmech.numeric.daesolve import DAE_METHODS
from dualmech.numeric.formulations import Formulation, formulations
from dualmech.numeric.inputs import driven_problem
from dualmech.numeric.symplectic import energy_drift
from dualmech.numeric.integrators import DID_NOT_FINISH, METHODS, WorkBudget, Run
from dualmech.numeric.studies.wplesson import lesson_chart, scene_text
from dualmech.numeric.units import work_conjugate_unit

__all__ = ["RunResult", "WorkPrecision", "work_precision", "NotApplicable", "TOLERANCES",
           "STEPS", "MEASURES", "BUDGET", "QUICK_BUDGET"]

TOLERANCES = tuple(10.0 ** -k for k in range(3, 11))
#: Steps per span of the midpoint rule's sweep.
STEPS = (32, 64, 128, 256, 512, 1024, 2048)
REFERENCE_RTOL, CHECK_RTOL = 1e-13, 1e-12
#: The most one point may spend by default (the reference run: ten times as much); a run
#: past it is a *did not finish* point.  The quick sweep of ``dualmech chart`` uses
#: :data:`QUICK_BUDGET`.
BUDGET = WorkBudget(seconds=20.0, evaluations=2_000_000)
QUICK_BUDGET = WorkBudget(seconds=1.0, evaluations=100_000)
#: ``(field, axis label)`` of the measures, one chart panel each.
MEASURES = (("final_error", "state error at the end\n[relative to range]"),
            ("path_error", "state error along the path\n[relative to range]"),
            ("reaction_error", "reaction error\n[relative to largest]"),
            ("drift", "constraint drift $|g|$ [{drift_unit}]"),
            ("energy_drift", "energy drift $|E - E_0|$ [N m]"))


class NotApplicable(ModelError):
    """The chart does not apply to the problem: the message says why and which declaration
    would make it apply (a model in the reference coordinates that integrates)."""


@dataclass
class RunResult:
    """One point of the diagram (``nan`` where a measure does not apply)."""

    formulation: str
    kind: str
    method: str
    tolerance: float
    cpu: float
    calls: int
    evaluations: int
    steps: int
    success: bool
    message: str
    final_error: float = math.nan
    path_error: float = math.nan
    reaction_error: float = math.nan
    drift: float = math.nan
    energy_drift: float = math.nan
    same_as: str = ""
    backend: str = ""
    repeats: int = 1
    cpu_spread: float = math.nan
    did_not_finish: bool = False

    @property
    def curve(self) -> tuple[str, str]:
        return self.formulation, self.method


@dataclass
class WorkPrecision:
    """The sweep's results; :meth:`write` saves data and charts."""

    problem: str
    title: str
    span: tuple
    span_note: str
    samples: int
    reference_error: float
    drift_unit: str
    runs: list = field(default_factory=list)
    skipped: dict = field(default_factory=dict)
    #: the parameter values and initial conditions of the runs, as a line of text
    scene: str = ""
    #: the most one point could spend (:class:`~dualmech.numeric.integrators.WorkBudget`, as text)
    budget: str = ""

    def curves(self) -> dict:
        """``{(formulation, method): [RunResult, ...]}`` in sweep order."""
        out: dict = {}
        for r in self.runs:
            out.setdefault(r.curve, []).append(r)
        return out

    def to_dict(self) -> dict:
        head = {k: getattr(self, k) for k in ("problem", "title", "span", "span_note",
                                              "samples", "reference_error", "drift_unit",
                                              "skipped", "scene", "budget")}
        head["span"] = list(self.span)
        head["runs"] = [{k: _json(v) for k, v in asdict(r).items()} for r in self.runs]
        return head

    def write(self, out_dir: Path) -> list[Path]:
        """``NAME_workprecision.{csv,json,png,svg}`` (the full grid) and
        ``NAME_workprecision_lesson.{png,svg}`` (the one-panel figure of
        :func:`~dualmech.numeric.studies.wplesson.lesson_chart`) in ``out_dir``; returns the
        paths."""
        out_dir = Path(out_dir)
        out_dir.mkdir(parents=True, exist_ok=True)
        stem = out_dir / f"{self.problem}_workprecision"
        rows = [asdict(r) for r in self.runs]
        with open(stem.with_suffix(".csv"), "w", newline="") as fh:
            writer = csv.DictWriter(fh, fieldnames=list(rows[0]) if rows else ["formulation"])
            writer.writeheader()
            writer.writerows(rows)
        stem.with_suffix(".json").write_text(json.dumps(self.to_dict(), indent=1) + "\n")
        lesson = out_dir / f"{self.problem}_workprecision_lesson"
        return [stem.with_suffix(".csv"), stem.with_suffix(".json")] + self.chart(stem) \
            + lesson_chart(self, lesson)

    def chart(self, stem: Path) -> list[Path]:
        from dualmech.numeric.charts import METHOD_COLORS, panels, save, style_of
        measures = [(k, label.format(drift_unit=self.drift_unit)) for k, label in MEASURES
                    if any(np.isfinite(getattr(r, k)) for r in self.runs)]
        fig, axes = panels(2 * len(measures), f"{self.problem}: work against precision, "
                           f"t in [{self.span[0]:g}, {self.span[1]:.3g}] s; each point "
                           "marked with log10(tolerance) (midpoint: steps)", height=2.6,
                           width=17.0, columns=2, sharex=False)
        forms = list(dict.fromkeys(r.formulation for r in self.runs))
        for row, (key, label) in enumerate(measures):
            for col, work in enumerate(("cpu", "evaluations")):
                ax = axes[2 * row + col]
                for (form, method), runs in self.curves().items():
                    if runs[0].same_as:
                        continue
                    ok = [r for r in runs if r.success and np.isfinite(getattr(r, key))]
                    if not ok:
                        continue
                    ls, mk = style_of(forms.index(form))
                    colour = METHOD_COLORS.get(method, "k")
                    xs = [max(float(getattr(r, work)), 1e-5) for r in ok]
                    ys = [max(getattr(r, key), 1e-17) for r in ok]
                    ax.plot(xs, ys, linestyle=ls, marker=mk, markersize=3.5, color=colour,
                            linewidth=1.1)
                    for r, x, y in zip(ok, xs, ys):
                        ax.annotate(_tag(r), (x, y), xytext=(2, 2), textcoords="offset points",
                                    fontsize=4.5, color=colour, alpha=0.8)
                for r in self.runs:  # did not finish: an x at the top, at the work spent
                    if r.did_not_finish and np.isfinite(getattr(r, work)) and \
                            getattr(r, work) > 0:
                        ax.plot([getattr(r, work)], [0.97], "x", markersize=6,
                                color=METHOD_COLORS.get(r.method, "k"),
                                transform=ax.get_xaxis_transform(), clip_on=False)
                ax.set_xscale("log")
                ax.set_yscale("log")
                if col == 0:
                    ax.set_ylabel(label, fontsize="small")
                ax.grid(True, which="major", alpha=0.3)
                if key in ("final_error", "path_error"):
                    ax.axhline(self.reference_error, color="0.5", linewidth=0.8, linestyle=":")
        axes[-2].set_xlabel("CPU time of the integration [s] (median of the repeats)")
        axes[-1].set_xlabel("states evaluated (RHS calls, Jacobian columns, DAE residuals)")
        _legends(fig, self, forms)
        if self.skipped:
            fig.text(0.735, 0.05, not_run_note(self.skipped), fontsize="x-small",
                     va="bottom", ha="left", color="0.25")
        fig.subplots_adjust(left=0.06, right=0.72, top=0.96, bottom=0.05, hspace=0.3,
                            wspace=0.12)
        return save(fig, stem, tight=False)


def not_run_note(skipped: Mapping, width: int = 62, each: int = 180) -> str:
    """The chart's note on the forms it could not run and why (each reason shortened).

    >>> print(not_run_note({"m (DAE, index 3)": "not applicable to the index-3 form: x."}))
    not run:
    m (DAE, index 3): not applicable to the index-3
        form: x.
    """
    import textwrap
    lines = ["not run:"]
    for form, why in skipped.items():
        text = textwrap.shorten(f"{form}: {why}", each, placeholder=" ...")
        lines += textwrap.wrap(text, width, subsequent_indent="    ")
    return "\n".join(lines)


def _tag(r: "RunResult") -> str:
    """The tolerance's exponent (``-6``), or the midpoint rule's step count."""
    if r.method == "midpoint":
        return f"{r.steps}"
    return f"{math.log10(r.tolerance):.0f}"


def _legends(fig, wp: WorkPrecision, forms) -> None:
    from matplotlib.lines import Line2D
    from dualmech.numeric.charts import METHOD_COLORS, style_of
    methods = list(dict.fromkeys(r.method for r in wp.runs))
    same = {r.formulation: r.same_as.split(" x ")[0] for r in wp.runs if r.same_as}
    h1 = [Line2D([], [], color=METHOD_COLORS.get(m, "k"), label=m) for m in methods]
    h2 = []
    backends = {r.formulation: r.backend for r in wp.runs}
    for i, f in enumerate(forms):
        ls, mk = style_of(i)
        note = f"\n    identical to {same[f]}: drawn once" if f in same else ""
        tag = f" [{backends[f]}]" if backends.get(f) else ""
        h2.append(Line2D([], [], color="0.3", linestyle=ls, marker=mk, label=f + tag + note))
    h2.append(Line2D([], [], color="0.5", linestyle=":", label="reference's own error"))
    h2.append(Line2D([], [], color="0.3", linestyle="", marker="x",
                     label="did not finish within the budget\n    (at the top, at the work spent)"))
    fig.legend(handles=h1, title="integrator (colour)", fontsize="small", loc="upper left",
               bbox_to_anchor=(0.735, 0.96))
    fig.legend(handles=h2, title="formulation [backend of its generated code]\n"
               "(line and marker)", fontsize="x-small", loc="upper left",
               bbox_to_anchor=(0.735, 0.96 - 0.028 * (len(methods) + 2)))


def _json(v):
    if isinstance(v, float) and not math.isfinite(v):
        return None
    if isinstance(v, (np.floating, np.integer)):
        return _json(v.item())
    return v


def _measure(f: Formulation, run: Run, ref: dict, te: np.ndarray) -> dict:
    """The five measures of one run against the mapped reference ``ref``."""
    out = {}
    if not run.success or run.t.size != te.size:
        return out
    Yr = ref["states"][f.name]
    err = np.abs(run.y - Yr) / f.scales[:, None]
    out["final_error"] = float(err[:, -1].max())
    out["path_error"] = float(err.max())
    R = f.reactions(te, run.y)
    common = [k for k in R if k in ref["reactions"]]
    if common and ref["reaction_scale"] > 0:
        out["reaction_error"] = max(float(np.abs(R[k] - ref["reactions"][k]).max())
                                    for k in common) / ref["reaction_scale"]
    d = f.drift(run.y)
    if d is not None:
        out["drift"] = float(np.abs(d[0]).max())
    if f.energy_change(run.y[:, :1]) is not None:   # on a fixed-step method's own steps
        out["energy_drift"] = energy_drift(f.energy_change, run)
    return out


def _reference_form(forms, coordinates: tuple) -> Formulation | None:
    """The formulation that gives the reference motion: the first ODE in the reference
    model's coordinates (the reference model itself unless it is constrained); failing
    that, the first DAE form projected after every step in those coordinates (a model with
    static rows or constraints and no ODE form: DOP853 with the state put back on the
    manifold after each step, so the reference itself does not drift off it)."""
    same = [f for f in forms if tuple(f.coordinates) == coordinates]
    return next((f for f in same if f.kind == "ode"), None) or \
        next((f for f in same if f.stabilisation == "projection"), None)


def _drift_unit(problem, constraints, k: int) -> str:
    """The unit of constraint ``k``'s drift: conjugate to its multiplier's (per second at
    velocity level); a static balance's residual is a force or moment (``"?"`` unknown)."""
    u = constraints.multipliers[k]
    info = problem.reaction_info()
    if u is None or u.name not in info:
        return "static row residual" if u is None else "?"
    unit = work_conjugate_unit(info[u.name].dimension)
    return unit + "/s" if constraints.levels[k] == "velocity" else unit


def _scaled(budget: WorkBudget, factor: float) -> WorkBudget:
    return WorkBudget(budget.seconds and budget.seconds * factor,
                  budget.evaluations and int(budget.evaluations * factor))


def _reference(forms, span, te, budget: WorkBudget | None = None) -> tuple[dict, float]:
    base = forms[0]
    n = base.n
    run = base.run("DOP853", span, te, rtol=REFERENCE_RTOL, budget=budget)
    check = base.run("DOP853", span, te, rtol=CHECK_RTOL, budget=budget) if run.success \
        else run
    if not (run.success and check.success):
        raise RuntimeError(f"the reference run ({base.name}, DOP853 at rtol "
                           f"{REFERENCE_RTOL:g}) failed: {run.message or check.message}")
    error = float((np.abs(run.y - check.y) / base.scales[:, None]).max())
    states = {f.name: f.from_reference(te, run.y[:n], run.y[n:]) for f in forms}
    reactions = {}
    for f in forms:
        for k, v in f.reactions(te, states[f.name]).items():
            reactions.setdefault(k, v)
    scale = max((float(np.abs(v).max()) for v in reactions.values()), default=0.0)
    return {"states": states, "reactions": reactions, "reaction_scale": scale}, error


def _identical(runs: list[RunResult]) -> None:
    """Mark curves whose every run equals an earlier curve's (same steps, same errors, and
    the same backend: a C curve identical to a NumPy one in its numbers differs in CPU time,
    the point of the CPU panel, and stays drawn)."""
    curves: dict = {}
    for r in runs:
        curves.setdefault(r.curve, []).append(r)
    seen = []
    keys = ("steps", "calls", "final_error", "path_error", "reaction_error", "energy_drift",
            "backend")
    for curve, rs in curves.items():
        sig = [tuple(_json(getattr(r, k)) for k in keys) for r in rs]
        for other, osig in seen:
            if other[1] == curve[1] and osig == sig:
                for r in rs:
                    r.same_as = f"{other[0]} x {other[1]}"
                break
        else:
            seen.append((curve, sig))


def work_precision(problem, *, duration: float = 5.0, tolerances: Sequence[float] = TOLERANCES,
                   steps: Sequence[int] = STEPS,
                   methods: Sequence[str] = METHODS + DAE_METHODS,
                   models: Sequence[str] | None = None, samples: int = 101,
                   params: Mapping | None = None, y0=None, progress: bool = True,
                   stabilisations: Sequence[str] = STABILISATIONS + DAE_SOLVED,
                   baumgarte_gains: Sequence[float] = BAUMGARTE_GAINS,
                   repeats: int = 5, budget: WorkBudget | None = BUDGET) -> WorkPrecision:
    """The sweep of the module docstring over ``duration`` seconds (cut to fit the scene);
    ``models``, ``stabilisations`` and ``baumgarte_gains`` narrow the formulations;
    ``repeats`` runs per point give its CPU time (their median; fewer once a point's runs
    have spent ``budget.seconds``).  A run past ``budget`` (:class:`~dualmech.numeric.
    integrators.WorkBudget`) is a *did not finish* point (``did_not_finish``), and so are the
    tighter tolerances of its curve, recorded as not run (a tighter tolerance costs more);
    the reference run gets ten times the budget."""
    if repeats < 1:
        raise ValueError(f"`repeats` must be at least 1, got {repeats}.")
    budget = budget or WorkBudget()
    problem = driven_problem(problem)   # given inputs: their declared default histories
    from tqdm import tqdm

    from dualmech.progress import is_tty
    asked = None if models is None else tuple(models) + (problem.reference,)
    forms, skipped = formulations(problem, params, y0, models=asked,
                                  stabilisations=stabilisations,
                                  baumgarte_gains=baumgarte_gains)
    coords = tuple(problem.model(problem.reference).coordinates)
    if models is not None and not _reference_form(forms, coords):
        forms, skipped = formulations(problem, params, y0, stabilisations=stabilisations,
                                      baumgarte_gains=baumgarte_gains)
    base = _reference_form(forms, coords)
    only_reference = base is None and "projection" not in stabilisations
    if only_reference:   # the projected DAE gives the reference; not charted unless asked
        more, _ = formulations(problem, params, y0, stabilisations=("projection",))
        base = _reference_form(more, coords)
        forms.insert(0, base) if base is not None else None
    if base is None:
        why = skipped.get(problem.reference, "it has no formulation").rstrip(".")
        raise NotApplicable(f"not applicable: no model of `{problem.name}` in its reference "
                            f"coordinates integrates as an ODE, nor as a DAE projected "
                            f"after every step, to give the chart's reference motion; the "
                            f"reference model `{problem.reference}`: {why}.")
    forms.remove(base)
    forms.insert(0, base)
    dae = base.kind == "dae"   # a DAE reference: its consistent start, its index-1 form
    scene = scene_span(problem, duration, base.y0 if dae else y0, params,
                       rhs=base.rhs if dae else None)
    span = (scene.t0, scene.t_end)
    te = np.linspace(span[0], span[1], samples)
    ref, ref_error = _reference(forms, span, te, _scaled(budget, 10))
    if only_reference:
        forms = forms[1:]
    if models is not None:  # the reference motion comes from forms[0], charted if asked
        forms = [f for f in forms if f.model.name in models]
        skipped = {k: v for k, v in skipped.items() if k in models}
    units = {_drift_unit(problem, f.constrained.constraints, k)
             for f in forms if f.constrained for k in range(f.constrained.k)}
    wp = WorkPrecision(problem.name, problem.title, span, scene.reason, samples, ref_error,
                       ", ".join(sorted(units)) or "-", skipped=skipped,
                       scene=scene_text(problem, params, y0), budget=str(budget))
    jobs = []
    for f in forms:
        for m in f.methods(methods):
            if m == "midpoint":
                if f.kind == "ode" and f.energy is not None and not f.not_free_flow:
                    jobs += [(f, m, (span[1] - span[0]) / s) for s in steps]
            else:
                jobs += [(f, m, tol) for tol in tolerances]
    bar = tqdm(jobs, desc=f"{problem.name}: work-precision", unit="run", file=sys.stderr,
               leave=False, disable=not progress or not is_tty(sys.stderr))
    spent: dict = {}   # curves whose looser tolerance already spent the whole budget
    for f, m, tol in bar:
        if (f.name, m) in spent and m != "midpoint" and tol < spent[f.name, m]:
            wp.runs.append(RunResult(f.name, f.kind, m, tol, math.nan, 0, 0, 0, False,
                                     f"{DID_NOT_FINISH}: not run, rtol {spent[f.name, m]:g} "
                                     f"already spent the budget ({budget})",
                                     backend=f.backend, did_not_finish=True))
            continue
        wp.runs.append(_point(f, m, tol, span, te, ref, repeats, budget))
        if wp.runs[-1].did_not_finish:
            spent.setdefault((f.name, m), tol)
    _identical(wp.runs)
    return wp


def _point(f: Formulation, m: str, tol: float, span, te, ref, repeats: int,
           budget: WorkBudget) -> RunResult:
    """One point: the run, its repeats (while they fit in the budget's seconds), measures."""
    try:
        run = f.run(m, span, te, rtol=tol, step=tol, budget=budget)
    except Exception as exc:  # noqa: BLE001 - a failed run is a point of the diagram
        return RunResult(f.name, f.kind, m, tol, math.nan, 0, 0, 0, False,
                         f"{type(exc).__name__}: {exc}", backend=f.backend)
    cpus = [run.cpu]
    while run.success and len(cpus) < repeats and \
            (budget.seconds is None or sum(cpus) + cpus[0] <= budget.seconds):
        cpus.append(f.run(m, span, te, rtol=tol, step=tol, budget=budget).cpu)
    return RunResult(f.name, f.kind, m, tol, float(np.median(cpus)), run.calls,
                     run.evaluations, run.steps, run.success, str(run.message),
                     **_measure(f, run, ref, te), backend=f.backend, repeats=len(cpus),
                     cpu_spread=float(max(cpus) / max(min(cpus), 1e-9)),
                     did_not_finish=str(run.message).startswith(DID_NOT_FINISH))
