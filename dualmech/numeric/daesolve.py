r"""Index-3 and stabilised index-2 (GGL) forms, solved as DAEs by SUNDIALS IDA.

A model in maximal coordinates with multipliers, ``M(q) q'' + W(q) lambda = b(q, q', t)``
and holonomic constraints ``g(q) = g0`` (:class:`~dualmech.numeric.dae.ConstrainedModel`),
is integrated as a differential-algebraic system by IDA (variable-order BDF with a Newton
iteration on the residual; Brenan, Campbell & Petzold, *Numerical Solution of IVPs in DAEs*),
through the ``scikit-sundae`` bindings, in two forms:

* ``index3`` -- the original system in ``y = [q, v, lambda]``::

      q' - v = 0,   M v' + W lambda - b = 0,   g(q) - g0 = 0;

  the multipliers (index 3) and the velocities of the coordinates that enter a constraint
  (index 2) are left out of the error test (``atol`` set far above their size), whose
  estimate is not valid for them (Brenan et al., section 5.4); the velocities of coordinates
  no constraint holds are index-1 variables and stay in it;
* ``ggl`` -- Gear, Gupta & Leimkuhler's stabilised index-2 form in ``y = [q, v, lambda, mu]``
  (*J. Comput. Appl. Math.* 12, 1985)::

      q' - v + G^T mu = 0,   M v' + W lambda - b = 0,   g(q) - g0 = 0,   G(q) v = 0,

  with ``G = dg/dq``: position and velocity constraints both hold at every step, the extra
  multiplier ``mu`` is zero on exact solutions; ``lambda`` and ``mu`` are left out of the
  error test.

Both start from a consistent state: ``q`` on the manifold, ``v`` tangent to it, ``v'`` and
``lambda`` from the index-1 system.  IDA's own finite-difference Jacobian of the residual is
used (dense).  Samples come from IDA's interpolant at the requested times; the accepted steps
are counted one by one.

Example
-------
>>> from dualmech.problems import get
>>> from dualmech.numeric.formulations import formulations
>>> forms, _ = formulations(get("pendulum_particle"), stabilisations=("ggl",))
>>> f = {g.name: g for g in forms}["cartesian (DAE, GGL index 2)"]
>>> r = f.run("IDA", (0, 1), [0, 0.5, 1], rtol=1e-8)
>>> r.success, r.y.shape, r.steps > 10
(True, (4, 3), True)
"""
from __future__ import annotations

import time as _time
from typing import Sequence

import numpy as np

from dualmech.model.equations import ModelError
from dualmech.numeric.integrators import WorkBudget, BudgetExceeded, Run, _Meter

__all__ = ["DAE_FORMS", "DAE_METHODS", "IDASolver"]

#: The forms solved by a DAE solver, and the solver's method name.
DAE_FORMS = ("index3", "ggl")
DAE_METHODS = ("IDA",)
#: The ``atol`` that takes a component out of IDA's error test (its weight ~ 1e-30).
_EXCLUDED = 1e30


