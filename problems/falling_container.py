"""Example 15: a mass--spring--dashpot subsystem inside a falling container.

Source: ``sources/000_203248afac9714e6.txt``, "Example 15: Mass Spring Dashpot Subsystem in
Falling Container" -- derived twice there, in absolute heights ``(x1, x2)`` and in
``(y1, y2)`` (container height and relative displacement of ``m2``).

Geometry (the source's figure is missing; this is the one used here)
--------------------------------------------------------------------
::

        j (up)                         |      |   guides (not shown in the source):
        ^                              |      |   horizontal forces only
        |      +----------------+      |      |
        |      |      +----+    |  m1  = container, floor at height x1
        |      |      | m2 |    |  m2  = mass inside, at height x2
        |      |      +----+ <-- x2    spring k (free length l0) and dashpot c
        |      |     |     |    |      in parallel, floor -> m2
        |      |    k/     [ c  |
        |      |     \\     [    |      extension of the spring:  x2 - x1 - l0
        |      |     |     |    |      rate of the dashpot:      x2' - x1'
        |      +================+ <-- x1 (floor of m1)
        |
   -----+------------------------------> i        gravity  -g j
       ground (height 0)

Coordinates.  ``x1`` = height of the container floor, ``x2`` = height of ``m2`` (both from the
ground, along ``j``).  The second choice of the source is ``y1 = x1`` and
``y2 = x2 - x1 - l0``, the displacement of ``m2`` relative to the container, measured from
the unstretched spring.  The map between the two choices is what
:meth:`FallingContainer.coordinate_maps` declares; "the two choices are the same motion" is
that map applied to one model giving the other.

Nothing models the ground: the equations hold until the container lands.

Frames and bodies.  One inertial frame ``O`` (``i`` horizontal, ``j`` up).  Neither body
rotates, so both are particles: the container (mass ``m1``) at its floor point
``C = x1 j``, and ``m2`` at ``B = x2 j``.

Free-body diagrams (Newton--Euler)::

      container m1                          m2
      ------------                          --
      -m1 g j                  weight       -m2 g j
      +k (x2 - x1 - l0) j      spring       -k (x2 - x1 - l0) j
      +c (x2' - x1') j         dashpot      -c (x2' - x1') j
      H1 i   (guide on m1)     guides       H2 i   (wall of m1 on m2)
      -H2 i  (m2 on the wall)

``sum F = m a`` along ``i`` and ``j`` for each body::

      i, m1:   H1 - H2 = 0                  i, m2:   H2 = 0
      j, m1:   m1 x1'' = -m1 g + k (x2 - x1 - l0) + c (x2' - x1')
      j, m2:   m2 x2'' = -m2 g - k (x2 - x1 - l0) - c (x2' - x1')

so the guide reactions vanish, ``H1 = H2 = 0``: nothing pushes sideways.

Lagrangian (written independently)::

      T = m1 x1'^2/2 + m2 x2'^2/2
      V = k (x2 - x1 - l0)^2/2 + m1 g x1 + m2 g x2
      R = c (x2' - x1')^2/2,            Q1 = Q2 = 0

      m1 x1'' + c (x1' - x2') + k (x1 - x2 + l0) + m1 g = 0
      m2 x2'' + c (x2' - x1') + k (x2 - x1 - l0) + m2 g = 0

In ``(y1, y2)``: ``T = m1 y1'^2/2 + m2 (y1' + y2')^2/2``,
``V = k y2^2/2 + m1 g y1 + m2 g (y1 + y2 + l0)``, ``R = c y2'^2/2``::

      (m1 + m2) y1'' + m2 y2'' + (m1 + m2) g = 0
      m2 y1'' + m2 y2'' + c y2' + k y2 + m2 g = 0

Errata
------
* The printed second ``x`` equation has ``m1 x2''``; it must be ``m2 x2''`` (the momentum of
  ``m2`` is ``m2 x2'``).
* The datum of ``x2``.  The source says both heights are measured "with respect to horizontal
  ground", yet its ``U = k (x1 - x2)^2/2`` makes the spring unstretched at ``x1 = x2``: that
  energy implies ``x2`` measured from the spring's free length (``l0`` above the floor's
  datum).  The two statements cannot both hold, so each printed ``x`` equation is judged under
  both readings, and the report says which reading gives which verdict:

  - ``x2`` from the ground (the reference model's coordinate): the spring term must be
    ``k (x1 - x2 + l0)`` in the first equation and ``k (x2 - x1 - l0)`` in the second; the
    printed ``k (x1 - x2)`` is WRONG (right only for ``l0 = 0``);
  - ``x2`` from the free length (the energy's reading, ``x2_printed = x2 - l0``): the first
    printed equation is CORRECT; the second is still WRONG by its ``m1 x2''``.

  The model keeps the ground datum (the source's words, and the coordinate the ``y`` form's
  ``y2 = x2 - x1 - l0`` is written against); the printed answers are re-read for the other
  datum by substituting ``x2 -> x2 - l0`` into them (:meth:`FallingContainer.published`).
* The printed ``y`` equations are right.

Example
-------
>>> p = FallingContainer(); p.validate()
>>> sp.expand(p.model("lagrange").equations[0]).coeff(k)   # the spring term of the x1 equation
l0 + x1(t) - x2(t)
>>> p.model("newton_euler").reactions_solved()
{H1: 0, H2: 0}
"""
from __future__ import annotations

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Published, Reaction, StiffScene, coordinate, rate, t,
                      ACCELERATION, DAMPING, FORCE, LENGTH, MASS, STIFFNESS)

