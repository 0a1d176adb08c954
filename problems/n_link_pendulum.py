r"""Planar n-link pendulum: a chain of n point masses on massless rods, or of n uniform rods.

A parametric problem for scaling: ``NLinkPendulum(n)`` (point masses, the default of
``dualmech check n_link_pendulum --n 10``) and ``NLinkRigidPendulum(n)`` (uniform rigid links).
Written both ways like every problem, with the rod forces as reactions, and each reaction
derived a second time as a multiplier of a maximal-coordinate model (``cartesian=True``, the
default).

Sign convention (absolute angles from the downward vertical, counter-clockwise positive)::

        O (pivot)          y
        |\                 ^
        | \ theta_1        |
        |  \ l_1           +--> x        gravity -g y
            m_1
             \ theta_2 (from the vertical, not from link 1)
              \ l_2
               m_2 ...

Frames: ``L_i = O.child(rot_z(theta_i))``; link ``i`` points along ``-j_{L_i}``, so mass
``i`` sits at ``r_i = sum_{j <= i} -l_j j_{L_j}``.

Point masses, direct form: rod ``i`` pulls mass ``i`` with ``T_i j_{L_i}`` (towards the
joint above) and mass ``i-1`` with ``-T_i j_{L_i}``; ``m_i a_i = forces`` on ``x`` and ``y``:
``2n`` equations for ``n`` accelerations and ``n`` tensions.

Lagrange, written by hand (no frames)::

    x_i' = sum_{j<=i} l_j theta_j' cos(theta_j),  y_i' = sum_{j<=i} l_j theta_j' sin(theta_j)
    T = sum_i m_i (x_i'^2 + y_i'^2) / 2,   V = -g sum_i m_i sum_{j<=i} l_j cos(theta_j)

The tensions once more (``cartesian=True``): each mass free in the plane, ``(x_i, y_i)``, held by
the constraints ``(l_i^2 - (x_i - x_{i-1})^2 - (y_i - y_{i-1})^2) / (2 l_i) = 0``, whose
gradient on the constraint is the unit vector from mass ``i`` towards the joint above, the
direction of the rod's pull: the multiplier is the tension.

Uniform rods (``NLinkRigidPendulum``): rod ``i`` of mass ``m_i`` and length ``l_i``, centre at
the middle, ``I_i = m_i l_i^2 / 12``; joint ``i`` (top of rod ``i``) carries the force
``(X_i, Y_i)`` on rod ``i`` and its opposite on rod ``i-1``.  Direct form: ``sum F = m a_C``
(x, y) and Euler's equation about the centre for each rod, ``3n`` equations for ``n``
accelerations and ``2n`` joint forces.  Lagrange: ``T = sum (m_i v_Ci^2 + I_i theta_i'^2)/2``
written by hand.

The joint forces once more (``cartesian=True``, model ``multiplier``): each rod free in the
plane, its centre at ``(xc_i, yc_i)`` and its angle ``theta_i``, the joints closed again by
constraints.  Rod ``i``'s top and bottom are ``(xc_i, yc_i) -/+ (l_i/2)(sin theta_i,
-cos theta_i)``; joint ``i`` puts the top of rod ``i`` on the bottom of rod ``i-1`` (on O for
``i = 1``)::

    g_Xi = xc_i - (l_i/2) sin theta_i - xc_{i-1} - (l_{i-1}/2) sin theta_{i-1} = 0
    g_Yi = yc_i + (l_i/2) cos theta_i - yc_{i-1} + (l_{i-1}/2) cos theta_{i-1} = 0
    T = sum (m_i (xc_i'^2 + yc_i'^2) + (m_i l_i^2/12) theta_i'^2)/2,   V = g sum m_i yc_i

``X_i`` on rod ``i`` at its top and ``-X_i`` on rod ``i-1`` at its bottom do the virtual work
``X_i dg_Xi``: the multipliers of ``g_Xi``, ``g_Yi`` are the joint forces ``X_i``, ``Y_i`` of the
direct form, sign and all.  Lagrange's equations are then each rod's free body::

    xc_i:     m_i xc_i''  = X_i - X_{i+1}
    yc_i:     m_i yc_i''  = -m_i g + Y_i - Y_{i+1}
    theta_i:  I_i theta_i'' = -(l_i/2) ((X_i + X_{i+1}) cos theta_i + (Y_i + Y_{i+1}) sin theta_i)

(``X_{n+1} = Y_{n+1} = 0``): ``5n`` equations with the constraints' acceleration level, for
``3n`` accelerations and ``2n`` forces.  Mapped back (``xc_i = sum_{j<i} l_j sin theta_j +
(l_i/2) sin theta_i``, likewise ``yc_i``), every joint force is derived twice.
"""
from __future__ import annotations

