"""Kane's method from a direct model's declarations, reactions brought out by auxiliary speeds.

A third derivation the toolkit makes itself (the *referee*).  From what a
:class:`~dualmech.model.direct.NewtonEuler` declares -- the inertial frame, the coordinates,
the bodies with their mass centres and inertias, every load (gravity, springs, dampers, forces,
torques) and the reactions with their points and directions
(:class:`~dualmech.model.direct.Declarations`) -- and nothing else (not its balances, not its
projections), Kane's equations are formed with the generalised speeds ``u_j = q_j'``::

    F_j + F*_j = 0,   F_j  = sum F . dv_P/du_j + sum tau . dw_B/du_j
                      F*_j = -sum m a_C . dv_C/du_j - sum (I alpha + w x I w) . dw_B/du_j

the acceleration-level row of each constraint the direct model declares (rolling, velocity
and holonomic: :meth:`~dualmech.model.direct.NewtonEuler.rolling`, ...), and one more
equation per reaction, for an *auxiliary speed* that releases it: a reaction
force ``R n`` on body B gives B (with every body fixed to B and not separated from it by a
declared reaction) the extra velocity ``u_R n``; a reaction couple ``M n`` the extra angular
velocity ``u_R n`` about B's mass centre.  The auxiliary equation is Kane's equation for that
speed at ``u_R = 0``: the reaction does work in it, so it gives the reaction a second time,
independently of the direct form's free-body projections.  Every force between the moved
bodies and the others must then be declared (as a reaction, spring, ...); a body fixed to B
(a point mass on a disc) moves with it.

The equations are linear in ``(q'', reactions)``: an :class:`EquationSet` like any model.

Example
-------
>>> import sympy as sp
>>> from dualmech import Frame, Point, Particle, NewtonEuler, coordinate, rot_z
>>> th = coordinate("theta"); m, l, g = sp.symbols("m l g", positive=True)
>>> O = Frame.ground("O"); arm = O.child("arm", rot_z(th))
>>> bob = Particle("bob", m, Point.origin(O).locate("bob", -l * arm.y))
>>> ne = NewtonEuler(coordinates=[th], ground=O)
>>> ne.gravity(-g * O.y); T = ne.reaction("T", bob, arm.y)
>>> ne.linear_momentum(bob, arm.x); ne.linear_momentum(bob, arm.y)
>>> kane = kane_equations(ne.declarations())
>>> kane.labels
('Kane, theta', 'auxiliary speed along T (bob)')
>>> sp.trigsimp(sp.expand(kane.equations[1]))
T - g*m*cos(theta(t)) - l*m*Derivative(theta(t), t)**2
"""
from __future__ import annotations

import symengine as se

from dualmech.model._algebra import is_zero_trig as _is_zero, merge_names, names_of, to_se
from dualmech.model.bodies import Particle, RigidBody
from dualmech.model.constraints import acceleration_row
from dualmech.model.direct import Declarations, ReactionDeclaration
from dualmech.model.equations import EquationSet, ModelError, Rows, state_symbols, to_plain_se
from dualmech.model.kinematics import Frame, Point, Vector

__all__ = ["kane_equations", "moved_with"]


