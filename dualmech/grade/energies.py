r"""The ingredients of a problem's Lagrange model, sorted by what they are.

A Lagrange model records, per equation, the piece each ingredient contributes
(:attr:`dualmech.model.equations.EquationSet.contributions`): ``d/dt dT/dq' - dT/dq`` for a kinetic
energy, ``dV/dq`` for a potential, ``dR/dq'`` for a dissipation function, ``-Q`` for a
generalised force, ``-lambda dg/dq`` for a constraint.  The grader sorts them by their
symbols, which needs no knowledge of how the problem named them:

* **kinetic** -- the piece contains an acceleration;
* **constraint** -- it contains a multiplier;
* **velocity** -- it contains a velocity and no acceleration (a damper, a velocity-dependent
  force): never part of a Lagrangian;
* **drive** -- it depends on the coordinates and explicitly on time only (a driving force, a
  moving support): it may be written as a generalised force or as a time-dependent potential,
  and both are accepted;
* **potential** -- it depends on the coordinates only (springs, gravity);
* **load** -- the same, but the problem declares it as a generalised force (a steady applied
  force): a student may count it in ``V`` or leave it to ``Q``, and both are accepted.

From these: ``T`` (``q'^T M q' / 2`` when the kinetic pieces are exactly its Lagrange terms --
checked exactly; otherwise ``T`` is judged by its Lagrange terms), ``V`` up to a constant (by
its gradient; a potential is also reconstructed by integration for feedback, and checked),
``L`` (by its Lagrange equations, up to a constant factor and a total time derivative), and the
generalised forces ``Q``.

Example
-------
>>> from dualmech.problems import get
>>> from dualmech.grade.context import ProblemContext
>>> parts = LagrangeParts.of(ProblemContext.of(get("simple_pendulum")))
>>> sorted(parts.kinds.values())
['kinetic', 'potential']
>>> parts.kinetic_energy()
M*a**2*theta_dot**2/2
"""
from __future__ import annotations

import sympy as sp

from dualmech.model.kinematics import t
from dualmech.grade.context import GradingUnavailable, ProblemContext, off_motion, zero
from dualmech.grade.formula import Formula

__all__ = ["LagrangeParts", "euler_lagrange"]


def euler_lagrange(L, states) -> list:
    """``d/dt dL/dq'_j - dL/dq_j`` for each coordinate, in plain state symbols."""
    out = []
    for s in states:
        p = sp.diff(L, s.qd)
        total = sp.diff(p, t)
        for s2 in states:
            total += sp.diff(p, s2.q) * s2.qd + sp.diff(p, s2.qd) * s2.qdd
        out.append(total - sp.diff(L, s.q))
    return out


def _generalised_forces(model) -> set:
    """The ingredients ``model``'s builder declares as generalised forces (none if unknown)."""
    from dualmech.model.declared import builder_of
    b = builder_of(model)
    return set(getattr(b, "_Q", {}) or {})