import sympy as sp

from dualmech import (Coordinate, EquationSet, FidelityRung, Frame, Lagrangian, NewtonEuler,
                      Parameter, Particle, Point, Problem, Reaction, RigidBody, coordinate, rate,
                      rot_z, thin_rod, ACCELERATION, ANGLE, FORCE, LENGTH, MASS)

__all__ = ["NLinkPendulum", "NLinkRigidPendulum", "PROBLEMS"]

g = sp.Symbol("g", positive=True)


def _check_n(n) -> int:
    if isinstance(n, bool) or not isinstance(n, int) or n < 1:
        raise ValueError(f"`n` must be a positive integer (the number of links), got {n!r}.")
    if n > 60:
        raise ValueError(f"`n` = {n} is more links than this problem supports (at most 60).")
    return n


class _Chain(Problem):
    """Shared declarations of the two chains (parameters, coordinates, frames)."""

    parametric = "n"
    source = "dualmech: parametric scaling problem (after 002's compound double pendulum)"
    reference = "lagrange"
    # both chains' fidelity ladder, three links each (the classes are defined below)
    fidelity_ladder = (
        FidelityRung("point masses on massless rods", lambda: NLinkPendulum(n=3),
                     "the rods' mass distribution (each rod's mass lumped at its lower end)"),
        FidelityRung("uniform rigid rods", lambda: NLinkRigidPendulum(n=3)),
    )

    def __init__(self, n: int = 3, cartesian: bool = True):
        self.n = _check_n(n)
        self.cartesian = bool(cartesian)
        self.m = sp.symbols(f"m1:{n + 1}", positive=True)
        self.l = sp.symbols(f"l1:{n + 1}", positive=True)
        self.q = tuple(coordinate(f"theta{i + 1}") for i in range(n))
        self.parameters = tuple(
            Parameter(s, MASS, 1.0 + 0.1 * i, (0.1, 10.0), f"mass {i + 1}")
            for i, s in enumerate(self.m)) + tuple(
            Parameter(s, LENGTH, 0.5 + 0.05 * i, (0.1, 2.0), f"length of link {i + 1}")
            for i, s in enumerate(self.l)) + (
            Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),)
        self.coordinates = tuple(
            Coordinate(q, ANGLE, (-1.0, 1.0), (-2.0, 2.0), f"link {i + 1} from the vertical")
            for i, q in enumerate(self.q))

    def _frames(self):
        O = Frame.ground("O")
        links = [O.child(f"L{i + 1}", rot_z(q)) for i, q in enumerate(self.q)]
        joints = [Point.origin(O, "O")]
        for i, L in enumerate(links):
            joints.append(joints[-1].locate(f"J{i + 1}", -self.l[i] * L.y))
        return O, links, joints


