"""The indirect form: Lagrange's equations with dissipation, generalised forces and multipliers.

For each coordinate ``q_j``::

    d/dt dT/dq'_j - dT/dq_j + dR/dq'_j + dV/dq_j = Q_j + sum_k lambda_k dg_k/dq_j

``T`` is the kinetic energy (given, or built from bodies), ``V`` the potential energy, ``R``
Rayleigh's dissipation function, ``Q_j`` the generalised forces of non-conservative loads from
their virtual work (``Q_j = F . dr/dq_j``, computed as ``F . dv/dq'_j``), and ``g_k`` the
constraints with their multipliers ``lambda_k``.  A coordinate with prescribed (rheonomic)
motion is replaced by its known function of time before differentiating.

Example
-------
>>> import sympy as sp
>>> from dualmech import coordinate, t
>>> from dualmech.model.lagrange import Lagrangian
>>> x = coordinate("x"); m, k, b, F0, w = sp.symbols("m k b F0 omega", positive=True)
>>> lg = Lagrangian(coordinates=[x])
>>> lg.kinetic("mass", m*x.diff(t)**2/2); lg.potential("spring", k*x**2/2)
>>> lg.dissipation("dashpot", b*x.diff(t)**2/2); lg.generalized_force("drive", [F0*sp.sin(w*t)])
>>> lg.equations().equations
(-F0*sin(omega*t) + b*Derivative(x(t), t) + k*x(t) + m*Derivative(x(t), (t, 2)),)
"""
from __future__ import annotations

from typing import Sequence

import symengine as se
import sympy as sp

from dualmech.model._expr import as_expr, refuse_jumps, refuse_text_in
from dualmech.model.bodies import Particle, RigidBody
from dualmech.model.declared import note
from dualmech.model._algebra import Bridge, total_derivative
from dualmech.model.equations import (Constraint, EquationSet, ModelError, Rows, state_symbols,
                                     to_plain)
from dualmech.model.kinematics import Frame, Point, Vector, t

__all__ = ["Lagrangian"]