class LagrangeParts:
    """Sorted ingredients of the Lagrange model of a problem (see the module docstring)."""

    def __init__(self, ctx: ProblemContext):
        self.ctx = ctx
        if ctx.method != "exact":
            raise GradingUnavailable(f"`{ctx.problem.name}` has models the fast exact "
                                     "evaluator cannot handle; T, V, L and Q are not graded "
                                     "for it.")
        model = self._model()
        order = [model.coordinates.index(q) for q in ctx.coordinates]
        states = ctx.states
        qdd = {s.qdd for s in states}
        qd = {s.qd for s in states}
        lam = set(model.unknowns)
        self.pieces: dict = {}
        for key in model.ingredients():
            vec = [ctx.plain(model.contributions[i].get(key, 0)) for i in order]
            self.pieces[key] = vec
        self.kinds = {}
        declared = _generalised_forces(model)
        for key, vec in self.pieces.items():
            free = set().union(*(sp.sympify(v, strict=True).free_symbols for v in vec))
            if free & lam:
                self.kinds[key] = "constraint"
            elif free & qdd:
                self.kinds[key] = "kinetic"
            elif free & qd:
                self.kinds[key] = "velocity"
            elif t in free:
                self.kinds[key] = "drive"
            else:
                self.kinds[key] = "load" if key in declared else "potential"
        self.formulas = {k: [Formula.from_sympy(v) for v in vec] for k, vec in self.pieces.items()}

    @classmethod
    def of(cls, ctx: ProblemContext) -> "LagrangeParts":
        return ctx.memo("lagrange_parts", lambda: cls(ctx))

    def _model(self):
        ctx = self.ctx
        names = [ctx.problem.reference] + [n for n in ctx.problem.models()
                                           if n != ctx.problem.reference]
        for name in names:
            m = ctx.problem.models()[name]
            if (set(m.coordinates) == set(ctx.coordinates) and m.contributions and
                    all(lb.startswith("Lagrange, ") for lb in m.labels)):
                return m
        raise GradingUnavailable(f"problem `{ctx.problem.name}` has no Lagrange model in its "
                                 "reference coordinates; T, V, L and Q cannot be graded.")

    def keys(self, *kinds: str) -> list[str]:
        return [k for k, v in self.kinds.items() if v in kinds]

    def total(self, keys) -> list:
        """Sum of the pieces of ``keys``, per coordinate (sympy)."""
        return [sp.Add(*[self.pieces[k][j] for k in keys]) for j in range(len(self.ctx.states))]

    # -- T ------------------------------------------------------------------------------
    def mass_matrix(self):
        kin = self.total(self.keys("kinetic"))
        return sp.Matrix([[sp.diff(e, s.qdd) for s in self.ctx.states] for e in kin])

    def kinetic_energy(self):
        """``q'^T M q' / 2`` when its Lagrange terms are exactly the kinetic pieces, else None."""
        return self.ctx.memo(("kinetic_energy",), self._kinetic_energy)

    def _kinetic_energy(self):
        M = self.mass_matrix()
        qd = sp.Matrix([s.qd for s in self.ctx.states])
        T2 = sp.expand((qd.T * M * qd)[0, 0] / 2)
        ok = self._same(euler_lagrange(T2, self.ctx.states), self.total(self.keys("kinetic")))
        return T2 if ok else None

    def declared_kinetic_energy(self):
        """The kinetic energy the problem's Lagrange model was built from (its ``T`` terms),
        when its Lagrange terms are the kinetic pieces (checked), else None: for feedback on
        a ``T`` with terms of a moving constraint, which is judged by its Lagrange terms."""
        return self.ctx.memo(("declared_kinetic_energy",), self._declared_kinetic_energy)

    def _declared_kinetic_energy(self):
        from dualmech.model.declared import builder_of
        b = builder_of(self._model())
        if b is None or not getattr(b, "_T", None):
            return None
        T = sp.Add(*b._T.values())
        if hasattr(b, "_known"):   # prescribed coordinates as the functions of time they are
            T = b._known(T)
        T = sp.expand(self.ctx.plain(T))
        if T.has(sp.Derivative) or T.atoms(sp.core.function.AppliedUndef):
            return None
        ok = self._same(euler_lagrange(T, self.ctx.states), self.total(self.keys("kinetic")))
        return T if ok else None

    def _same(self, left: list, right: list) -> bool:
        """Exactly equal at the context's points, with random accelerations (off the motion)."""
        fl = [Formula.from_sympy(e) for e in left]
        fr = [Formula.from_sympy(e) for e in right]
        if not all(f.exact for f in fl + fr):
            return False
        for point in self.ctx.points("exact"):
            env = off_motion(point, self.ctx)
            for a, b in zip(fl, fr):
                if not zero(a.evaluate(env) - b.evaluate(env), [a.evaluate(env)]):
                    return False
        return True

    # -- V ------------------------------------------------------------------------------
    def potential(self, keys) -> sp.Expr | None:
        """A function ``U(q, t)`` whose gradient is the pieces of ``keys`` (checked), or None."""
        key = ("potential", tuple(sorted(keys)))
        return self.ctx.memo(key, lambda: self._integrate(self.total(keys)))

    def _integrate(self, grad: list):
        states = self.ctx.states
        if sum(sp.count_ops(g) for g in grad) > 400:
            return None
        U = sp.Integer(0)
        try:
            for j, s in enumerate(states):
                rest = sp.expand(grad[j] - sp.diff(U, s.q))
                if rest != 0:
                    part = sp.integrate(rest, s.q)
                    if part.has(sp.Integral):
                        return None
                    U += part
        except Exception:  # integration is cosmetic (feedback); the verdict never needs it
            return None
        U = sp.expand(U)
        ok = self._same([sp.diff(U, s.q) for s in states], grad)
        return U if ok else None

    def potential_energy(self):
        """``V`` (up to a constant) of the potential pieces, or None if it cannot be found."""
        return self.potential(self.keys("potential"))
