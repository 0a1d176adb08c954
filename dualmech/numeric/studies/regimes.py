"""Where methods fail beyond coordinates: stiffness, linearisation, chaos, DAE drift.

* :func:`stiffness` -- a stiffness parameter swept past its declared range (a stand-in for a
  stiff contact), from a state that leaves the fast mode at rest (the scene a problem
  declares, ``stiff_scene = StiffScene(...)``): the exact motion is smooth,
  so any growth of the step count is stability, not accuracy.  Each explicit method's
  minimal step count is predicted from the fastest eigenvalue of the Jacobian and the size of
  the method's stability region along its direction (from the method's own Butcher tableau);
  the implicit methods' cost is measured beside it.
* :func:`linearisation` -- the small-oscillation model about a stable equilibrium (Jacobian
  at the equilibrium) against the nonlinear model, released along the slowest mode: the
  error over one linear period as a function of the amplitude, and the amplitudes where it
  passes 1 % and 10 %.
* :func:`chaos` -- two formulations of one problem from one state at each tolerance: how
  long their trajectories agree; and first whether the motion is chaotic at all: Benettin's
  finite-time exponents over doubling windows settle on a positive limit (chaos: that limit
  is the Lyapunov exponent) or fall with the window like ``ln(t)/t`` (regular motion: no
  chaos verdict, no exponent).
* :func:`dae_drift` -- the constraint residual over time for each DAE stabilisation, with
  its growth exponent (``|g| ~ t^p``).

Example
-------
Two stiffnesses and two methods, to keep the example fast (``dualmech atlas`` sweeps more):

>>> from dualmech.problems import get
>>> s = stiffness(get("falling_container"), values=(100.0, 1e6), methods=("RK45", "Radau"))
>>> sorted({(r["value"], r["method"]) for r in s.rows})
[(100.0, 'RK45'), (100.0, 'Radau'), (1000000.0, 'RK45'), (1000000.0, 'Radau')]
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Mapping, Sequence

import numpy as np
from scipy.integrate import RK45, DOP853, solve_ivp
from scipy.optimize import brentq, root

from dualmech.model.facts import StiffScene, not_declared, state_vector
from dualmech.numeric.formulations import formulations
from dualmech.numeric.integrators import EXPLICIT
from dualmech.numeric.simulation import problem_parameters
from dualmech.numeric.studies.horizon import finite_time_exponents, regular
from dualmech.numeric.units import unit

__all__ = ["stability_radius", "stable_equilibrium", "jacobian", "Stiffness", "stiffness",
           "NO_STIFF_SCENE",
           "Linearisation", "linearisation", "Chaos", "chaos", "Drift", "dae_drift"]

#: What the atlas says of a problem that declares no stiff scene.
NO_STIFF_SCENE = not_declared("stiff scene",
                              "stiff_scene = StiffScene(parameter, state, duration, why)")


def stability_radius(method: str, direction: float) -> float:
    """Largest ``r`` with ``|R(r e^{i direction})| <= 1`` for scipy's explicit ``method``
    (``R`` the stability function of its Butcher tableau, ``R(z) = 1 + z b^T (I - zA)^-1 1``)."""
    cls = {"RK45": RK45, "DOP853": DOP853}[method]
    raw = np.asarray(cls.A, dtype=float)[: cls.n_stages, : cls.n_stages]
    A = np.zeros((cls.n_stages, cls.n_stages), dtype=complex)
    A[:, : raw.shape[1]] = raw  # scipy stores RK45's A without its (zero) last column
    b = np.asarray(cls.B, dtype=complex)[: cls.n_stages]
    one = np.ones(cls.n_stages)
    unit = np.exp(1j * direction)

    def growth(r):
        z = r * unit
        return abs(1 + z * b @ np.linalg.solve(np.eye(cls.n_stages) - z * A, one)) - 1
    r = np.geomspace(1e-3, 50, 4000)
    g = np.array([growth(x) for x in r])
    k = np.flatnonzero(g > 1e-12)
    k = k[r[k] > 0.5]  # past the origin, where |R| = 1 - O(r^p) may be flat
    if not k.size:
        return float(r[-1])
    j = k[0]
    return float(brentq(growth, r[j - 1], r[j], xtol=1e-12))


def jacobian(rhs, t0: float, y0: np.ndarray) -> np.ndarray:
    """Central finite differences of ``rhs`` at ``y0`` (error O(h^2), h ~ 1e-6 ``|y|``)."""
    y0 = np.asarray(y0, dtype=float)
    J = np.empty((y0.size, y0.size))
    for j in range(y0.size):
        h = 1e-6 * max(1.0, abs(y0[j]))
        e = np.zeros_like(y0)
        e[j] = h
        J[:, j] = (rhs(t0, y0 + e) - rhs(t0, y0 - e)) / (2 * h)
    return J


# -- stiffness ---------------------------------------------------------------------------------
@dataclass
class Stiffness:
    """Per parameter value: the fastest eigenvalue and each method's work and error."""

    problem: str
    parameter: str
    unit: str
    declared: tuple
    scene: str
    span: tuple
    rtol: float
    rows: list = field(default_factory=list)

    def crossover(self, explicit: str = "RK45", implicit: str = "Radau") -> float | None:
        """Smallest swept value where ``explicit`` needs more right-hand sides than ``implicit``."""
        by = {(r["value"], r["method"]): r for r in self.rows}
        for v in sorted({r["value"] for r in self.rows}):
            e, i = by.get((v, explicit)), by.get((v, implicit))
            if e and i and e["evaluations"] > i["evaluations"]:
                return v
        return None

    def __str__(self) -> str:
        lines = [f"{self.problem}: stiffness in {self.parameter} [{self.unit}] (declared "
                 f"range {self.declared}); {self.scene}; rtol {self.rtol:g}"]
        for r in self.rows:
            pred = f", stability boundary: ~{r['min_steps']:.0f}" if r["min_steps"] else ""
            lines.append(f"  {self.parameter} = {r['value']:.3g}: |lambda| = "
                         f"{r['lambda_max']:.3g} 1/s, {r['method']:6s} {r['steps']:7d} steps "
                         f"{r['evaluations']:8d} evaluations {r['cpu']:.3f} s error "
                         f"{r['error']:.2g}{pred}")
        c = self.crossover()
        if c is not None:
            lines.append(f"  explicit RK45 costs more than implicit Radau from "
                         f"{self.parameter} = {c:.3g} {self.unit} on")
        return "\n".join(lines)


