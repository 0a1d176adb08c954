"""Energy of a natural conservative model, read off its own equations.

A Lagrange model of a scleronomic system with only conservative loads has rows
``M(q) q'' + dM/dt q' - dT/dq + dV/dq = 0`` with ``T = q'^T M q' / 2``.  In the canonical form
``A [q''; lambda] = b`` of its dynamic rows that means, exactly:

* ``M`` symmetric, a function of ``q`` only, no explicit time anywhere;
* ``b(q, q') - b(q, 0) = -dM/dt q' + d/dq (q'^T M q' / 2)`` (only Coriolis and centrifugal
  terms depend on the rates: no dissipation, no velocity-dependent force);
* ``Phi(q) = b(q, 0)`` is a gradient, ``Phi = -dV/dq`` (its Jacobian is symmetric).

:func:`conservative_reason` decides these identities with the library's exact comparator
(:mod:`dualmech.exact.form`) and says which one fails; :class:`EnergyFunction` then gives
``E = T + V`` along a trajectory, with ``V`` differences integrated along the path
(Gauss--Legendre on short straight pieces: a gradient's line integral does not depend on the
path) -- so no problem needs to state its energy.  Rows labelled ``constraint ...`` (the
acceleration form of a multiplier model's constraints) are left out; their forces do no work
on the constraint manifold.

Example
-------
>>> import numpy as np, sympy as sp
>>> from dualmech import EquationSet, coordinate, t
>>> th = coordinate("theta"); m, l, g = sp.symbols("m l g", positive=True)
>>> eqs = EquationSet("pendulum", (th,), (m*l**2*th.diff(t, 2) + m*g*l*sp.sin(th),))
>>> conservative_reason(eqs) is None
True
>>> E = EnergyFunction(eqs, {m: 1.0, l: 1.0, g: 9.81})
>>> q = np.array([[0.3, 0.0]]); qd = np.array([[0.0, 1.0]])   # two states, in columns
>>> dE = E.along(q, qd)[1]; expected = 0.5 - 9.81 * (1 - np.cos(0.3))
>>> bool(abs(dE - expected) < 1e-12)
True
"""
from __future__ import annotations

import random
from functools import lru_cache
from typing import Mapping

import numpy as np
import sympy as sp

from dualmech.model.equations import EquationSet, ModelError, from_plain, state_symbols
from dualmech.exact.form import ExactForm, is_zero
from dualmech.model.kinematics import t
from dualmech.exact.sample_space import Undecidable
from dualmech.numeric.model import StateFunction

__all__ = ["EnergyFunction", "conservative_reason", "dynamic_rows", "identically_zero"]

#: Gauss--Legendre nodes per straight piece of a path, and the longest piece (in the
#: coordinates' own units): the rule is exact for polynomials of degree 15 and its error on a
#: piece of length h of an analytic integrand falls like h^16.
_NODES, _PIECE = 8, 0.25


def dynamic_rows(eqs: EquationSet) -> list[int]:
    """Rows of ``eqs`` that are equations of motion (not a constraint's acceleration form)."""
    return [i for i, lab in enumerate(eqs.labels) if not lab.startswith("constraint ")]


def identically_zero(exprs, symbols, points: int = 6, seed: int = 0) -> bool:
    """Whether every expression is identically zero (exact rational-point test).

    ``False`` also when the test cannot decide (an undecidable expression, too few usable
    points): callers treat "not shown zero" as "not zero".
    """
    exprs = [sp.expand(e) for e in exprs]
    exprs = [e for e in exprs if e != 0]
    if not exprs:
        return True
    try:
        form = ExactForm.build(exprs, list(symbols))
    except (Undecidable, ValueError):
        return False
    rng = random.Random(seed)
    need = form.points_needed(points)
    done = tries = 0
    while done < need and tries < 4 * need:
        tries += 1
        point = form.sample(rng)
        try:
            values = form.evaluate(point)
        except (ZeroDivisionError, ValueError):
            continue
        if any(not is_zero(v) for v in values):
            if form.certain(point):
                return False
            continue
        done += 1
    return done >= need


