"""Periodically driven scenes: periodic motions, their monodromy matrix and Floquet multipliers.

A model whose only explicit time dependence is through ``sin``/``cos`` of ``omega_k t + c_k``
with commensurate ``omega_k`` is periodic in time (:func:`forcing_period`).  Its equilibria
are not those of a frozen instant: a linearisation at ``t = 0`` says nothing about stability
(it calls the inverted position of Kapitza's pendulum unstable).  What decides is the
**monodromy matrix** ``Phi(T)`` of the variational equations ``Phi' = J(t, y(t)) Phi``,
``Phi(0) = I``, along a periodic motion ``y(t + T) = y(t)``: its eigenvalues, the **Floquet
multipliers**, all in the closed unit disc means linearly stable (a conservative system's
come in pairs ``mu``, ``1/mu``: stable means all on the unit circle); one outside, unstable.

:func:`floquet` finds periodic motions near rest points of the period-averaged accelerations
(Newton shooting on the period map), integrates the variational equations with a tight
tolerance (``J`` by central differences of the model's own right-hand side, all columns in
one vectorised call), and classifies each by its multipliers; the multipliers' error is
estimated from two tolerances.  :func:`mathieu_coefficients` recognises a one-coordinate
orbit whose linearisation is Mathieu's equation (see :mod:`~dualmech.numeric.studies.mathieu`).

Example
-------
>>> import numpy as np
>>> rhs = lambda t, y: np.array([y[1], -(1 + 0.2 * np.cos(2 * t)) * np.sin(y[0])])
>>> M = monodromy(rhs, np.zeros(2), 0.0, np.pi)[0]
>>> bool(abs(np.linalg.det(M) - 1) < 1e-9)      # Liouville: no damping, volume kept
True
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Callable, Mapping

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp
from scipy.optimize import root

from dualmech.model.kinematics import t
from dualmech.numeric.simulation import problem_parameters

__all__ = ["forcing_period", "monodromy", "PeriodicOrbit", "Floquet", "floquet",
           "mathieu_coefficients", "NotDriven"]

#: Tolerance of the variational runs (and a hundred times it, to estimate their error).
RTOL = 1e-11


class NotDriven(ValueError):
    """The model is autonomous, or its time dependence is not periodic."""


def forcing_period(eqs, values: Mapping) -> float:
    """The common period (s) of ``eqs``' explicit time dependence at parameter ``values``.

    Raises :class:`NotDriven` when there is none, when ``t`` appears outside ``sin``/``cos``
    of an argument linear in ``t``, or when the frequencies are not commensurate.
    """
    A, b = eqs.plain_matrix()
    exprs = [e for e in list(A) + list(b) if e.has(t)]
    if not exprs:
        raise NotDriven(f"`{eqs.name}` does not depend on time explicitly: it is autonomous")
    subs = {s: v for s, v in values.items()}
    omegas = set()
    probe = sp.Dummy("probe")
    for e in exprs:
        for f in e.atoms(sp.sin, sp.cos):
            arg = f.args[0]
            if not arg.has(t):
                continue
            w = sp.diff(arg, t)
            if w.has(t):
                raise NotDriven(f"`{eqs.name}`: {f} is not periodic in t")
            omegas.add(abs(float(w.subs(subs))))
        rest = e.replace(lambda x: isinstance(x, (sp.sin, sp.cos)) and x.args[0].has(t),
                         lambda x: probe)
        if rest.has(t):
            raise NotDriven(f"`{eqs.name}`: time appears outside a sine or cosine ({rest}); "
                            "the forcing is not periodic")
    w0 = min(omegas)
    ratios = [Fraction(w / w0).limit_denominator(12) for w in omegas]
    if any(abs(float(r) - w / w0) > 1e-12 * (w / w0) for r, w in zip(ratios, omegas)):
        raise NotDriven(f"`{eqs.name}`: forcing frequencies {sorted(omegas)} are not "
                        "commensurate: the motion has no common period")
    den = math.lcm(*(r.denominator for r in ratios))
    return float(2 * np.pi * den / w0)


def monodromy(rhs: Callable, y0: np.ndarray, t0: float, period: float, rtol: float = RTOL,
              scales: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """``(Phi(T), y(t0 + T))``: the variational equations integrated with DOP853 over one
    period from ``y0``; ``J Phi`` column by column as central differences of ``rhs`` along
    each column (one vectorised call of ``rhs`` per evaluation)."""
    y0 = np.asarray(y0, dtype=float)
    N = y0.size
    scales = np.ones(N) if scales is None else np.asarray(scales, dtype=float)

    def aug(time, z):
        y, Phi = z[:N], z[N:].reshape(N, N)
        norms = np.linalg.norm(Phi / scales[:, None], axis=0)
        eps = 1e-6 / np.where(norms > 0, norms, 1.0)
        cols = np.ascontiguousarray(np.hstack([y[:, None], y[:, None] + eps * Phi,
                                               y[:, None] - eps * Phi]))
        F = np.asarray(rhs(time, cols))
        JPhi = (F[:, 1:N + 1] - F[:, N + 1:]) / (2 * eps)
        return np.concatenate([F[:, 0], JPhi.ravel()])
    z0 = np.concatenate([y0, np.eye(N).ravel()])
    atol = rtol * np.concatenate([scales, np.ones(N * N)])
    sol = solve_ivp(aug, (t0, t0 + period), z0, method="DOP853", rtol=rtol, atol=atol)
    if not sol.success:
        raise RuntimeError(f"the variational equations could not be integrated over one "
                           f"period from {y0.tolist()}: {sol.message}")
    z = sol.y[:, -1]
    return z[N:].reshape(N, N), z[:N]


@dataclass
class PeriodicOrbit:
    """A periodic motion through ``state`` at ``t = 0``, its multipliers and the verdict."""

    state: list
    names: list
    multipliers: list
    radius: float
    error: float
    stable: bool
    equilibrium: bool
    mathieu: tuple | None = None

    @property
    def label(self) -> str:
        """``"theta = 3.1416"``: the coordinates of the state at ``t = 0``."""
        return ", ".join(f"{k} = {v:.5g}" for k, v in zip(self.names, self.state))

    def __str__(self) -> str:
        what = "equilibrium" if self.equilibrium else "periodic motion through"
        mus = ", ".join(f"{complex(m).real:.6g}{complex(m).imag:+.6g}i" for m in self.multipliers)
        verdict = (f"STABLE: every |mu| <= 1 (largest {self.radius:.10f} +- {self.error:.1g})"
                   if self.stable else
                   f"unstable: |mu| = {self.radius:.6g} > 1 (+- {self.error:.1g})")
        out = f"  {what} {self.label}: multipliers {mus}; {verdict}"
        if self.mathieu is not None:
            out += (f"\n    linearised: Mathieu's equation, alpha = {self.mathieu[0]:.6g}, "
                    f"q = {self.mathieu[1]:.6g}")
        return out


@dataclass
class Floquet:
    """The periodic motions found for a driven problem, with their multipliers."""

    problem: str
    period: float
    orbits: list = field(default_factory=list)
    notes: list = field(default_factory=list)

    def __str__(self) -> str:
        lines = [f"{self.problem}: driven with period {self.period:.6g} s; stability from "
                 "Floquet multipliers (eigenvalues of the monodromy matrix over one period), "
                 "not from a linearisation frozen at one instant"]
        lines += [str(o) for o in self.orbits] + [f"  {n}" for n in self.notes]
        return "\n".join(lines)

    @property
    def stable(self) -> list:
        return [o for o in self.orbits if o.stable]


def _averaged_rest(f, period: float, guess: np.ndarray) -> np.ndarray | None:
    """A rest point of the period-averaged accelerations near ``guess`` (trapezoid rule over
    one period: spectrally accurate for periodic integrands)."""
    n = f.n
    times = np.linspace(0.0, period, 33)[:-1]

    def acc(q):
        y = np.concatenate([q, np.zeros(n)])
        return np.mean([f.rhs(s, y)[n:] for s in times], axis=0)
    # the size of the accelerations a tenth of each range away sets what "zero" is
    shifted = [np.concatenate([guess + 0.1 * np.eye(n)[i] * f.scales[i], np.zeros(n)])
               for i in range(n)]
    scale = max(np.abs(f.rhs(s, y)[n:]).max() for s in times for y in shifted) or 1.0
    x = root(acc, guess, tol=1e-13).x
    return x if np.abs(acc(x)).max() <= 1e-10 * scale else None


def _shoot(f, period: float, y: np.ndarray, rtol: float):
    """Newton on ``P(y) - y = 0`` (``P`` the period map); returns ``(y, Phi, residual)``."""
    for _ in range(12):
        Phi, end = monodromy(f.rhs, y, 0.0, period, rtol, f.scales)
        res = end - y
        if np.all(np.abs(res) <= 1e3 * rtol * f.scales):
            return y, Phi, res
        y = y - np.linalg.lstsq(Phi - np.eye(y.size), res, rcond=None)[0]
    return y, Phi, res


def mathieu_coefficients(f, state: np.ndarray, period: float) -> tuple | None:
    """``(alpha, q)`` when the linearisation of a one-coordinate model about the rest point
    ``state`` is ``x'' + (A + B cos(omega t)) x = 0`` (no damping, one harmonic):
    ``alpha = 4 A / omega^2``, ``q = -2 B / omega^2`` in ``x_tt + (alpha - 2 q cos 2 tau) x = 0``,
    ``tau = omega t / 2``; ``None`` otherwise."""
    if f.n != 1 or abs(state[1]) > 0:
        return None
    times = np.linspace(0.0, period, 65)[:-1]
    h = 1e-6 * max(1.0, abs(state[0]))
    k, c = [], []
    for s in times:
        dq = (f.rhs(s, state + [h, 0]) - f.rhs(s, state - [h, 0]))[1] / (2 * h)
        dv = (f.rhs(s, state + [0, h]) - f.rhs(s, state - [0, h]))[1] / (2 * h)
        k.append(-dq)
        c.append(dv)
    k, omega = np.array(k), 2 * np.pi / period
    A = k.mean()
    B = 2 * np.mean(k * np.cos(omega * times))
    fit = A + B * np.cos(omega * times)
    size = max(abs(A), abs(B))
    if np.abs(k - fit).max() > 1e-6 * size or np.abs(c).max() > 1e-6 * size / omega:
        return None
    return 4 * A / omega**2, -2 * B / omega**2


def floquet(problem, params: Mapping | None = None, rtol: float = RTOL) -> Floquet:
    """The periodic motions of a driven problem and their Floquet multipliers.

    Candidates: rest points of the period-averaged accelerations from ``q = 0``, the initial
    state, the middle of the declared ranges and each angle turned half over; each is made
    exactly periodic by shooting.  Raises :class:`NotDriven` for an autonomous model.
    """
    from dualmech.model.dimensions import ANGLE
    from dualmech.numeric.formulations import formulations
    values = problem_parameters(problem, params)
    ref = problem.model(problem.reference)
    period = forcing_period(ref, values)
    f = formulations(problem, params, models=[problem.reference])[0][0]
    n = f.n
    guesses = [np.zeros(n), f.y0[:n], np.array([np.mean(problem.coordinate_info(q).range)
                                                for q in f.coordinates])]
    for i, q in enumerate(f.coordinates):
        if problem.coordinate_info(q).dimension == ANGLE:
            g = np.zeros(n)
            g[i] = np.pi
            guesses.append(g)
    out = Floquet(problem.name, period)
    for guess in guesses:
        q = _averaged_rest(f, period, guess)
        if q is None:
            continue
        y, Phi, res = _shoot(f, period, np.concatenate([q, np.zeros(n)]), rtol)
        if any(np.allclose(y, np.array(o.state), atol=1e-6 * f.scales.max())
               for o in out.orbits):
            continue
        if np.any(np.abs(res) > 1e3 * rtol * f.scales):
            out.notes.append(f"no periodic motion near rest at {q.tolist()} (shooting left "
                             f"a residual {np.abs(res).max():.2g})")
            continue
        coarse, _ = monodromy(f.rhs, y, 0.0, period, 100 * rtol, f.scales)
        mu = np.linalg.eigvals(Phi)
        mu_c = np.linalg.eigvals(coarse)
        # the multipliers' error: their change from a hundredfold looser run; near a double
        # multiplier (two closer than the square root of the monodromy's change) a
        # perturbation d of the matrix moves them by sqrt(d)
        d = float(np.abs(Phi - coarse).max())
        err = float(np.abs(np.sort_complex(mu) - np.sort_complex(mu_c)).max())
        gaps = np.abs(mu[:, None] - mu[None, :]) + np.eye(mu.size) * 1e300
        if gaps.min() < 10 * np.sqrt(d):
            err = max(err, np.sqrt(d))
        radius = float(np.abs(mu).max())
        equilibrium = bool(np.abs(f.rhs(0.0, y)).max() <= 1e-9 * max(1.0, np.abs(y).max())
                           and np.abs(y[n:]).max() == 0)
        out.orbits.append(PeriodicOrbit(
            [round(float(x), 12) + 0.0 for x in y],
            [q.func.__name__ for q in f.coordinates] + [f"{q.func.__name__}'"
                                                       for q in f.coordinates],
            [complex(m) for m in mu], radius,
            float(err), radius <= 1 + 10 * err, equilibrium,
            mathieu_coefficients(f, y, period) if equilibrium else None))
    if not out.orbits:
        out.notes.append("no periodic motion found near rest")
    return out