def _exact(problem, scene: StiffScene, f, values: dict, te: np.ndarray) -> np.ndarray:
    """The scene's exact motion at ``te``: its declared ``exact`` function with the problem's
    own parameter values (the smooth motion does not depend on the stiffness), else a run of
    Radau at rtol 1e-12 in the formulation ``f``."""
    if scene.exact is not None:
        by_name = {s.name: float(v) for s, v in problem_parameters(problem).items()}
        out = np.asarray(scene.exact(by_name, f.y0.copy(), te), dtype=float)
        if out.shape != (f.y0.size, te.size):
            raise ValueError(f"`{problem.name}`: `StiffScene.exact` returned shape {out.shape}; "
                             f"it must return ({f.y0.size}, {te.size}): the states at the times "
                             "given.")
        return out
    run = f.run("Radau", (float(te[0]), float(te[-1])), te, rtol=1e-12)
    if not run.success or run.y.shape[1] < te.size:
        raise ValueError(f"`{problem.name}`: the tight reference run of the stiff scene at "
                         f"{scene.parameter} = {values[scene.parameter]:g} failed "
                         f"({run.message}); declare the exact motion (`StiffScene.exact`).")
    return run.y


def stiffness(problem, values: Sequence[float] = tuple(10.0 ** k for k in range(2, 9)),
              methods: Sequence[str] = ("RK45", "DOP853", "Radau", "BDF", "LSODA"),
              rtol: float = 1e-6, samples: int = 51) -> Stiffness:
    """The stiffness sweep of the module docstring, in the scene the problem declares
    (``stiff_scene``, :class:`~dualmech.model.facts.StiffScene`)."""
    scene = problem.stiff_scene
    if scene is None:
        raise ValueError(f"`{problem.name}`: {NO_STIFF_SCENE}")
    name, duration = scene.parameter, scene.duration
    y0 = state_vector(problem, scene.state, "`StiffScene.state`")
    decl = {p.symbol.name: p for p in problem.parameters}[name]
    out = Stiffness(problem.name, name, unit(decl.dimension), tuple(decl.range), scene.why,
                    (0.0, duration), rtol)
    te = np.linspace(0.0, duration, samples)
    for v in values:
        f = formulations(problem, {name: v}, y0, models=[problem.reference],
                         strict=False)[0][0]
        lam = np.linalg.eigvals(jacobian(f.rhs, 0.0, f.y0))
        fast = lam[np.argmax(np.abs(lam))]
        exact = _exact(problem, scene, f, {name: v}, te)
        for m in methods:
            run = f.run(m, (0.0, duration), te, rtol=rtol)
            err = float(np.abs(run.y - exact[:, : run.y.shape[1]]).max()) if run.success \
                else float("nan")
            bound = 0.0
            if m in EXPLICIT:
                bound = duration * abs(fast) / stability_radius(m, float(np.angle(fast)))
            out.rows.append({"value": float(v), "method": m, "steps": run.steps,
                             "evaluations": run.evaluations, "cpu": run.cpu, "error": err,
                             "success": run.success, "lambda_max": float(abs(fast)),
                             "lambda": [float(fast.real), float(fast.imag)],
                             "min_steps": bound})
    return out


