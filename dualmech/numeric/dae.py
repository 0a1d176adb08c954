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

Velocity-level (nonholonomic) constraints ``c = a(q) . q' + a0(q) = 0`` -- declared on the
model (``EquationSet.constraints``, level ``"velocity"``) -- have no position level: ``c``
itself is the invariant.  The index-1 row is ``c' = 0``; Baumgarte's is ``c' + 2 alpha c =
0`` (the first-order term only); projection puts the rates onto ``c = 0`` and moves the
configuration only onto the position-level constraints; IDA's forms
(:mod:`~dualmech.numeric.daesolve`) hold ``c = 0`` as the algebraic row (the DAE is index 2
in its multiplier).  A massless part's static balances -- rows holding no acceleration and
no reaction -- are constraints held by no multiplier
(:func:`~dualmech.numeric.formulations.with_static_rows`): their acceleration-level rows
replace them, and the same forms keep the state on them.

A position-level constraint the model declares (``EquationSet.constraints``, level
``"position"``) is taken as declared.  Any other is not stored in the equations:
:func:`constraints_of` recovers it from its acceleration row (the coefficients of ``q''``
are ``G = dg/dq``; the rest must be ``q'^T (dG/dq) q'``, checked exactly) by integrating
``G`` coordinate by coordinate, and checks ``dg/dq = G`` exactly.  A direct model in the same maximal
coordinates that imposes the constraints only through its coordinate map (fewer equations
than unknowns) is made square by the same rows, borrowed from the multiplier model
(:func:`~dualmech.numeric.formulations.formulations`).

Example
-------
>>> from dualmech.problems import get
>>> p = get("pendulum_particle"); eqs = p.model("cartesian")
>>> constraints_of(eqs).expressions      # as the model declares it
((l**2 - x(t)**2 - y(t)**2)/(2*l),)
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
           "BAUMGARTE_GAINS", "dae_refusal"]

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
    """Constraints of a model in maximal coordinates, each at its own level.

    ``expressions`` are in the coordinates ``q(t)``: a position-level ``g_k(q) = 0`` (up
    to a constant), or a velocity-level ``c_k = a_k(q) . q' + a0_k(q) = 0`` (``levels[k]``
    ``"velocity"``: nonholonomic, no position level exists).  ``multipliers`` are the
    model's unknowns that hold them (the reactions), in the same order; ``None`` for a
    static balance of a massless part (a row of the model itself, held by no multiplier:
    its acceleration-level form replaces row ``static_rows[k]``).
    """

    coordinates: tuple
    multipliers: tuple
    expressions: tuple
    levels: tuple = ()
    static_rows: tuple = ()
    #: the labels of the static rows (``""`` for a constraint held by a multiplier)
    labels: tuple = ()

    def __post_init__(self):
        if not self.levels:
            object.__setattr__(self, "levels", ("position",) * len(self.expressions))
        if not self.static_rows:
            object.__setattr__(self, "static_rows", (None,) * len(self.expressions))
        if not self.labels:
            object.__setattr__(self, "labels", ("",) * len(self.expressions))
        bad = [lv for lv in self.levels if lv not in ("position", "velocity")]
        if bad or len(self.levels) != len(self.expressions):
            raise ModelError(f"constraint levels {self.levels} must be 'position' or "
                             f"'velocity', one per expression ({len(self.expressions)}).")

    @property
    def gradients(self) -> tuple:
        """The coefficients of ``q''`` in each constraint's acceleration-level row, as a tuple
        of rows: ``dg_k/dq_j`` (position level) or ``dc_k/dq'_j`` (velocity level)."""
        return tuple(tuple(e.diff(q.diff(t) if lv == "velocity" else q)
                           for q in self.coordinates)
                     for e, lv in zip(self.expressions, self.levels))

    @property
    def has_velocity_level(self) -> bool:
        return "velocity" in self.levels

    def names(self) -> list[str]:
        """A name per constraint: its multiplier's, or its static row's ``[label]``."""
        return [str(u) if u is not None else f"[{lab or f'row {r}'}]"
                for u, r, lab in zip(self.multipliers, self.static_rows, self.labels)]


def _constraint_rows(eqs: EquationSet) -> list[int]:
    return [i for i in range(len(eqs.equations)) if i not in set(dynamic_rows(eqs))]