class _Plain:
    """Vectors of the declarations with plain state symbols (``q``, ``q_dot``, ``q_ddot``)."""

    def __init__(self, decl: Declarations):
        self.decl = decl
        self.coordinates = tuple(decl.coordinates)
        self.speeds = [se.Symbol(state_symbols(q).qd.name) for q in self.coordinates]
        self.names: dict = {}
        self._vel: dict = {}
        self._omega: dict = {}
        self.together: dict = {}    # (id a, id b) -> whether the two bodies move as one

    def plain(self, expr):
        return to_plain_se(expr, self.coordinates)

    def comps(self, v: Vector, frame: Frame) -> tuple:
        """Components of ``v`` in ``frame``, plain."""
        w = v.express(frame)
        self.names = merge_names(self.names, w.se_names)
        return tuple(self.plain(c) for c in w.se_components)

    def velocity(self, point) -> tuple:
        """Plain components of the point's velocity in the ground frame."""
        hit = self._vel.get(id(point))
        if hit is None or hit[0] is not point:
            hit = self._vel[id(point)] = (point, self.comps(point.vel(self.decl.ground),
                                                            self.decl.ground))
        return hit[1]

    def material_velocity(self, body, point) -> tuple:
        """Velocity of the body's material point at ``point`` (ground components): a rigid
        body's ``v_C + w x r_CP`` (a declared point need not be fixed in the body: a contact
        point moves along the surface), a particle's own velocity."""
        if not isinstance(body, RigidBody) or point is body.masscenter:
            return self.velocity(body.masscenter if isinstance(body, RigidBody)
                                 else body.point)
        key = (id(body), id(point))
        hit = self._vel.get(key)
        if hit is None or hit[0] is not point:
            G = self.decl.ground
            w = self.comps(body.frame.ang_vel_in(G), G)
            r = self.comps(point.pos_from(body.masscenter), G)
            v = tuple(a + b for a, b in zip(self.velocity(body.masscenter), _cross(w, r)))
            hit = self._vel[key] = (point, v)
        return hit[1]

    def omega(self, body: RigidBody) -> tuple:
        """Plain components of the body's angular velocity in its own frame."""
        hit = self._omega.get(id(body))
        if hit is None or hit[0] is not body:
            hit = self._omega[id(body)] = (body, self.comps(
                body.frame.ang_vel_in(self.decl.ground), body.frame))
        return hit[1]


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _partial(v: tuple, u) -> tuple:
    return tuple(c.diff(u) for c in v)


def _inertia_torque(p: _Plain, body: RigidBody) -> tuple:
    """``I alpha + w x I w`` in the body's frame, plain."""
    w = body.frame.ang_vel_in(p.decl.ground)
    alpha = p.comps(w.dt(p.decl.ground), body.frame)
    w = p.omega(body)
    I = [to_se(x) for x in body.inertia]
    for x in body.inertia:
        p.names = merge_names(p.names, names_of(x))
    Iv = lambda v: tuple(I[3 * i] * v[0] + I[3 * i + 1] * v[1] + I[3 * i + 2] * v[2]  # noqa
                         for i in range(3))
    Iw = Iv(w)
    return tuple(a + b for a, b in zip(Iv(alpha), _cross(w, Iw)))


class _Motion:
    """A virtual motion: partial velocity of any point and partial angular velocity of any
    body, both as plain components in the ground frame (or ``None`` for zero)."""

    def point(self, body, point):   # pragma: no cover - the subclasses say
        raise NotImplementedError

    def angular(self, body):   # pragma: no cover
        raise NotImplementedError


class _Speed(_Motion):
    """Partial velocities with respect to the generalised speed ``u``."""

    def __init__(self, p: _Plain, u):
        self.p, self.u = p, u

    def point(self, body, point):
        return _partial(self.p.material_velocity(body, point), self.u)

    def angular(self, body):
        if not isinstance(body, RigidBody):
            return None
        w = _partial(self.p.omega(body), self.u)
        return self.p.comps(Vector.from_se(body.frame, w, {}), self.p.decl.ground)


class _Release(_Motion):
    """An auxiliary motion: the bodies ``moved`` translate along ``n`` (``centre=None``) or
    turn about ``n`` through the point ``centre`` (ground components)."""

    def __init__(self, p: _Plain, moved: list, n: tuple, centre=None):
        self.p = p
        self.moved = {id(b) for b in moved}
        self.n = n
        self.centre = centre

    def point(self, body, point):
        if id(body) not in self.moved:
            return None
        if self.centre is None:
            return self.n
        r = self.p.comps(point.pos_from(self.centre), self.p.decl.ground)
        return _cross(self.n, r)

    def angular(self, body):
        if id(body) not in self.moved or self.centre is None or \
                not isinstance(body, RigidBody):
            return None
        return self.n


