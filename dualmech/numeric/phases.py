"""Simulation across contact phases: when a one-sided reaction lets go, the next model.

:func:`simulate_phases` integrates a problem's reference model while watching its one-sided
reactions (:func:`~dualmech.numeric.contacts.watch`).  Where one would change sign and the
problem declares what follows (``Problem.phases``, :mod:`dualmech.model.phases`), the state is
mapped across -- each next coordinate from its declared expression, each rate by the chain rule
-- and the run goes on with the next problem, parameters passed by name; where nothing is
declared the run ends there and says why.  Each phase runs on CVODE with the reactions and
the declared bounds as event functions in C where it can (:func:`~dualmech.numeric.contacts.
watch`'s ``method="auto"``), else on scipy; :attr:`PhasedRun.method` says which ran and
:attr:`PhasedRun.cpu` how long the integrations took.  :func:`phase_series` gives what a chart of the run
shows (each coordinate and reaction over every phase that has it, and the switches);
:func:`phase_chart` draws it, the switches marked.

Example
-------
>>> from dualmech.problems import get
>>> run = simulate_phases(get("simple_pendulum"), (0, 1), samples=5)
>>> len(run.phases), run.switches
(1, [])
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Mapping

import numpy as np
import sympy as sp

from dualmech.model._expr import as_expr
from dualmech.model.phases import next_problem
from dualmech.numeric.contacts import _range_events, watch
from dualmech.numeric.cvode import integrate
from dualmech.numeric.model import NumericModel, SingularityError
from dualmech.numeric.simulation import (Trajectory, check_t_span, default_initial_state,
                                         problem_parameters, reactions_along, refuse_static)

__all__ = ["PhaseRun", "PhasedRun", "Switch", "simulate_phases", "map_state", "phase_series",
           "phase_chart", "MAX_PHASES"]

#: the most phases one run chains (a declaration that loops is stopped here, and says so)
MAX_PHASES = 12


@dataclass(frozen=True)
class Switch:
    """One change of phase: when, which reaction let go, from which problem to which, why."""

    time: float
    reaction: str
    source: str
    target: str
    why: str

    def __str__(self) -> str:
        return (f"t = {self.time:.6g} s: {self.reaction} reaches zero; `{self.source}` -> "
                f"`{self.target}` ({self.why})")


@dataclass
class PhaseRun:
    """One phase of a run: its problem's name, its trajectory (reactions included)."""

    problem: str
    trajectory: Trajectory


@dataclass
class PhasedRun:
    """What :func:`simulate_phases` returns: the phases in order, the switches between them
    and why the last one ends (``""``: it reached the end of the span); the integrator that
    ran (``method``, e.g. ``"CVODE-Adams"``, or scipy's ``"DOP853"``; several joined by
    ``", "`` if the phases differ), why the compiled route could not run (``fallback``) and
    the CPU seconds of the integrations alone (``cpu``: each phase's watched run and its
    sampled run; deriving and compiling come before the clocks start); ``open_contact``:
    the :class:`~dualmech.numeric.contacts.ContactBreak` that ended the run where no next
    phase is declared (else ``None``)."""

    phases: list = field(default_factory=list)
    switches: list = field(default_factory=list)
    ended: str = ""
    method: str = ""
    fallback: str = ""
    cpu: float = 0.0
    open_contact: object = None

    def to_dict(self, samples: bool = False) -> dict:
        """The run as plain data: ``phases`` (each its ``problem``, ``coordinates`` -- its
        own, then their rates --, ``t_start``, ``t_end``, ``initial_state`` and
        ``final_state``), ``switches``, ``ended``; with ``samples``, every sample of every
        phase in time order, ``{"t", "phase", "states"}`` (``phase``: the index of the
        phase whose coordinates the row is in; a switch time appears twice, once in each
        phase's coordinates).

        >>> from dualmech.problems import get
        >>> d = simulate_phases(get("simple_pendulum"), (0, 1), samples=3).to_dict(True)
        >>> d["phases"][0]["coordinates"], d["samples"]["t"], d["switches"]
        (['theta', "theta'"], [0.0, 0.5, 1.0], [])
        """
        out = {"phases": [], "switches": [vars(s) for s in self.switches],
               "ended": self.ended}
        rows = {"t": [], "phase": [], "states": []}
        for i, ph in enumerate(self.phases):
            tr = ph.trajectory
            y = np.vstack([tr.q, tr.qd])
            out["phases"].append({
                "problem": ph.problem,
                "coordinates": tr.coordinate_names + [f"{c}'" for c in tr.coordinate_names],
                "t_start": float(tr.t[0]), "t_end": float(tr.t[-1]),
                "initial_state": y[:, 0].tolist(), "final_state": y[:, -1].tolist()})
            rows["t"] += tr.t.tolist()
            rows["phase"] += [i] * tr.t.size
            rows["states"] += y.T.tolist()
        if samples:
            out["samples"] = rows
        return out

    def _ran(self, method: str, fallback: str, cpu: float) -> None:
        if method and method not in self.method.split(", "):
            self.method = ", ".join(filter(None, [self.method, method]))
        self.fallback = self.fallback or fallback
        self.cpu += cpu


