"""How long a chaotic run stays right: horizons against a reference more accurate than the run.

:func:`reference` integrates a formulation with DOP853 at rtol 1e-13 and again at 1e-12; the
second's departure from the first bounds the looser one's error, and the tighter one is
trusted only while that departure stays below a thousandth of the error threshold (its
**validity**).  :func:`horizons` runs the formulation at each tolerance and finds the first
time its error passes ``threshold`` -- the error of each coordinate and rate divided by the
root-mean-square size of that component along the reference (the state's own size, not a
declared range).  A horizon past the reference's validity is reported as a lower bound.

An error that starts near the tolerance and grows like ``e^(lambda t)`` passes the threshold
at ``t = (ln threshold - ln tol) / lambda``: the horizons against ``-ln tol`` lie on a line of
slope ``1 / lambda``.  :func:`lyapunov` estimates ``lambda`` independently (Benettin's method:
a companion orbit a small distance away, renormalised at fixed intervals), so the two can be
checked against each other.

Example
-------
A saddle ``x' = x/2, y' = -y`` has the exponent 1/2 exactly (by hand: the companion's offset
turns into the unstable direction and then grows like ``e^(t/2)``):

>>> import numpy as np
>>> lam = lyapunov(lambda t, y: np.array([0.5 * y[0], -y[1]]), [1.0, 1.0], duration=4.0,
...                transient=2.0)
>>> abs(lam - 0.5) < 1e-2
True

The double pendulum's horizons (``horizons(get("compound_double_pendulum"), y0=[2.0, 2.5,
0.0, 0.0])``) take a minute; ``dualmech atlas`` and tests/test_horizon*.py run them.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Sequence

import numpy as np
from scipy.integrate import solve_ivp

__all__ = ["Reference", "reference", "Horizons", "horizons", "lyapunov", "state_sizes",
           "fit_slope", "finite_time_exponents", "regular", "FALLING"]

#: Tolerances of the reference and of its check.
REFERENCE_RTOL, CHECK_RTOL = 1e-13, 1e-12


@dataclass
class Reference:
    """States ``y`` at ``t``, the check run's departure, and the time it stays trustworthy."""

    t: np.ndarray
    y: np.ndarray
    departure: np.ndarray
    valid_until: float


def state_sizes(y: np.ndarray) -> np.ndarray:
    """The state's own size along a trajectory ``y`` (``(2n, K)``), per component
    (``(2n,)``): the root-mean-square of the coordinates together for each coordinate, of
    the rates together for each rate -- so a coordinate that stays near zero (a track tilted
    by a milliradian) is measured against the motion's size, not its own tiny one."""
    n = y.shape[0] // 2
    out = np.empty(y.shape[0])
    for block in (slice(0, n), slice(n, 2 * n)):
        rms = float(np.sqrt(np.mean(y[block]**2)))
        out[block] = rms if rms > 0 else 1.0
    return out


def reference(f, span: tuple, t_eval: np.ndarray, threshold: float) -> Reference:
    """The reference run of ``f`` (see the module docstring)."""
    runs = []
    for rtol in (REFERENCE_RTOL, CHECK_RTOL):
        sol = solve_ivp(f.rhs, span, f.y0, method="DOP853", rtol=rtol, atol=rtol * f.scales,
                        t_eval=t_eval, dense_output=False)
        if not sol.success:
            raise RuntimeError(f"the reference run of {f.name} failed: {sol.message}")
        runs.append(sol.y)
    sizes = state_sizes(runs[0])
    dep = (np.abs(runs[0] - runs[1]) / sizes[:, None]).max(axis=0)
    bad = np.flatnonzero(dep > threshold / 1000)
    valid = float(t_eval[bad[0]]) if bad.size else float(t_eval[-1])
    return Reference(t_eval, runs[0], dep, valid)


