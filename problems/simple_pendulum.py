r"""Simple pendulum, with the tension of its string (Cambridge 3C5, Lagrangian mechanics).

Source: ``sources/002_df41972c66c4514e.txt``, section 2.2, "Lagrange's Equation For a Simple
Pendulum", and section 3.1 (its generalised momentum is the angular momentum).

Sign convention (the figure is missing from the extraction; ``V = M g a (1 - cos theta)`` fixes
it)::

              O  pivot
              |\                 j (up), i (right), k = i x j out of the page
              | \                gravity -g j
              |  \   a           arm frame: arm.y points from the bob to the pivot,
              |th \                         arm.x = e_theta (direction of increasing theta)
              |    \
                    o  bob M     r_bob = -a arm.y = a (sin th, -cos th)

``theta`` is measured from the downward vertical, counterclockwise about ``k``.

Frames.  ``O`` inertial; ``arm = O`` rotated by ``theta`` about ``k`` (``rot_z(theta)``).

Body and free-body diagram.  A particle ``M`` at ``-a arm.y``; the string is massless.  Forces
on the bob: weight ``-M g j`` and the string's pull ``T arm.y`` (towards the pivot).  With
``a_bob = a theta'' arm.x + a theta'^2 arm.y``::

        arm.x:  M a theta''   = -M g sin theta
        arm.y:  M a theta'^2  = T - M g cos theta     =>   T = M (g cos theta + a theta'^2)

The pull passes through O, so the moment balance about O needs no reaction:
``d/dt (M a^2 theta') = -M g a sin theta`` (a second direct derivation, ``angular_momentum``).

Lagrangian (written independently)::

        T = M (a theta')^2 / 2,      V = M g a (1 - cos theta)
        M a^2 theta'' + M g a sin theta = 0;      small angles: M a^2 theta'' + M g a theta = 0

The tension once more, independently: free the bob from the string with its distance ``r``
from O (``r_bob = r (sin th, -cos th)``) and close it with the constraint ``a - r = 0``,
multiplier ``T``::

        T = M (r'^2 + r^2 theta'^2) / 2,     V = -M g r cos theta
        r:  M r'' - M r theta'^2 - M g cos theta + T = 0

(the pull ``T arm.y = -T e_r`` does virtual work ``-T dr``, which is ``T d(a - r)``), so on the
string ``T = M (g cos theta + a theta'^2)``, as the free-body diagram gives.

Reading the extraction.  ``T = M (a theta)^2/2`` and ``M a^2 theta + M g a sin theta = 0`` are
printed with their dots lost; the first line of Lagrange's equation reads
``d/dt [dT/dtheta]`` for ``d/dt [dT/dtheta']`` likewise.  Section 3.1's formula for the
pendulum's generalised momentum is missing from the extraction; only its statement in words
("the generalised momentum is equal to the angular momentum of the system") survives, and is
checked.  No errata.

Example
-------
>>> p = SimplePendulum(); p.validate()
>>> p.model("newton_euler").reactions_solved()
{T: M*(a*Derivative(theta(t), t)**2 + g*cos(theta(t)))}
"""
from __future__ import annotations

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Published, Reaction, coordinate, rate, rot_z, ACCELERATION,
                      ANGLE, FORCE, LENGTH, MASS)

__all__ = ["SimplePendulum", "PROBLEMS", "M", "a", "g", "theta", "r", "hand_tension"]

M, a, g = sp.symbols("M a g", positive=True)
theta = coordinate("theta")
r = coordinate("r")  # distance of the bob from the pivot, only in the multiplier model


def hand_tension() -> sp.Expr:
    """The string's pull on the bob, solved by hand: ``M (g cos theta + a theta'^2)``."""
    return M * (g * sp.cos(theta) + a * rate(theta)**2)


class _Scene:
    """Frames, points and the bob of the direct form (also used for published references)."""

    def __init__(self):
        self.O = Frame.ground("O")
        self.arm = self.O.child("arm", rot_z(theta))
        self.o = Point.origin(self.O, "pivot")
        self.B = self.o.locate("bob", -a * self.arm.y)
        self.bob = Particle("bob", M, self.B)