@refuse_text_in
class Lagrangian:
    """The indirect form of one model: ``T``, ``V``, ``R``, generalised forces, constraints.

    Add named terms, then :meth:`equations` gives, for each coordinate ``q_j``, the row::

        d/dt dT/dq'_j - dT/dq_j + dR/dq'_j + dV/dq_j - Q_j - sum_k lambda_k dg_k/dq_j = 0

    Terms keep their names (``"T of bob"``, ``"gravity"``), so a report can say which term of
    which energy differs from the direct form.

    Energies: :meth:`kinetic` (or :meth:`kinetic_of` a body), :meth:`potential`,
    :meth:`gravity`, :meth:`spring`; dissipation: :meth:`damper`, :meth:`dissipation`;
    non-conservative loads: :meth:`generalized_force`, :meth:`force_at` and :meth:`torque_on`
    (virtual work); constraints with multipliers: :meth:`constraint` (position level),
    :meth:`velocity_constraint` (rolling); prescribed motion: :meth:`prescribe`.

    Parameters
    ----------
    name : str
        The derivation's name in reports (``"lagrange"``).
    coordinates : sequence of coordinates
        The generalised coordinates, in the order of the rows.
    description : str
        One line shown beside the name.

    Examples
    --------
    The pendulum of :class:`~dualmech.model.direct.NewtonEuler`'s example, by energies:

    >>> import sympy as sp
    >>> from dualmech import Lagrangian, coordinate, rate
    >>> theta = coordinate("theta"); m, l, g = sp.symbols("m l g", positive=True)
    >>> lg = Lagrangian(coordinates=[theta])
    >>> lg.kinetic("T of bob", m * (l * rate(theta))**2 / 2)
    >>> lg.potential("gravity", -m * g * l * sp.cos(theta))
    >>> lg.equations().equations
    (g*l*m*sin(theta(t)) + l**2*m*Derivative(theta(t), (t, 2)),)
    """

    def __init__(self, name: str = "lagrange", *, coordinates: Sequence, description: str = ""):
        self.name = name
        self.coordinates = tuple(coordinates)
        self.description = description
        self._T: dict[str, sp.Expr] = {}
        self._V: dict[str, sp.Expr] = {}
        self._R: dict[str, sp.Expr] = {}
        self._Q: dict[str, list] = {}
        self._constraints: list[tuple[sp.Symbol, sp.Expr, list]] = []
        self._declared: list[tuple[str, sp.Expr]] = []   # each constraint at its own level
        self._velocity_level: set = set()   # multipliers of constraints kept at velocity level
        self._prescribed: dict = {}

    # -- energies ----------------------------------------------------------------------
    def kinetic(self, key: str, T) -> None:
        """Add the kinetic-energy term ``T`` under the name ``key``."""
        T = as_expr(T)
        refuse_jumps([T], f"kinetic energy `{key}`")
        self._T[key] = self._T.get(key, 0) + T

    def kinetic_of(self, body: Particle | RigidBody, frame: Frame) -> None:
        """Add the kinetic energy of ``body`` seen from the inertial ``frame``."""
        self.kinetic(f"T of {body.name}", body.kinetic_energy(frame))

    def potential(self, key: str, V) -> None:
        """Add the potential-energy term ``V``."""
        V = as_expr(V)
        refuse_jumps([V], f"potential energy `{key}`")
        self._V[key] = self._V.get(key, 0) + V

    def gravity(self, g: Vector, bodies, frame: Frame) -> None:
        """Potential ``-m g . r_C`` of each body (``g`` the gravity vector, ``frame`` inertial)."""
        origin = Point.origin(frame)
        for body in bodies:
            self.potential(f"gravity on {body.name}",
                           -body.mass * g.dot(body.masscenter.pos_from(origin)))

    def spring(self, key: str, k, extension) -> None:
        """Potential ``k extension^2 / 2`` of a linear (or, with angles, torsional) spring."""
        self.potential(key, k * as_expr(extension)**2 / 2)

    def damper(self, key: str, c, rate) -> None:
        """Rayleigh dissipation ``c rate^2 / 2`` of a linear (or torsional) damper."""
        self.dissipation(key, c * as_expr(rate)**2 / 2)

    def dissipation(self, key: str, R) -> None:
        """Add the Rayleigh dissipation term ``R`` (e.g. ``c v^2 / 2``)."""
        R = as_expr(R)
        refuse_jumps([R], f"dissipation `{key}`")
        self._R[key] = self._R.get(key, 0) + R

    # -- generalised forces ------------------------------------------------------------
    def generalized_force(self, key: str, Q: Sequence) -> None:
        """Add generalised forces ``Q`` (one per coordinate)."""
        Q = [as_expr(x) for x in Q]
        refuse_jumps(Q, f"generalised force `{key}`")
        if len(Q) != len(self.coordinates):
            raise ModelError(f"`Q` needs {len(self.coordinates)} entries (one per coordinate), "
                             f"got {len(Q)}.")
        old = self._Q.get(key, [0] * len(Q))
        self._Q[key] = [a + b for a, b in zip(old, Q)]

    def force_at(self, key: str, force: Vector, point: Point, frame: Frame) -> None:
        """Generalised forces of ``force`` applied at ``point``: ``Q_j = F . d v / d q'_j``.

        ``frame`` is the inertial frame in which the velocity of ``point`` is taken.
        """
        v = point.vel(frame)
        self.generalized_force(key, [force.dot(v.diff(q.diff(t), frame)) for q in self.coordinates])

    def torque_on(self, key: str, torque: Vector, body_frame: Frame, frame: Frame) -> None:
        """Generalised forces of a couple on a body: ``Q_j = tau . d w / d q'_j``."""
        w = body_frame.ang_vel_in(frame)
        self.generalized_force(key, [torque.dot(w.diff(q.diff(t), frame)) for q in self.coordinates])

    # -- constraints and prescribed motion ---------------------------------------------
    def constraint(self, name: str, g) -> sp.Symbol:
        """Holonomic constraint ``g(q, t) = 0`` with multiplier ``name``; returns the multiplier.

        The equations hold its acceleration level; ``g`` itself is kept on the equation set
        (``EquationSet.constraints``, position level) for the verdict's manifold."""
        lam = sp.Symbol(name, real=True)
        # differentiated in symengine by :meth:`equations` (``None``: ``g`` itself is kept)
        self._constraints.append((lam, as_expr(g), None))
        self._declared.append(("position", as_expr(g)))
        return lam

    def velocity_constraint(self, name: str, coefficients, rest=0) -> sp.Symbol:
        """Constraint ``sum a_j q'_j + a_0 = 0`` (``coefficients = a``, ``rest = a_0``); kept at
        velocity level on the equation set (``EquationSet.constraints``).

        ``coefficients`` may also be the velocity-level expression itself, linear in the rates
        (``x' - r cos(psi) phi'``, ``rest`` then 0): its coefficients are read off it.  Either
        way the acceleration level is differentiated in symengine by :meth:`equations`.

        Example
        -------
        >>> from dualmech import coordinate, rate
        >>> x, phi = coordinate("x"), coordinate("phi"); r = sp.Symbol("r", positive=True)
        >>> lg = Lagrangian(coordinates=[x, phi])
        >>> lg.kinetic("T", (rate(x)**2 + rate(phi)**2) / 2)
        >>> lg.velocity_constraint("F", rate(x) - r * rate(phi))
        F
        >>> lg.equations().equations[-1]      # its acceleration level
        -r*Derivative(phi(t), (t, 2)) + Derivative(x(t), (t, 2))
        """
        lam = sp.Symbol(name, real=True)
        if isinstance(coefficients, (sp.Basic, int, float)) and not isinstance(rest, sp.Basic) \
                and rest == 0:
            level, a = as_expr(coefficients), None   # its coefficients: in equations()
        else:
            a = [as_expr(c) for c in coefficients]
            if len(a) != len(self.coordinates):
                raise ModelError(f"`coefficients` needs {len(self.coordinates)} entries.")
            level = sum(c * q.diff(t) for c, q in zip(a, self.coordinates)) + as_expr(rest)
        self._constraints.append((lam, level, a))
        self._velocity_level.add(lam)
        self._declared.append(("velocity", level))
        return lam

    def prescribe(self, q, motion) -> None:
        """Coordinate ``q`` follows the known function of time ``motion`` (rheonomic)."""
        self._prescribed[q] = as_expr(motion)

    @property
    def prescribed(self) -> dict:
        """The coordinates given a known motion (:meth:`prescribe`): ``{q: motion}``."""
        return dict(self._prescribed)

    # -- equations ---------------------------------------------------------------------
    def _known(self, expr):
        if not self._prescribed:
            return as_expr(expr)
        rules = {}
        for q, f in self._prescribed.items():
            rules[q.diff(t, 2)] = f.diff(t, 2)
            rules[q.diff(t)] = f.diff(t)
        expr = as_expr(expr).xreplace(rules)
        return expr.xreplace(dict(self._prescribed))

    def _constraint_se(self, constraint, free, states, br) -> tuple:
        """``(multiplier, acceleration level, gradient by coordinate index)`` in symengine.

        A holonomic ``g(q, t)`` (gradient ``None``) is differentiated here, by the chain rule
        on plain symbols (twice in time, once per free coordinate), not in sympy."""
        lam, level, grad = constraint
        if lam in self._velocity_level:   # velocity level: differentiated once more
            v = br.se(level)
            gradient = [br.se(x) for x in grad] if grad is not None else \
                self._rate_gradient(lam, v, free, states, br)
            return lam, total_derivative(v, states, t, br), gradient
        if grad is not None:
            return lam, br.se(level), [br.se(x) for x in grad]
        g = br.se(level)
        gradient = [0] * len(self.coordinates)
        for q, s in zip(free, states):
            gradient[self.coordinates.index(q)] = g.diff(br.se(s.q))
        rate = total_derivative(g, states, t, br)
        return lam, total_derivative(rate, states, t, br), gradient

    def _rate_gradient(self, lam, v, free, states, br) -> list:
        """The coefficients of the rates in the velocity-level expression ``v`` (plain
        symbols, symengine), by coordinate index; refused unless ``v`` is linear in them."""
        rates = [br.se(s.qd) for s in states]
        gradient = [0] * len(self.coordinates)
        for q, qd in zip(free, rates):
            a = v.diff(qd)
            if a.free_symbols & set(rates):
                raise ModelError(f"velocity constraint `{lam.name}` is not linear in the rates "
                                 f"(its coefficient of {q.func.__name__}' holds a rate); "
                                 "write it as a(q, t) . q' + a0(q, t).")
            gradient[self.coordinates.index(q)] = a
        if not any(x != 0 for x in gradient):
            raise ModelError(f"velocity constraint `{lam.name}` holds no rate of a free "
                             "coordinate; a condition on the positions is a constraint(), "
                             "not a velocity_constraint().")
        return gradient

    def _declared_constraints(self) -> tuple:
        """The constraints at the level they were declared (prescribed motion put in), for
        ``EquationSet.constraints``; one made identically zero by the prescribed motion is
        left out."""
        out = []
        for (lam, _, _), (level, expr) in zip(self._constraints, self._declared):
            expr = self._known(expr)
            if expr != 0:
                out.append(Constraint(lam.name, level, expr,
                                      f"constraint {lam.name} (acceleration level)"))
        return tuple(out)

    def equations(self) -> EquationSet:
        """Lagrange's equations, one per free coordinate, plus each constraint's acceleration level.

        The algebra runs on plain symbols in symengine (:mod:`dualmech.model._algebra`):
        ``d/dt dT/dq'_j`` is expanded by the chain rule, so nothing is differentiated with
        respect to a ``Derivative``.
        """
        free = [q for q in self.coordinates if q not in self._prescribed]
        if not (self._T or self._V or self._R or self._Q):
            raise ModelError(f"`{self.name}` has no energy or force terms.")
        plain = lambda e: to_plain(self._known(e), free)  # noqa: E731
        terms = {"T": {k: plain(v) for k, v in self._T.items()},
                 "V": {k: plain(v) for k, v in self._V.items()},
                 "R": {k: plain(v) for k, v in self._R.items()}}
        Q = {k: [plain(x) for x in v] for k, v in self._Q.items()}
        cons = [(lam, plain(level), None if grad is None else [plain(g) for g in grad])
                for lam, level, grad in self._constraints]
        everything = [e for d in terms.values() for e in d.values()] + \
            [x for v in Q.values() for x in v] + \
            [x for _, lv, gr in cons for x in [lv] + (gr or [])]
        states = [state_symbols(q) for q in free]
        try:
            br = Bridge(everything, [t] + [x for s in states for x in (s.q, s.qd, s.qdd)])
        except ValueError as exc:
            raise ModelError(f"`{self.name}`: {exc}") from None
        cons = [self._constraint_se(c, free, states, br) for c in cons]
        T_se = {k: br.se(v) for k, v in terms["T"].items()}
        contributions = []
        index = {q: j for j, q in enumerate(self.coordinates)}
        for q, s in zip(free, states):
            j = index[q]
            qs, qds = br.se(s.q), br.se(s.qd)
            parts: dict = {}
            for key, T in T_se.items():
                parts[key] = total_derivative(T.diff(qds), states, t, br) - T.diff(qs)
            for key, V in terms["V"].items():
                parts[key] = parts.get(key, 0) + br.se(V).diff(qs)
            for key, R in terms["R"].items():
                parts[key] = parts.get(key, 0) + br.se(R).diff(qds)
            for key, Qk in Q.items():
                parts[key] = parts.get(key, 0) - br.se(Qk[j])
            for lam, _, grad in cons:
                parts[f"constraint {lam.name}"] = -br.se(lam) * grad[j]
            contributions.append((f"Lagrange, {q.func.__name__}", parts))
        for lam, level, _ in cons:
            contributions.append((f"constraint {lam.name} (acceleration level)",
                                  {f"constraint {lam.name}": level}))
        names = dict(br.by_name)
        eqs = [sum(p.values(), se.Integer(0)) for _, p in contributions]
        out = EquationSet(self.name, tuple(free), Rows(eqs, names, free, plain=True),
                          tuple(lam for lam, _, _ in self._constraints),
                          tuple(label for label, _ in contributions),
                          Rows([p for _, p in contributions], names, free, plain=True),
                          self.description, self._declared_constraints())
        note(self, out)   # the named T, V, R and Q terms, for an explanation (declared.py)
        return out
