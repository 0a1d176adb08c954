"""Coordinate singularities: where each formulation's system degenerates, and what runs do there.

:func:`scan` sweeps each reference coordinate (angles over a full turn, lengths over their
declared range and half as much again on each side; the others at the initial state, at
rest), maps every state into each formulation's coordinates and measures its system matrix
(the mass matrix of a reaction-free model, ``[M B]`` of a direct or DAE form) by its
**degeneracy** ``kappa = max(cond A, |A|/|A_0|, |A_0^-1|/|A^-1|)`` -- the condition number,
and how far the matrix has grown or shrunk since the initial state (a 1x1 mass matrix that
becomes infinite, like the two-rod linkage's in ``x`` at the fold, has condition number 1).
Where ``kappa`` passes :data:`KAPPA_LIMIT` (a solve there keeps fewer than 8 of 16 digits)
the point is refined, its **order** ``p`` fitted (``kappa ~ distance^-p``), compared with the
problem's declared singular set (:attr:`Problem.singular`), and classified:

* ``"det M = 0"`` / ``"M unbounded"`` -- the coordinates themselves fail (the reference
  model degenerates there too, or this form's coordinates do);
* ``"reactions undetermined"`` -- the motion is regular (the reference model is fine) but the
  reaction directions of this form are dependent: their sum is known, not each one.

:func:`probe` runs each integrator from a state that heads for the singular set (a
:class:`~dualmech.model.facts.Probe` the problem declares in ``probes``): unguarded
(what the integrator does: slows down, stops with an error, or returns garbage -- judged by
its error against a tight run and by the energy; the error is measured where the
singularity cannot distort it, in the ground frame's positions and velocities of the
problem's points (:mod:`dualmech.numeric.scene`), not in the angles that degenerate), guarded (a terminal event where ``kappa``
reaches the limit: a clear message), and, where another formulation is regular there, the
guarded run continues in that safe form (the state lifted into its coordinates by Newton
continuation along the run).

Example
-------
>>> from dualmech.problems import get
>>> [str(p) for p in scan(get("toy_car")).points][0]
'lagrange: det M = 0 at theta = -1.5708 (kappa ~ d^-2; declared: cos(theta) = 0)'
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Mapping, Sequence

import time

import numpy as np
from scipy.integrate import BDF, DOP853, LSODA, RK45, Radau
from scipy.optimize import minimize_scalar

from dualmech.model.dimensions import ANGLE
from dualmech.model.facts import Probe, not_declared, state_vector
from dualmech.numeric.formulations import Formulation, formulations
from dualmech.numeric.integrators import Run
from dualmech.numeric.model import NumericModel, SingularityError, StateFunction
from dualmech.numeric.scene import NoScene, scene
from dualmech.numeric.studies.horizon import state_sizes
from dualmech.numeric.simulation import problem_parameters
from dualmech.numeric.units import unit

__all__ = ["KAPPA_LIMIT", "GARBAGE", "WRONG", "Scan", "SingularPoint", "ProbeRun",
           "ProbeReport", "scan", "probe", "degeneracy", "verdict_word", "NO_PROBE"]

#: Beyond this degeneracy a linear solve keeps fewer than half of double precision's digits.
KAPPA_LIMIT = 1e8
#: A run is garbage when its error exceeds this many times its tolerance; the guard stops
#: (or switches form) where the degeneracy -- the factor by which the system amplifies an
#: error of the state into the accelerations -- passes the same factor.
GARBAGE = 1e3
#: A run whose error passes this fraction of the state's own size is wrong (between
#: ``GARBAGE x rtol`` and this it is degraded: fine for a picture, not for the digits asked).
WRONG = 1e-2
#: What the atlas says when degenerate points are found but no probe run is declared.
NO_PROBE = not_declared("probe run", "probes = (Probe(state, formulation, duration, why),)")
def _system(f: Formulation, values):
    return f.constrained.numeric if f.constrained else NumericModel(f.model, values)


def degeneracy(A: np.ndarray, A0: np.ndarray) -> np.ndarray:
    """``kappa`` of the module docstring for matrices ``A`` (``(K, m, m)``) against ``A0``."""
    with np.errstate(all="ignore"):
        ok = np.isfinite(A).all(axis=(1, 2))
        sv = np.full((A.shape[0], A.shape[1]), np.nan)
        if ok.any():
            sv[ok] = np.linalg.svd(A[ok], compute_uv=False)
        s0 = np.linalg.svd(A0, compute_uv=False)
        kappa = np.maximum.reduce([sv[:, 0] / sv[:, -1], sv[:, 0] / s0[0], s0[-1] / sv[:, -1]])
    kappa[~np.isfinite(kappa)] = np.inf
    return kappa


@dataclass(frozen=True)
class SingularPoint:
    """A degenerate point of one formulation along one reference coordinate."""

    formulation: str
    coordinate: str
    value: float
    kind: str
    order: float
    declared: str

    def __str__(self) -> str:
        decl = f"declared: {self.declared} = 0" if self.declared else "NOT among the declared"
        order = f"kappa ~ d^-{self.order:.0f}" if np.isfinite(self.order) else "kappa infinite"
        value = 0.0 if abs(self.value) < 1e-6 else self.value
        return (f"{self.formulation}: {self.kind} at {self.coordinate} = {value:.6g} "
                f"({order}; {decl})")


class _Scanner:
    """Degeneracy of every formulation at reference states (vectorised)."""

    def __init__(self, problem, forms, values):
        self.problem, self.forms, self.values = problem, forms, values
        self.ref = forms[0]
        self.systems = {f.name: _system(f, values) for f in forms}
        q0 = self.ref.y0[: self.ref.n]
        self.base = {f.name: self._matrices(f, q0[:, None])[0] for f in forms}
        sing = [e for e in getattr(problem, "singular", ())]
        self.singular = StateFunction(sing, problem.model(problem.reference).coordinates,
                                      values) if sing else None
        self.singular_text = [str(e).replace("(t)", "") for e in sing]

    def _matrices(self, f, Q):
        Y = f.from_reference(0.0, Q, np.zeros_like(Q))
        with np.errstate(all="ignore"):
            try:
                A, _ = self.systems[f.name].system(0.0, Y[: f.n], Y[f.n:])
            except (ValueError, ZeroDivisionError):
                A = np.full((Q.shape[1],) + self.systems[f.name].shape, np.nan)
        A = A if A.ndim == 3 else A[None]
        return A if f.constrained or f.model.unknowns else A[:, : f.n, : f.n]

    def kappa(self, f, Q) -> np.ndarray:
        return degeneracy(self._matrices(f, Q), self.base[f.name])

    def declared(self, q) -> str:
        if self.singular is None:
            return ""
        vals = self.singular(0.0, q, np.zeros_like(q))
        return " or ".join(t for t, v in zip(self.singular_text, vals) if abs(v) < 1e-6)


def _grid(problem, coordinate, q0: float) -> np.ndarray:
    info = problem.coordinate_info(coordinate)
    if info.dimension == ANGLE:
        return np.linspace(-np.pi, np.pi, 1441)
    lo, hi = info.range
    w = hi - lo
    return np.linspace(lo - w / 2, hi + w / 2, 1441)


@dataclass
class Scan:
    """The degenerate ``points`` and the curves behind them: ``curves[coordinate] = (grid,
    {formulation: kappa})``, and the declared singular set's zeros per coordinate."""

    problem: str
    points: list
    curves: dict = field(repr=False, default_factory=dict)
    declared: list = field(default_factory=list)
    units: dict = field(default_factory=dict)

    def __str__(self) -> str:
        if not self.points:
            return (f"{self.problem}: no formulation degenerates along any coordinate "
                    f"(degeneracy below {KAPPA_LIMIT:.0e} everywhere scanned)")
        return "\n".join([f"{self.problem}: degenerate points (degeneracy > "
                          f"{KAPPA_LIMIT:.0e})"] + [f"  {p}" for p in self.points])


