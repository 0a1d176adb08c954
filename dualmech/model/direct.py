"""The direct form: free-body diagrams and momentum balances (Newton--Euler).

Each body gets a free-body diagram: applied forces and torques, gravity, springs and dampers,
and *unknown* reactions (a magnitude along a known direction, or unknown components of a
vector).  Equations are ``sum F = m a_C`` and the angular-momentum balance about the mass
centre, a fixed point or a moving point B::

    sum tau_B = d/dt H_B + m v_B x v_C,     H_B = I_B w + m r_BC x v_B

projected on unit vectors the user chooses.  The result is an :class:`EquationSet` linear in
``(q'', reactions)``.

Example
-------
A mass on a spring, with the floor's normal force as an unknown reaction:

>>> import sympy as sp
>>> from dualmech import Frame, Point, Particle, coordinate
>>> from dualmech.model.direct import NewtonEuler
>>> x = coordinate("x"); m, k, g = sp.symbols("m k g", positive=True)
>>> O = Frame.ground(); P = Point.origin(O).locate("P", x*O.x)
>>> block = Particle("block", m, P)
>>> ne = NewtonEuler(coordinates=[x], ground=O)
>>> ne.gravity(-g*O.y)
>>> N = ne.reaction("N", block, O.y)
>>> ne.linear_spring("spring", block, k, x, O.x)
>>> ne.linear_momentum(block, O.x); ne.linear_momentum(block, O.y)
>>> eqs = ne.equations()
>>> eqs.equations
(-k*x(t) - m*Derivative(x(t), (t, 2)), N - g*m)
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

import sympy as sp

from dualmech.model._algebra import merge_names, names_of, to_se, to_sp
from dualmech.model._expr import as_expr, refuse_jumps, refuse_text_in

from dualmech.model.bodies import Particle, RigidBody
from dualmech.model.declared import builder_of, note
from dualmech.model.constraints import acceleration_row, declared, material_velocity, \
    trig_reduced
from dualmech.model.equations import Constraint, EquationSet, ModelError, Rows
from dualmech.model.kinematics import Frame, Point, Vector

__all__ = ["NewtonEuler", "Load", "ReactionDeclaration", "Declarations", "declarations_of"]

Body = Particle | RigidBody


@dataclass(frozen=True)
class Load:
    """One entry of a free-body diagram: a force applied at a point, and/or a torque."""

    key: str
    force: Vector | None = None
    point: Point | None = None
    torque: Vector | None = None


@dataclass(frozen=True, eq=False)
class ReactionDeclaration:
    """One declared reaction: the unknown ``symbol`` times the unit vector ``direction``, a
    force at ``point`` of ``body`` (``kind="force"``) or a couple on it (``kind="torque"``),
    and the opposite on ``against`` (at ``against_at``) when given."""

    symbol: sp.Symbol
    kind: str
    body: "Body"
    direction: Vector
    point: Point | None = None
    against: "Body | None" = None
    against_at: Point | None = None


@dataclass(frozen=True, eq=False)
class Declarations:
    """What a direct model declares, apart from its balances: the inertial frame, the
    coordinates, the bodies, every load on each body (gravity included), the reactions and
    the declared constraints (:meth:`NewtonEuler.constraint`, ...).

    A second derivation built from these (the Kane referee, :mod:`dualmech.model.kane`)
    shares them with the direct form and nothing else.
    """

    name: str
    coordinates: tuple
    ground: Frame
    bodies: tuple
    loads: dict            # id(body) -> tuple of Load, gravity included
    reactions: tuple       # ReactionDeclaration, in the order of the unknowns
    constraints: tuple = ()   # Constraint: declared rolling, velocity and holonomic ones


def declarations_of(eqs) -> "Declarations | None":
    """The :class:`Declarations` behind an :class:`EquationSet` made by
    :meth:`NewtonEuler.equations` (``None`` for any other set; see
    :mod:`dualmech.model.declared`)."""
    builder = builder_of(eqs)
    return builder.declarations() if isinstance(builder, NewtonEuler) else None


@refuse_text_in
class NewtonEuler:
    r"""The direct form of one model: free-body diagrams, then momentum balances.

    Declare the loads on each body (applied forces and torques, gravity, springs, dampers and
    the *unknown* reactions), then write one balance per equation you want, projected on a unit
    vector you choose; :meth:`equations` gives the :class:`EquationSet`, linear in
    ``(q'', reactions)``.  Every balance is written as *applied minus inertia* (``sum F - m a_C``
    and ``sum tau_B - dH_B/dt - m v_B x v_C``), equal to zero::

        body C, mass m            sum F . e   -  m a_C . e             = 0   (linear_momentum)
          F1 \   / R (unknown)    sum tau_B . e - (dH_B/dt + m v_B x v_C) . e = 0
              \ /                                                        (angular_momentum)
               C ---> e           B: the mass centre, a fixed or a moving point

    Declaring loads: :meth:`force`, :meth:`torque`, :meth:`gravity`, :meth:`linear_spring`,
    :meth:`spring_between`, :meth:`linear_damper`, :meth:`torsional_spring`,
    :meth:`torsional_damper`; reactions: :meth:`reaction` (a magnitude along a direction),
    :meth:`reaction_vector` (components in a frame), :meth:`reaction_torque`.  Balances:
    :meth:`linear_momentum`, :meth:`angular_momentum`, or :meth:`equation` given directly.

    Parameters
    ----------
    name : str
        The derivation's name in reports (``"newton_euler"``).
    coordinates : sequence of coordinates
        The generalised coordinates (``coordinate("x")``...), in the order of the equations'
        accelerations.
    ground : Frame
        The inertial frame (``Frame.ground()``); accelerations are taken in it.
    description : str
        One line shown beside the name.

    Examples
    --------
    A bead of mass ``m`` on a pendulum string of length ``l``, the string's pull ``T`` unknown:

    >>> import sympy as sp
    >>> from dualmech import Frame, NewtonEuler, Particle, Point, coordinate, rot_z
    >>> theta = coordinate("theta"); m, l, g = sp.symbols("m l g", positive=True)
    >>> O = Frame.ground(); arm = O.child("arm", rot_z(theta))
    >>> bob = Particle("bob", m, Point.origin(O).locate("bob", -l * arm.y))
    >>> ne = NewtonEuler(coordinates=[theta], ground=O)
    >>> ne.gravity(-g * O.y)
    >>> T = ne.reaction("T", bob, arm.y)          # the string pulls the bob towards O
    >>> ne.linear_momentum(bob, arm.x); ne.linear_momentum(bob, arm.y)
    >>> ne.equations().reactions_solved()
    {T: m*(g*cos(theta(t)) + l*Derivative(theta(t), t)**2)}
    """

    def __init__(self, name: str = "newton_euler", *, coordinates: Sequence, ground: Frame,
                 description: str = ""):
        self.name = name
        self.coordinates = tuple(coordinates)
        self.ground = ground
        self.description = description
        self._loads: dict[int, list[Load]] = {}
        self._bodies: dict[int, Body] = {}
        self._unknowns: list[sp.Symbol] = []
        self._reactions: list[ReactionDeclaration] = []
        self._equations: list[tuple[str, dict]] = []   # parts held in symengine
        self._names: dict = {}
        self._constraints: list[Constraint] = []

    # -- free-body diagrams ------------------------------------------------------------
    def _add(self, body: Body, load: Load) -> None:
        if not isinstance(body, (Particle, RigidBody)):
            raise ModelError(f"`body` must be a Particle or RigidBody, got {type(body).__name__}.")
        for vector in (load.force, load.torque):
            if vector is not None:
                refuse_jumps(_held(vector), f"`{load.key}` on `{body.name}`")
        self._bodies[id(body)] = body
        self._loads.setdefault(id(body), []).append(load)

    def force(self, key: str, body: Body, vector: Vector, at: Point | None = None) -> None:
        """Force ``vector`` on ``body`` applied at ``at`` (default: its mass centre)."""
        self._add(body, Load(key, vector, at or body.masscenter))

    def torque(self, key: str, body: Body, vector: Vector) -> None:
        """Pure torque (couple) ``vector`` on ``body``."""
        if not isinstance(body, RigidBody):
            raise ModelError(f"a torque needs a rigid body; `{body.name}` is a particle.")
        self._add(body, Load(key, torque=vector))

    def gravity(self, g: Vector, bodies: Sequence[Body] | None = None) -> None:
        """Weight ``m g`` at the mass centre of each body (default: bodies added so far and later)."""
        self._gravity = (g, None if bodies is None else list(bodies))

    def linear_spring(self, key: str, body: Body, k, extension, direction: Vector,
                      at: Point | None = None, against: Body | None = None,
                      against_at: Point | None = None) -> None:
        """Spring force ``-k * extension * direction`` on ``body`` (and the opposite on ``against``).

        ``direction`` is the unit vector along which ``extension`` grows for ``body``.
        """
        f = -k * extension * direction
        self.force(key, body, f, at)
        if against is not None:
            self.force(key, against, -f, against_at)

    def spring_between(self, key: str, k, free_length, a: tuple, b: tuple) -> None:
        """Spring of stiffness ``k`` and free length ``free_length`` between two points.

        ``a`` and ``b`` are ``(body, point)`` pairs; ``body`` may be ``None`` for a fixed
        anchor.  The force on ``a``'s body is ``-k (|r_ab| - free_length) e_ab`` with ``e_ab``
        the unit vector from ``b`` to ``a`` (and the opposite on ``b``'s body).  The length is
        a square root, so the comparator decides such models in high precision (mpmath).
        """
        (body_a, pa), (body_b, pb) = a, b
        r = pa.pos_from(pb)
        length = sp.sqrt(r.dot(r))
        f = -k * (length - free_length) / length * r
        if body_a is not None:
            self.force(key, body_a, f, pa)
        if body_b is not None:
            self.force(key, body_b, -f, pb)

    def linear_damper(self, key: str, body: Body, c, rate, direction: Vector,
                      at: Point | None = None, against: Body | None = None,
                      against_at: Point | None = None) -> None:
        """Damper force ``-c * rate * direction`` on ``body`` (opposite on ``against``)."""
        self.linear_spring(key, body, c, rate, direction, at, against, against_at)

    def torsional_spring(self, key: str, body: Body, kt, angle, axis: Vector,
                         against: Body | None = None) -> None:
        """Torque ``-kt * angle * axis`` on ``body`` (opposite on ``against``)."""
        tau = -kt * angle * axis
        self._torque_pair(key, body, tau, against)

    def torsional_damper(self, key: str, body: Body, ct, rate, axis: Vector,
                         against: Body | None = None) -> None:
        """Torque ``-ct * rate * axis`` on ``body`` (opposite on ``against``)."""
        self._torque_pair(key, body, -ct * rate * axis, against)

    def _torque_pair(self, key, body, tau, against):
        self._add(body, Load(key, torque=tau))
        if against is not None:
            self._add(against, Load(key, torque=-tau))

    def reaction(self, name: str, on: Body, direction: Vector, at: Point | None = None,
                 against: Body | None = None, against_at: Point | None = None) -> sp.Symbol:
        """An unknown force ``R * direction`` on ``on`` (and ``-R * direction`` on ``against``).

        Returns the unknown magnitude ``R`` (a symbol named ``name``).
        """
        _check_unit(name, direction)
        R = self._unknown(name)
        self.force(f"reaction {name}", on, R * direction, at)
        if against is not None:
            self.force(f"reaction {name}", against, -R * direction, against_at)
        self._reactions.append(ReactionDeclaration(
            R, "force", on, direction, at or on.masscenter, against,
            None if against is None else (against_at or against.masscenter)))
        return R

    def reaction_vector(self, name: str, on: Body, frame: Frame, axes: str = "xyz",
                        at: Point | None = None, against: Body | None = None,
                        against_at: Point | None = None) -> Vector:
        """Unknown force components ``name_x, name_y, ...`` along ``frame``'s ``axes``."""
        comps = []
        for a in "xyz":
            comps.append(self._unknown(f"{name}_{a}") if a in axes else 0)
        F = frame.vector(*comps)
        self.force(f"reaction {name}", on, F, at)
        if against is not None:
            self.force(f"reaction {name}", against, -F, against_at)
        for a, c in zip("xyz", comps):
            if c != 0:
                self._reactions.append(ReactionDeclaration(
                    c, "force", on, getattr(frame, a), at or on.masscenter, against,
                    None if against is None else (against_at or against.masscenter)))
        return F

    def reaction_torque(self, name: str, on: RigidBody, direction: Vector,
                        against: Body | None = None) -> sp.Symbol:
        """An unknown couple ``M * direction`` on ``on`` (opposite on ``against``)."""
        _check_unit(name, direction)
        M = self._unknown(name)
        self._torque_pair(f"reaction {name}", on, M * direction, against)
        self._reactions.append(ReactionDeclaration(M, "torque", on, direction, None, against))
        return M

    def _unknown(self, name: str) -> sp.Symbol:
        if any(u.name == name for u in self._unknowns):
            raise ModelError(f"reaction `{name}` is declared twice in `{self.name}`.")
        s = sp.Symbol(name, real=True)
        self._unknowns.append(s)
        return s

    # -- balances ----------------------------------------------------------------------
    def _all_loads(self, body: Body) -> list[Load]:
        loads = list(self._loads.get(id(body), []))
        grav = getattr(self, "_gravity", None)
        if grav is not None:
            g, which = grav
            if which is None or any(b is body for b in which):
                loads.append(Load(f"gravity on {body.name}", body.mass * g, body.masscenter))
        return loads

    def linear_momentum(self, body: Body | Sequence[Body], direction: Vector,
                        label: str | None = None) -> None:
        """``(sum F - sum m a_C) . direction = 0`` for one body or a system of bodies."""
        bodies = _as_list(body)
        parts: dict = {}
        for b in bodies:
            self._bodies[id(b)] = b
            for ld in self._all_loads(b):
                if ld.force is not None:
                    self._acc(parts, ld.key, ld.force.dot_se(direction))
            a = b.masscenter.acc(self.ground)
            self._acc(parts, f"inertia of {b.name}", a.dot_se(direction), -b.mass)
        self._equations.append((label or f"sum F . {_dir_name(direction)} ({_names(bodies)})", parts))

    def angular_momentum(self, body: Body | Sequence[Body], direction: Vector,
                         about: Point | None = None, label: str | None = None) -> None:
        """``(sum tau_B - dH_B/dt - m v_B x v_C) . direction = 0`` about point ``about``.

        ``about`` defaults to the mass centre of a single body; give it for a system.
        """
        bodies = _as_list(body)
        if about is None:
            if len(bodies) != 1:
                raise ModelError("give `about` for the angular momentum of a system of bodies.")
            about = bodies[0].masscenter
        parts: dict = {}
        vB = about.vel(self.ground)
        for b in bodies:
            self._bodies[id(b)] = b
            for ld in self._all_loads(b):
                moment, names = to_se(0), {}
                if ld.force is not None:
                    moment, names = ld.point.pos_from(about).cross(ld.force).dot_se(direction)
                if ld.torque is not None:
                    m2, n2 = ld.torque.dot_se(direction)
                    moment, names = moment + m2, merge_names(names, n2)
                if moment != 0:
                    self._acc(parts, ld.key, (moment, names))
            H = b.angular_momentum(about, self.ground)
            rate = H.dt(self.ground) + b.mass * vB.cross(b.masscenter.vel(self.ground))
            self._acc(parts, f"inertia of {b.name}", rate.dot_se(direction), -1)
        self._equations.append(
            (label or f"sum tau_{about.name} . {_dir_name(direction)} ({_names(bodies)})", parts))

    def equation(self, label: str, parts: dict) -> None:
        """Add an equation given directly as ``{ingredient: expression}`` (sum = 0)."""
        mine: dict = {}
        for key, value in parts.items():
            value = as_expr(value)
            refuse_jumps([value], f"`{key}` in equation `{label}`")
            self._acc(mine, key, (to_se(value), names_of(value)))
        self._equations.append((label, mine))

    # -- constraints -------------------------------------------------------------------
    def constraint(self, name: str, g) -> None:
        """Holonomic constraint ``g(q, t) = 0`` the motion keeps.

        Kept at position level on the equation set (``EquationSet.constraints``); the
        equations get its second time derivative as the row ``constraint name (acceleration
        level)``.  The force that keeps it is a reaction declared on the free-body diagram.
        """
        self._constrain(declared(name, g, "position", self.coordinates, self._unknowns,
                                 self.name))

    def velocity_constraint(self, name: str, expression) -> None:
        """Velocity-level constraint ``expression = 0``, linear in the rates
        (``a(q, t) . q' + a0(q, t)``), e.g. no slip; kept at velocity level, its time
        derivative is the row ``constraint name (acceleration level)``."""
        self._constrain(declared(name, expression, "velocity", self.coordinates,
                                 self._unknowns, self.name))

    def rolling(self, name: str, body: RigidBody, contact: Point,
                directions: Sequence[Vector]) -> tuple:
        """Rolling without slipping of ``body`` at ``contact``, along each of ``directions``.

        The condition is on the **material point** of ``body`` instantaneously at
        ``contact``: ``(v_C + w x r_C->contact) . d = 0`` for each direction ``d`` (``C`` its
        mass centre, ``w`` its angular velocity; see
        :func:`~dualmech.model.constraints.material_velocity`).  The classic mistake is to
        write the velocity of the *geometric* contact point instead (``contact.vel(O)``):
        that point slides along the ground as the body rolls (for a disk located by the
        contact's ``x, y`` it gives ``x' = y' = 0``, a disk that cannot roll anywhere), and
        the verdict names such a model.  Give the tangent directions of the ground only; the
        normal component is usually built into the coordinates (it is then identically zero
        and refused).  One velocity constraint ``name O.x``, ... per direction; returns their
        expressions.  The friction force that enforces it is a reaction declared separately.

        Examples
        --------
        A wheel of radius ``r`` on a line (``x`` its centre, ``theta`` its turn):

        >>> import sympy as sp
        >>> from dualmech import Frame, NewtonEuler, Point, RigidBody, coordinate, rot_z
        >>> x, th = coordinate("x"), coordinate("theta"); m, r = sp.symbols("m r", positive=True)
        >>> O = Frame.ground(); W = O.child("W", rot_z(-th))
        >>> C = Point.origin(O).locate("C", x * O.x + r * O.y)
        >>> wheel = RigidBody("wheel", m, C, W, sp.diag(1, 1, m * r**2 / 2))
        >>> ne = NewtonEuler(coordinates=[x, th], ground=O)
        >>> ne.rolling("no slip", wheel, C.locate("P", -r * O.y), [O.x])
        (-r*Derivative(theta(t), t) + Derivative(x(t), t),)
        """
        v = material_velocity(body, contact, self.ground)
        directions = list(directions) if isinstance(directions, (list, tuple)) else [directions]
        out = []
        for d in directions:
            if not isinstance(d, Vector):
                raise ModelError(f"rolling `{name}`: each direction must be a Vector, got "
                                 f"{type(d).__name__}.")
            label = name if len(directions) == 1 else f"{name} {_dir_name(d)}"
            self.velocity_constraint(label, _readable(*v.dot_se(d), self.coordinates))
            out.append(self._constraints[-1].expression)
        return tuple(out)

    def _constrain(self, c: Constraint) -> None:
        if any(old.name == c.name for old in self._constraints):
            raise ModelError(f"constraint `{c.name}` is declared twice in `{self.name}`.")
        self._constraints.append(c)
        row, names = acceleration_row(c)
        parts: dict = {}
        self._acc(parts, f"constraint {c.name}", (row, names))
        self._equations.append((c.label, parts))

    def equations(self) -> EquationSet:
        """The :class:`EquationSet` (see :meth:`EquationSet.simplified` for a tidier form)."""
        if not self._equations:
            raise ModelError(f"`{self.name}` has no equations: call linear_momentum or "
                             "angular_momentum for each body.")
        contributions = [dict(parts) for _, parts in self._equations]
        eqs = [sum(c.values(), to_se(0)) for c in contributions]
        names = self._names
        for u in self._unknowns:
            names = merge_names(names, {u.name: u})
        out = EquationSet(self.name, self.coordinates,
                          Rows(eqs, names, self.coordinates, plain=False),
                          tuple(self._unknowns),
                          tuple(label for label, _ in self._equations),
                          Rows(contributions, names, self.coordinates, plain=False),
                          self.description, tuple(self._constraints))
        note(self, out)   # the free-body diagrams, for the referee and the diagnosis
        return out

    def declarations(self) -> Declarations:
        """The frames, bodies, loads and reactions declared so far (not the balances)."""
        bodies = tuple(self._bodies.values())
        return Declarations(self.name, self.coordinates, self.ground, bodies,
                            {id(b): tuple(self._all_loads(b)) for b in bodies},
                            tuple(self._reactions), tuple(self._constraints))

    def _acc(self, parts: dict, key: str, value_names: tuple, factor=None) -> None:
        """Add a symengine term (``(value, names)``, times the sympy ``factor``) to ``parts``."""
        value, names = value_names
        if factor is not None:
            factor = as_expr(factor)
            value = to_se(factor) * value
            names = merge_names(names, names_of(factor))
        self._names = merge_names(self._names, names)
        parts[key] = parts.get(key, 0) + value


def _readable(value, names: dict, coordinates: tuple):
    """The symengine ``value`` back in sympy with the caller's atoms, so a declared constraint
    reads like a hand one: expanded (in symengine; sympy's ``expand`` of a wheel's contact
    velocity on a steered frame takes minutes) and reduced by ``sin^2 + cos^2 = 1``
    (:func:`~dualmech.model.constraints.trig_reduced`: a coefficient that vanishes
    identically is then 0).  One of 300 terms or more, or not polynomial in the sines and
    cosines, is left as built (expanded, the steered wheel's is a hundred times longer)."""
    import symengine as se
    expanded = se.expand(value)
    if isinstance(expanded, se.Add) and len(expanded.args) >= 300:
        return to_sp(value, names)
    reduced = trig_reduced(to_sp(expanded, names), coordinates)
    return reduced if reduced is not None else to_sp(value, names)


def _held(v: Vector):
    """The components of ``v`` in the form it holds them (symengine when not yet read)."""
    return v._se if v._sp is None else list(v._sp)


def _check_unit(name: str, direction: Vector) -> None:
    """Refuse a reaction direction whose squared length is not 1 (the unknown would be the
    force divided by that length, silently): a number other than 1, or an expression that is
    not 1 at a sample point and does not change with the coordinates (``o.pos_from(P)``, of
    length ``R``; :func:`_not_one`).  A length that changes with the coordinates is not
    refused here: it may be 1 only on the constraint the coordinates keep.

    >>> import sympy as sp
    >>> from dualmech import Frame
    >>> R = sp.Symbol("R", positive=True)
    >>> _check_unit("N", R * Frame.ground("O").y)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    dualmech.model.equations.ModelError: the direction of reaction `N` is not a unit vector (its squared length is R**2, 25/4 at R = 5/2); ...
    """
    if not isinstance(direction, Vector):
        raise ModelError(f"the direction of reaction `{name}` must be a Vector, got "
                         f"{type(direction).__name__}.")
    length2, names = direction.dot_se(direction)
    length2 = length2.expand()
    if length2.is_Number:
        shown = None if length2 == 1 else str(length2)
    else:
        shown = _not_one(to_sp(length2, names))
    if shown is not None:
        raise ModelError(
            f"the direction of reaction `{name}` is not a unit vector (its squared length is "
            f"{shown}); `{name}` would be the force divided by that length.  Divide the "
            "direction by its length, e.g. (O.x + O.y)/sqrt(2), or use a frame's unit vector.")


def _not_one(length2, points: int = 3) -> str | None:
    """``None`` when ``length2`` (sympy, in parameters, time and coordinates) is 1 at
    ``points`` sample points (every atom a rational in (1, 3), to 40 digits: a unit vector of
    a turning frame, ``sin^2 + cos^2``, passes), or when it changes with the coordinates at
    fixed parameters (it may be 1 on the constraint they keep: ``(x O.x + y O.y)/l`` with
    ``x^2 + y^2 = l^2``); else the text ``"<length2>, <value> at <point>"``."""
    import random
    from sympy.core.function import AppliedUndef
    state = sorted(length2.atoms(sp.Derivative), key=str, reverse=True) \
        + sorted(length2.atoms(AppliedUndef), key=str)
    fixed = sorted(length2.free_symbols, key=str)
    rng = random.Random(11)

    def at(values):
        out = length2
        for a in state:                  # rates before the coordinates they differentiate
            out = out.xreplace({a: values[a]})
        return out.xreplace(values)

    def near(a, b) -> bool:
        return a == b if (a - b).is_Rational else abs(sp.N(a - b, 40)) < sp.Float("1e-30", 40)

    for _ in range(points):
        point = {a: sp.Rational(rng.randint(11, 29), 10) for a in fixed + state}
        value = at(point)
        if near(value, sp.Integer(1)):
            continue
        moved = {**point, **{a: sp.Rational(rng.randint(31, 49), 10) for a in state}}
        if state and not near(at(moved), value):
            return None                  # depends on the state: not decided here
        short = sp.trigsimp(length2)    # the message only: sin^2 + cos^2 read as 1
        short = short if sp.count_ops(short) < sp.count_ops(length2) else length2
        if not (short.free_symbols - set(fixed)) and not short.atoms(AppliedUndef):
            value = short.xreplace(point)
        shown = value if value.is_Rational else sp.N(value, 6)
        where = ", ".join(f"{a} = {point[a]}" for a in fixed if a in short.free_symbols)
        return f"{short}, {shown} at {where}" if where else f"{short}"
    return None


def _as_list(body) -> list:
    return list(body) if isinstance(body, (list, tuple)) else [body]


def _names(bodies) -> str:
    return ", ".join(b.name for b in bodies)


def _dir_name(v: Vector) -> str:
    c = list(v.components)
    axes = [a for a, x in zip("xyz", c) if x != 0]
    if len(axes) == 1 and c["xyz".index(axes[0])] == 1:
        return f"{v.frame.name}.{axes[0]}"
    return f"{v.frame.name}{list(c)}"