def map_state(problem, phase, y, values: Mapping, target=None) -> list:
    """The next phase's ``[q..., q'...]`` from this problem's state ``y`` (values by symbol
    in ``values``): the declared expressions and their time derivatives (``target``: the next
    problem's instance, if already built; else built here)."""
    coords = list(problem.model(problem.reference).coordinates)
    n = len(coords)
    rates = {q.diff(q.args[0]): float(v) for q, v in zip(coords, y[n:])}
    here = {q: float(v) for q, v in zip(coords, y[:n])}
    nxt = target if target is not None else next_problem(phase)
    out_q, out_qd = [], []
    for q in nxt.model(nxt.reference).coordinates:
        e = as_expr(phase.coordinates[q]).subs(values)
        out_q.append(float(e.subs(here)))
        out_qd.append(float(e.diff(q.args[0]).subs(rates).subs(here)))
    return out_q + out_qd


def simulate_phases(problem, t_span=(0.0, 5.0), y0=None, params: Mapping | None = None,
                    samples: int = 200, rtol: float = 1e-10,
                    atol: float = 1e-12, method: str = "auto") -> PhasedRun:
    """Integrate ``problem`` and the phases it declares after it (see the module docstring).

    ``samples`` output times are shared among the phases in proportion to their spans (at
    least two each); ``params`` are this problem's and pass to the next ones by name;
    ``method``: as :func:`~dualmech.numeric.contacts.watch` takes it.
    """
    t0, t1 = check_t_span(t_span)
    if y0 is None:
        q0, qd0 = default_initial_state(problem)
        y0 = list(q0) + list(qd0)
    named = {s.name: v for s, v in problem_parameters(problem, params).items()}
    run = PhasedRun()
    for _ in range(MAX_PHASES):
        mine = {p.symbol.name for p in problem.parameters}
        values = problem_parameters(problem, {k: v for k, v in named.items() if k in mine})
        ref = problem.model(problem.reference)
        report = watch(problem, (t0, t1), y0, values, rtol=rtol, atol=atol, method=method,
                       extra_events=_range_events(problem, ref, values))
        run._ran(report.method, report.fallback, report.cpu)
        brk = report.first
        stop = report.stopped if brk is None else None
        end = brk.time if brk is not None else stop[1] if stop is not None else t1
        if end > t0:
            k = max(2, int(round(samples * (end - t0) / (t_span[1] - t_span[0]))))
            traj = _sampled(problem, (t0, end), y0, values, k, rtol, atol,
                            report.method or "auto", run)
            run.phases.append(PhaseRun(problem.name, traj))
        if stop is not None:
            run.ended = (f"t = {stop[1]:.6g} s: {stop[0]} in `{problem.name}`: the model "
                         "no longer describes the scene there (a phase follows only a "
                         "one-sided reaction reaching zero)")
            return run
        if brk is None:
            return run
        phase = (getattr(problem, "phases", None) or {}).get(brk.reaction)
        if phase is None:
            run.ended, run.open_contact = str(brk), brk
            return run
        nxt = next_problem(phase)
        run.switches.append(Switch(brk.time, brk.reaction, problem.name, nxt.name,
                                   phase.why or brk.meaning))
        y0 = map_state(problem, phase, brk.y, values, nxt)
        named.update({s.name: v for s, v in values.items()})
        problem, t0 = nxt, brk.time
    run.ended = f"stopped after {MAX_PHASES} phases (does the declaration loop?)"
    return run