__all__ = ["FallingContainer", "PROBLEMS", "free_fall"]

m1, m2, k, c, l0, g = sp.symbols("m1 m2 k c l0 g", positive=True)
x1, x2 = coordinate("x1"), coordinate("x2")
y1, y2 = coordinate("y1"), coordinate("y2")


def free_fall(values: dict, y0, times) -> list:
    """The exact motion from a state with the spring at its free length and both masses at
    the same speed: the spring and dashpot stay idle, so each height falls with ``g``,
    ``x = x0 + x0' t - g t^2 / 2`` -- the rows ``x1, x2, x1', x2'`` at ``times`` (an array).
    """
    fall = values["g"] * times
    return [y0[0] + y0[2] * times - fall * times / 2, y0[1] + y0[3] * times - fall * times / 2,
            y0[2] - fall, y0[3] - fall]


class FallingContainer(Problem):
    """Container ``m1`` with ``m2`` inside on a spring and dashpot, vertical motion, gravity."""

    name = "falling_container"
    title = "Mass-spring-dashpot subsystem in a falling container"
    source = "000_203248afac9714e6.txt: Example 15"
    summary = ("Two choices of coordinates (absolute heights, relative displacement) for the "
               "same motion; the printed absolute-height equations carry two errors.")
    parameters = (
        Parameter(m1, MASS, 3.0, (0.5, 10.0), "mass of the container"),
        Parameter(m2, MASS, 1.0, (0.1, 5.0), "mass inside the container"),
        Parameter(k, STIFFNESS, 200.0, (10.0, 1000.0), "spring constant"),
        Parameter(c, DAMPING, 4.0, (0.1, 40.0), "dashpot constant"),
        Parameter(l0, LENGTH, 0.3, (0.05, 1.0), "free length of the spring"),
        Parameter(g, ACCELERATION, 9.81, (9.0, 10.0), "gravitational acceleration"),
    )
    coordinates = (
        Coordinate(x1, LENGTH, (1.0, 3.0), (-5.0, 1.0), "height of the container floor"),
        Coordinate(x2, LENGTH, (1.3, 3.6), (-5.0, 1.0), "height of m2"),
    )
    extra_coordinates = (
        Coordinate(y1, LENGTH, (1.0, 3.0), (-5.0, 1.0), "height of the container floor"),
        Coordinate(y2, LENGTH, (-0.3, 0.4), (-2.0, 2.0),
                   "displacement of m2 relative to m1, from the unstretched spring"),
    )
    reactions = (
        Reaction("H1", FORCE, "guide on the container, along i"),
        Reaction("H2", FORCE, "container wall on m2, along i"),
    )
    reference = "lagrange"
    extra_models = ("lagrange_y", "newton_euler_y")
    stiff_scene = StiffScene("k", (2.2, 2.5, 0.0, 0.0), 0.5,
                             "released at rest with the spring at its free length (x2 - x1 = "
                             "l0): both masses fall freely, the spring never stretches",
                             exact=free_fall)

    # -- direct form ---------------------------------------------------------------------
    def newton_euler(self) -> EquationSet:
        """Free-body diagrams of the container and of ``m2`` in heights ``(x1, x2)``."""
        return _direct("newton_euler", (x1, x2), floor=x1, inner=x2)

    def newton_euler_y(self) -> EquationSet:
        """The same free-body diagrams with the points placed by ``(y1, y2)``."""
        return _direct("newton_euler_y", (y1, y2), floor=y1, inner=y1 + y2 + l0)

    # -- indirect form -------------------------------------------------------------------
    def lagrange(self) -> EquationSet:
        """``T``, ``V``, ``R`` in absolute heights."""
        lg = Lagrangian("lagrange", coordinates=[x1, x2])
        lg.kinetic("T of container", m1 * rate(x1)**2 / 2)
        lg.kinetic("T of m2", m2 * rate(x2)**2 / 2)
        lg.potential("spring", k * (x2 - x1 - l0)**2 / 2)
        lg.potential("gravity", m1 * g * x1 + m2 * g * x2)
        lg.dissipation("dashpot", c * (rate(x2) - rate(x1))**2 / 2)
        return lg.equations()

    def lagrange_y(self) -> EquationSet:
        """``T``, ``V``, ``R`` in the container height and the relative displacement."""
        lg = Lagrangian("lagrange_y", coordinates=[y1, y2])
        lg.kinetic("T of container", m1 * rate(y1)**2 / 2)
        lg.kinetic("T of m2", m2 * (rate(y1) + rate(y2))**2 / 2)
        lg.potential("spring", k * y2**2 / 2)
        lg.potential("gravity", m1 * g * y1 + m2 * g * (y1 + y2 + l0))
        lg.dissipation("dashpot", c * rate(y2)**2 / 2)
        return lg.equations()

    def coordinate_maps(self) -> dict:
        to_x = {y1: x1, y2: x2 - x1 - l0}
        return {"lagrange_y": dict(to_x), "newton_euler_y": dict(to_x)}

    # -- the source's answers ------------------------------------------------------------
    def published(self) -> list[Published]:
        where = "Example 15, Lagrange's equations in x1, x2"
        where_y = "Example 15, Lagrange's equations in y1, y2"
        eq1 = m1 * rate(x1, 2) + c * (rate(x1) - rate(x2)) + k * (x1 - x2) + m1 * g       # as printed
        eq2 = m1 * rate(x2, 2) + c * (rate(x2) - rate(x1)) + k * (x2 - x1) + m2 * g

        def free(e):
            """``e`` with its ``x2`` read from the spring's free length: x2_printed = x2 - l0."""
            return e.subs(x2, x2 - l0).doit()

        return [
            # Ground datum: the spring term must be k(x1 - x2 + l0); right only for l0 = 0.
            Published("x-equation 1, x2 from the ground", "equation", (eq1,),
                      where=where + ": WRONG if x2 is measured from the ground (the source's "
                      "words): the spring term is k (x1 - x2 + l0)"),
            # The energy's datum (x2 from the free length): right.
            Published("x-equation 1, x2 from the free length", "equation", (free(eq1),),
                      where=where + ": x2 read from the spring's free length, the datum "
                      "U = k (x1 - x2)^2/2 implies"),
            # Wrong in both readings: m1 x2'' must be m2 x2''.
            Published("x-equation 2, x2 from the ground", "equation", (eq2,),
                      where=where + ": WRONG, m1 x2'' for m2 x2'' (and k (x2 - x1) for "
                      "k (x2 - x1 - l0))"),
            Published("x-equation 2, x2 from the free length", "equation", (free(eq2),),
                      where=where + ": WRONG in this reading too, m1 x2'' for m2 x2''"),
            # Right: d/dt dT/dy1' = (m1 + m2) y1'' + m2 y2'', dV/dy1 = (m1 + m2) g.
            Published("y-equation 1", "equation",
                      ((m1 + m2) * rate(y1, 2) + m2 * rate(y2, 2) + m1 * g + m2 * g,),
                      where=where_y, coordinates="lagrange_y"),
            # Right: d/dt dT/dy2' = m2 (y1'' + y2''), dR/dy2' = c y2', dV/dy2 = k y2 + m2 g.
            Published("y-equation 2", "equation",
                      (m2 * rate(y1, 2) + m2 * rate(y2, 2) + c * rate(y2) + k * y2 + m2 * g,),
                      where=where_y, coordinates="lagrange_y"),
        ]


def _direct(name: str, coords: tuple, floor, inner) -> EquationSet:
    """Newton--Euler with the container floor at height ``floor`` and ``m2`` at ``inner``.

    ``floor`` and ``inner`` are expressions in ``coords``; the spring extension and the
    dashpot rate follow from them, so the one free-body diagram serves both coordinate choices.
    """
    O = Frame.ground("O")
    ground = Point.origin(O)
    container = Particle("container", m1, ground.locate("C", floor * O.y))
    mass2 = Particle("m2", m2, ground.locate("B", inner * O.y))
    ne = NewtonEuler(name, coordinates=coords, ground=O)
    ne.gravity(-g * O.y)
    extension = sp.expand(inner - floor - l0)
    ne.linear_spring("spring", mass2, k, extension, O.y, against=container)
    ne.linear_damper("dashpot", mass2, c, extension.diff(t), O.y, against=container)
    ne.reaction("H1", container, O.x)
    ne.reaction("H2", mass2, O.x, against=container)
    for body in (container, mass2):
        ne.linear_momentum(body, O.x)
        ne.linear_momentum(body, O.y)
    return ne.equations()


PROBLEMS = (FallingContainer,)