class IDASolver:
    """One DAE form (``"index3"`` or ``"ggl"``) of a constrained model, solved by IDA.

    Parameters
    ----------
    constrained : ConstrainedModel
    form : ``"index3"`` or ``"ggl"``
    """

    def __init__(self, constrained, form: str):
        if form not in DAE_FORMS:
            raise ValueError(f"`form` must be one of {DAE_FORMS}, got {form!r}.")
        self.cm, self.form = constrained, form
        self.n, self.k = constrained.n, constrained.k
        self.size = 2 * self.n + self.k * (2 if form == "ggl" else 1)
        #: coordinates that enter a constraint (their velocities are index-2 variables)
        self.constrained = np.array([any(row[j] != 0 for row in constrained.constraints.gradients)
                                     for j in range(self.n)])
        self.calls = 0
        self._meter = _Meter(None)

    def residual(self, t: float, y: np.ndarray, yp: np.ndarray, res: np.ndarray) -> None:
        """IDA's residual ``F(t, y, y') = 0`` written into ``res``."""
        n, k = self.n, self.k
        self.calls += 1
        self._meter.charge(t)
        q, v, lam = y[:n], y[n:2 * n], y[2 * n:2 * n + k]
        A, b = self.cm.numeric.system(t, q, v)
        res[:n] = yp[:n] - v
        res[n:2 * n] = A[:n, :n] @ yp[n:2 * n] + A[:n, n:] @ lam - b[:n]
        g, _ = self.cm.residuals(q, v)
        res[2 * n:2 * n + k] = g
        if self.form == "ggl":
            G = self.cm.gradient(q)
            res[:n] += G.T @ y[2 * n + k:]
            res[2 * n + k:] = G @ v

    def initial(self, time: float, y0: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """A consistent ``(y, y')`` from ``y0 = [q, v]`` (projected onto the manifold)."""
        n = self.n
        y0 = self.cm.project(time, np.asarray(y0, dtype=float))
        x = self.cm.numeric.solve(time, y0[:n], y0[n:])
        y = np.concatenate([y0, x[n:], np.zeros(self.size - 2 * n - self.k)])
        yp = np.concatenate([y0[n:], x[:n], np.zeros(self.size - 2 * n)])
        return y, yp

    def run(self, t_span: Sequence[float], y0, t_eval, *, rtol: float, atol,
            max_steps: int = 500_000, budget: WorkBudget | None = None) -> Run:
        """Integrate from ``y0 = [q, v]``; the :class:`Run` holds ``[q; v]`` at ``t_eval``.

        Past ``budget`` (CPU seconds and residual calls,
        :class:`~dualmech.numeric.integrators.WorkBudget`) the run ends as *did not finish*."""
        import sksundae as sun
        n = self.n
        t_eval = np.asarray(t_eval, dtype=float)
        start = _time.process_time()
        self.calls = 0
        self._meter = _Meter(budget)
        tol = np.full(self.size, _EXCLUDED)
        atol = np.broadcast_to(np.asarray(atol, dtype=float), (2 * n,))
        tol[:2 * n] = atol
        if self.form == "index3":  # index-2 velocities: those of coordinates the loop holds
            tol[n:2 * n][self.constrained] = _EXCLUDED
        t0, t1 = float(t_span[0]), float(t_span[1])
        solver = sun.ida.IDA(self.residual, rtol=rtol, atol=tol, max_num_steps=max_steps,
                             algebraic_idx=list(range(2 * n, self.size)))
        ys, k, steps, ok, message, njev = [], 0, 0, True, "IDA", 0
        try:
            y, yp = self.initial(t0, y0)
            while k < t_eval.size and t_eval[k] <= t0:
                ys.append(y[:2 * n].copy())
                k += 1
            solver.init_step(t0, y, yp)
            now = t0
            while k < t_eval.size:
                out = solver.step(t1, method="onestep", tstop=t1)
                if not out.success:
                    ok, message = False, f"IDA stopped at t={now:.6g}: {out.message}"
                    break
                steps += 1
                now = float(out.t)
                njev = int(out.njev)
                while k < t_eval.size and t_eval[k] <= now * (1 + 1e-15):
                    ys.append(solver.step(t_eval[k]).y[:2 * n].copy())
                    k += 1
                if steps >= max_steps:
                    ok, message = False, f"more than {max_steps} steps"
                    break
        except BudgetExceeded as exc:
            ok, message = False, str(exc)
        except (ModelError, RuntimeError, ValueError, ZeroDivisionError, FloatingPointError,
                np.linalg.LinAlgError) as exc:
            ok, message = False, f"IDA failed: {exc}"
        y_out = np.array(ys).T if ys else np.empty((2 * n, 0))
        return Run(method="IDA", t=t_eval[: len(ys)].copy(), y=y_out,
                   success=ok and len(ys) == t_eval.size, message=message,
                   cpu=_time.process_time() - start, calls=self.calls,
                   evaluations=self.calls, steps=steps, jacobians=njev, factorisations=njev,
                   t_end=float(t_eval[len(ys) - 1]) if ys else t0)
