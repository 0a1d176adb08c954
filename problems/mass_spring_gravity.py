r"""Mass on a spring under gravity, with an applied force (Cambridge 3C5, Lagrangian mechanics).

Source: ``sources/002_df41972c66c4514e.txt``, section 2.2, "Lagrange's Equation for a
Mass/Spring System" (and section 3.1, its generalised momentum; the closing note "Mass spring
system done (gravity as a generalised force or potential?)").

Sign convention (the figure is missing from the extraction; ``V = k x^2/2 + M g x`` fixes it)::

          ^ F (applied, along +x)
        +-----+
        |  M  |   x: height of the mass, measured up from where the spring is unstretched
        +-----+
           /
           \    k          j (up), gravity -g j
           /
        ///////// ground

Frames.  ``O`` inertial, ``j = O.y`` up.  The mass moves along ``j`` only: a particle ``M`` at
``x j``.

Free-body diagram (Newton--Euler): weight ``-M g j``, spring ``-k x j`` (``x`` is the
spring's extension), applied force ``F j``::

        j:  M x'' = F - k x - M g

Lagrangian (written independently)::

        T = M x'^2 / 2,      V = k x^2 / 2 + M g x,      Q = F      (virtual work F dx)
        d/dt (M x') + k x + M g = F

A third derivation answers the source's closing question: gravity as a *generalised force*
instead of a potential, ``Q_gravity = -M g j . d(x j)/dx = -M g``.  It gives the same
equation, as it must (gravity is conservative, so either way is right).

Generalised momentum (section 3.1): ``dT/dx' = M x'``, the linear momentum of the mass.

Static equilibrium and frequency (not printed; computed in the tests with the library):
``x* = (F - M g) / k``, and small oscillations about it at ``omega^2 = k / M`` -- gravity and
the steady force only move the equilibrium.

Reading the extraction.  The printed Lagrange's equation shows ``d/dt [dT/dx] - dT/dx``; the
dot of the first ``x'`` is lost in the extraction (the next line, ``d/dt [M x']``, shows what
was meant).  ``T`` is printed ``M x^2/2`` with the dot lost likewise, and section 3.1's
``T = dT/dx = M x'`` is the line ``dT/dx' = M x'``.  The potential is printed as ``U``.  No
errata: every printed line is right once read this way.

Example
-------
>>> p = MassSpringGravity(); p.validate()
>>> p.model("lagrange").equations
(-F + M*g + M*Derivative(x(t), (t, 2)) + k*x(t),)
"""
from __future__ import annotations

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Published, coordinate, rate, ACCELERATION, FORCE, LENGTH,
                      MASS, STIFFNESS)

__all__ = ["MassSpringGravity", "PROBLEMS", "M", "k", "g", "F", "x", "static_equilibrium"]

M, k, g, F = sp.symbols("M k g F", positive=True)
x = coordinate("x")


def static_equilibrium() -> sp.Expr:
    """``x*`` by hand: ``k x* = F - M g`` (spring, weight and applied force balance)."""
    return (F - M * g) / k


class _Scene:
    """Frame, point and particle of the direct form (also used for published references)."""

    def __init__(self):
        self.O = Frame.ground("O")
        self.o = Point.origin(self.O, "o")   # where the spring is unstretched
        self.P = self.o.locate("P", x * self.O.y)
        self.mass = Particle("mass", M, self.P)


class MassSpringGravity(Problem):
    """Mass ``M`` on a spring ``k`` under gravity, with an applied force ``F`` (see module doc)."""

    name = "mass_spring_gravity"
    title = "Mass on a spring under gravity"
    source = "002_df41972c66c4514e.txt: section 2.2, Lagrange's equation for a mass/spring system"
    summary = ("One coordinate, three derivations: free-body diagram, gravity as a potential "
               "and gravity as a generalised force.")
    parameters = (
        Parameter(M, MASS, 2.0, (0.1, 10.0), "mass"),
        Parameter(k, STIFFNESS, 200.0, (10.0, 2000.0), "spring stiffness"),
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
        Parameter(F, FORCE, 5.0, (0.1, 50.0), "applied force along +x (steady)"),
    )
    coordinates = (
        Coordinate(x, LENGTH, (-0.5, 0.5), (-2.0, 2.0),
                   "height of the mass above the spring's unstretched position"),
    )
    extra_models = ("gravity_as_force",)

    def newton_euler(self) -> EquationSet:
        """``sum F = M a`` along ``j``: weight, spring, applied force."""
        sc = _Scene()
        ne = NewtonEuler("newton_euler", coordinates=[x], ground=sc.O,
                         description="sum F = M a on the mass, along j")
        ne.gravity(-g * sc.O.y)
        ne.linear_spring("spring", sc.mass, k, x, sc.O.y)
        ne.force("applied force", sc.mass, F * sc.O.y)
        ne.linear_momentum(sc.mass, sc.O.y)
        return ne.equations()

    def lagrange(self) -> EquationSet:
        """``T = M x'^2/2``, ``V = k x^2/2 + M g x``, ``Q = F``, as the source writes them."""
        lg = Lagrangian("lagrange", coordinates=[x],
                        description="gravity as a potential (the source's choice)")
        lg.kinetic("T of mass", M * rate(x)**2 / 2)
        lg.spring("spring", k, x)
        lg.potential("gravity", M * g * x)
        lg.generalized_force("applied force", [F])
        return lg.equations()

    def gravity_as_force(self) -> EquationSet:
        """Gravity's virtual work instead of its potential: ``Q = F - M g``."""
        sc = _Scene()
        lg = Lagrangian("gravity_as_force", coordinates=[x],
                        description="gravity as a generalised force (the source's closing note)")
        lg.kinetic("T of mass", M * rate(x)**2 / 2)
        lg.spring("spring", k, x)
        lg.force_at("gravity", -M * g * sc.O.y, sc.P, sc.O)
        lg.force_at("applied force", F * sc.O.y, sc.P, sc.O)
        return lg.equations()

    def published(self) -> list[Published]:
        sc = _Scene()
        height = sc.P.pos_from(sc.o).dot(sc.O.y)
        where = "section 2.2, mass/spring system"
        return [
            # Right: v = x' j.
            Published("T", "expression", (M * rate(x)**2 / 2,), (sc.mass.kinetic_energy(sc.O),),
                      where=where + " (printed 'T = M x^2/2', dot lost in the extraction)"),
            # Right: the spring's extension is the height x; the mass is x above the datum.
            Published("U", "expression", (k * x**2 / 2 + M * g * x,),
                      (k * height**2 / 2 + M * g * height,), where=where),
            # Right: d/dt (M x') + k x + M g = F.
            Published("Lagrange's equation", "motion", (rate(M * x, 2) + k * x + M * g - F,),
                      where=where + ": d/dt[M x'] + k x + M g = F"),
            # Right: the same, rearranged.
            Published("equation of motion", "motion", (M * rate(x, 2) + k * x - (F - M * g),),
                      where=where + ": M x'' + k x = F - M g"),
            # Right: dT/dx' = M x' is the linear momentum of the mass.
            Published("generalised momentum", "expression", (M * rate(x),),
                      (sc.mass.linear_momentum(sc.O).dot(sc.O.y),),
                      where="section 3.1: dT/dx' = M x', the linear momentum"),
        ]


PROBLEMS = (MassSpringGravity,)