def _sampled(problem, span, y0, values, samples: int, rtol: float, atol: float,
             method: str, run: PhasedRun) -> Trajectory:
    """The phase's motion at ``samples`` times over ``span``, with its reactions, by the
    method that watched it (:func:`~dualmech.numeric.cvode.integrate`)."""
    ref = problem.model(problem.reference)
    refuse_static(problem, ref)
    done = integrate(NumericModel(ref, values), span, y0, t_eval=np.linspace(*span, samples),
                     rtol=rtol, atol=atol, method=method)
    run._ran(done.method, "", done.cpu)
    if not done.success:
        raise SingularityError(f"integration of `{problem.name}` failed: {done.message}")
    n = ref.n
    traj = Trajectory(done.t, done.y[:n], done.y[n:], [q.func.__name__ for q in
                                                        ref.coordinates], message=done.message)
    traj.reactions = reactions_along(problem, traj, values)
    return traj


def phase_series(run: PhasedRun) -> dict:
    """``{name: (times, values)}`` of every coordinate, rate (``name'``) and reaction over the
    phases that have it (NaN between them), with ``"switches"``: the switch times."""
    out: dict = {}
    for ph in run.phases:
        tr = ph.trajectory
        rows = {n: tr.q[i] for i, n in enumerate(tr.coordinate_names)}
        rows.update({f"{n}'": tr.qd[i] for i, n in enumerate(tr.coordinate_names)})
        rows.update(tr.reactions)
        for name, values in rows.items():
            ts, vs = out.setdefault(name, ([], []))
            if ts:
                ts.append(np.nan)
                vs.append(np.nan)
            ts.extend(tr.t.tolist())
            vs.extend(np.asarray(values, dtype=float).tolist())
    series = {k: (np.array(t), np.array(v)) for k, (t, v) in out.items()}
    series["switches"] = [s.time for s in run.switches]
    return series


def phase_chart(run: PhasedRun, path, title: str = "") -> str:
    """Draw the coordinates and the reactions of every phase, each switch marked by a dashed
    line and what happened; write the PNG to ``path`` and return its path."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    series = phase_series(run)
    reactions = {k for ph in run.phases for k in ph.trajectory.reactions}
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    for name, tv in series.items():
        if name == "switches" or name.endswith("'"):
            continue
        (bottom if name in reactions else top).plot(*tv, label=name)
    for s in run.switches:
        for ax in (top, bottom):
            ax.axvline(s.time, color="k", linestyle="--", linewidth=1)
        top.annotate(f" {s.reaction} = 0", (s.time, 0.97), xycoords=("data", "axes fraction"),
                     va="top", ha="left", fontsize=8)
    top.set_ylabel("coordinates")
    bottom.set_ylabel("reactions")
    bottom.set_xlabel("t (s)")
    top.legend(loc="best", fontsize=8)
    bottom.legend(loc="best", fontsize=8)
    whys = "; ".join([f"t = {s.time:.3g} s: {s.why}" for s in run.switches]
                     + ([f"ends at t = {run.phases[-1].trajectory.t[-1]:.3g} s: the model "
                         "leaves its domain"] if run.ended and "domain" in run.ended else []))
    top.set_title(title or " -> ".join(ph.problem for ph in run.phases), fontsize=10)
    if whys:
        bottom.set_title(whys, fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return str(path)