# -- linearisation ------------------------------------------------------------------------------
@dataclass
class Linearisation:
    """Error of the small-oscillation model against amplitude; the 1 % and 10 % amplitudes."""

    problem: str
    equilibrium: list
    frequency: float
    mode: list
    coordinate: str
    unit: str
    amplitudes: list
    errors: list
    thresholds: dict
    times: np.ndarray = field(repr=False, default=None)

    def __str__(self) -> str:
        marks = "; ".join(f"{100 * lv:g} % at amplitude {a:.4g} {self.unit}" if a is not None
                          else f"{100 * lv:g} % not reached" for lv, a in
                          self.thresholds.items())
        return (f"{self.problem}: small-oscillation model about {self.equilibrium} "
                f"(omega = {self.frequency:.5g} rad/s, mode {self.mode} led by "
                f"{self.coordinate}): error over one period passes {marks}")


def stable_equilibrium(problem, f) -> tuple[np.ndarray, np.ndarray]:
    """The first stable equilibrium found from ``q = 0``, the initial state and the middle
    of the declared ranges; with the Jacobian there."""
    n = f.n
    mids = [np.mean(problem.coordinate_info(q).range) for q in f.coordinates]
    found, why = [], ""
    for guess in (np.zeros(n), f.y0[:n], np.array(mids)):
        try:
            q = _equilibrium(f, guess)
        except ValueError as exc:
            why = why or str(exc)
            continue
        if any(np.allclose(q, p) for p in found):
            continue
        found.append(q)
        J = jacobian(f.rhs, 0.0, np.concatenate([q, np.zeros(n)]))
        lam = np.linalg.eigvals(J)
        if lam.real.max() <= 1e-6 * np.abs(lam).max():
            return q, J
    if not found:
        raise ValueError(f"`{problem.name}` has no equilibrium near q = 0, its initial state "
                         f"or the middle of its ranges ({why})")
    raise ValueError(f"every equilibrium found of `{problem.name}` "
                     f"({', '.join(str([round(float(x), 6) for x in q]) for q in found)}) is "
                     "unstable: there is no small oscillation to linearise about")


def _equilibrium(f, q_guess) -> np.ndarray:
    n = f.n

    def acc(q):
        return f.rhs(0.0, np.concatenate([q, np.zeros(n)]))[n:]
    sol = root(acc, q_guess, tol=1e-14)
    if not sol.success or np.abs(acc(sol.x)).max() > 1e-9:
        raise ValueError(f"none near {[round(float(x), 6) for x in q_guess]}: "
                         f"{' '.join(str(sol.message).split())}")
    return sol.x


def linearisation(problem, levels: Sequence[float] = (0.01, 0.1), params: Mapping | None = None,
                  rtol: float = 1e-11, samples: int = 201) -> Linearisation:
    """The amplitude sweep of the module docstring, about the equilibrium nearest ``q = 0``."""
    f = formulations(problem, params, models=[problem.reference])[0][0]
    n = f.n
    q_eq, J = stable_equilibrium(problem, f)
    y_eq = np.concatenate([q_eq, np.zeros(n)])
    lam, vec = np.linalg.eig(J)
    osc = [k for k in range(lam.size) if lam[k].imag > 1e-9 * np.abs(lam).max()]
    if not osc:
        raise ValueError(f"`{problem.name}` does not oscillate about {list(q_eq)}.")
    k = min(osc, key=lambda j: lam[j].imag)
    w = float(lam[k].imag)
    v = vec[:n, k]
    lead = int(np.argmax(np.abs(v)))
    mode = np.real(v / v[lead])
    period = 2 * np.pi / w
    te = np.linspace(0.0, period, samples)
    info = problem.coordinate_info(f.coordinates[lead])
    top = min(abs(info.range[1] - q_eq[lead]), abs(q_eq[lead] - info.range[0]))

    def error(a: float) -> float:
        y0 = np.concatenate([q_eq + a * mode, np.zeros(n)])
        size = a * np.abs(mode).max()          # tolerances scaled with the motion's size
        atol = rtol * size * np.concatenate([np.ones(n), np.full(n, w)])
        nl = solve_ivp(f.rhs, (0.0, period), y0, method="DOP853", rtol=rtol, atol=atol,
                       t_eval=te).y[:n]
        lin = _linear(J, y0 - y_eq, te)[:n] + q_eq[:, None]
        return float(np.abs(nl - lin).max() / (a * np.abs(mode).max()))
    amps = list(np.geomspace(top * 1e-3, top, 25))
    errs = [error(a) for a in amps]
    marks = {}
    for lv in levels:
        j = next((i for i, e in enumerate(errs) if e > lv), None)
        marks[lv] = None if j in (None, 0) else \
            float(brentq(lambda a: np.log(error(a) / lv), amps[j - 1], amps[j], xtol=1e-12))
    return Linearisation(problem.name, [round(float(x), 9) for x in q_eq], w,
                         [round(float(x), 6) + 0.0 for x in mode], info.name,
                         unit(info.dimension), amps, errs, marks, te)