@lru_cache(maxsize=64)
def constraints_of(eqs: EquationSet) -> Constraints:
    """The constraints behind a multiplier model's acceleration rows, each at its level.

    A row the model declares at velocity level (``EquationSet.constraints``, e.g.
    :meth:`Lagrangian.velocity_constraint
    <dualmech.model.lagrange.Lagrangian.velocity_constraint>`) is kept there: ``c(q, q') =
    0`` is the invariant, no position level exists.  One declared at position level
    (:meth:`Lagrangian.constraint <dualmech.model.lagrange.Lagrangian.constraint>`) keeps its
    declared ``g(q)``.  Any other row is integrated to its position level ``g(q)``; :class:`ModelError` when it is not the second derivative of a
    function of the coordinates (velocity-level but not declared, rheonomic or not
    integrable): declare it then.
    """
    rows = _constraint_rows(eqs)
    if not rows or len(rows) != len(eqs.unknowns):
        raise ModelError(f"model `{eqs.name}` is not a multiplier model: it has {len(rows)} "
                         f"constraint rows for {len(eqs.unknowns)} multipliers.")
    A, b = eqs.plain_matrix()
    declared = {c.label: c for c in eqs.constraints if c.level == "velocity"}
    # a constraint declared at position level is taken as written, not integrated back
    # from its acceleration row (the bicycle's front contact: a square root of the angles)
    positions = {c.label: c for c in eqs.constraints if c.level == "position"}
    by_name = {u.name: u for u in eqs.unknowns}
    found, levels, multipliers = [], [], []
    for k, r in enumerate(rows):
        what = f"model `{eqs.name}`, row [{eqs.labels[r]}]"
        if any(A[r, j] != 0 for j in range(eqs.n, A.cols)):
            raise ModelError(f"{what} holds a multiplier; it is not a constraint row.")
        c = declared.get(eqs.labels[r])
        if c is not None:
            found.append(_velocity_level(c, eqs, what))
            levels.append("velocity")
            multipliers.append(by_name.get(c.name, eqs.unknowns[k]))
        else:
            held = positions.get(eqs.labels[r])
            found.append(held.expression if held is not None else
                         _position_level(eqs, A, b, r, what))
            levels.append("position")
            multipliers.append(by_name.get(held.name, eqs.unknowns[k]) if held is not None
                               else eqs.unknowns[k])
    return Constraints(eqs.coordinates, tuple(multipliers), tuple(found), tuple(levels))


def _velocity_level(c, eqs: EquationSet, what: str) -> sp.Expr:
    """A declared velocity constraint ``a(q) . q' + a0(q)``, refused if ``a`` holds time."""
    plain = c.plain(eqs.coordinates)
    rates = [state_symbols(q).qd for q in eqs.coordinates]
    if any(t in plain.diff(u).free_symbols for u in rates):
        raise ModelError(f"{what}: the coefficients of the rates depend on time (a rheonomic "
                         "velocity constraint); the DAE forms take a(q) . q' + a0(q, t) = 0.")
    return c.expression