def scan(problem, params: Mapping | None = None, y0=None, forms=None) -> Scan:
    """The degenerate points of every formulation (see the module docstring)."""
    values = problem_parameters(problem, params)
    if forms is None:
        forms = formulations(problem, params, y0, stabilisations=("none",))[0]
    sc = _Scanner(problem, forms, values)
    ref = sc.ref
    n = ref.n
    q0 = ref.y0[:n]
    out = Scan(problem.name, [], {}, list(sc.singular_text))
    for i, q in enumerate(ref.coordinates):
        grid = _grid(problem, q, q0[i])
        Q = np.repeat(q0[:, None], grid.size, axis=1)
        Q[i] = grid
        ref_kappa = sc.kappa(ref, Q)
        curves = {}
        for f in forms:
            kap = ref_kappa if f is ref else sc.kappa(f, Q)
            curves[f.name] = kap
            for j in _peaks(kap):
                out.points.append(_refine(sc, f, i, q, grid, j, Q[:, j], ref_kappa[j]))
        out.curves[q.func.__name__] = (grid, curves)
        out.units[q.func.__name__] = unit(problem.coordinate_info(q).dimension)
    return out


def _peaks(kappa: np.ndarray) -> list[int]:
    """Index of the largest ``kappa`` in each run of points above the limit."""
    above = kappa > KAPPA_LIMIT
    out, j = [], 0
    while j < kappa.size:
        if above[j]:
            k = j
            while k < kappa.size and above[k]:
                k += 1
            seg = kappa[j:k]
            out.append(j + int(np.argmax(np.where(np.isfinite(seg), seg, 1e300))))
            j = k
        else:
            j += 1
    return out