def _linear(J, dy0, te) -> np.ndarray:
    """``exp(J t) dy0`` at the times ``te`` (eigen-decomposition; ``J`` diagonalisable)."""
    lam, V = np.linalg.eig(J)
    c = np.linalg.solve(V, dy0.astype(complex))
    return np.real(V @ (c[:, None] * np.exp(lam[:, None] * te[None, :])))


# -- chaos -------------------------------------------------------------------------------------
#: Benettin windows of :func:`chaos` [s]: doubling, a 16-fold range.
WINDOWS = (5.0, 10.0, 20.0, 40.0, 80.0)


@dataclass
class Chaos:
    """How long two formulations agree at each tolerance, and whether the motion is chaotic:
    Benettin's finite-time exponents (``exponents``, 1/s) over ``windows`` (s) -- settling on
    a positive limit (chaotic; ``lyapunov`` is the longest window's) or falling with the
    window (``regular``; ``lyapunov`` is then ``nan``: there is no positive exponent)."""

    problem: str
    pair: tuple
    y0: list
    span: tuple
    threshold: float
    rows: list
    windows: list
    exponents: list
    regular: bool
    lyapunov: float

    def verdict(self) -> str:
        """One sentence: chaotic with the exponent and its window, or regular and why."""
        shown = ", ".join(f"{e:.2g}" for e in self.exponents)
        over = f"over windows of {', '.join(f'{w:g}' for w in self.windows)} s"
        if self.regular:
            return (f"regular motion, no chaos: Benettin's finite-time exponents {shown} 1/s "
                    f"{over} fall with the window (as ln(t)/t does when nearby motions part "
                    "only like a power of t), so no positive Lyapunov exponent")
        return (f"chaotic: largest Lyapunov exponent {self.lyapunov:.3g} 1/s (Benettin, "
                f"window {self.windows[-1]:g} s; finite-time exponents {shown} 1/s {over})")

    def __str__(self) -> str:
        lines = [f"{self.problem}: {self.verdict()}",
                 f"{self.pair[0]} against {self.pair[1]} from {self.y0}: agreement = every "
                 f"coordinate within {self.threshold:g} of its declared range"]
        for r in self.rows:
            lines.append(f"  rtol {r['rtol']:.0e}: agree until t = {r['horizon']:.3g} s")
        return "\n".join(lines)


def chaos(problem, pair: Sequence[str] | None = None, y0=None, duration: float = 20.0,
          tolerances: Sequence[float] = tuple(10.0 ** -k for k in range(4, 13, 2)),
          threshold: float = 0.01, samples: int = 2001,
          windows: Sequence[float] = WINDOWS) -> Chaos:
    """Agreement horizon of two formulations against tolerance (see the module docstring),
    and whether the motion is chaotic at all (:func:`~.horizon.finite_time_exponents` over
    ``windows``, judged by :func:`~.horizon.regular`).

    ``threshold`` is the disagreement, as a fraction of each coordinate's declared range,
    beyond which two runs no longer describe the same motion.
    """
    forms, _ = formulations(problem, y0=y0, stabilisations=())
    odes = [f for f in forms if f.kind == "ode" and
            tuple(f.coordinates) == tuple(forms[0].coordinates)]
    chosen = [f for f in odes if pair is None or f.name in pair][:2]
    if len(chosen) < 2:
        raise ValueError(f"`{problem.name}` has no two ODE formulations in the reference "
                         "coordinates to compare.")
    a, b = chosen
    te = np.linspace(0.0, duration, samples)
    n = a.n
    rows = []
    for tol in tolerances:
        ra, rb = a.run("DOP853", (0.0, duration), te, rtol=tol), \
            b.run("DOP853", (0.0, duration), te, rtol=tol)
        k = min(ra.y.shape[1], rb.y.shape[1])
        gap = (np.abs(ra.y[:n, :k] - rb.y[:n, :k]) / a.scales[:n, None]).max(axis=0)
        out = np.flatnonzero(gap > threshold)
        rows.append({"rtol": tol, "horizon": float(te[out[0]]) if out.size else duration,
                     "diverged": bool(out.size)})
    exps = finite_time_exponents(a.rhs, a.y0, windows)
    calm = regular(windows, exps)
    return Chaos(problem.name, (a.name, b.name), [float(x) for x in a.y0], (0.0, duration),
                 threshold, rows, [float(w) for w in windows], exps, calm,
                 float("nan") if calm else exps[-1])


