"""Symplectic integrators of natural conservative models: midpoint, Stormer--Verlet, RATTLE.

All three step the canonical state ``(q, p = M q')`` with a fixed step ``h`` and keep a
modified energy exactly, so the energy error stays bounded over long runs (it oscillates,
of size ``O(h^2)``) instead of drifting as an error-controlled Runge--Kutta run's does.

* :func:`midpoint` -- the implicit midpoint rule for any ``M(q)``:
  ``q1 = q + h v(qm, pm)``, ``p1 = p + h dL/dq(qm, v(qm, pm))``, ``qm, pm`` the averages,
  ``v = M(qm)^-1 pm``; the implicit equations solved by Newton's method, its Jacobian by
  finite differences of the generated code (recomputed when the iteration contracts
  slowly), converging where a fixed-point iteration needs ``h`` below one over the fastest
  motion's Lipschitz constant.
* :func:`verlet` -- Stormer--Verlet (leapfrog), explicit, for a separable ``H = p^T M^-1 p / 2
  + V(q)`` (a constant mass matrix).
* :func:`rattle` -- RATTLE for a constant mass matrix with holonomic constraints
  ``g(q) = 0``: Verlet with the multipliers that keep ``g(q1) = 0`` (Newton) and
  ``G(q1) M^-1 p1 = 0`` (a linear solve): the run stays on the constraint manifold to
  round-off.

Each returns a :class:`~dualmech.numeric.integrators.Run` sampled at ``t_eval`` by cubic
interpolation of the steps (fourth order, below the methods' second), with the steps
themselves in ``Run.nodes`` ``(T, Y)``: the bounded energy error is a property of the steps,
so an energy drift is measured there (:func:`energy_drift`), not on interpolated samples.
``Run.calls`` counts every evaluation of the model (``step_terms`` or ``force``).

Example
-------
>>> import numpy as np, sympy as sp
>>> from dualmech import EquationSet, coordinate, t
>>> from dualmech.numeric.energy import EnergyFunction
>>> x = coordinate("x")
>>> E = EnergyFunction(EquationSet("spring", (x,), (x.diff(t, 2) + x,)), {})
>>> run = verlet(E, (0.0, 2 * np.pi), [1.0, 0.0], np.array([0.0, 2 * np.pi]), h=0.01)
>>> bool(abs(run.y[0, -1] - 1.0) < 1e-4)       # one period: back where it started
True
"""
from __future__ import annotations

import numpy as np

__all__ = ["midpoint", "verlet", "rattle", "constraint_functions", "energy_drift",
           "SymplecticError"]


class SymplecticError(RuntimeError):
    """A symplectic step could not be taken; the message says what to change."""


def _grid(t_span, h: float, max_steps: int, name: str) -> tuple[float, float, int]:
    t0, t1 = float(t_span[0]), float(t_span[1])
    if not (h > 0 and np.isfinite(h)):
        raise ValueError(f"`step` of `{name}` must be a positive number, got {h!r}.")
    steps = int(np.ceil(abs(t1 - t0) / h - 1e-9))
    if steps > max_steps:
        raise SymplecticError(f"`{name}` would take {steps} steps (> {max_steps}); take a "
                              "larger `step`.")
    return t0, (t1 - t0) / steps, steps


def _run(name, t0, h, qs, vs, t_eval, calls, steps, message=""):
    from dualmech.numeric.integrators import Run
    T = t0 + h * np.arange(len(qs))
    Y = np.vstack([np.array(qs).T, np.array(vs).T])
    y = _lagrange4(T, Y, np.asarray(t_eval, dtype=float))
    return Run(method=name, t=np.asarray(t_eval, dtype=float).copy(), y=y, success=True,
               message=message or f"{steps} steps of {h:.4g} s", cpu=0.0, calls=calls,
               evaluations=calls, steps=steps, t_end=float(T[-1]), nodes=(T, Y))


def energy_drift(energy_change, run) -> float:
    """The largest ``|E - E_0|`` of ``run`` on its own steps (``run.nodes``) when it has
    them, else on its samples; ``energy_change(y)`` gives ``E - E_0`` along states ``y``
    (``(2n, K)``), e.g. :meth:`Formulation.energy_change
    <dualmech.numeric.formulations.Formulation.energy_change>`.

    Example
    -------
    >>> import numpy as np
    >>> from dualmech.numeric.integrators import Run
    >>> r = Run(method="midpoint", t=np.zeros(1), y=np.zeros((2, 1)), success=True,
    ...         message="", cpu=0.0, calls=0, evaluations=0, steps=1,
    ...         nodes=(np.arange(2.0), np.array([[1.0, 0.0], [0.0, 1.0]])))
    >>> energy_drift(lambda y: 0.5 * (y**2).sum(axis=0) - 0.5, r)
    0.0
    """
    y = run.nodes[1] if getattr(run, "nodes", None) is not None else run.y
    dE = energy_change(y)
    return float("nan") if dE is None or not np.size(dE) else float(np.abs(dE).max())