def _generalised(p: _Plain, motion: _Motion) -> dict:
    """``{ingredient: F_r + F*_r}`` for one virtual motion."""
    G = p.decl.ground
    parts: dict = {}

    def add(key, value):
        if value != 0:
            parts[key] = parts.get(key, se.Integer(0)) + value

    for body in p.decl.bodies:
        for load in p.decl.loads[id(body)]:
            if load.force is not None:
                vp = motion.point(body, load.point)
                if vp is not None:
                    add(load.key, _dot(p.comps(load.force, G), vp))
            if load.torque is not None:
                wb = motion.angular(body)
                if wb is not None:
                    add(load.key, _dot(p.comps(load.torque, G), wb))
        vc = motion.point(body, body.masscenter)
        key = f"inertia of {body.name}"
        mass = to_se(body.mass)
        p.names = merge_names(p.names, names_of(body.mass))
        if vc is not None:
            a = p.comps(body.masscenter.acc(G), G)
            add(key, -mass * _dot(a, vc))
        wb = motion.angular(body) if isinstance(body, RigidBody) else None
        if wb is not None:
            torque = p.comps(Vector.from_se(body.frame, _inertia_torque(p, body), p.names), G)
            add(key, -_dot(torque, wb))
    return parts


def moved_with(decl: Declarations, reaction: ReactionDeclaration, p: "_Plain | None" = None
               ) -> tuple[list, int]:
    """``(bodies, sign)``: the bodies an auxiliary speed of ``reaction`` moves (its *side*),
    and the sign of the reaction's force on them.

    A reaction on B from the ground moves B; one between B and A moves one side: B (sign +1),
    or A (sign -1) when B is *anchored* (a rigid body whose mass centre never moves and on
    which no force from the ground is declared: held by a pivot the declarations leave out)
    or when B's side carries a declared ground reaction and A's does not (so two reactions on
    B are not released by the same motion).  Each side is its body and every body fixed to it
    (same rotation, constant relative position) that no declared reaction separates from it.
    """
    p = p or _Plain(decl)
    side_b = _fixed_set(p, decl, reaction.body, reaction.against)
    if reaction.against is None:
        return side_b, 1
    side_a = _fixed_set(p, decl, reaction.against, reaction.body)
    grounded = lambda side: any(  # noqa: E731
        r.against is None and r.kind == "force" and any(r.body is b for b in side)
        for r in decl.reactions)
    anchored = lambda side: any(_anchored(p, b) and not grounded([b]) for b in side)  # noqa
    if anchored(side_b) and not anchored(side_a):
        return side_a, -1
    if grounded(side_b) and not grounded(side_a) and not anchored(side_a):
        return side_a, -1
    return side_b, 1


def _auxiliary(p: _Plain, decl: Declarations) -> tuple[list, list]:
    """Rows and labels of the auxiliary speeds: one translation per reaction force (of its
    side, along its direction), and turns of a side about the ground axes -- through its pin
    when it is pinned (then instead of translations), or through its mass centre when
    reactions act on it at two or more points (translations alone cannot tell them apart).
    """
    G = decl.ground
    rows, labels, turned = [], [], []
    for r in decl.reactions:
        side, sign = moved_with(decl, r, p)
        pin = _pin(p, decl, side)
        who = ", ".join(b.name for b in side)
        if r.kind == "force" and pin is None:
            n = tuple(sign * c for c in p.comps(r.direction, G))
            rows.append(_generalised(p, _Release(p, side, n)))
            labels.append(f"auxiliary speed along {r.symbol} ({who})")
        points = {id(x.point) for x in decl.reactions if any(x.body is b for b in side)
                  and x.kind == "force"}
        if pin is None and len(points) < 2 and r.kind == "force":
            continue
        if any({id(b) for b in side} == t for t in turned):
            continue
        turned.append({id(b) for b in side})
        centre = pin or side[0].masscenter
        for axis in range(3):
            n = tuple(se.Integer(1 if i == axis else 0) for i in range(3))
            parts = _generalised(p, _Release(p, side, n, centre))
            parts = {k: v for k, v in parts.items() if not _is_zero(v)}
            if parts:
                rows.append(parts)
                labels.append(f"auxiliary speed: {who} turning about {G.name}.{'xyz'[axis]} "
                              f"through {centre.name}")
    return rows, labels


def _pin(p: _Plain, decl: Declarations, side: list):
    """A point at which a rigid body of ``side`` is held by a pivot the declarations leave
    out: a known point (a frame's origin, a load's point, a mass centre) where the body's
    material point never moves and no declared reaction acts; ``None`` when there is none."""
    G = decl.ground
    reacted = [x.point for x in decl.reactions
               if x.kind == "force" and any(x.body is b for b in side)]
    reacted += [x.against_at for x in decl.reactions
                if x.against_at is not None and any(x.against is b for b in side)]
    for body in side:
        if not isinstance(body, RigidBody):
            continue
        for point in _known_points(decl):
            v = p.material_velocity(body, point)
            if not all(_is_zero(c) for c in v):
                continue
            if any(all(_is_zero(p.plain(c)) for c in point.pos_from(x).se_components)
                   for x in reacted):
                continue
            return point
    return None