def _refine(sc: _Scanner, f, i, q, grid, j, state, ref_kappa) -> SingularPoint:
    lo, hi = grid[max(j - 1, 0)], grid[min(j + 1, grid.size - 1)]

    def at(x):
        Q = state[:, None].copy()
        Q[i] = x
        return Q

    def neg_log(x):
        k = sc.kappa(f, at(x))[0]
        return -np.log(min(k, 1e300))
    x = minimize_scalar(neg_log, bounds=(lo, hi), method="bounded",
                        options={"xatol": 1e-12 * max(1.0, abs(grid[j]))}).x
    near = [sc.kappa(f, at(x + d))[0] for d in (1e-3, 1e-4)]
    near = [v if np.isfinite(v) else np.nan for v in near]
    order = np.log10(near[1] / near[0]) if all(np.isfinite(near)) else np.inf
    ref_regular = sc.kappa(sc.ref, at(x))[0] < KAPPA_LIMIT
    if _grown(sc, f, at(x)):
        kind = "M unbounded"
    elif f is not sc.ref and ref_regular and (f.constrained or f.model.unknowns):
        kind = "reactions undetermined"   # the motion is regular; the reaction directions
    else:                                 # of this form are dependent there
        kind = "det M = 0"
    return SingularPoint(f.name, q.func.__name__, float(x), kind, float(order),
                         sc.declared(at(x)[:, 0]))


def _grown(sc, f, Q) -> bool:
    A = sc._matrices(f, Q)[0]
    if not np.isfinite(A).all():
        return True
    return np.linalg.norm(A, 2) > np.sqrt(KAPPA_LIMIT) * np.linalg.norm(sc.base[f.name], 2)


# -- runs towards the singular set -------------------------------------------------------------
@dataclass
class ProbeRun:
    """One integrator's run towards the singular set, and the verdict on it."""

    method: str
    mode: str
    success: bool
    message: str
    t_end: float
    steps: int
    calls: int
    cpu: float
    max_kappa: float
    error: float
    energy: float
    verdict: str