@lru_cache(maxsize=64)
def _structure(eqs: EquationSet, values: tuple = ()) -> tuple:
    """``(reason or None, M, Phi, dT/dq)`` in plain symbols, for the dynamic rows, with the
    parameter ``values`` (pairs symbol, exact number) put in."""
    A, b = eqs.plain_matrix()
    if values:
        A, b = A.xreplace(dict(values)), b.xreplace(dict(values))
    n = eqs.n
    rows = dynamic_rows(eqs)
    states = [state_symbols(q) for q in eqs.coordinates]
    qs, us = [s.q for s in states], [s.qd for s in states]
    if len(rows) != n:
        return (f"{len(rows)} equations of motion for {n} coordinates", None, None, None)
    M = sp.Matrix([[A[i, j] for j in range(n)] for i in rows])
    f = sp.Matrix([b[i] for i in rows])
    free = set(M.free_symbols) | set(f.free_symbols)
    if t in free:
        return ("it depends on time explicitly (a driven or rheonomic system)", M, None, None)
    if set(us) & set(M.free_symbols):
        return ("its mass matrix depends on the rates", M, None, None)
    rest = {u: 0 for u in us}
    phi = f.xreplace(rest)
    symbols = sorted(free | set(qs) | set(us), key=lambda s: s.name)
    if not identically_zero([M[i, j] - M[j, i] for i in range(n) for j in range(i + 1, n)],
                            symbols):
        return ("its mass matrix is not symmetric (rows are not Lagrange's equations)", M,
                None, None)
    dT = sp.Matrix([sum(M[j, k].diff(qs[i]) * us[j] * us[k] for j in range(n)
                        for k in range(n)) / 2 for i in range(n)])
    Mdot_u = sp.Matrix([sum(M[i, j].diff(qs[k]) * us[k] * us[j] for j in range(n)
                            for k in range(n)) for i in range(n)])
    if not identically_zero(list(f - phi + Mdot_u - dT), symbols):
        return ("a force depends on the rates (dissipation or a velocity-dependent load)", M,
                None, None)
    curl = [phi[i].diff(qs[j]) - phi[j].diff(qs[i]) for i in range(n) for j in range(i + 1, n)]
    if not identically_zero(curl, symbols):
        return ("a position-dependent force is not the gradient of a potential", M, None, None)
    return (None, M, phi, dT)


def _exact_values(eqs: EquationSet, params: Mapping | None) -> tuple:
    """The parameter values as exact numbers (a float's exact binary value), sorted pairs."""
    if not params:
        return ()
    from dualmech.numeric.model import parameters_of
    symbols = parameters_of(eqs.equations, eqs.unknowns)
    by_name = {s.name: s for s in symbols}
    out = {}
    for k, v in params.items():
        s = by_name.get(k if isinstance(k, str) else k.name)
        if s is not None:
            out[s] = sp.Rational(float(v))
    return tuple(sorted(out.items(), key=lambda kv: kv[0].name))


def conservative_reason(eqs: EquationSet, params: Mapping | None = None) -> str | None:
    """``None`` when ``eqs`` is a natural conservative model, else why not (one sentence).

    With ``params`` the parameters take those values first (a torque that is zero in this
    run does no work), else the identities must hold for every parameter value.
    """
    return _structure(eqs, _exact_values(eqs, params))[0]