class NLinkPendulum(_Chain):
    """A planar chain of ``n`` point masses on massless rods (see the module docstring)."""

    name = "n_link_pendulum"
    title = "Planar n-link pendulum of point masses"
    source = "dualmech: parametric scaling problem (after 002's compound double pendulum)"
    parametric = "n"
    summary = ("A chain of n point masses on massless rods: n angles, the n rod tensions from "
               "the direct form and again as multipliers of the Cartesian form.")

    def __init__(self, n: int = 3, cartesian: bool = True):
        super().__init__(n, cartesian)
        self.reactions = tuple(Reaction(f"T{i + 1}", FORCE, f"rod {i + 1} on mass {i + 1}, "
                                        "towards the joint above") for i in range(n))
        self.extra_models = ("multiplier",) if cartesian else ()
        if cartesian:
            self.x = tuple(coordinate(f"x{i + 1}") for i in range(n))
            self.y = tuple(coordinate(f"y{i + 1}") for i in range(n))
            self.extra_coordinates = tuple(
                Coordinate(c, LENGTH, (-3.0, 3.0), (-3.0, 3.0), f"{c.func.__name__} of mass")
                for c in self.x + self.y)

    def coordinate_maps(self) -> dict:
        if not self.cartesian:
            return {}
        rules, X, Y = {}, 0, 0
        for i, q in enumerate(self.q):
            X, Y = X + self.l[i] * sp.sin(q), Y - self.l[i] * sp.cos(q)
            rules[self.x[i]], rules[self.y[i]] = X, Y
        return {"multiplier": rules}

    def newton_euler(self) -> EquationSet:
        O, links, joints = self._frames()
        ne = NewtonEuler(coordinates=list(self.q), ground=O,
                         description="m_i a_i = rod forces + weight, on x and y")
        bodies = [Particle(f"mass {i + 1}", self.m[i], joints[i + 1]) for i in range(self.n)]
        ne.gravity(-g * O.y)
        for i, body in enumerate(bodies):
            ne.reaction(f"T{i + 1}", body, links[i].y,
                        against=bodies[i - 1] if i else None)
        for body in bodies:
            ne.linear_momentum(body, O.x)
            ne.linear_momentum(body, O.y)
        return ne.equations()

    def lagrange(self) -> EquationSet:
        lg = Lagrangian(coordinates=list(self.q), description="T and V of the chain by hand")
        vx = vy = height = 0
        for i, q in enumerate(self.q):
            vx += self.l[i] * rate(q) * sp.cos(q)
            vy += self.l[i] * rate(q) * sp.sin(q)
            height -= self.l[i] * sp.cos(q)
            lg.kinetic(f"T of mass {i + 1}", self.m[i] * (vx**2 + vy**2) / 2)
            lg.potential(f"gravity on mass {i + 1}", self.m[i] * g * height)
        return lg.equations()

    def multiplier(self) -> EquationSet:
        coords = list(self.x) + list(self.y)
        lg = Lagrangian("multiplier", coordinates=coords,
                        description="free masses in the plane, held by the rods as multipliers")
        px = py = 0
        for i in range(self.n):
            x, y = self.x[i], self.y[i]
            lg.kinetic(f"T of mass {i + 1}", self.m[i] * (rate(x)**2 + rate(y)**2) / 2)
            lg.potential(f"gravity on mass {i + 1}", self.m[i] * g * y)
            lg.constraint(f"T{i + 1}", (self.l[i]**2 - (x - px)**2 - (y - py)**2)
                          / (2 * self.l[i]))
            px, py = x, y
        return lg.equations()