def _position_level(eqs: EquationSet, A, b, r: int, what: str) -> sp.Expr:
    """The ``g(q)`` whose second derivative is row ``r`` (checked exactly)."""
    n = eqs.n
    states = [state_symbols(q) for q in eqs.coordinates]
    qs, us = [s.q for s in states], [s.qd for s in states]
    G = [A[r, j] for j in range(n)]
    free = set().union(*[e.free_symbols for e in G])
    if t in free or set(us) & free or t in b[r].free_symbols:
        raise ModelError(f"{what}: the constraint depends on time or on the rates; declare "
                         "it (`velocity_constraint`) or give its position-level form.")
    H = sum(G[i].diff(qs[j]) * us[i] * us[j] for i in range(n) for j in range(n))
    symbols = sorted(free | set(qs) | set(us) | b[r].free_symbols, key=lambda s: s.name)
    curl = [G[i].diff(qs[j]) - G[j].diff(qs[i]) for i in range(n) for j in range(i + 1, n)]
    if not identically_zero([b[r] + H] + curl, symbols):
        raise ModelError(f"{what} is not the second derivative of a function of the "
                         "coordinates: its gradient has no potential (a velocity-level "
                         "constraint, or one scaled by a function); declare it with "
                         "`velocity_constraint`, or give its position-level form with "
                         "`constraints=`.")
    g = _potential(G, qs)
    if g is None or not identically_zero([g.diff(q) - Gi for q, Gi in zip(qs, G)], symbols):
        raise ModelError(f"{what}: could not integrate the constraint gradient {G}; give "
                         "its position-level form with `constraints=`.")
    return from_plain(g, eqs.coordinates)


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
    constraint -- ``g'' = 0`` or (``stabilised``) ``g'' + 2 alpha g' + beta^2 (g - g0) = 0``
    at position level, ``c' = 0`` or ``c' + 2 alpha c = 0`` at velocity level (Baumgarte's
    first-order term only: no position level to pull back to).

    The offsets ``g0`` are parameters ``constraint_offset_k``: the value of ``g_k`` on the
    manifold (the recovered ``g`` is known up to a constant).  A static balance
    (``constraints.static_rows[k]`` not ``None``) replaces its own row of ``eqs``.
    """
    if tuple(constraints.coordinates) != tuple(eqs.coordinates):
        raise ModelError(f"the constraints are written in {list(constraints.coordinates)}, "
                         f"model `{eqs.name}` in {list(eqs.coordinates)}.")
    replaced = {r for r in constraints.static_rows if r is not None}
    keep = [i for i in dynamic_rows(eqs) if i not in replaced]
    rows = [eqs.equations[i] for i in keep]
    labels = [eqs.labels[i] for i in keep]
    for k, (name, g, level) in enumerate(zip(constraints.names(), constraints.expressions,
                                              constraints.levels)):
        if level == "velocity":
            row = g.diff(t) + (2 * ALPHA * g if stabilised else 0)
        else:
            row = g.diff(t, 2)
            if stabilised:
                row += 2 * ALPHA * g.diff(t) + BETA**2 * (g - offset_symbol(k))
        rows.append(row)
        labels.append(f"constraint {name} (acceleration level"
                      + (", Baumgarte)" if stabilised else ")"))
    if len(rows) != eqs.n + len(eqs.unknowns):
        raise ModelError(f"model `{eqs.name}`: {len(rows)} equations with the constraints for "
                         f"{eqs.n} accelerations and {len(eqs.unknowns)} reactions; the "
                         "constraints must hold one reaction each.")
    suffix = "Baumgarte" if stabilised else "index 1"
    return EquationSet(f"{eqs.name} ({suffix})", eqs.coordinates, tuple(rows), eqs.unknowns,
                       tuple(labels), (), eqs.description)


def dae_refusal(stab: str, constraints) -> str:
    """Why the DAE form ``stab`` cannot take ``constraints`` (``""`` if it can).

    >>> import sympy as sp
    >>> from dualmech.numeric.dae import Constraints
    >>> from dualmech import coordinate, t
    >>> x = coordinate("x")
    >>> c = Constraints((x,), (sp.Symbol("F"),), (x.diff(t) - 1,), ("velocity",))
    >>> dae_refusal("index3", c).split(":")[0], dae_refusal("projection", c)
    ('not applicable to the index-3 form', '')
    """
    levels, names = constraints.levels, constraints.names()
    static = [nm for nm, r in zip(names, constraints.static_rows) if r is not None]
    if stab in DAE_SOLVED and static:
        return (f"not applicable to IDA's {stab} form: the static balance(s) of a massless "
                f"part {', '.join(static)} hold no multiplier, and its residual "
                "(numeric/daesolve) holds each constraint by one; the index-1 forms integrate "
                "them (projection keeps the state on the static rows' manifold).")
    if stab == "index3" and "position" not in levels:
        return ("not applicable to the index-3 form: every constraint is at velocity level "
                "(nonholonomic), so the DAE as written is index 2 -- the 'DAE, index 2' form "
                "(run under 'ggl'), not run twice.")
    if stab == "ggl" and "position" in levels and "velocity" in levels:
        vel = [nm for nm, lv in zip(names, levels) if lv == "velocity"]
        return ("not applicable to the GGL form: its residual (numeric/daesolve) holds every "
                "constraint at position and velocity level with an extra multiplier, and "
                f"the velocity-level constraint(s) {', '.join(vel)} have no position level; "
                "the index-3 form holds each constraint at its declared level.")
    return ""


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
        why = dae_refusal(stabilisation, self.constraints)
        if why:
            raise ModelError(f"model `{eqs.name}`: {why}")
        self.eqs, self.n, self.k = eqs, eqs.n, len(self.constraints.expressions)
        self.stabilisation = stabilisation
        coords = eqs.coordinates
        g = list(self.constraints.expressions)
        self.position = np.array([lv == "position" for lv in self.constraints.levels])
        rate = [e.diff(t) if p else e for e, p in zip(g, self.position)]
        self._g = StateFunction(g + rate, coords, params)
        self._G = StateFunction([d for row in self.constraints.gradients for d in row], coords,
                                params)
        anchor = np.asarray(anchor, dtype=float)
        # a recovered g is known up to a constant (fixed by the anchor); a static balance
        # and a velocity-level constraint are exact as written
        recovered = self.position & np.array([r is None for r in self.constraints.static_rows],
                                             dtype=bool)
        self.offsets = np.where(recovered, self._g(0.0, anchor, np.zeros(self.n))[: self.k],
                                0.0)
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
        """``(invariant, velocity level)``: ``(g(q) - g0, g'(q, q'))`` for a position-level
        constraint, ``(c, c)`` for a velocity-level one (its own invariant); shapes ``(k,)``
        or ``(k, K)``."""
        vals = self._g(0.0, q, qd)
        off = self.offsets if np.ndim(q) == 1 else self.offsets[:, None]
        return vals[: self.k] - off, vals[self.k:]

    def gradient(self, q) -> np.ndarray:
        """``G`` at one configuration, ``(k, n)``: ``dg/dq`` (position level), ``dc/dq'``
        (velocity level) -- the coefficients of ``q''`` in the acceleration rows."""
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
        give the diagonal of each coordinate's inertia (the norms of the columns of its
        accelerations in the model's own rows: zero for a massless part, so the projection
        moves it and not the parts that carry inertia).
        """
        A, _ = self.numeric.system(time, q, qd)
        G = self.gradient(q)
        M = self._mass_rows(A)
        if not _is_metric(M):   # a direct model's rows: each coordinate's inertia, unsigned
            M = np.diag(np.linalg.norm(A[: A.shape[0] - self.k, : self.n], axis=0))
            if not M.any():
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

    def _mass_rows(self, A: np.ndarray) -> np.ndarray:
        """The model's own first ``n`` rows' coefficients of ``q''`` (a static row's: zero),
        read off the index-1 system ``A``, whose rows are the kept rows then the constraints'."""
        replaced = {r for r in self.constraints.static_rows if r is not None}
        if not replaced:
            return A[: self.n, : self.n]
        keep = [i for i in dynamic_rows(self.eqs) if i not in replaced]
        M = np.zeros((self.n, self.n))
        for row, i in enumerate(keep):
            if i < self.n:
                M[i] = A[row, : self.n]
        return M

    def project(self, time, y: np.ndarray, tol: float = 1e-13, iterations: int = 8) -> np.ndarray:
        """``y = [q; q']`` put back on the manifold (see the module docstring), in the metric
        of :meth:`_metric`: the configuration onto the position-level constraints only
        (Gauss--Newton), then the rates onto every constraint's velocity level (``G q' = 0``
        and ``c(q, q') = 0``, affine in ``q'``: one exact step).  Raises :class:`ModelError`
        if Gauss--Newton does not converge, the constraints are dependent, or a massless
        coordinate is not held by them (naming it)."""
        n, P = self.n, self.position
        q, qd = y[:n].copy(), y[n:].copy()
        for _ in range(iterations if P.any() else 0):
            g = self.residuals(q, qd)[0][P]
            scale = max(1.0, float(np.abs(q).max()))
            if np.abs(g).max() <= tol * scale:
                break
            W, G = self._metric(time, q, qd)
            WiGt = np.linalg.solve(W, G[P].T)
            q -= WiGt @ np.linalg.solve(G[P] @ WiGt, g)
        else:
            if P.any():
                raise ModelError(
                    f"projection onto the constraints of `{self.eqs.name}` did not converge "
                    f"at t={float(time):.6g} (residual {np.abs(g).max():.3g}); the state has "
                    "left the manifold's neighbourhood -- use a tighter tolerance or project "
                    "more often.")
        W, G = self._metric(time, q, qd)
        WiGt = np.linalg.solve(W, G.T)
        qd -= WiGt @ np.linalg.solve(G @ WiGt, self.residuals(q, qd)[1])
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