class EnergyFunction:
    """``E = q'^T M q' / 2 + V(q)`` of a natural conservative model (see the module docstring).

    Parameters
    ----------
    eqs : EquationSet
        A model for which :func:`conservative_reason` is ``None`` (else :class:`ModelError`).
    params : mapping symbol (or name) -> float
    """

    def __init__(self, eqs: EquationSet, params: Mapping):
        reason, M, phi, dT = _structure(eqs, _exact_values(eqs, params))
        if reason is not None:
            raise ModelError(f"model `{eqs.name}` has no conserved energy: {reason}.")
        coords = eqs.coordinates
        back = lambda e: from_plain(e, coords)  # noqa: E731
        n = eqs.n
        self.n, self.name = n, eqs.name
        qsyms = {state_symbols(q).q for q in coords}
        #: whether ``M`` is constant (a separable Hamiltonian: Stormer--Verlet applies)
        self.constant_mass = not any(e.free_symbols & qsyms for e in M)
        exprs = [M[i, j] for i in range(n) for j in range(n)] + list(dT) + list(phi)
        # one generated function for everything a step needs: M, dT/dq and -dV/dq
        self._all = StateFunction([back(e) for e in exprs], coords, params)
        self._phi = StateFunction([back(e) for e in phi], coords, params)

    def _parts(self, q, qd):
        vals = self._all(0.0, q, qd)
        n = self.n
        return vals[: n * n], vals[n * n: n * n + n], vals[n * n + n:]

    def mass_matrix(self, q) -> np.ndarray:
        """``M`` at the states in the columns of ``q`` (``(K, n, n)``) or at one (``(n, n)``)."""
        q = np.asarray(q, dtype=float)
        vals = self._parts(q, np.zeros_like(q))[0]
        n = self.n
        return vals.reshape(n, n) if q.ndim == 1 else np.moveaxis(vals.reshape(n, n, -1), 2, 0)

    def kinetic(self, q, qd) -> np.ndarray:
        """``T`` at the states in the columns of ``q``, ``qd`` (``(K,)``)."""
        q, qd = np.atleast_2d(q), np.atleast_2d(qd)
        M = self.mass_matrix(q)
        return 0.5 * np.einsum("ik,kij,jk->k", qd, M, qd)

    def force(self, q, qd=None) -> np.ndarray:
        """``-dV/dq`` (``qd`` ignored), in the shape of ``q``."""
        q = np.asarray(q, dtype=float)
        return self._phi(0.0, q, np.zeros_like(q))

    def canonical_force(self, q, qd) -> np.ndarray:
        """``dL/dq = dT/dq - dV/dq``: the rate of the momenta ``p = M q'``."""
        _, dT, phi = self._parts(np.asarray(q, dtype=float), np.asarray(qd, dtype=float))
        return dT + phi

    def step_terms(self, q, qd) -> tuple[np.ndarray, np.ndarray]:
        """``(M, dL/dq)`` at one state, from one evaluation (for the midpoint rule)."""
        M, dT, phi = self._parts(q, qd)
        return M.reshape(self.n, self.n), dT + phi

    def potential_change(self, q) -> np.ndarray:
        """``V(q[:, k]) - V(q[:, 0])`` along the path through the columns of ``q`` (``(K,)``).

        Each step between columns is split into straight pieces no longer than 0.25 (in the
        coordinates' units) and integrated with 8-point Gauss--Legendre.
        """
        q = np.atleast_2d(np.asarray(q, dtype=float))
        steps = np.diff(q, axis=1)
        pieces = np.maximum(1, np.ceil(np.abs(steps).max(axis=0, initial=0.0) / _PIECE)).astype(int)
        x, w = np.polynomial.legendre.leggauss(_NODES)
        s, w = (x + 1) / 2, w / 2
        starts, deltas, owner = [], [], []
        for k in range(steps.shape[1]):
            p = pieces[k]
            frac = np.arange(p) / p
            starts.append(q[:, [k]] + steps[:, [k]] * frac)
            deltas.append(np.repeat(steps[:, [k]] / p, p, axis=1))
            owner.append(np.full(p, k))
        if not starts:
            return np.zeros(q.shape[1])
        a, d, owner = np.hstack(starts), np.hstack(deltas), np.concatenate(owner)
        nodes = (a[:, :, None] + d[:, :, None] * s).reshape(self.n, -1)
        phi = self.force(nodes).reshape(self.n, a.shape[1], _NODES)
        work = np.einsum("ipk,ip,k->p", phi, d, w)
        per_step = np.bincount(owner, weights=work, minlength=steps.shape[1])
        return np.concatenate([[0.0], -np.cumsum(per_step)])

    def change(self, q0, q, qd) -> np.ndarray:
        """``T + V(q) - V(q0)`` at the states in the columns of ``q``, ``qd``: the energy
        measured from the configuration ``q0`` at rest (path: ``q0``, then the columns)."""
        q, qd = np.atleast_2d(q), np.atleast_2d(qd)
        path = np.hstack([np.asarray(q0, dtype=float).reshape(-1, 1), q])
        return self.kinetic(q, qd) + self.potential_change(path)[1:]

    def along(self, q, qd) -> np.ndarray:
        """``E(t) - E(t_0)`` along a trajectory (states in the columns, ``(K,)``)."""
        q, qd = np.atleast_2d(q), np.atleast_2d(qd)
        T = self.kinetic(q, qd)
        return T - T[0] + self.potential_change(q)