@dataclass
class ProbeReport:
    """The runs of :func:`probe` (``runs``) from ``y0`` over ``span`` in ``formulation``."""

    problem: str
    formulation: str
    y0: list
    span: tuple
    description: str
    rtol: float
    measured: str = ""
    runs: list = field(default_factory=list)

    def __str__(self) -> str:
        lines = [f"{self.problem}: {self.description}; {self.formulation} from {self.y0}, "
                 f"rtol {self.rtol:g}; errors in {self.measured}"]
        for r in self.runs:
            lines.append(f"  {r.method:8s} {r.mode:9s} {r.verdict}")
        return "\n".join(lines)


def _kappa_of(f: Formulation, values):
    system = _system(f, values)
    A0 = None

    def kappa(y) -> float:
        nonlocal A0
        with np.errstate(all="ignore"):
            try:
                A, _ = system.system(0.0, y[: f.n], y[f.n:])
            except (ValueError, ZeroDivisionError):
                return np.inf
        A = A if (f.constrained or f.model.unknowns) else A[: f.n, : f.n]
        if A0 is None:
            A0 = A
        return float(degeneracy(A[None], A0)[0])
    return kappa


def _lift(f: Formulation, ref: Formulation, y_ref0: np.ndarray, Y: np.ndarray) -> np.ndarray:
    """Reference-coordinate states whose image under ``f``'s map is ``Y`` (columns), by
    Gauss--Newton continuation from ``y_ref0`` (the run's own starting state)."""
    n = ref.n
    out = np.empty((2 * n, Y.shape[1]))
    y = y_ref0.copy()
    for k in range(Y.shape[1]):
        for _ in range(30):
            F = f.from_reference(0.0, y[:n], y[n:]) - Y[:, k]
            J = np.empty((F.size, 2 * n))
            for j in range(2 * n):
                h = 1e-7 * max(1.0, abs(y[j]))
                yp = y.copy()
                yp[j] += h
                J[:, j] = (f.from_reference(0.0, yp[:n], yp[n:]) - Y[:, k] - F) / h
            step = np.linalg.lstsq(J, -F, rcond=None)[0]
            y = y + step
            if np.abs(step).max() <= 1e-13 * max(1.0, np.abs(y).max()):
                break
        out[:, k] = y
    return out


def probe(problem, declared: Probe | None = None, *, methods: Sequence[str] = ("RK45",
          "DOP853", "Radau", "BDF", "LSODA"), rtol: float = 1e-6, samples: int = 101,
          params: Mapping | None = None) -> ProbeReport:
    """Each integrator run towards the problem's singular set, from ``declared`` (default:
    the first of the problem's ``probes``, :class:`~dualmech.model.facts.Probe`): unguarded,
    guarded, and (where another form is regular there) switched."""
    if declared is None:
        if not problem.probes:
            raise ValueError(f"`{problem.name}`: {NO_PROBE}")
        declared = problem.probes[0]
    if not isinstance(declared, Probe):
        raise TypeError(f"`declared` must be a Probe(state, formulation, duration, why), got "
                        f"{declared!r:.60}.")
    y0 = state_vector(problem, declared.state, "`Probe.state`")
    fname, duration, description = declared.formulation, declared.duration, declared.why
    values = problem_parameters(problem, params)
    forms = {f.name: f for f in formulations(problem, params, y0, stabilisations=("none",))[0]}
    if fname not in forms:
        raise ValueError(f"`{problem.name}`: the probe's formulation `{fname}` is not one of "
                         f"its formulations ({', '.join(forms)}).")
    ref, f = next(iter(forms.values())), forms[fname]
    span = (0.0, float(duration))
    te = np.linspace(*span, samples)
    tight = ref.run("DOP853", span, te, rtol=1e-12)
    truth = f.from_reference(tight.t, tight.y[: ref.n], tight.y[ref.n:])
    measure, measured = _measure(problem, params, f, ref, te, truth)
    kappa = _kappa_of(f, values)
    ref_kappa = _kappa_of(ref, values)
    out = ProbeReport(problem.name, fname, list(y0), span, description, rtol, measured)
    for method in methods:
        run = f.run(method, span, te, rtol=rtol)
        out.runs.append(_judge(f, run, "unguarded", measure, kappa, rtol))
        g = _guarded(f, method, span, te, rtol, kappa)
        out.runs.append(_judge(f, g, "guarded", measure, kappa, rtol))
        if g.t_end < span[1] and f is not ref:
            out.runs.append(_switch(f, ref, g, te, truth, rtol, ref_kappa, measure))
    return out


