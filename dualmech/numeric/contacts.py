"""Unilateral contacts watched, and simulated spans that fit the scene.

A contact that can only push (a track under a car, an incline under a block, the ground) or
a string that can only pull is modelled as a bilateral constraint: the equations hold it
closed whatever force that takes.  :func:`watch` integrates the problem's reference model
with an event on each such reaction and stops where it changes sign -- *when* (the event is
located by the integrator's root finder on its dense output) and *where* (the state there) --
saying that the model's assumption breaks, instead of going on silently.

Which reactions are one-sided is physics the equations do not carry: a problem declares
``unilateral = {"N": "the block lifts off"}`` (the force must stay >= 0 along its declared
direction, :attr:`Problem.unilateral <dualmech.model.problem.Problem>`); a problem that
declares none is integrated without a watch.

:func:`scene_span` also ends a simulation where a length coordinate leaves the range the
problem declares for it (the block at the end of its incline, the container at the floor of
its working range), so a chart never shows a block sliding 85 m down a 2 m wedge.

Example
-------
>>> from dualmech.problems import get
>>> print(watch(get("toy_car"), (0, 3), y0=[0.3, 2.4, 0.0, 0.0]))     # doctest: +ELLIPSIS
F_r is negative from the start (theta = 0.3, phi = 2.4): the car leaves the track ...
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Mapping, Sequence

import numpy as np
from scipy.integrate import solve_ivp

from dualmech.model.dimensions import ANGLE, reduce
from dualmech.model.facts import not_declared
from dualmech.numeric import cvode
from dualmech.numeric.cvode import (CVODE_METHODS, FALLBACK, METHODS, CvodeUnavailable,
                                    integrate_until)
from dualmech.numeric.cvode_events import Bound, ReactionEvent, Stops
from dualmech.numeric.model import NumericModel, SingularityError
from dualmech.numeric.simulation import default_initial_state, direct_models, problem_parameters

__all__ = ["ContactBreak", "ContactReport", "unilateral_of", "watch",
           "scene_span", "SceneSpan", "left_declared"]


def unilateral_of(problem) -> dict:
    """``{reaction: consequence}`` of the problem's one-sided reactions, as it declares them
    (``Problem.unilateral``)."""
    return dict(getattr(problem, "unilateral", None) or {})


@dataclass(frozen=True)
class ContactBreak:
    """A one-sided reaction reaching zero: when, where, which way, and what it means
    (``y``: the whole state ``[q..., q'...]`` there)."""

    reaction: str
    time: float
    state: dict
    meaning: str
    at_start: bool = False
    y: tuple = ()

    def __str__(self) -> str:
        where = ", ".join(f"{k} = {v:.4g}" for k, v in self.state.items())
        change = ("is negative from the start" if self.at_start else
                  f"changes sign (+ to -) at t = {self.time:.6g} s")
        return (f"{self.reaction} {change} ({where}): {self.meaning}; "
                "the model holds the contact closed, so its motion after this instant is "
                "not the real one")


@dataclass
class ContactReport:
    """What :func:`watch` found: the first break (or ``None``) and each force's smallest value
    before it (``minimum = {name: (value, time)}``); the integrator that ran (``method``:
    ``"CVODE-Adams"``, ``"CVODE-BDF"`` or a scipy method; ``""`` when nothing was integrated),
    its CPU seconds alone (``cpu``) and why the compiled route could not run
    (``fallback``, ``""`` when it did or was not asked for); with ``t_eval``, the run's own
    samples: ``t`` and ``y`` (states in the columns), the asked times before the stop, then
    the state where it stopped -- the very numbers of :attr:`ContactBreak.y` (``None``
    without ``t_eval``, or when nothing was integrated)."""

    watched: dict
    t_end: float
    first: ContactBreak | None = None
    minimum: dict = field(default_factory=dict)
    stopped: tuple | None = None
    method: str = ""
    cpu: float = 0.0
    fallback: str = ""
    t: np.ndarray | None = None
    y: np.ndarray | None = None

    def __str__(self) -> str:
        if not self.watched:
            return not_declared("one-sided reaction",
                                'unilateral = {"N": "what happens when N would change sign"}')
        if self.first is not None:
            return str(self.first)
        mins = "; ".join(f"{k} >= {v:.4g} (at t = {s:.3g} s)" for k, (v, s) in
                         self.minimum.items())
        return f"every one-sided contact holds up to t = {self.t_end:.6g} s: {mins}"


def _reaction_functions(problem, values, names, inputs=None) -> dict:
    """``{name: (numeric model, row)}`` from the direct models in the reference coordinates
    (``inputs``: the given inputs' histories, as :class:`NumericModel` binds them)."""
    out = {}
    for m in direct_models(problem, square=True):
        nm = NumericModel(m, values, inputs=inputs)
        for i, u in enumerate(m.unknowns):
            if u.name in names and u.name not in out:
                out[u.name] = (nm, m.n + i)
    return out


def _value(force, t, y) -> np.ndarray:
    """A reaction at one state (a float) or at states in the columns of ``y``."""
    nm, row = force
    n = nm.n
    return nm.solve(t, y[:n], y[n:])[row]


def watch(problem, t_span: Sequence[float], y0=None, params: Mapping | None = None,
          rtol: float = 1e-9, atol: float = 1e-11, method: str = "auto",
          extra_events: Sequence = (), rhs=None, inputs: Mapping | None = None,
          t_eval=None) -> ContactReport:
    """Integrate the reference model until a one-sided reaction changes sign (or the end).

    ``method="auto"`` runs CVODE on the generated C (:func:`~dualmech.numeric.cvode.
    integrate_until`: each reaction and bound an event function in C, no Python per step)
    where it can (:func:`dualmech.numeric.cvode.available`), else scipy's ``DOP853`` with
    Python event functions, the reason in ``ContactReport.fallback``; a CVODE method by name
    raises :class:`~dualmech.numeric.cvode.CvodeUnavailable` instead, a scipy method by name
    runs on scipy.  ``extra_events`` are more terminal events (each with a ``what``
    attribute; :class:`~dualmech.numeric.cvode_events.Bound` s run in C, any other function
    takes the scipy route); the first to fire is reported in ``ContactReport.stopped`` as
    ``(what, time)``.  ``rhs`` integrates the reference coordinates instead of the reference
    model's own system (a reference model that is a DAE: its index-1 form; scipy's route).
    ``ContactReport.minimum`` is each force's smallest value at 400 times evenly spread over
    the run (the compiled route: over ``t_span``, up to the break, and at the break).
    ``inputs``: ``{symbol: history}`` of the problem's given inputs
    (:func:`~dualmech.numeric.inputs.input_functions`), bound in the run and in the reactions
    alike; ``t_eval``: increasing times in ``t_span`` at which the run itself is sampled
    (``ContactReport.t`` and ``y``).
    """
    if method not in METHODS:
        raise ValueError(f"`method` must be one of {', '.join(METHODS)}, got {method!r}.")
    values = problem_parameters(problem, params)
    watched = unilateral_of(problem)
    ref = problem.model(problem.reference)
    n = ref.n
    if y0 is None:
        q0, qd0 = default_initial_state(problem)
        y0 = q0 + qd0
    y0 = np.asarray(y0, dtype=float)
    forces = _reaction_functions(problem, values, set(watched), inputs)
    names = [k for k in watched if k in forces]
    report = ContactReport({k: watched[k] for k in names}, float(t_span[1]))
    coords = [q.func.__name__ for q in ref.coordinates]
    for k in names:
        value = float(_value(forces[k], t_span[0], y0))
        report.minimum[k] = (value, float(t_span[0]))
        if value < 0:
            report.first = ContactBreak(k, float(t_span[0]), dict(zip(coords, y0[:n])),
                                        watched[k], at_start=True, y=tuple(map(float, y0)))
            report.t_end = float(t_span[0])
            return report
    if not names and not extra_events:
        return report
    model = None if rhs is not None else NumericModel(ref, values, inputs=inputs)
    run = (model, None if t_eval is None else np.asarray(t_eval, dtype=float))
    compiled, report.fallback = _route(method, rhs, extra_events)
    if compiled:
        try:
            return _watch_cvode(problem, report, forces, coords, t_span, y0, run,
                                extra_events, rtol, atol, compiled)
        except CvodeUnavailable as exc:
            if method != "auto":
                raise
            report.fallback = str(exc)
    return _watch_scipy(problem, report, forces, coords, t_span, y0, run, extra_events,
                        rtol, atol, FALLBACK if method == "auto" else method, rhs)


def _route(method: str, rhs, extra_events) -> tuple[str | None, str]:
    """The CVODE method :func:`watch` runs (``None``: scipy's route) and, for ``"auto"``
    taking scipy's, why; a CVODE method asked for by name that cannot run is refused."""
    python = ("a Python right-hand side (`rhs`) was given" if rhs is not None else
              "an event function in Python was given" if not all(
                  isinstance(e, Bound) for e in extra_events) else None)
    if method in CVODE_METHODS:
        if python:
            raise CvodeUnavailable(f"CVODE runs compiled code only: {python}.")
        return method, ""
    if method != "auto":
        return None, ""
    reason = python or cvode.available()
    return (None, reason) if reason else (CVODE_METHODS[0], "")


def _watch_scipy(problem, report, forces, coords, t_span, y0, run, extra_events, rtol,
                 atol, method, rhs) -> ContactReport:
    """:func:`watch` on :func:`scipy.integrate.solve_ivp`, the events in Python (``run``:
    the reference model and the sample times, or ``None``)."""
    model, t_eval = run
    names, n = list(report.watched), len(coords)
    events = []
    for k in names:
        ev = (lambda t, y, f=forces[k]: float(_value(f, t, y)))
        ev.terminal, ev.direction = True, -1
        events.append(ev)
    rhs = rhs or model.rhs
    start = time.process_time()
    sol = solve_ivp(rhs, tuple(t_span), y0, method=method, rtol=rtol, atol=atol,
                    events=events + list(extra_events), dense_output=True)
    report.cpu, report.method = time.process_time() - start, method
    if sol.status < 0:
        raise SingularityError(f"integration of `{problem.name}` failed: {sol.message}")
    report.t_end = float(sol.t[-1])
    grid = np.linspace(t_span[0], report.t_end, 400)
    _minima(report, forces, grid, sol.sol(grid))
    for k, times, ys in zip(names, sol.t_events, sol.y_events):
        if len(times) and (report.first is None or times[0] < report.first.time):
            report.first = ContactBreak(k, float(times[0]), dict(zip(coords, ys[0][:n])),
                                        report.watched[k], y=tuple(map(float, ys[0])))
    for ev, times in zip(extra_events, sol.t_events[len(names):]):
        if len(times) and (report.stopped is None or times[0] < report.stopped[1]):
            report.stopped = (ev.what, float(times[0]))
    if t_eval is not None:
        before = t_eval[t_eval < report.t_end]
        end = np.asarray(report.first.y if report.first is not None else sol.y[:, -1])
        report.t = np.append(before, report.t_end)
        report.y = np.column_stack([sol.sol(before).reshape(len(y0), before.size), end])
    return report


def _watch_cvode(problem, report, forces, coords, t_span, y0, run, bounds, rtol, atol,
                 method) -> ContactReport:
    """:func:`watch` on CVODE: the reactions and bounds as event functions in C (``run``:
    the reference model and the sample times, or ``None``)."""
    names, n = list(report.watched), len(coords)
    model, t_eval = run
    stops = Stops(model, reactions=[ReactionEvent(k, *forces[k]) for k in names],
                  bounds=bounds)
    grid = np.linspace(float(t_span[0]), float(t_span[1]), 400)
    if t_eval is not None:
        grid = np.union1d(grid, t_eval)
    run, hit = integrate_until(model, t_span, y0, stops, t_eval=grid, rtol=rtol, atol=atol,
                               method=method)
    report.cpu, report.method = run.cpu, method
    if not run.success:
        raise SingularityError(f"integration of `{problem.name}` failed: {run.message}")
    report.t_end = float(run.t_end)
    times, states = run.t, run.y
    if hit is not None:
        times = np.append(times, hit.time)
        states = np.column_stack([states, hit.y])
        if hit.index < len(names):
            k = names[hit.index]
            report.first = ContactBreak(k, hit.time, dict(zip(coords, hit.y[:n])),
                                        report.watched[k], y=hit.y)
        else:
            report.stopped = (bounds[hit.index - len(names)].what, hit.time)
    _minima(report, forces, times, states)
    if t_eval is not None:
        mine = np.isin(times, t_eval)
        mine[-1] = True                     # where the run stopped (or the end of the span)
        report.t, report.y = times[mine], states[:, mine]
    return report


def _minima(report: ContactReport, forces: dict, times, states) -> None:
    """Each watched force's smallest value at the sample ``times`` (states in the columns)."""
    for k in report.watched:
        vals = np.asarray(_value(forces[k], times, states), dtype=float)
        j = int(np.argmin(vals))
        report.minimum[k] = (float(vals[j]), float(times[j]))


@dataclass(frozen=True)
class SceneSpan:
    """The simulated span ``(t0, t_end)`` and why it ends there (``""``: the full duration)."""

    t0: float
    t_end: float
    reason: str = ""


def _range_events(problem, ref, values) -> list:
    """Terminal events (:class:`~dualmech.numeric.cvode_events.Bound`) for the coordinates
    leaving where the model describes the scene: a declared ``domain`` (any coordinate: the
    ladder's angle past the floor), else the declared range of a length (an angle's range is
    only where states are sampled)."""
    events = []
    for i, q in enumerate(ref.coordinates):
        info = problem.coordinate_info(q)
        domain = getattr(info, "domain", None)
        if domain is not None:
            lo, hi = (float(v) for v in domain)
            what = f"{info.name} leaves its declared domain ({lo:.4g}, {hi:.4g})"
        elif info.dimension == ANGLE or not reduce(info.dimension):
            continue
        else:
            lo, hi = (float(v) for v in info.range)
            what = f"{info.name} leaves its declared range [{lo:g}, {hi:g}]"
        what += f" ({info.description})" if info.description else ""
        events += [Bound(i, lo, -1, what), Bound(i, hi, 1, what)]
    return events


def left_declared(problem, ref, t, Y) -> list[str]:
    """Where a run (sample times ``t``, states in the columns of ``Y``) leaves what the
    problem declares about its scene, each a sentence with the first time: a coordinate's
    ``domain``, a length's range, and a rate whose declared range excludes zero (a declared
    direction: a sliding phase's friction is written for it).  Empty when it never does.

    >>> import numpy as np
    >>> from dualmech.problems import load
    >>> p = load("simple_pendulum")
    >>> left_declared(p, p.model(p.reference), np.array([0.0, 1.0]), np.zeros((2, 2)))
    []
    """
    out = []
    n = ref.n
    for i, q in enumerate(ref.coordinates):
        info = problem.coordinate_info(q)
        checks = []
        domain = getattr(info, "domain", None)
        if domain is not None:
            checks.append((Y[i], tuple(float(v) for v in domain), "declared domain", info.name))
        elif info.dimension != ANGLE and reduce(info.dimension):
            checks.append((Y[i], tuple(float(v) for v in info.range), "declared range",
                           info.name))
        lo, hi = (float(v) for v in info.rate_range)
        if lo > 0 or hi < 0:
            checks.append((Y[n + i], (lo, hi), "declared rate range (a declared direction)",
                           info.name + "'"))
        for values, (lo, hi), what, name in checks:
            off = np.flatnonzero((values < lo) | (values > hi))
            if off.size:
                out.append(f"{name} leaves its {what} [{lo:g}, {hi:g}] at t = "
                           f"{float(t[off[0]]):.4g} s")
    return out


def scene_span(problem, duration: float, y0=None, params: Mapping | None = None,
               t0: float = 0.0, rhs=None) -> SceneSpan:
    """The part of ``(t0, t0 + duration)`` in which the problem's model describes its scene.

    Ends where a length coordinate leaves its declared range, or where a one-sided contact
    would have to pull (:func:`watch`), whichever comes first.  ``rhs``: see :func:`watch`.
    """
    values = problem_parameters(problem, params)
    ref = problem.model(problem.reference)
    end = t0 + float(duration)
    report = watch(problem, (t0, end), y0, params,
                   extra_events=_range_events(problem, ref, values), rhs=rhs)
    if report.first is not None:
        return SceneSpan(t0, report.first.time,
                         f"{report.first.reaction} would have to change sign at t = "
                         f"{report.first.time:.3g} s: {report.first.meaning}")
    if report.stopped is not None:
        what, when = report.stopped
        return SceneSpan(t0, when, f"{what} at t = {when:.3g} s")
    return SceneSpan(t0, end, "")
