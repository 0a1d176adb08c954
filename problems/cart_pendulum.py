"""Example 17: a pendulum on a spring-restrained cart, torsional spring and dashpot, driven bob.

Source: ``sources/000_203248afac9714e6.txt``, "Example 17: Pair-Share: Mass Pendulum Dynamic
System" (its solution slide is headed "Example 16").

Geometry (the source's figure is missing; this is the one used here)
--------------------------------------------------------------------
::

      wall
      |/|        k         +--------------------+
      |/|---/\\/\\/\\/\\-------|       cart m       |    x: cart position, spring unstretched
      |/|                  |                    |       at x = 0
      |/|------[ c --------|         P          |    P: pivot; the torsional spring k_t
      |/|                  +--o------:\\------o--+       (undeformed at theta = 0) and the
      |/|   ===bed (slotted)=============\\==========      torsional dashpot c_t act here
                                     : \\   l  (massless rod P--B)
                                     :th\\
                                     :   o B   bob m0  ---> F0 sin(w t) i  (always horizontal)

      j                 e_r  = -R.y = (sin th, -cos th)    from P to B
      ^                 e_th =  R.x = (cos th,  sin th)    direction of increasing theta
      +--> i            gravity -g j

``theta`` is measured from the downward vertical, counterclockwise about ``k`` (positive when
the bob swings toward ``+i``).  The cart rides on the bed (normal force ``N``) and stays on it.

Frames.  ``O`` inertial (``i`` right, ``j`` up, ``k = i x j`` out of the page), origin at the
pivot's position when ``x = 0``.  The rod frame ``R = O`` rotated by ``theta`` about ``k``:
``R.x = e_th = (cos th, sin th)``, ``R.y = (-sin th, cos th)`` points from the bob to the
pivot, so ``e_r = -R.y = (sin th, -cos th)``.

Bodies.  The cart translates: a particle ``m`` at ``P = x i``.  The bob is a point mass: a
particle ``m0`` at ``B = P + l e_r``.  The rod is massless; it is kept as a body only because
it carries loads, and its balances say that the loads on it sum to zero.

Free-body diagrams (Newton--Euler)::

      bob m0:   -m0 g j,   F0 sin(wt) i,   T R.y (rod tension),   S R.x (rod, transverse)
      rod:      -T R.y - S R.x at B (bob on rod),   T R.y + S R.x at P (cart on rod),
                torsional spring -k_t th k,  torsional dashpot -c_t th' k
      cart m:   -m g j,  N j (bed),  -k x i,  -c x' i,  -T R.y - S R.x at P (rod on cart),
                +(k_t th + c_t th') k  (reacted by the distribution of N; the cart is a particle)

The rod's force balance (massless: ``sum F = 0``) has been used in drawing it: the pivot force
on the rod is the opposite of the bob's, so the cart receives the bob's pull unchanged and no
new unknown appears.  The rod's moments about P must also sum to zero:
``l e_r x (-S e_th) - (k_t th + c_t th') k = 0``, so ``S = -(k_t th + c_t th')/l``.  The
torsional elements reach the bob as a *transverse* force through the rod -- the rod is not a
two-force member.  With ``F = F0 sin(wt)`` and ``a_B = x'' i + l th'' e_th - l th'^2 e_r``::

      bob . e_th:  m0 (x'' cos th + l th'') = -m0 g sin th + F cos th + S
      bob . e_r :  m0 (x'' sin th - l th'^2) = m0 g cos th + F sin th - T
      cart . i  :  m x'' = -k x - c x' + T sin th - S cos th
      cart . j  :  0 = N - m g - T cos th - S sin th
      rod, tau_P . k:  -S l - k_t th - c_t th' = 0

Reactions solved by hand (``x''``, ``th''`` the true accelerations)::

      S  = -(k_t th + c_t th') / l
      T  = m0 g cos th + F sin th + m0 l th'^2 - m0 x'' sin th
      N  = m g + T cos th + S sin th
         = (m + m0) g + m0 l (th'' sin th + th'^2 cos th)      (whole system along j)

Lagrangian (written independently)::

      T = m x'^2/2 + m0 (x'^2 + l^2 th'^2 + 2 x' l th' cos th)/2
      V = k x^2/2 + k_t th^2/2 + m0 g l (1 - cos th)
      R = c x'^2/2 + c_t th'^2/2
      Q = F (dx_B/dx, dx_B/dth) = (F0 sin wt, F0 sin wt l cos th)      (x_B = x + l sin th)

      (m + m0) x'' + c x' + k x + m0 l (th'' cos th - th'^2 sin th) = F0 sin wt
      m0 l^2 th'' + c_t th' + k_t th + m0 g l sin th + m0 l x'' cos th = F0 sin wt l cos th

(the second is ``l`` times the bob's ``e_th`` balance with ``S`` put in).

Lagrange with multipliers (the reactions, independently of the free-body diagrams).  Free
the three contacts: the cart may lift off the bed (height ``y``), the bob may slide along the
rod (distance ``r`` from P) and turn about P apart from the rod (angle ``phi``; the rod keeps
``theta`` and the torsional elements).  With ``B = P + r (sin phi, -cos phi)``, ``P = (x, y)``::

      T = m (x'^2 + y'^2)/2 + m0 |B'|^2/2          (the rod is massless: no theta' in T)
      V = k x^2/2 + k_t th^2/2 + m g y + m0 g (y - r cos phi),   R as above
      Q_j = F i . dB/dq_j
      constraints  y = 0 (multiplier N),  l - r = 0 (multiplier T),  l (phi - th) = 0 (S)

Virtual work: ``N j`` on the cart does ``N delta y``; the tension ``-T e_r`` on the bob does
``-T delta r``; the transverse pair (``S e_phi`` on the bob at distance ``l``, ``-S e_th`` on
the rod) does ``S l (delta phi - delta th)``.  Those are the constraint gradients times the
multipliers, so the multipliers are ``N``, ``T``, ``S``; the ``theta`` equation reads
``k_t th + c_t th' = -S l``, the rod's moment balance again.

Errata
------
The printed second equation begins ``m0 l th''``: every other term is a torque
(``M L^2 T^-2``), that one a force.  It must be ``m0 l^2 th''``.  The dimension audit flags it.
Everything else printed (``Q1``, ``Q2``, ``U``, ``T_pendulum``, the ``x`` equation) is right.

Example
-------
>>> p = CartPendulum(); p.validate()
>>> sp.factor(sp.trigsimp(p.model("lagrange").mass_matrix().det()))
l**2*m0*(m + m0*sin(theta(t))**2)
"""
from __future__ import annotations

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Published, Reaction, RigidBody, coordinate, rate, rot_z, t,
                      ACCELERATION, ANGLE, DAMPING, FORCE, FREQUENCY, LENGTH, MASS, STIFFNESS,
                      TORSIONAL_DAMPING, TORSIONAL_STIFFNESS)