def _measure(problem, params, f, ref, te, truth):
    """``(error(y), what it measures)``: a run's error against ``truth`` in the ground
    frame's positions and velocities of the problem's points (:mod:`dualmech.numeric.scene`)
    where its states are in the reference coordinates -- near a pole the angles themselves
    are distorted, a tiny move of the body a large change of one angle -- else in the form's
    own coordinates, relative to each component's size along the truth."""
    sc = None
    if tuple(f.coordinates) == tuple(ref.coordinates) and f.n == ref.n:
        try:
            sc = scene(problem, params)
        except NoScene:
            sc = None
    if sc is not None:
        def cartesian(y):
            return sc.error(te, y, truth) if y.shape[1] else np.nan
        return cartesian, ("positions and velocities of " + ", ".join(sc.names) +
                           " in the ground frame, relative to their motion's size")
    sizes = state_sizes(truth)

    def own(y):
        k = y.shape[1]
        return float((np.abs(y - truth[:, :k]) / sizes[:, None]).max()) if k else np.nan
    return own, f"{f.name}'s coordinates and rates, relative to their size along the run"


def verdict_word(error: float, rtol: float) -> str:
    """``"right"`` (relative error within ``GARBAGE x rtol``), ``"degraded"`` (within
    :data:`WRONG` of the state's own size) or ``"wrong"`` (beyond, or not a number)."""
    if not np.isfinite(error) or error > WRONG:
        return "wrong"
    return "right" if error <= GARBAGE * rtol else "degraded"


def _judge(f, run, mode, measure, kappa, rtol) -> ProbeRun:
    k = run.y.shape[1]
    kmax = max((kappa(run.y[:, j]) for j in range(k)), default=np.nan)
    err = measure(run.y)
    dE = f.energy_change(run.y) if k else None
    energy = float(np.abs(dE).max()) if dE is not None else np.nan
    word = verdict_word(err, rtol)
    if not run.success and mode == "guarded":
        verdict = f"stopped, with the state kept: {run.message}"
    elif not run.success:
        verdict = f"stopped with an error: {run.message}"
    elif word == "right":
        verdict = (f"right: relative error {err:.2g} in {run.steps} steps (max degeneracy "
                   f"{kmax:.2g})")
    elif word == "degraded":
        verdict = (f"degraded: relative error {err:.2g} (> {GARBAGE:g} x rtol, below "
                   f"{WRONG:g}) after degeneracy {kmax:.2g}")
    else:
        verdict = (f"wrong: reports success, but it is off by {err:.2g} of the motion's "
                   f"size (> {WRONG:g}) after degeneracy {kmax:.2g}")
        if np.isfinite(energy):
            verdict += f"; its energy error is {energy:.2g} N m"
    return ProbeRun(run.method, mode, run.success, str(run.message), run.t_end, run.steps,
                    run.calls, run.cpu, kmax, err, energy, verdict)


_SOLVERS = {"RK45": RK45, "DOP853": DOP853, "Radau": Radau, "BDF": BDF, "LSODA": LSODA}