# -- DAE drift --------------------------------------------------------------------------------
@dataclass
class Drift:
    """Constraint residual ``|g|`` over time per stabilisation (``times``, ``residual``), its
    growth exponent, and why a run stopped early (``stopped``)."""

    problem: str
    model: str
    method: str
    rtol: float
    unit: str
    times: dict = field(repr=False, default_factory=dict)
    residual: dict = field(repr=False, default_factory=dict)
    growth: dict = field(default_factory=dict)
    stopped: dict = field(default_factory=dict)

    def __str__(self) -> str:
        lines = [f"{self.problem}: drift of {self.model}'s constraints, {self.method} at rtol "
                 f"{self.rtol:g}"]
        for k, g in self.residual.items():
            if g.size:
                lines.append(f"  {k:10s} max |g| = {np.abs(g).max():.3g} {self.unit}, at the "
                             f"end {np.abs(g[-1]):.3g} {self.unit}; |g| ~ t^{self.growth[k]:.2f}")
            if k in self.stopped:
                lines.append(f"  {k:10s} stopped: {self.stopped[k]}")
        return "\n".join(lines)


def dae_drift(problem, model: str | None = None, duration: float = 20.0, method: str = "RK45",
              rtol: float = 1e-6, samples: int = 401) -> Drift:
    """The drift of each stabilisation of a multiplier model (see the module docstring)."""
    from dualmech.numeric.units import work_conjugate_unit
    forms = [f for f in formulations(problem)[0] if f.kind == "dae"
             and (model is None or f.model.name == model)]
    if not forms:
        raise ValueError(f"`{problem.name}` has no DAE formulation" +
                         (f" named {model!r}." if model else ": declare a model whose "
                          "coordinates are held by constraints closed with multipliers (a "
                          "method named in `extra_models` building a Lagrangian in more "
                          "coordinates, with `lg.constraint(name, g)` and the multiplier "
                          "declared in `reactions`) to make it applicable."))
    name = forms[0].model.name
    forms = [f for f in forms if f.model.name == name]
    te = np.linspace(0.0, duration, samples)
    info = problem.reaction_info()
    c = forms[0].constrained.constraints
    held = [(u.name, lv) for u, lv in zip(c.multipliers, c.levels) if u is not None]
    lam, level = held[0] if held else ("", "position")   # static rows alone: no unit known
    unit = work_conjugate_unit(info[lam].dimension) if lam in info else ""
    unit += "/s" if unit and level == "velocity" else ""
    out = Drift(problem.name, name, method, rtol, unit)
    for f in forms:
        run = f.run(method, (0.0, duration), te, rtol=rtol)
        k = f.stabilisation
        g = np.abs(f.drift(run.y)[0]).max(axis=0) if run.y.shape[1] else np.zeros(0)
        out.times[k], out.residual[k] = run.t, g
        out.growth[k] = growth_exponent(run.t, g)
        if not run.success or run.t.size < te.size:
            out.stopped[k] = f"at t = {run.t_end:.4g} s: {run.message}"
    return out


def growth_exponent(t: np.ndarray, g: np.ndarray, start: float = 1.0) -> float:
    """``p`` of ``|g| ~ t^p``: least squares on the running maximum of ``|g|`` for ``t >= start``."""
    env = np.maximum.accumulate(np.abs(g))
    keep = (t >= start) & (env > 0)
    if keep.sum() < 2:
        return 0.0
    return float(np.polyfit(np.log(t[keep]), np.log(env[keep]), 1)[0])
