r"""Satellite in polar coordinates under central gravity; angular momentum and circular orbits.

Source: ``sources/002_df41972c66c4514e.txt``, Cambridge 3C5 notes, handwritten examples at the
end ("3 Satellite"; listed at the start as "Particle in polar coordinates").

A satellite of mass ``m`` moves in a plane about a fixed attracting centre O (gravitational
parameter ``mu = G M_earth``); polar coordinates ``r`` (distance from O) and ``theta`` (angle
from the fixed X axis)::

          Y
          |        e_theta
          |      ^
          |     /     o satellite m, at r e_r
          |    /   .
          |   / .  e_r
          |  /.
          | /  theta
          O ---------------- X        force on the satellite: -m mu / r^2 e_r

Frames: ``O`` ground; the polar frame ``E = O.child(rot_z(theta))`` with ``e_r = E.x``,
``e_theta = E.y``.  The satellite is the particle at ``r e_r``.

Free-body diagram: one force, the central attraction ``-m mu / r^2 e_r``.

Direct form, ``sum F = m a`` with ``a = (r'' - r theta'^2) e_r + (r theta'' + 2 r' theta')
e_theta`` (from the frames by the transport theorem)::

    e_r:      -m mu / r^2 = m (r'' - r theta'^2)
    e_theta:            0 = m (r theta'' + 2 r' theta')

Lagrangian, written independently::

    T = m (r'^2 + r^2 theta'^2) / 2,     V = -m mu / r
    r:      m r'' - m r theta'^2 + m mu / r^2 = 0
    theta:  d/dt (m r^2 theta') = 0

theta is ignorable (section 3.1: no generalised force, ``dV/dtheta = dT/dtheta = 0``), so the
angular momentum ``p_theta = m r^2 theta'`` is conserved; ``r`` times the direct form's
``e_theta`` equation is its rate.  Circular orbits (``r`` constant, every rate constant) need
``theta'^2 = mu / r^3`` -- computed from the verified equations by
:func:`dualmech.model.steady.steady_rates` -- so the period is ``2 pi sqrt(r^3 / mu)`` (Kepler's
third law).

Singular set: the mass matrix ``diag(m, m r^2)`` is singular at ``r = 0`` (the centre, where
theta is undefined).

Errata and unreadable formulas:

* The extraction prints ``T = 2/2 m (r^2 theta'^2 + r'^2)``; read as the handwritten
  ``1/2`` (the ``2/2`` reading would be ``m (...)``, twice the kinetic energy).  So read, it is
  right.
* The three "V = ..." lines of the extraction are copies of the T line, and the equations of
  motion after them ("IT is m So is dig da ...") cannot be read: the potential, the equations
  and any conservation statement of the source are not judged.
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Published, coordinate, rate, rot_z, ANGLE, LENGTH, MASS,
                      TIME)

__all__ = ["SatellitePolar", "PROBLEMS", "frames", "angular_momentum", "m", "mu", "r", "theta"]

m, mu = sp.symbols("m mu", positive=True)
r, theta = coordinate("r"), coordinate("theta")


def frames() -> SimpleNamespace:
    """Ground ``O``, polar frame ``E`` (``E.x = e_r``), the centre ``o`` and the satellite."""
    O = Frame.ground("O")
    E = O.child("E", rot_z(theta))
    o = Point.origin(O, "O")
    return SimpleNamespace(O=O, E=E, o=o, sat=o.locate("satellite", r * E.x))


def angular_momentum() -> sp.Expr:
    """``p_theta = dT/dtheta' = m r^2 theta'`` (by hand)."""
    return m * r**2 * rate(theta)


class SatellitePolar(Problem):
    """Satellite about a fixed attracting centre, in polar coordinates (see module doc)."""

    name = "satellite_polar"
    title = "Satellite in polar coordinates"
    source = "002_df41972c66c4514e.txt: handwritten examples, 3 Satellite"
    summary = ("Particle under an inverse-square central force in polar coordinates: "
               "conserved angular momentum, circular-orbit rate from the verified equations.")
    parameters = (
        Parameter(m, MASS, 50.0, (1.0, 1000.0), "mass of the satellite"),
        Parameter(mu, LENGTH**3 / TIME**2, 4.0, (0.5, 50.0),
                  "gravitational parameter G M of the attracting body"),
    )
    coordinates = (
        Coordinate(r, LENGTH, (0.5, 5.0), (-2.0, 2.0), "distance from the attracting centre"),
        Coordinate(theta, ANGLE, (-3.0, 3.0), (-3.0, 3.0), "polar angle from the X axis"),
    )
    reactions = ()
    singular = (r,)

    # -- direct form: sum F = m a in the polar frame ------------------------------------------
    def newton_euler(self) -> EquationSet:
        f = frames()
        sat = Particle("satellite", m, f.sat)
        ne = NewtonEuler(coordinates=[r, theta], ground=f.O,
                         description="sum F = m a on the satellite, projected on e_r, e_theta")
        ne.force("central gravity", sat, -m * mu / r**2 * f.E.x)
        for axis in (f.E.x, f.E.y):
            ne.linear_momentum(sat, axis)
        return ne.equations()

    # -- indirect form ---------------------------------------------------------------------
    def lagrange(self) -> EquationSet:
        """``T`` and ``V`` by hand (module docstring)."""
        lg = Lagrangian(coordinates=[r, theta], description="T = m(r'^2 + r^2 theta'^2)/2, "
                                                             "V = -m mu / r")
        lg.kinetic("T of satellite", m * (rate(r)**2 + r**2 * rate(theta)**2) / 2)
        lg.potential("gravity", -m * mu / r)
        return lg.equations()

    # -- the source's answers --------------------------------------------------------------
    def published(self) -> list[Published]:
        f = frames()
        sat = Particle("satellite", m, f.sat)
        return [
            Published("(3) kinetic energy", "expression",
                      (sp.Rational(1, 2) * m * (r**2 * rate(theta)**2 + rate(r)**2),),
                      (sat.kinetic_energy(f.O),),
                      where="examples, 3 Satellite: T = 1/2 m (r^2 theta'^2 + r'^2) (the "
                      "extraction shows 2/2)"),
        ]


PROBLEMS = (SatellitePolar,)
