"""Simulation across contact phases: when a one-sided reaction lets go, the next model.

:func:`simulate_phases` integrates a problem's reference model while watching its one-sided
reactions (:func:`~dualmech.numeric.contacts.watch`).  Where one would change sign and the
problem declares what follows (``Problem.phases``, :mod:`dualmech.model.phases`), the state is
mapped across -- each next coordinate from its declared expression, each rate by the chain rule
-- and the run goes on with the next problem, parameters passed by name; where nothing is
declared the run ends there and says why.  Each phase runs on CVODE with the reactions and
the declared bounds as event functions in C where it can (:func:`~dualmech.numeric.contacts.
watch`'s ``method="auto"``), else on scipy; :attr:`PhasedRun.method` says which ran and
:attr:`PhasedRun.cpu` how long the integrations took; the samples of a phase come from
the run that watched it, so its last one is the state carried across.  A problem driven by
given inputs (``Problem.inputs``) drives every phase with the same histories, time running on
across the switches; each next problem must declare those inputs.  :func:`phase_series` gives
what a chart of the run shows (each coordinate and reaction over every phase that has it, and the switches);
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

from dualmech.model._expr import as_expr
from dualmech.model.phases import next_problem
from dualmech.numeric.contacts import _range_events, watch
from dualmech.numeric.cvode import integrate
from dualmech.numeric.inputs import declared_inputs, input_functions
from dualmech.numeric.phase_chart import phase_chart, phase_series
from dualmech.numeric.model import NumericModel, SingularityError
from dualmech.numeric.simulation import (Trajectory, check_t_span, default_initial_state,
                                         problem_parameters, reactions_along, refuse_static)
from dualmech.numeric.units import unit

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
    """One phase of a run: its problem's name, its trajectory (reactions included), its
    problem's ``title``, ``units`` (``{coordinate, reaction or input: unit}``, e.g.
    ``"rad"``) and the given ``inputs``' values at the trajectory's times."""

    problem: str
    trajectory: Trajectory
    title: str = ""
    units: dict = field(default_factory=dict)
    inputs: dict = field(default_factory=dict)


@dataclass
class PhasedRun:
    """What :func:`simulate_phases` returns: the phases in order, the switches between them
    and why the last one ends (``""``: it reached the end of the span); the integrator that
    ran (``method``, e.g. ``"CVODE-Adams"``, or scipy's ``"DOP853"``; several joined by
    ``", "`` if the phases differ), why the compiled route could not run (``fallback``) and
    the CPU seconds of the integrations alone (``cpu``: each phase's watched run, which also
    gives its samples; deriving and compiling come before the clocks start); ``open_contact``:
    the :class:`~dualmech.numeric.contacts.ContactBreak` that ended the run where no next
    phase is declared (else ``None``); ``end``: what ended the run early, in a few words
    (``""``: it reached the end of the span)."""

    phases: list = field(default_factory=list)
    switches: list = field(default_factory=list)
    ended: str = ""
    method: str = ""
    fallback: str = ""
    cpu: float = 0.0
    open_contact: object = None
    end: str = ""

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
                    atol: float = 1e-12, method: str = "auto",
                    inputs: Mapping | None = None) -> PhasedRun:
    """Integrate ``problem`` and the phases it declares after it (see the module docstring).

    ``samples`` output times are spread evenly over ``t_span``, each phase taking those in
    its span, with its start and its end (so at least two each; a switch time appears in both
    phases); every sample of a phase comes from the one integration that watched it, so a
    phase's last sample is the very state carried across the switch.  ``params`` are this
    problem's and pass to the next ones by name; ``method``: as
    :func:`~dualmech.numeric.contacts.watch` takes it.  ``inputs``: the histories of the
    problem's given inputs by name (:func:`~dualmech.numeric.inputs.input_functions`; an
    input given none takes its declared default): every phase is driven by the same
    histories, time running on across each switch.

    Raises
    ------
    ValueError
        A phase the problem can reach does not declare an input the run is driven by (or an
        input has no history).

    Example
    -------
    >>> from dualmech.problems import get
    >>> run = simulate_phases(get("simple_pendulum"), (0, 1), samples=5)
    >>> run.phases[0].trajectory.t.tolist()
    [0.0, 0.25, 0.5, 0.75, 1.0]
    """
    t0, t1 = check_t_span(t_span)
    if y0 is None:
        q0, qd0 = default_initial_state(problem)
        y0 = list(q0) + list(qd0)
    named = {s.name: v for s, v in problem_parameters(problem, params).items()}
    how = _How(np.linspace(t0, t1, max(int(samples), 2)), rtol, atol, method)
    drive = {s.name: h for s, h in input_functions(problem, inputs, (t0, t1),
                                                   problem_parameters(problem, params)).items()}
    nexts = _reachable(problem, drive)
    run = PhasedRun()
    for _ in range(MAX_PHASES):
        mine = {p.symbol.name for p in problem.parameters}
        values = problem_parameters(problem, {k: v for k, v in named.items() if k in mine})
        here = input_functions(problem, drive, (t0, t1), values)
        report = _watched(problem, (t0, t1), y0, values, here, how, run)
        brk = report.first
        stop = report.stopped if brk is None else None
        end = brk.time if brk is not None else stop[1] if stop is not None else t1
        if end > t0:
            run.phases.append(_phase_run(problem, _trajectory(
                problem, report, (t0, end), y0, values, here, how, run), here))
        if stop is not None:
            run.end = stop[0]
            run.ended = (f"t = {stop[1]:.6g} s: {stop[0]} in `{problem.name}`: the model "
                         "no longer describes the scene there (a phase follows only a "
                         "one-sided reaction reaching zero)")
            return run
        if brk is None:
            return run
        phase = (getattr(problem, "phases", None) or {}).get(brk.reaction)
        if phase is None:
            return _open_end(run, problem, brk)
        nxt = nexts[id(phase)]
        run.switches.append(Switch(brk.time, brk.reaction, problem.name, nxt.name,
                                   phase.why or brk.meaning))
        y0 = map_state(problem, phase, brk.y, values, nxt)
        named.update({s.name: v for s, v in values.items()})
        drive.update({s.name: h for s, h in here.items()})
        problem, t0 = nxt, brk.time
    run.ended = run.end = f"stopped after {MAX_PHASES} phases (does the declaration loop?)"
    return run


def _open_end(run: PhasedRun, problem, brk) -> PhasedRun:
    """``run`` ended by the one-sided reaction ``brk`` for which no next phase is declared."""
    run.ended, run.open_contact = str(brk), brk
    sign = "is negative from the start" if brk.at_start else "reaches zero"
    run.end = (f"{brk.reaction} {sign} ({brk.meaning}) and `{problem.name}` declares no "
               "next phase for it")
    return run


def _reachable(problem, drive: Mapping) -> dict:
    """``{id(phase): next problem}`` for every phase declared from ``problem`` on (each
    built once), each checked to declare every input of ``drive`` (else refused)."""
    out, todo, seen = {}, [problem], {problem.name}
    while todo and len(out) < 4 * MAX_PHASES:
        here = todo.pop()
        for reaction, phase in (getattr(here, "phases", None) or {}).items():
            if id(phase) in out:
                continue
            nxt = out[id(phase)] = next_problem(phase)
            missing = [k for k in drive if k not in declared_inputs(nxt)]
            if missing:
                raise ValueError(
                    f"`inputs`: the run is driven by {', '.join(missing)}, but the phase "
                    f"after `{here.name}` ({reaction} reaching zero), problem `{nxt.name}`, "
                    f"does not declare {'it' if len(missing) == 1 else 'them'}: declare the "
                    "same Input(...) on it (every phase is driven by the same histories).")
            if nxt.name not in seen:
                seen.add(nxt.name)
                todo.append(nxt)
    return out


@dataclass(frozen=True)
class _How:
    """How a run integrates each phase: the sample times over the whole run, the
    tolerances, the method."""

    grid: np.ndarray
    rtol: float
    atol: float
    method: str


def _watched(problem, span, y0, values, inputs, how: _How, run: PhasedRun):
    """:func:`~dualmech.numeric.contacts.watch` of one phase from ``span[0]``, sampled at the
    run's grid times in its span."""
    ref = problem.model(problem.reference)
    refuse_static(problem, ref)
    report = watch(problem, span, y0, values, rtol=how.rtol, atol=how.atol,
                   method=how.method, extra_events=_range_events(problem, ref, values),
                   inputs=inputs, t_eval=_phase_grid(how.grid, *span))
    run._ran(report.method, report.fallback, report.cpu)
    return report


