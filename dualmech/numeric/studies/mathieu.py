"""Mathieu's equation ``x'' + (alpha - 2 q cos 2 tau) x = 0``: its stability chart.

The monodromy matrix over the period ``pi`` has determinant 1, so the motion is bounded when
its trace has ``|tr| < 2`` and grows when ``|tr| > 2``; the transition curves ``|tr| = 2``
are the characteristic values ``a_m(q)`` and ``b_m(q)`` (``tr = 2`` for an even ``m``,
``tr = -2`` for an odd one).  :func:`trace` integrates the two fundamental
solutions with the classical Runge--Kutta method, vectorised over any grid of ``(alpha, q)``
(fourth order: halving the step divides its error by 16, which :func:`trace` can report);
:func:`boundary` finds a transition curve at given ``q`` by root-finding on the trace; the
published small-``q`` series of the first curves (NIST DLMF 28.6.1-28.6.4, the same as
Abramowitz & Stegun 20.2.25) are in :data:`SERIES`.

Example
-------
>>> round(float(boundary("a0", 0.1)), 8)    # DLMF 28.6.1: -q^2/2 + 7 q^4/128 - ...
-0.00499454
"""
from __future__ import annotations

from typing import Callable

import numpy as np

__all__ = ["trace", "boundary", "SERIES", "series", "stable", "draw_chart"]


def _terms(*pairs) -> Callable:
    return lambda q: [c * q**k for k, c in pairs]


#: Power series of the characteristic values (DLMF 28.6.1-28.6.4), term by term.
SERIES = {
    "a0": _terms((2, -1 / 2), (4, 7 / 128), (6, -29 / 2304), (8, 68687 / 18874368)),
    "b1": _terms((0, 1), (1, -1), (2, -1 / 8), (3, 1 / 64), (4, -1 / 1536), (5, -11 / 36864),
                 (6, 49 / 589824), (7, -55 / 9437184)),
    "a1": _terms((0, 1), (1, 1), (2, -1 / 8), (3, -1 / 64), (4, -1 / 1536), (5, 11 / 36864),
                 (6, 49 / 589824), (7, 55 / 9437184)),
    "b2": _terms((0, 4), (2, -1 / 12), (4, 5 / 13824), (6, -289 / 79626240)),
}
#: The largest ``q`` where the series start :func:`boundary` near its own curve (checked
#: against scipy.special.mathieu_a/_b on a 0.05 grid: a1 lands on another curve by q = 5.95).
_TRUSTED = {"a0": 2.0, "b1": 4.0, "a1": 4.0, "b2": 4.0}
#: ``tr`` on each transition curve, and its value at ``q = 0`` (``alpha = m^2``).
_ON = {"a0": (2.0, 0.0), "b1": (-2.0, 1.0), "a1": (-2.0, 1.0), "b2": (2.0, 4.0)}


def series(name: str, q: float) -> tuple[float, float]:
    """``(value, last term)`` of the published series ``name`` at ``q``: for the small ``q``
    where the series converge fast, the truncation error is below the last term kept."""
    terms = SERIES[name](q)
    return float(sum(terms)), float(abs(terms[-1]))


def trace(alpha, q, steps: int = 400, error: bool = False):
    """Trace of the monodromy matrix at ``alpha``, ``q`` (broadcast arrays).

    With ``error=True`` returns ``(trace, estimate)``, the estimate being the change from
    half as many steps divided by 15 (Richardson: the classical RK4's error falls as h^4).
    """
    alpha, q = np.broadcast_arrays(np.asarray(alpha, dtype=float), np.asarray(q, dtype=float))
    if error:
        fine, coarse = trace(alpha, q, 2 * steps), trace(alpha, q, steps)
        return fine, np.abs(fine - coarse) / 15
    h = np.pi / steps
    # the two fundamental solutions: (x, v) = (1, 0) and (0, 1)
    y = np.zeros((4,) + alpha.shape)
    y[0], y[3] = 1.0, 1.0

    def f(tau, y):
        k = alpha - 2 * q * np.cos(2 * tau)
        return np.stack([y[1], -k * y[0], y[3], -k * y[2]])
    for i in range(steps):
        s = i * h
        k1 = f(s, y)
        k2 = f(s + h / 2, y + h / 2 * k1)
        k3 = f(s + h / 2, y + h / 2 * k2)
        k4 = f(s + h, y + h * k3)
        y = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return y[0] + y[3]