def midpoint(energy, t_span, y0, t_eval, h: float, max_steps: int = 2_000_000,
             tol: float = 4e-16):
    """The implicit midpoint rule (module docstring) with Newton's method; raises
    :class:`SymplecticError` if Newton does not converge in 40 iterations."""
    y0 = np.asarray(y0, dtype=float)
    n = y0.size // 2
    t0, h, steps = _grid(t_span, h, max_steps, "midpoint")
    q, qd = y0[:n].copy(), y0[n:].copy()
    M, force = energy.step_terms(q, qd)
    p = M @ qd
    calls = 1

    def residual(z, q, p):
        qm, pm = (q + z[:n]) / 2, (p + z[n:]) / 2
        Mm, _ = energy.step_terms(qm, np.zeros(n))
        vm = np.linalg.solve(Mm, pm)
        _, f = energy.step_terms(qm, vm)
        return np.concatenate([z[:n] - q - h * vm, z[n:] - p - h * f])

    qs, vs = [q.copy()], [qd.copy()]
    J, previous = None, None
    for i in range(steps):
        here = np.concatenate([q, p])
        # predictor: the last step's increment again (second order), explicit Euler at first
        z = here + (here - previous) if previous is not None else \
            np.concatenate([q + h * qd, p + h * force])
        previous = here
        last, size = np.inf, np.inf
        R = residual(z, q, p)
        calls += 2                       # a residual evaluates the model twice
        for it in range(40):
            if J is None:
                J = _jacobian(lambda w: residual(w, q, p), z, R)
                calls += 4 * n
            try:
                dz = np.linalg.solve(J, -R)
            except np.linalg.LinAlgError:
                dz = np.full_like(z, np.nan)
            # damped Newton: halve the correction until the residual falls (or stop trying)
            norm = np.abs(R).max()
            for _ in range(8):
                trial = z + dz
                with np.errstate(all="ignore"):
                    try:
                        R_trial = residual(trial, q, p)
                    except (np.linalg.LinAlgError, ValueError, ZeroDivisionError):
                        R_trial = np.full_like(R, np.nan)
                calls += 2
                if np.abs(R_trial).max() < norm or np.abs(R_trial).max() <= 1e-13 * \
                        max(1.0, np.abs(trial).max()):
                    break
                dz = dz / 2
            else:
                J = None
                if it < 39:
                    continue
            z, R = trial, R_trial
            size = np.abs(dz).max()
            scale = max(1.0, np.abs(z).max())
            if size <= tol * scale or (size >= last and size <= 1e-13 * scale):
                break                     # converged, or at the floor of rounding
            if size > 0.1 * last or size > 1e-6 * scale:
                J = None                  # far off, or contracting slowly: a fresh Jacobian
            last = size
        else:
            raise SymplecticError(
                f"`midpoint`: Newton's method did not converge at t={t0 + i * h:.6g} with "
                f"step {h:.3g} (last correction {size:.2g}); halve `step`.")
        q, p = z[:n], z[n:]
        M, _ = energy.step_terms(q, np.zeros(n))
        qd = np.linalg.solve(M, p)
        _, force = energy.step_terms(q, qd)
        calls += 2
        qs.append(q.copy())
        vs.append(qd.copy())
        if i % 16 == 15:
            J = None                     # the Jacobian follows the motion
    return _run("midpoint", t0, h, qs, vs, t_eval, calls, steps)


def _jacobian(fun, z, f0):
    """Forward differences of ``fun`` at ``z`` (enough for Newton's direction)."""
    J = np.empty((f0.size, z.size))
    for j in range(z.size):
        d = 1e-7 * max(1.0, abs(z[j]))
        w = z.copy()
        w[j] += d
        J[:, j] = (fun(w) - f0) / d
    return J


def _constant_mass(energy, q) -> np.ndarray:
    if not getattr(energy, "constant_mass", False):
        raise ValueError(f"`verlet` and `rattle` need a separable Hamiltonian (a constant "
                         f"mass matrix); `{energy.name}`'s mass matrix depends on the "
                         "coordinates: use `midpoint`.")
    return energy.mass_matrix(q)