def _known_points(decl: Declarations) -> list:

    out = [Point.origin(decl.ground)]
    for b in decl.bodies:
        out.append(b.masscenter)
        for load in decl.loads[id(b)]:
            if load.point is not None:
                out.append(load.point)
    return out


def _anchored(p: _Plain, body) -> bool:
    if not isinstance(body, RigidBody):
        return False
    return all(_is_zero(c) for c in p.velocity(body.masscenter))


def _fixed_set(p: _Plain, decl: Declarations, body, other) -> list:
    separated = set()
    for r in decl.reactions:
        if r.against is not None:
            separated.add(frozenset((id(r.body), id(r.against))))
    moved, frontier = [body], [body]
    while frontier:
        b = frontier.pop()
        for x in decl.bodies:
            if any(x is y for y in moved) or x is other:
                continue
            if frozenset((id(b), id(x))) in separated:
                continue
            if _fixed_together(p, b, x):
                moved.append(x)
                frontier.append(x)
    return moved


def _fixed_together(p: _Plain, a, b) -> bool:
    """Do bodies ``a`` and ``b`` move as one rigid body (decided on the expanded forms)?
    Kept in ``p`` for the pair: every reaction's side asks again."""
    key = (id(a), id(b))
    hit = p.together.get(key)
    if hit is None:
        hit = p.together[key] = p.together[(id(b), id(a))] = _moves_as_one(p, a, b)
    return hit


def _moves_as_one(p: _Plain, a, b) -> bool:
    G = p.decl.ground
    rigid = [x for x in (a, b) if isinstance(x, RigidBody)]
    if len(rigid) == 2:
        rel = a.frame.ang_vel_in(G) - b.frame.ang_vel_in(G)
        if not all(_is_zero(p.plain(c)) for c in rel.se_components):
            return False
    frame = rigid[0].frame if rigid else G
    r = b.masscenter.pos_from(a.masscenter).dt(frame)
    return all(_is_zero(p.plain(c)) for c in r.se_components)


def kane_equations(decl: Declarations, name: str = "referee") -> EquationSet:
    """Kane's equations of the declared bodies and loads, one auxiliary row per reaction.

    Raises :class:`ModelError` when the declarations cannot give a referee: a coordinate
    that moves no declared body, or no bodies at all.
    """
    if not decl.bodies:
        raise ModelError(f"`{decl.name}` declares no bodies; the referee has nothing to move.")
    p = _Plain(decl)
    rows, labels = [], []
    for q, u in zip(p.coordinates, p.speeds):
        parts = _generalised(p, _Speed(p, u))
        if not any(k.startswith("inertia of ") for k in parts):
            raise ModelError(
                f"coordinate {q.func.__name__} moves no declared body of `{decl.name}` (its "
                "partial velocities are all zero): the declared kinematics do not describe "
                "its motion, so the Kane method cannot derive its equation.")
        rows.append(parts)
        labels.append(f"Kane, {q.func.__name__}")
    rows_aux, labels_aux = _auxiliary(p, decl)
    rows += rows_aux
    labels += labels_aux
    for c in decl.constraints:   # the declared constraints, as the direct form holds them
        row, names = acceleration_row(c)
        p.names = merge_names(p.names, names)
        rows.append({f"constraint {c.name}": p.plain(row)})
        labels.append(c.label)
    names = dict(p.names)
    for r in decl.reactions:
        names = merge_names(names, {r.symbol.name: r.symbol})
    eqs = [se.Add(*c.values()) if c else se.Integer(0) for c in rows]
    return EquationSet(name, p.coordinates, Rows(eqs, names, p.coordinates, plain=True),
                       tuple(r.symbol for r in decl.reactions), tuple(labels),
                       Rows(rows, names, p.coordinates, plain=True),
                       f"the Kane method from the declarations of `{decl.name}`",
                       tuple(decl.constraints))