def _phase_grid(grid, t0: float, t1: float) -> np.ndarray:
    """The phase's sample times: its start, then the run's ``grid`` times after it."""
    return np.concatenate([[t0], grid[(grid > t0) & (grid <= t1)]])


def _phase_run(problem, traj: Trajectory, inputs: Mapping) -> PhaseRun:
    """The phase's :class:`PhaseRun`: its trajectory, title, units and inputs' values."""
    units = {c.name: unit(c.dimension) for c in problem.all_coordinates()}
    units.update({r.name: unit(r.dimension) for r in problem.reactions})
    units.update({x.name: unit(x.dimension) for x in declared_inputs(problem).values()})
    driven = {s.name: np.array([h(float(t)) for t in traj.t]) for s, h in inputs.items()}
    return PhaseRun(problem.name, traj, getattr(problem, "title", "") or "", units, driven)


def _trajectory(problem, report, span, y0, values, inputs, how: _How,
                run: PhasedRun) -> Trajectory:
    """The phase's samples with its reactions: the watched run's own (the last one the state
    where it stopped), or -- where nothing was watched, so nothing stops it -- one run at
    the grid times."""
    ref = problem.model(problem.reference)
    if report.t is not None:
        t, y = report.t, report.y
    else:
        done = integrate(NumericModel(ref, values, inputs=inputs), span, y0,
                         t_eval=_phase_grid(how.grid, *span), rtol=how.rtol, atol=how.atol,
                         method=how.method)
        run._ran(done.method, "", done.cpu)
        if not done.success:
            raise SingularityError(f"integration of `{problem.name}` failed: {done.message}")
        t, y = done.t, done.y
    n = ref.n
    traj = Trajectory(np.asarray(t, dtype=float), y[:n], y[n:],
                      [q.func.__name__ for q in ref.coordinates])
    traj.reactions = reactions_along(problem, traj, values, inputs)
    return traj