def verlet(energy, t_span, y0, t_eval, h: float, max_steps: int = 2_000_000):
    """Stormer--Verlet (module docstring); raises ``ValueError`` for a non-constant ``M``."""
    y0 = np.asarray(y0, dtype=float)
    n = y0.size // 2
    t0, h, steps = _grid(t_span, h, max_steps, "verlet")
    q, v = y0[:n].copy(), y0[n:].copy()
    M = _constant_mass(energy, q)
    p = M @ v
    f = energy.force(q)
    qs, vs = [q.copy()], [v.copy()]
    for _ in range(steps):
        half = p + h / 2 * f
        q = q + h * np.linalg.solve(M, half)
        f = energy.force(q)
        p = half + h / 2 * f
        qs.append(q.copy())
        vs.append(np.linalg.solve(M, p))
    return _run("verlet", t0, h, qs, vs, t_eval, steps + 1, steps)


def rattle(energy, g, G, t_span, y0, t_eval, h: float, max_steps: int = 2_000_000,
           tol: float = 1e-14):
    """RATTLE (module docstring): ``g(q)`` the constraint residuals ``(k,)`` and ``G(q)``
    their gradients ``(k, n)``; ``y0`` must satisfy both constraint levels."""
    y0 = np.asarray(y0, dtype=float)
    n = y0.size // 2
    t0, h, steps = _grid(t_span, h, max_steps, "rattle")
    q, v = y0[:n].copy(), y0[n:].copy()
    M = _constant_mass(energy, q)
    Minv = np.linalg.inv(M)
    p = M @ v
    f = energy.force(q)
    Gq = G(q)
    qs, vs = [q.copy()], [v.copy()]
    calls = 1
    for i in range(steps):
        # position level: q1 = q + h Minv (p + h/2 (f + Gq^T lam)), g(q1) = 0 for lam
        base = q + h * Minv @ (p + h / 2 * f)
        D = h**2 / 2 * Minv @ Gq.T
        lam = np.zeros(Gq.shape[0])
        for _ in range(30):
            q1 = base + D @ lam
            r = g(q1)
            calls += 1
            dl = np.linalg.solve(G(q1) @ D, -r)
            lam = lam + dl
            if np.abs(r).max() <= tol * max(1.0, np.abs(q1).max()):
                break
        else:
            raise SymplecticError(f"`rattle`: the constraint could not be met at "
                                  f"t={t0 + i * h:.6g} with step {h:.3g}; halve `step`.")
        q = base + D @ lam
        half = p + h / 2 * (f + Gq.T @ lam)
        # velocity level: G(q1) Minv p1 = 0 for mu
        f, Gq = energy.force(q), G(q)
        calls += 2
        p_free = half + h / 2 * f
        mu = np.linalg.solve(Gq @ Minv @ Gq.T * (h / 2), -Gq @ Minv @ p_free)
        p = p_free + h / 2 * Gq.T @ mu
        qs.append(q.copy())
        vs.append(Minv @ p)
    return _run("rattle", t0, h, qs, vs, t_eval, calls, steps)


def constraint_functions(constrained, values) -> tuple:
    """``(g, G)`` for :func:`rattle` from a
    :class:`~dualmech.numeric.dae.ConstrainedModel` at parameter ``values``: the residuals
    ``g(q)`` it keeps and their exact gradients ``G(q)`` (generated code)."""
    from dualmech.model.equations import ModelError
    from dualmech.numeric.model import StateFunction
    c = constrained.constraints
    if "velocity" in c.levels or any(r is not None for r in c.static_rows):
        raise ModelError("RATTLE holds position-level constraints, each by a multiplier; "
                         f"{', '.join(c.names())} include velocity-level constraints or "
                         "static rows -- use the DAE forms (projection) instead.")
    k, n = len(c.expressions), len(c.coordinates)
    grads = StateFunction([d for row in c.gradients for d in row], c.coordinates, values)
    zeros = np.zeros(n)

    def g(q):
        return constrained.residuals(q, zeros)[0]

    def G(q):
        return grads(0.0, q, zeros).reshape(k, n)
    return g, G


def _lagrange4(T, Y, t):
    """Cubic interpolation through the four nodes around each time of ``t`` (uniform ``T``):
    error O(h^4), below the methods' O(h^2); exact at the nodes."""
    if len(T) < 4:
        return np.vstack([np.interp(t, T, row) for row in Y])
    h = T[1] - T[0]
    i = np.clip(np.floor((t - T[0]) / h + 1e-9).astype(int) - 1, 0, len(T) - 4)
    s = (t - T[i]) / h  # position in units of h from the first of the four nodes
    w = [-(s - 1) * (s - 2) * (s - 3) / 6, s * (s - 2) * (s - 3) / 2,
         -s * (s - 1) * (s - 3) / 2, s * (s - 1) * (s - 2) / 6]
    return sum(Y[:, i + k] * w[k] for k in range(4))