@dataclass
class Horizons:
    """Per tolerance: the horizon (s) and whether it is only a lower bound; the fitted and
    the independently estimated Lyapunov exponents (1/s).  ``slope_error`` is the standard
    error of the fitted slope (s), from the fit's residuals (:func:`fit_slope`)."""

    problem: str
    formulation: str
    method: str
    threshold: float
    reference_valid: float
    rows: list = field(default_factory=list)
    fitted: float = float("nan")
    slope_error: float = float("nan")
    lyapunov: float = float("nan")

    def __str__(self) -> str:
        lines = [f"{self.problem}: {self.formulation} with {self.method} against a reference "
                 f"at rtol {REFERENCE_RTOL:g} (trusted until t = {self.reference_valid:.3g} s); "
                 f"a run is right until its error passes {self.threshold:g} of the state's "
                 "own size"]
        for r in self.rows:
            mark = "at least " if r["bound"] else ""
            lines.append(f"  rtol {r['rtol']:.0e}: right until {mark}t = {r['horizon']:.3g} s")
        if np.isfinite(self.fitted):
            slope = 1 / self.fitted
            lo, hi = slope + self.slope_error, slope - self.slope_error
            band = (f"{1 / lo:.3g} to {1 / hi:.3g}" if hi > 0 else f"above {1 / lo:.3g}")
            lines.append(f"  horizon against -ln(rtol): slope {slope:.3g} +- "
                         f"{self.slope_error:.2g} s (standard error from the fit's residuals), "
                         f"i.e. lambda = {self.fitted:.3g} 1/s ({band}) implied by the horizons, "
                         f"against Benettin's {self.lyapunov:.3g} 1/s")
        else:
            lines.append("  fewer than 3 horizons before the reference's validity ends: no "
                         f"slope fitted (Benettin's {self.lyapunov:.3g} 1/s)")
        return "\n".join(lines)


def horizons(problem, y0=None, tolerances: Sequence[float] = tuple(10.0 ** -k for k in
                                                                   range(4, 11)),
             duration: float = 15.0, threshold: float = 0.01, method: str = "DOP853",
             samples: int = 3001, lyapunov_time: float = 60.0,
             exponent: float | None = None) -> Horizons:
    """The horizons of the module docstring for the problem's reference formulation;
    ``exponent`` is Benettin's exponent when already measured (the atlas passes the chaos
    section's, so a report shows one), else measured over ``lyapunov_time`` seconds."""
    from dualmech.numeric.formulations import formulations
    f = formulations(problem, y0=y0, models=[problem.reference])[0][0]
    te = np.linspace(0.0, duration, samples)
    ref = reference(f, (0.0, duration), te, threshold)
    sizes = state_sizes(ref.y)
    out = Horizons(problem.name, f.name, method, threshold, ref.valid_until)
    for tol in tolerances:
        run = f.run(method, (0.0, duration), te, rtol=tol)
        k = run.y.shape[1]
        err = (np.abs(run.y - ref.y[:, :k]) / sizes[:, None]).max(axis=0)
        over = np.flatnonzero(err > threshold)
        t_h = float(te[over[0]]) if over.size else float(te[k - 1])
        bound = (not over.size) or t_h > ref.valid_until
        out.rows.append({"rtol": tol, "horizon": min(t_h, ref.valid_until) if bound else t_h,
                         "bound": bool(bound)})
    good = [r for r in out.rows if not r["bound"]]
    if len(good) >= 3:
        slope, out.slope_error = fit_slope(-np.log([r["rtol"] for r in good]),
                                           [r["horizon"] for r in good], te[1] - te[0])
        out.fitted = float(1 / slope)
    out.lyapunov = float(exponent) if exponent is not None else \
        lyapunov(f.rhs, f.y0, lyapunov_time)
    return out


def fit_slope(x, horizons, resolution: float) -> tuple[float, float]:
    """The least-squares slope of ``horizons`` against ``x`` and its standard error.

    The error is the classical one of a straight-line fit, ``s / sqrt(sum (x - mean x)^2)``,
    with ``s^2`` the residuals' variance on ``N - 2`` degrees of freedom -- but never below
    what the horizons' own rounding allows: each is found on a grid of spacing
    ``resolution`` (a uniform error of variance ``resolution^2 / 12``).  So a fit whose
    points scatter has a large error, one through points on a line a small one.

    Example
    -------
    >>> slope, err = fit_slope([1.0, 2.0, 3.0, 4.0], [1.0, 2.2, 2.8, 4.1], 0.001)
    >>> round(slope, 3), round(err, 4)      # scipy.stats.linregress: 0.99, 0.0933
    (0.99, 0.0933)
    """
    x, y = np.asarray(x, dtype=float), np.asarray(horizons, dtype=float)
    if x.size < 3:
        raise ValueError(f"a slope and its error need at least 3 horizons, got {x.size}.")
    slope, intercept = np.polyfit(x, y, 1)
    rss = float(((y - slope * x - intercept) ** 2).sum())
    variance = max(rss / (x.size - 2), resolution**2 / 12)
    return float(slope), float(np.sqrt(variance / ((x - x.mean()) ** 2).sum()))