def _guarded(f: Formulation, method: str, span, te, rtol, kappa) -> Run:
    """Step ``method`` by hand; stop at the last accepted state where the degeneracy passes
    :data:`GARBAGE` or the next step cannot evaluate the model."""
    from dualmech.numeric.integrators import _Counted
    fun = _Counted(f.rhs)
    kw = {"vectorized": True} if method in ("Radau", "BDF") else {}
    start = time.process_time()
    solver = _SOLVERS[method](fun, span[0], f.y0, span[1], rtol=rtol, atol=rtol * f.scales,
                              **kw)
    pieces, message, ok = [], "", True
    t_end, y_end = solver.t, solver.y.copy()
    while solver.status == "running":
        t_prev = solver.t
        try:
            step_message = solver.step()
        except (SingularityError, ValueError, ZeroDivisionError, FloatingPointError) as exc:
            message = (f"the next step past t = {t_prev:.6g} s cannot evaluate the model "
                       f"({str(exc).split(':')[0]}); the last accepted state is kept")
            ok = False
            break
        if solver.status == "failed":
            message, ok = str(step_message), False
            break
        dense = solver.dense_output()
        # the degeneracy inside the step too: a long step can jump over a narrow singular set
        inside = [kappa(dense(t_prev + (solver.t - t_prev) * s)) for s in (0.25, 0.5, 0.75)]
        k = max(inside + [kappa(solver.y)])
        if k > GARBAGE:
            message = (f"guard: degeneracy {k:.2g} > {GARBAGE:g} within the step after "
                       f"t = {t_prev:.6g} s -- past it an error of the tolerance can grow "
                       f"{GARBAGE:g}-fold in these coordinates; the last accepted state is kept")
            ok = False
            break
        pieces.append((t_prev, solver.t, dense))
        t_end, y_end = solver.t, solver.y.copy()
    reached = te[te <= t_end]
    y = np.empty((f.y0.size, reached.size))
    for j, tt in enumerate(reached):
        piece = next((p for p in pieces if p[0] <= tt <= p[1]), None)
        y[:, j] = f.y0 if piece is None else piece[2](tt)
    return Run(method=method, t=reached, y=y, success=ok or solver.status == "finished",
               message=message or "finished", cpu=time.process_time() - start,
               calls=fun.calls, evaluations=fun.evaluations, steps=len(pieces),
               t_end=float(t_end), event_states=[y_end])


def _switch(f, ref, run, te, truth, rtol, ref_kappa, measure) -> ProbeRun:
    """Continue a guarded run in the reference form from where the guard stopped it."""
    from dualmech.numeric.integrators import integrate
    n = ref.n
    lifted = _lift(f, ref, ref.y0, run.y)
    start = lifted[:, -1] if lifted.shape[1] else ref.y0
    y_sw = _lift(f, ref, start, run.event_states[0][:, None])[:, 0]
    t_sw = run.t_end
    k_sw = ref_kappa(y_sw)
    if k_sw > GARBAGE:
        return ProbeRun(run.method, "switched", False, "", t_sw, run.steps, run.calls,
                        run.cpu, k_sw, np.nan, np.nan, f"no switch: {ref.name} is degenerate "
                        f"there too (degeneracy {k_sw:.2g})")
    rest = te[te > t_sw]
    cont = integrate(ref.rhs, (t_sw, te[-1]), y_sw, run.method,
                     t_eval=np.concatenate([[t_sw], rest]), rtol=rtol, atol=rtol * ref.scales)
    Y = np.hstack([lifted, cont.y[:, 1:]])
    k = min(Y.shape[1], truth.shape[1])
    back = f.from_reference(0.0, Y[:n, :k], Y[n:, :k])
    err = measure(back)
    verdict = (f"switched to {ref.name} at t = {t_sw:.6g} s (its degeneracy there "
               f"{k_sw:.2g}); the joined run's error is {err:.2g}")
    return ProbeRun(run.method, "switched", cont.success, str(cont.message), cont.t_end,
                    run.steps + cont.steps, run.calls + cont.calls, run.cpu + cont.cpu,
                    k_sw, err, float("nan"), verdict)