def stable(alpha, q, steps: int = 400) -> np.ndarray:
    """Whether the solutions stay bounded (``|tr| < 2``) at each ``alpha``, ``q``."""
    return np.abs(trace(alpha, q, steps)) < 2


def boundary(name: str, q: float, steps: int = 1600) -> float:
    """The transition curve ``name`` (``"a0"``, ``"b1"``, ``"a1"``, ``"b2"``) at ``q``,
    from the trace alone: sign changes of ``tr - (+-2)`` on a grid of 401 points around the
    published series' value (+- 0.05 + q^2/4), the crossing nearest to it refined by three
    vectorised 65-point grids and linear interpolation.

    Accuracy: the root of the *computed* trace is found to ~1e-15 (the last grid's spacing
    is ~1e-9 and the trace is smooth there), but the computed trace itself carries the
    classical Runge--Kutta error of ``steps`` steps, so the curve is as good as that: with
    the default 1600 steps within 2e-10 of ``scipy.special.mathieu_a`` / ``mathieu_b`` for
    ``0.05 <= q <= 4`` (tests/test_mathieu_chart.py).  The search starts from the series,
    which diverge for large ``q``: ``a0`` is found up to ``q = 2``, the others up to
    ``q = 4`` (:data:`_TRUSTED`); beyond, a ``ValueError`` says so rather than return another
    curve's crossing (at ``q = 3`` the search for ``a0`` lands 19 away, on another curve).
    """
    on, _ = _ON[name]
    guess, _ = series(name, q)
    width = 0.05 + q**2 / 4
    if not 0 <= q <= _TRUSTED[name]:
        raise ValueError(f"`q` = {q:g} is outside 0 <= q <= {_TRUSTED[name]:g}, where the "
                         f"series of {name} that starts the search is close enough to find "
                         "its own curve (farther out the crossing found can be another "
                         "curve's).")
    grid = np.linspace(guess - width, guess + width, 401)
    for points in (None, 65, 65, 65):
        if points is not None:
            grid = np.linspace(grid[i], grid[i + 1], points)
        vals = trace(grid, q, steps) - on
        crossings = np.flatnonzero(np.sign(vals[:-1]) != np.sign(vals[1:]))
        if not crossings.size:
            raise ValueError(f"no transition curve {name} near alpha = {guess:.4g} at q = {q}")
        i = int(crossings[np.argmin(np.abs(grid[crossings] - guess))])
    return float(grid[i] - vals[i] * (grid[i + 1] - grid[i]) / (vals[i + 1] - vals[i]))


def draw_chart(ax, q_range: tuple, alpha_range: tuple, points: dict | None = None,
               resolution: int = 181, steps: int = 240) -> None:
    """Shade the stable region of Mathieu's equation on ``ax`` over ``q_range`` x
    ``alpha_range`` (``q`` across, ``alpha`` up), overlay the published series of the first
    transition curves (DLMF 28.6.1-28.6.4, where they converge: ``q <= 1``) and Kapitza's
    ``alpha = -q^2/2``, and mark ``points`` (``{label: (alpha, q)}``)."""
    qs = np.linspace(*q_range, resolution)
    als = np.linspace(*alpha_range, resolution)
    Q, A = np.meshgrid(qs, als)
    excess = np.abs(trace(A, Q, steps)) - 2
    ax.contourf(Q, A, (excess < 0).astype(float), levels=[0.5, 1.5], colors=["#cfe8cf"])
    ax.contour(Q, A, excess, levels=[0.0], colors="0.35", linewidths=0.8)
    small = qs[qs <= 1.0]
    for name, style in (("a0", "-"), ("b1", "--"), ("a1", "--"), ("b2", ":")):
        ax.plot(small, [series(name, x)[0] for x in small], color="#1f4e9c", linestyle=style,
                linewidth=1.0, label=rf"${name[0]}_{name[1]}(q)$, DLMF 28.6 series")
    ax.plot(qs, -qs**2 / 2, color="#b03030", linewidth=0.9, linestyle="-.",
            label=r"Kapitza: $\alpha = -q^2/2$ ($a^2\Omega^2 = 2gl$)")
    for label, (alpha, q) in (points or {}).items():
        ax.plot([abs(q)], [alpha], marker="o", markersize=6, linestyle="none", label=label)
    ax.set_xlim(*q_range)
    ax.set_ylim(*alpha_range)
    ax.set_xlabel(r"$q$ [1]")
    ax.set_ylabel(r"$\alpha$ [1]")