__all__ = ["CartPendulum", "PROBLEMS", "direct_form", "hand_reactions"]

m, m0, l, k, c, k_t, c_t, g, F0, omega = sp.symbols("m m0 l k c k_t c_t g F0 omega",
                                                     positive=True)
x, theta = coordinate("x"), coordinate("theta")
y, r, phi = coordinate("y"), coordinate("r"), coordinate("phi")

drive = F0 * sp.sin(omega * t)


def hand_reactions(xdd, thdd) -> dict:
    """Reactions solved by hand, given the true accelerations ``xdd``, ``thdd`` (see above)."""
    th, thd = theta, rate(theta)
    S = -(k_t * th + c_t * thd) / l
    T = m0 * g * sp.cos(th) + drive * sp.sin(th) + m0 * l * thd**2 - m0 * xdd * sp.sin(th)
    N = (m + m0) * g + m0 * l * (thdd * sp.sin(th) + thd**2 * sp.cos(th))
    return {"N": N, "T": T, "S": S}


class _Scene:
    """Frames, points and bodies of the direct form (also used for published references)."""

    def __init__(self):
        self.O = Frame.ground("O")
        self.R = self.O.child("R", rot_z(theta))
        self.P = Point.origin(self.O).locate("P", x * self.O.x)
        self.B = self.P.locate("B", -l * self.R.y)
        self.cart = Particle("cart", m, self.P)
        self.bob = Particle("bob", m0, self.B)
        self.rod = RigidBody("rod", sp.Integer(0), self.P.locate("G", -l / 2 * self.R.y),
                             self.R, sp.zeros(3, 3))