class NLinkRigidPendulum(_Chain):
    """A planar chain of ``n`` uniform rods joined by pins (see the module docstring)."""

    name = "n_link_rigid_pendulum"
    title = "Planar n-link pendulum of uniform rods"
    source = "dualmech: parametric scaling problem (after 002's compound double pendulum)"
    parametric = "n"
    summary = ("A chain of n uniform rods: Newton-Euler with the joint forces per rod, against "
               "the Lagrangian written by hand; the joint forces again as multipliers of the "
               "rods freed in the plane.")

    def __init__(self, n: int = 3, cartesian: bool = True):
        super().__init__(n, cartesian)
        self.reactions = tuple(
            Reaction(f"{a}{i + 1}", FORCE, f"joint {i + 1} on rod {i + 1}, along {a.lower()}")
            for i in range(n) for a in "XY")
        self.extra_models = ("multiplier",) if cartesian else ()
        if cartesian:
            self.xc = tuple(coordinate(f"xc{i + 1}") for i in range(n))
            self.yc = tuple(coordinate(f"yc{i + 1}") for i in range(n))
            self.extra_coordinates = tuple(
                Coordinate(c, LENGTH, (-3.0, 3.0), (-3.0, 3.0),
                           f"{c.func.__name__[:2]} of the centre of rod {c.func.__name__[2:]}")
                for c in self.xc + self.yc)

    def coordinate_maps(self) -> dict:
        if not self.cartesian:
            return {}
        rules, X, Y = {}, 0, 0          # X, Y: the joint above rod i
        for i, q in enumerate(self.q):
            half = self.l[i] / 2
            rules[q] = q
            rules[self.xc[i]], rules[self.yc[i]] = X + half * sp.sin(q), Y - half * sp.cos(q)
            X, Y = X + self.l[i] * sp.sin(q), Y - self.l[i] * sp.cos(q)
        return {"multiplier": rules}

    def newton_euler(self) -> EquationSet:
        O, links, joints = self._frames()
        ne = NewtonEuler(coordinates=list(self.q), ground=O,
                         description="sum F = m a_C and Euler's equation about C, per rod")
        rods = []
        for i, L in enumerate(links):
            centre = joints[i].locate(f"C{i + 1}", -self.l[i] / 2 * L.y)
            rods.append(RigidBody(f"rod {i + 1}", self.m[i], centre, L,
                                  thin_rod(self.m[i], self.l[i], axis="y")))
        ne.gravity(-g * O.y)
        for i, rod in enumerate(rods):
            ne.reaction(f"X{i + 1}", rod, O.x, at=joints[i],
                        against=rods[i - 1] if i else None, against_at=joints[i])
            ne.reaction(f"Y{i + 1}", rod, O.y, at=joints[i],
                        against=rods[i - 1] if i else None, against_at=joints[i])
        for rod in rods:
            ne.linear_momentum(rod, O.x)
            ne.linear_momentum(rod, O.y)
            ne.angular_momentum(rod, O.z)
        return ne.equations()

    def lagrange(self) -> EquationSet:
        lg = Lagrangian(coordinates=list(self.q), description="T and V of the rods by hand")
        vx = vy = height = 0          # of the joint above rod i
        for i, q in enumerate(self.q):
            l, m = self.l[i], self.m[i]
            cx = vx + l / 2 * rate(q) * sp.cos(q)
            cy = vy + l / 2 * rate(q) * sp.sin(q)
            lg.kinetic(f"T of rod {i + 1}", m * (cx**2 + cy**2) / 2
                       + m * l**2 / 12 * rate(q)**2 / 2)
            lg.potential(f"gravity on rod {i + 1}", m * g * (height - l / 2 * sp.cos(q)))
            vx += l * rate(q) * sp.cos(q)
            vy += l * rate(q) * sp.sin(q)
            height -= l * sp.cos(q)
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """Each rod free in the plane; the joints closed by the multipliers ``X_i``, ``Y_i``."""
        coords = [c for i in range(self.n) for c in (self.xc[i], self.yc[i], self.q[i])]
        lg = Lagrangian("multiplier", coordinates=coords,
                        description="rods free in the plane, joined by multipliers X_i, Y_i")
        bottom = (0, 0)                 # of the rod above (O for the first)
        for i, q in enumerate(self.q):
            x, y, l, m = self.xc[i], self.yc[i], self.l[i], self.m[i]
            lg.kinetic(f"T of rod {i + 1}", m * (rate(x)**2 + rate(y)**2) / 2
                       + m * l**2 / 12 * rate(q)**2 / 2)
            lg.potential(f"gravity on rod {i + 1}", m * g * y)
            top = (x - l / 2 * sp.sin(q), y + l / 2 * sp.cos(q))
            lg.constraint(f"X{i + 1}", top[0] - bottom[0])
            lg.constraint(f"Y{i + 1}", top[1] - bottom[1])
            bottom = (x + l / 2 * sp.sin(q), y - l / 2 * sp.cos(q))
        return lg.equations()


PROBLEMS = (NLinkPendulum, NLinkRigidPendulum)