class SimplePendulum(Problem):
    """Bob ``M`` on a massless string of length ``a`` (see module doc)."""

    name = "simple_pendulum"
    aliases = {"l": "a", "m": "M"}   # the string's length and the bob's mass as taught
    title = "Simple pendulum"
    source = "002_df41972c66c4514e.txt: section 2.2, Lagrange's equation for a simple pendulum"
    summary = ("One angle; the string's tension from the free-body diagram and again as the "
               "multiplier of the constraint a - r = 0.")
    parameters = (
        Parameter(M, MASS, 1.0, (0.1, 10.0), "mass of the bob"),
        Parameter(a, LENGTH, 0.8, (0.1, 3.0), "length of the string"),
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
    )
    coordinates = (
        Coordinate(theta, ANGLE, (-2.5, 2.5), (-4.0, 4.0),
                   "angle of the string from the downward vertical"),
    )
    extra_coordinates = (
        Coordinate(r, LENGTH, (0.1, 3.0), (-1.0, 1.0), "distance of the bob from the pivot"),
    )
    reactions = (Reaction("T", FORCE, "string on bob, along arm.y (towards the pivot)"),)
    extra_models = ("angular_momentum", "multiplier")
    unilateral = {"T": "the string goes slack"}

    def coordinate_maps(self) -> dict:
        return {"multiplier": {theta: theta, r: a}}

    def newton_euler(self) -> EquationSet:
        """``sum F = M a`` on the bob along ``arm.x`` and ``arm.y``."""
        sc = _Scene()
        ne = NewtonEuler("newton_euler", coordinates=[theta], ground=sc.O,
                         description="sum F = M a on the bob, along e_theta and the string")
        ne.gravity(-g * sc.O.y)
        ne.reaction("T", sc.bob, sc.arm.y)
        ne.linear_momentum(sc.bob, sc.arm.x)
        ne.linear_momentum(sc.bob, sc.arm.y)
        return ne.equations()

    def angular_momentum(self) -> EquationSet:
        """``sum tau_O = d/dt h_O`` about the pivot, along ``k``; the pull passes through O."""
        sc = _Scene()
        ne = NewtonEuler("angular_momentum", coordinates=[theta], ground=sc.O,
                         description="moments about the pivot O, along k")
        ne.gravity(-g * sc.O.y)
        ne.angular_momentum(sc.bob, sc.O.z, about=sc.o)
        return ne.equations()

    def lagrange(self) -> EquationSet:
        """``T = M (a theta')^2/2``, ``V = M g a (1 - cos theta)``, as the source writes them."""
        lg = Lagrangian("lagrange", coordinates=[theta], description="T and V by hand")
        lg.kinetic("T of bob", M * (a * rate(theta))**2 / 2)
        lg.potential("gravity", M * g * a * (1 - sp.cos(theta)))
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """Lagrange in ``(theta, r)`` with the string as the constraint ``a - r = 0``."""
        lg = Lagrangian("multiplier", coordinates=[theta, r],
                        description="the bob freed from the string, held by a multiplier")
        lg.kinetic("T of bob", M * (rate(r)**2 + r**2 * rate(theta)**2) / 2)
        lg.potential("gravity", -M * g * r * sp.cos(theta))
        lg.constraint("T", a - r)
        return lg.equations()

    def published(self) -> list[Published]:
        sc = _Scene()
        height = sc.B.pos_from(sc.o).dot(sc.O.y) + a   # above the lowest position
        Mlin, _, Klin = self.model("angular_momentum").linearize()
        where = "section 2.2, simple pendulum"
        return [
            # Right: the bob moves on a circle of radius a, |v| = a theta'.
            Published("T", "expression", (M * (a * rate(theta))**2 / 2,),
                      (sc.bob.kinetic_energy(sc.O),), where=where),
            # Right: the bob is a (1 - cos theta) above its lowest point.
            Published("V", "expression", (M * g * a * (1 - sp.cos(theta)),), (M * g * height,),
                      where=where),
            # Right.
            Published("equation of motion", "motion",
                      (M * a**2 * rate(theta, 2) + M * g * a * sp.sin(theta),), where=where),
            # Right: the moment balance about O linearised at theta = 0; it reads
            # tau - dh/dt = 0, Lagrange's equation dh/dt - tau = 0, hence the signs.
            Published("small angles: coefficients of theta'', theta", "expression",
                      (M * a**2, M * g * a), (-Mlin[0, 0], -Klin[0, 0]),
                      where=where + ": M a^2 theta'' + M g a theta = 0"),
            # Right: h_O . k = M a^2 theta' = dT/dtheta'.
            Published("generalised momentum is the angular momentum", "expression",
                      (sc.bob.angular_momentum(sc.o, sc.O).dot(sc.O.z),),
                      (sp.diff(M * (a * rate(theta))**2 / 2, rate(theta)),),
                      where="section 3.1, stated in words (the formula is missing from the "
                      "extraction): dT/dtheta' equals the angular momentum about the pivot"),
        ]


PROBLEMS = (SimplePendulum,)