def direct_form() -> tuple[NewtonEuler, _Scene]:
    """The free-body diagrams of cart, bob and rod, before any balance is written."""
    sc = _Scene()
    O, R = sc.O, sc.R
    ne = NewtonEuler("newton_euler", coordinates=[x, theta], ground=O)
    ne.gravity(-g * O.y)
    ne.reaction("N", sc.cart, O.y)
    ne.linear_spring("spring", sc.cart, k, x, O.x)
    ne.linear_damper("dashpot", sc.cart, c, rate(x), O.x)
    ne.force("drive", sc.bob, drive * O.x)
    for name, direction in (("T", R.y), ("S", R.x)):
        f = ne.reaction(name, sc.bob, direction, against=sc.rod, against_at=sc.B) * direction
        # massless rod, sum F = 0: the cart's pull at P is the opposite of the bob's at B
        ne.force(f"reaction {name}", sc.rod, f, at=sc.P)
        ne.force(f"reaction {name}", sc.cart, -f, at=sc.P)
    ne.torsional_spring("torsional spring", sc.rod, k_t, theta, O.z, against=sc.cart)
    ne.torsional_damper("torsional dashpot", sc.rod, c_t, rate(theta), O.z, against=sc.cart)
    return ne, sc


class CartPendulum(Problem):
    """Cart on a spring and dashpot carrying a pendulum with torsional spring and dashpot."""

    name = "cart_pendulum"
    title = "Pendulum on a cart with torsional spring and dashpot, driven bob"
    source = "000_203248afac9714e6.txt: Example 17"
    summary = ("The massless rod carries the torsional elements' torque to the bob as a "
               "transverse force; the printed theta equation lacks a factor l.")
    parameters = (
        Parameter(m, MASS, 2.0, (0.5, 10.0), "mass of the cart"),
        Parameter(m0, MASS, 0.5, (0.1, 5.0), "mass of the bob"),
        Parameter(l, LENGTH, 0.8, (0.2, 2.0), "length of the rod"),
        Parameter(k, STIFFNESS, 100.0, (10.0, 1000.0), "cart spring constant"),
        Parameter(c, DAMPING, 2.0, (0.1, 20.0), "cart dashpot constant"),
        Parameter(k_t, TORSIONAL_STIFFNESS, 5.0, (0.5, 50.0), "torsional spring constant"),
        Parameter(c_t, TORSIONAL_DAMPING, 0.3, (0.01, 5.0), "torsional dashpot constant"),
        Parameter(g, ACCELERATION, 9.81, (9.0, 10.0), "gravitational acceleration"),
        Parameter(F0, FORCE, 3.0, (0.1, 20.0), "amplitude of the horizontal force on the bob"),
        Parameter(omega, FREQUENCY, 4.0, (0.5, 20.0), "frequency of the force on the bob"),
    )
    coordinates = (
        Coordinate(x, LENGTH, (-0.4, 0.5), (-1.5, 2.0), "cart position"),
        Coordinate(theta, ANGLE, (-1.2, 1.3), (-3.0, 2.5), "rod angle from the downward vertical"),
    )
    extra_coordinates = (
        Coordinate(y, LENGTH, (-0.05, 0.05), (-0.2, 0.2), "height of the cart off the bed"),
        Coordinate(r, LENGTH, (0.2, 2.0), (-0.2, 0.2), "distance of the bob from the pivot"),
        Coordinate(phi, ANGLE, (-1.2, 1.3), (-3.0, 2.5), "angle of P->B from the vertical"),
    )
    extra_models = ("lagrange_multipliers",)
    reactions = (
        Reaction("N", FORCE, "bed on cart, along j"),
        Reaction("T", FORCE, "rod tension on the bob, along R.y (toward the pivot)"),
        Reaction("S", FORCE, "rod on the bob, transverse, along R.x = e_theta"),
    )
    unilateral = {"N": "the cart lifts off its bed"}

    def newton_euler(self) -> EquationSet:
        """Cart and bob along two directions each; the massless rod's moments about the pivot."""
        ne, sc = direct_form()
        O, R = sc.O, sc.R
        ne.linear_momentum(sc.cart, O.x)
        ne.linear_momentum(sc.cart, O.y)
        ne.linear_momentum(sc.bob, R.x)
        ne.linear_momentum(sc.bob, R.y)
        ne.angular_momentum(sc.rod, O.z, about=sc.P)
        return ne.equations()

    def lagrange(self) -> EquationSet:
        """``T``, ``V``, ``R`` and the virtual work of the drive, as the source writes them."""
        lg = Lagrangian("lagrange", coordinates=[x, theta])
        lg.kinetic("T of cart", m * rate(x)**2 / 2)
        # the source's expanded form (sin^2 + cos^2 = 1 already used)
        lg.kinetic("T of bob", m0 * (rate(x)**2 + (l * rate(theta))**2
                                     + 2 * rate(x) * l * rate(theta) * sp.cos(theta)) / 2)
        lg.potential("spring", k * x**2 / 2)
        lg.potential("torsional spring", k_t * theta**2 / 2)
        lg.potential("gravity", m0 * g * l * (1 - sp.cos(theta)))
        lg.dissipation("dashpot", c * rate(x)**2 / 2)
        lg.dissipation("torsional dashpot", c_t * rate(theta)**2 / 2)
        bob = sp.Matrix([x + l * sp.sin(theta), -l * sp.cos(theta)])  # from the pivot's x = 0
        force = sp.Matrix([drive, 0])
        lg.generalized_force("drive", [force.dot(bob.diff(q)) for q in (x, theta)])
        return lg.equations()

    def lagrange_multipliers(self) -> EquationSet:
        """Contacts freed (``y``, ``r``, ``phi``) and closed again by the multipliers N, T, S."""
        lg = Lagrangian("lagrange_multipliers", coordinates=[x, theta, y, r, phi])
        bob = sp.Matrix([x + r * sp.sin(phi), y - r * sp.cos(phi)])
        lg.kinetic("T of cart", m * (rate(x)**2 + rate(y)**2) / 2)
        lg.kinetic("T of bob", m0 * (rate(bob).T * rate(bob))[0, 0] / 2)
        lg.potential("spring", k * x**2 / 2)
        lg.potential("torsional spring", k_t * theta**2 / 2)
        lg.potential("gravity", m * g * y + m0 * g * bob[1])
        lg.dissipation("dashpot", c * rate(x)**2 / 2)
        lg.dissipation("torsional dashpot", c_t * rate(theta)**2 / 2)
        force = sp.Matrix([drive, 0])
        lg.generalized_force("drive", [force.dot(bob.diff(q)) for q in lg.coordinates])
        lg.constraint("N", y)
        lg.constraint("T", l - r)
        lg.constraint("S", l * (phi - theta))
        return lg.equations()

    def coordinate_maps(self) -> dict:
        return {"lagrange_multipliers": {x: x, theta: theta, y: 0, r: l, phi: theta}}

    def published(self) -> list[Published]:
        sc = _Scene()
        vB = sc.B.vel(sc.O)
        F = drive * sc.O.x
        Q = tuple(F.dot(vB.diff(q.diff(t), sc.O)) for q in (x, theta))
        height = sc.B.pos_from().dot(sc.O.y) + l  # of the bob, above its lowest position
        V = k * x**2 / 2 + k_t * theta**2 / 2 + m0 * g * height
        s, co = sp.sin(theta), sp.cos(theta)
        where = "Example 17 (solution slide headed 'Example 16')"
        return [
            # Right: partial velocities of B are i and l e_th; F . e_th = F cos th.
            Published("Q1, Q2", "expression", (drive, drive * l * co), Q, where=where),
            # Right: the bob rises l (1 - cos th) above its lowest point.
            Published("U", "expression",
                      (k * x**2 / 2 + k_t * theta**2 / 2 + m0 * g * l * (1 - co),), (V,),
                      where=where),
            # Right: v_B = (x' + l th' cos th) i + l th' sin th j.
            Published("T_pendulum", "expression",
                      (m0 * ((rate(x) + l * rate(theta) * co)**2 + (l * rate(theta) * s)**2) / 2,),
                      (sc.bob.kinetic_energy(sc.O),), where=where),
            # Right: the expanded form of the same.
            Published("T_pendulum (expanded)", "expression",
                      (m0 * (rate(x)**2 + (l * rate(theta))**2 + 2 * rate(x) * l * rate(theta) * co) / 2,),
                      (sc.bob.kinetic_energy(sc.O),), where=where),
            # Right: d/dt dT/dx' = (m + m0) x'' + m0 l (th'' cos th - th'^2 sin th).
            Published("equation of motion, x", "equation",
                      ((m + m0) * rate(x, 2) + c * rate(x) + k * x
                       + m0 * l * (rate(theta, 2) * co - rate(theta)**2 * s) - drive,), where=where),
            # Wrong: m0 l th'' must be m0 l^2 th'' (a force among torques; see the errata).
            Published("equation of motion, theta", "equation",
                      (m0 * l * rate(theta, 2) + c_t * rate(theta) + k_t * theta + m0 * g * l * s
                       + m0 * rate(x, 2) * l * co - drive * l * co,), where=where),
        ]


PROBLEMS = (CartPendulum,)
