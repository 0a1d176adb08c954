r"""The direct form as a DAE in maximal coordinates: index 3 reduced to index 1, kept on the manifold.

A multiplier model (:meth:`Lagrangian.constraint <dualmech.model.lagrange.Lagrangian.constraint>`)
holds, besides its equations of motion ``M q'' - G^T lambda = f``, each constraint at the
acceleration level, ``G q'' + (d/dt G) q' = 0``: that square system is the index-1 form of
the index-3 DAE ``M q'' - G^T lambda = f, g(q) = 0``, and it gives ``q''`` and the reactions
``lambda`` at once.  Integrated as it is, it holds ``g'' = 0`` only: the truncation errors
make ``g'`` drift linearly and ``g`` quadratically in time.  Two cures:

* **Baumgarte**: the constraint rows become ``g'' + 2 alpha g' + beta^2 g = 0`` -- with
  ``alpha = beta`` a critically damped error, ``(1 + beta t) e^{-beta t}``;
* **projection**: after every accepted step (:mod:`~dualmech.numeric.stepping`) the state
  is put back on the manifold, the configuration by Gauss--Newton steps
  ``dq = -W^{-1} G^T (G W^{-1} G^T)^{-1} g`` and the rates by
  ``dq' = -W^{-1} G^T (G W^{-1} G^T)^{-1} G q'``, in the metric ``W = M + s G^T G``: on the
  constraint's level sets it measures the kinetic energy exactly as ``M`` does (the least
  change of the motion that satisfies the constraints), and it stays regular where parts
  are massless and ``M`` alone is singular (:meth:`ConstrainedModel.project`, with a
  rank-revealing test, :func:`metric_defect`).

The position-level constraints ``g`` are not stored in the equations; :func:`constraints_of`
recovers them from the acceleration rows (the coefficients of ``q''`` are ``G = dg/dq``; the
rest must be ``q'^T (dG/dq) q'``, checked exactly) by integrating ``G`` coordinate by
coordinate, and checks ``dg/dq = G`` exactly.  A direct model in the same maximal
coordinates that imposes the constraints only through its coordinate map (fewer equations
than unknowns) is made square by the same rows, borrowed from the multiplier model
(:func:`~dualmech.numeric.formulations.formulations`).

Example
-------
>>> from dualmech.problems import get
>>> p = get("pendulum_particle"); eqs = p.model("cartesian")
>>> constraints_of(eqs).expressions
(-x(t)**2/(2*l) - y(t)**2/(2*l),)
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Mapping, Sequence

import numpy as np
import sympy as sp

from dualmech.model.equations import EquationSet, ModelError, from_plain, state_symbols
from dualmech.model.kinematics import t
from dualmech.numeric.energy import dynamic_rows, identically_zero
from dualmech.numeric.model import NumericModel, StateFunction

__all__ = ["Constraints", "ConstrainedModel", "constraints_of", "index1_equations",
           "metric_defect", "RANK_RTOL", "ALPHA", "BETA", "STABILISATIONS", "DAE_SOLVED",
           "BAUMGARTE_GAINS"]

#: Baumgarte's parameters (symbols of the index-1 equations; values given at run time).
ALPHA = sp.Symbol("baumgarte_alpha", nonnegative=True)
BETA = sp.Symbol("baumgarte_beta", nonnegative=True)
STABILISATIONS = ("none", "baumgarte", "projection")
#: Forms integrated by a DAE solver (:mod:`~dualmech.numeric.daesolve`), not as an ODE.
DAE_SOLVED = ("index3", "ggl")
#: Baumgarte gains ``alpha = beta`` [1/s] swept by the work-precision charts: slower than,
#: near, and far faster than the motions of the catalogue's closed loops (a few rad/s).
BAUMGARTE_GAINS = (1.0, 10.0, 100.0)


@dataclass(frozen=True)
class Constraints:
    """Holonomic constraints ``g_k(q) = 0`` (up to constants) of a model in maximal coordinates.

    ``expressions`` are in the coordinates ``q(t)``; ``multipliers`` are the model's
    unknowns that hold them (the reactions), in the same order.
    """

    coordinates: tuple
    multipliers: tuple
    expressions: tuple

    @property
    def gradients(self) -> tuple:
        """``dg_k/dq_j`` as a tuple of rows."""
        return tuple(tuple(g.diff(q) for q in self.coordinates) for g in self.expressions)


def _constraint_rows(eqs: EquationSet) -> list[int]:
    return [i for i in range(len(eqs.equations)) if i not in set(dynamic_rows(eqs))]


@lru_cache(maxsize=64)
def constraints_of(eqs: EquationSet) -> Constraints:
    """The position-level constraints behind a multiplier model's acceleration rows.

    Raises :class:`ModelError` when a row is not the second derivative of a function of the
    coordinates (velocity-level, rheonomic or not integrable): give ``constraints=`` then.
    """
    rows = _constraint_rows(eqs)
    if not rows or len(rows) != len(eqs.unknowns):
        raise ModelError(f"model `{eqs.name}` is not a multiplier model: it has {len(rows)} "
                         f"constraint rows for {len(eqs.unknowns)} multipliers.")
    A, b = eqs.plain_matrix()
    n = eqs.n
    states = [state_symbols(q) for q in eqs.coordinates]
    qs, us = [s.q for s in states], [s.qd for s in states]
    found = []
    for r in rows:
        what = f"model `{eqs.name}`, row [{eqs.labels[r]}]"
        if any(A[r, j] != 0 for j in range(n, A.cols)):
            raise ModelError(f"{what} holds a multiplier; it is not a constraint row.")
        G = [A[r, j] for j in range(n)]
        free = set().union(*[e.free_symbols for e in G])
        if t in free or set(us) & free or t in b[r].free_symbols:
            raise ModelError(f"{what}: the constraint depends on time or on the rates; give "
                             "its position-level form with `constraints=`.")
        H = sum(G[i].diff(qs[j]) * us[i] * us[j] for i in range(n) for j in range(n))
        symbols = sorted(free | set(qs) | set(us) | b[r].free_symbols, key=lambda s: s.name)
        curl = [G[i].diff(qs[j]) - G[j].diff(qs[i]) for i in range(n) for j in range(i + 1, n)]
        if not identically_zero([b[r] + H] + curl, symbols):
            raise ModelError(f"{what} is not the second derivative of a function of the "
                             "coordinates: its gradient has no potential (a velocity-level "
                             "constraint, or one scaled by a function); give its "
                             "position-level form with `constraints=`.")
        g = _potential(G, qs)
        if g is None or not identically_zero([g.diff(q) - Gi for q, Gi in zip(qs, G)],
                                             symbols):
            raise ModelError(f"{what}: could not integrate the constraint gradient {G}; give "
                             "its position-level form with `constraints=`.")
        found.append(from_plain(g, eqs.coordinates))
    return Constraints(eqs.coordinates, tuple(eqs.unknowns[k] for k in range(len(rows))),
                       tuple(found))


def _potential(G: Sequence, qs: Sequence):
    """``g`` with ``dg/dq_i = G_i``, integrated one coordinate at a time (``None`` on failure)."""
    g = sp.Integer(0)
    for i, q in enumerate(qs):
        rest = sp.expand(G[i] - g.diff(q))
        if rest == 0:
            continue
        part = sp.integrate(rest, q)
        if part.has(sp.Integral) or part.has(sp.Piecewise):
            return None
        g += part
    return g


def index1_equations(eqs: EquationSet, constraints: Constraints, *,
                     stabilised: bool = False) -> EquationSet:
    """The square index-1 system: ``eqs``' equations of motion and one acceleration row per
    constraint, ``g'' = 0`` or (``stabilised``) ``g'' + 2 alpha g' + beta^2 (g - g0) = 0``.

    The offsets ``g0`` are parameters ``constraint_offset_k``: the value of ``g_k`` on the
    manifold (the recovered ``g`` is known up to a constant).
    """
    if tuple(constraints.coordinates) != tuple(eqs.coordinates):
        raise ModelError(f"the constraints are written in {list(constraints.coordinates)}, "
                         f"model `{eqs.name}` in {list(eqs.coordinates)}.")
    rows = [eqs.equations[i] for i in dynamic_rows(eqs)]
    labels = [eqs.labels[i] for i in dynamic_rows(eqs)]
    for k, (lam, g) in enumerate(zip(constraints.multipliers, constraints.expressions)):
        row = g.diff(t, 2)
        if stabilised:
            row += 2 * ALPHA * g.diff(t) + BETA**2 * (g - offset_symbol(k))
        rows.append(row)
        labels.append(f"constraint {lam} (acceleration level"
                      + (", Baumgarte)" if stabilised else ")"))
    if len(rows) != eqs.n + len(eqs.unknowns):
        raise ModelError(f"model `{eqs.name}`: {len(rows)} equations with the constraints for "
                         f"{eqs.n} accelerations and {len(eqs.unknowns)} reactions; the "
                         "constraints must hold one reaction each.")
    suffix = "Baumgarte" if stabilised else "index 1"
    return EquationSet(f"{eqs.name} ({suffix})", eqs.coordinates, tuple(rows), eqs.unknowns,
                       tuple(labels), (), eqs.description)


def offset_symbol(k: int) -> sp.Symbol:
    return sp.Symbol(f"constraint_offset_{k}", real=True)


class ConstrainedModel:
    """A model in maximal coordinates with its constraints, ready to integrate as an index-1 DAE.

    Parameters
    ----------
    eqs : EquationSet
        A multiplier model, or a direct model in the same coordinates whose reactions hold
        ``constraints``.
    params : mapping symbol (or name) -> float
    constraints : Constraints, optional
        Default :func:`constraints_of` ``(eqs)``.
    anchor : sequence of n numbers
        A configuration on the manifold (fixes the constants of ``g``).
    stabilisation : ``"none"``, ``"baumgarte"``, ``"projection"``, ``"index3"`` or ``"ggl"``
        (the last two are solved by :mod:`~dualmech.numeric.daesolve`; the index-1
        system then gives the reactions only)
    alpha, beta : float
        Baumgarte's parameters in 1/s (default 5 and 5: a critically damped constraint error
        with time constant 0.2 s).
    """

    def __init__(self, eqs: EquationSet, params: Mapping, constraints: Constraints | None = None,
                 *, anchor: Sequence[float], stabilisation: str = "none", alpha: float = 5.0,
                 beta: float = 5.0):
        if stabilisation not in STABILISATIONS + DAE_SOLVED:
            raise ValueError(f"`stabilisation` must be one of {STABILISATIONS + DAE_SOLVED}, "
                             f"got {stabilisation!r}.")
        self.constraints = constraints or constraints_of(eqs)
        self.eqs, self.n, self.k = eqs, eqs.n, len(self.constraints.expressions)
        self.stabilisation = stabilisation
        coords = eqs.coordinates
        g = list(self.constraints.expressions)
        self._g = StateFunction(g + [e.diff(t) for e in g], coords, params)
        self._G = StateFunction([d for row in self.constraints.gradients for d in row], coords,
                                params)
        anchor = np.asarray(anchor, dtype=float)
        self.offsets = self._g(0.0, anchor, np.zeros(self.n))[: self.k]
        values = dict(params)
        values.update({offset_symbol(i): v for i, v in enumerate(self.offsets)})
        values.update({ALPHA: float(alpha), BETA: float(beta)})
        self.alpha, self.beta = float(alpha), float(beta)
        stab = stabilisation == "baumgarte"
        self.index1 = index1_equations(eqs, self.constraints, stabilised=stab)
        self.numeric = NumericModel(self.index1, values)
        self.rhs = self.numeric.rhs
        self.reaction_names = tuple(u.name for u in eqs.unknowns)

    def residuals(self, q, qd) -> tuple[np.ndarray, np.ndarray]:
        """``(g(q) - g0, g'(q, q'))``: shapes ``(k,)`` or ``(k, K)``."""
        vals = self._g(0.0, q, qd)
        off = self.offsets if np.ndim(q) == 1 else self.offsets[:, None]
        return vals[: self.k] - off, vals[self.k:]

    def gradient(self, q) -> np.ndarray:
        """``G = dg/dq`` at one configuration: ``(k, n)``."""
        return self._G(0.0, q, np.zeros(self.n)).reshape(self.k, self.n)

    def multipliers(self, time, q, qd) -> np.ndarray:
        """The reactions ``lambda`` at the states: ``(k,)`` or ``(k, K)``."""
        return self.numeric.solve(time, q, qd)[self.n:]

    def _metric(self, time, q, qd) -> tuple[np.ndarray, np.ndarray]:
        """The projection's metric ``W`` and ``G`` at a configuration (see :meth:`project`).

        ``W = M + s G^T G`` with ``M`` the kinetic-energy metric of the first rows and
        ``s = |M| / |G|^2``: on the set ``G dq = c`` the term ``s |G dq|^2`` is constant, so
        ``W`` gives the least change in kinetic energy exactly as ``M`` would, and ``W`` is
        regular wherever the motion is determined (``M`` positive definite on the tangent
        space ``G dq = 0``) even where parts are massless and ``M`` itself is singular.  The
        test is rank-revealing (:func:`metric_defect`), never a Cholesky accident; rows that
        are not a metric (a direct model's: not symmetric, or with a negative eigenvalue)
        give the Euclidean one.
        """
        A, _ = self.numeric.system(time, q, qd)
        G = self.gradient(q)
        M = A[: self.n, : self.n]
        if not _is_metric(M):
            M = np.eye(self.n)
        _check_rank(G, "the constraint gradients G = dg/dq", self, time, q)
        W = M + np.abs(M).max() / max(np.abs(G).max(), 1e-300) ** 2 * (G.T @ G)
        bad = metric_defect(W)
        if bad is not None:
            names = [str(self.eqs.coordinates[j]).replace("(t)", "") for j in bad[1]]
            raise ModelError(
                f"model `{self.eqs.name}` at t={float(time):.6g}: the motion along "
                f"{_direction(bad[0], self.eqs.coordinates)} carries no kinetic energy and no "
                f"constraint holds it (massless: {', '.join(names)}; smallest eigenvalue "
                f"{bad[2]:.3g} of the metric, relative to its largest), so projection has "
                "no metric for it -- eliminate the coordinate through its static balance, "
                "hold it by a constraint, or give the part a mass.")
        return W, G

    def project(self, time, y: np.ndarray, tol: float = 1e-13, iterations: int = 8) -> np.ndarray:
        """``y = [q; q']`` put back on the manifold (configuration, then rates; see the module
        docstring), in the metric of :meth:`_metric`.  Raises :class:`ModelError` if
        Gauss--Newton does not converge, the constraints are dependent, or a massless
        coordinate is not held by them (naming it)."""
        n = self.n
        q, qd = y[:n].copy(), y[n:].copy()
        for _ in range(iterations):
            g, _ = self.residuals(q, qd)
            scale = max(1.0, float(np.abs(q).max()))
            if np.abs(g).max() <= tol * scale:
                break
            W, G = self._metric(time, q, qd)
            WiGt = np.linalg.solve(W, G.T)
            q -= WiGt @ np.linalg.solve(G @ WiGt, g)
        else:
            raise ModelError(f"projection onto the constraints of `{self.eqs.name}` did not "
                             f"converge at t={float(time):.6g} (residual {np.abs(g).max():.3g})"
                             "; the state has left the manifold's neighbourhood -- use a "
                             "tighter tolerance or project more often.")
        W, G = self._metric(time, q, qd)
        WiGt = np.linalg.solve(W, G.T)
        qd -= WiGt @ np.linalg.solve(G @ WiGt, G @ qd)
        return np.concatenate([q, qd])


#: Relative threshold of the rank tests: a singular value (eigenvalue) below ``RANK_RTOL``
#: times the largest counts as zero.  Round-off leaves a massless direction at about
#: ``1e-16`` relative; the catalogue's lightest real inertia is above ``1e-4``.
RANK_RTOL = 1e-10


def metric_defect(W: np.ndarray) -> tuple[np.ndarray, list[int], float] | None:
    """``None`` if the symmetric ``W`` is positive definite by the rank test (eigenvalues
    above :data:`RANK_RTOL` times the largest), else ``(direction, coordinates, ratio)``:
    the eigenvector of the smallest eigenvalue, the indices of its large components and
    that eigenvalue relative to the largest.

    >>> metric_defect(np.diag([2.0, 1.0])) is None
    True
    >>> d, where, ratio = metric_defect(np.diag([2.0, 1e-17, 1.0]))
    >>> where, ratio < RANK_RTOL
    ([1], True)
    """
    values, vectors = np.linalg.eigh(0.5 * (W + W.T))
    top = float(np.abs(values).max())
    if top > 0 and values[0] > RANK_RTOL * top:
        return None
    v = vectors[:, 0]
    where = [int(j) for j in np.flatnonzero(np.abs(v) > 0.1 * np.abs(v).max())]
    return v, where, float(values[0] / top) if top > 0 else 0.0


def _is_metric(M: np.ndarray) -> bool:
    """Whether ``M`` is symmetric positive semi-definite (eigenvalues down to
    ``-RANK_RTOL`` times the largest): a kinetic-energy metric, possibly with massless parts."""
    top = float(np.abs(M).max())
    if top == 0 or not np.allclose(M, M.T, rtol=1e-12, atol=1e-14 * top):
        return False
    values = np.linalg.eigvalsh(0.5 * (M + M.T))
    return bool(values[0] >= -RANK_RTOL * np.abs(values).max())


def _direction(v: np.ndarray, coordinates) -> str:
    big = np.abs(v) > 0.1 * np.abs(v).max()
    v = v / v[np.argmax(np.abs(v))]
    return "(" + ", ".join(f"{str(q).replace('(t)', '')}: {x:+.3g}"
                           for q, x, b in zip(coordinates, v, big) if b) + ")"


def _check_rank(G: np.ndarray, what: str, cm: "ConstrainedModel", time, q) -> None:
    """Raise :class:`ModelError` when ``G``'s rows are dependent (SVD, :data:`RANK_RTOL`)."""
    s = np.linalg.svd(G, compute_uv=False)
    if s.size and s[-1] <= RANK_RTOL * max(s[0], 1e-300):
        raise ModelError(f"model `{cm.eqs.name}` at t={float(time):.6g}, q={np.round(q, 6)}: "
                         f"{what} are dependent (smallest singular value {s[-1]:.3g}, relative "
                         f"{s[-1] / max(s[0], 1e-300):.3g}): a singular configuration of the "
                         "loop, where projection is not defined.")