def lyapunov(rhs, y0, duration: float, d0: float = 1e-8, every: float = 0.5,
             transient: float = 0.0) -> float:
    """Benettin's estimate of the largest Lyapunov exponent: a companion ``d0`` away
    (relative to the state's size), renormalised every ``every`` seconds; the growth after
    ``transient`` seconds, averaged."""
    return finite_time_exponents(rhs, y0, (duration,), d0, every, transient)[0]


def finite_time_exponents(rhs, y0, windows: Sequence[float], d0: float = 1e-8,
                          every: float = 0.5, transient: float = 0.0) -> list[float]:
    """Benettin's finite-time exponent over each window ``[transient, transient + T]`` of
    ``windows`` (increasing), from one run of the longest: ``ln(growth) / T``.

    For chaotic motion they settle on the largest Lyapunov exponent as ``T`` grows; for
    regular motion the separation grows at most like a power of ``t`` and they fall like
    ``ln(t) / t`` (:func:`regular`).
    """
    windows = [float(w) for w in windows]
    if not windows or any(b <= a for a, b in zip(windows, windows[1:])) or windows[0] <= 0:
        raise ValueError(f"`windows` must be positive and increasing, got {windows}.")
    y = np.asarray(y0, dtype=float).copy()
    scale = max(1.0, np.abs(y).max())
    direction = np.ones_like(y) / np.sqrt(y.size)
    z = y + d0 * scale * direction
    total, t, counted, out = 0.0, 0.0, 0.0, []
    ends = [transient + w for w in windows]
    while t < ends[-1] - 1e-12:
        nxt = min(t + every, ends[-1], *[e for e in ends if e > t + 1e-12])
        span = (t, nxt)
        y = solve_ivp(rhs, span, y, method="DOP853", rtol=1e-12, atol=1e-14).y[:, -1]
        z = solve_ivp(rhs, span, z, method="DOP853", rtol=1e-12, atol=1e-14).y[:, -1]
        d = np.linalg.norm(z - y)
        if span[0] >= transient - 1e-12:
            total += np.log(d / (d0 * scale))
            counted += span[1] - span[0]
        z = y + (z - y) * (d0 * scale / d)
        t = span[1]
        if any(abs(t - e) <= 1e-9 for e in ends[len(out):len(out) + 1]):
            out.append(float(total / counted))
    return out


#: The log-log slope of the finite-time exponent against its window below which it is falling
#: (regular motion: ``ln(t)/t`` gives about -0.7 over a 16-fold range of windows, a separation
#: growing like ``t`` near -1) rather than settling on a positive limit (chaos: near 0).
FALLING = -0.3


def regular(windows: Sequence[float], exponents: Sequence[float]) -> bool:
    """Whether finite-time exponents over ``windows`` say "regular": none is positive, or
    they fall with the window (least-squares slope of ``ln exponent`` against ``ln window``
    below :data:`FALLING`) instead of settling on a positive limit.

    Example
    -------
    >>> regular([5, 10, 20, 40, 80], [0.31, 0.20, 0.09, 0.08, 0.05])   # toy car: regular
    True
    >>> regular([5, 10, 20, 40, 80], [2.2, 2.4, 2.6, 2.6, 2.7])        # double pendulum
    False
    """
    e = np.asarray(exponents, dtype=float)
    if e.size < 3:
        raise ValueError("telling regular from chaotic motion needs at least 3 windows.")
    if not (e > 0).all():        # an exponent at or below zero: no positive limit
        return True
    return bool(np.polyfit(np.log(windows), np.log(e), 1)[0] < FALLING)
