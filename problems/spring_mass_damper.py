r"""Example 11: the spring--mass--damper driven by a force f(t).

Source: ``sources/000_203248afac9714e6.txt``, "Example 11: Spring-Mass-Damper System" -- the
first worked use of Lagrange's equation with dissipation and a generalised force.

Geometry (the source's figure is missing; this is the one used here)
--------------------------------------------------------------------
::

      wall                                    the block slides on a frictionless guide;
      |/|        k                            x = 0 where the spring is unstretched
      |/|---/\/\/\/\/\---+-------+
      |/|                |   m   |----> f(t) = F0 cos(Omega t)
      |/|------[ b ------+-------+
      |/|                    |
                             +--> x,  i

The source writes a general force ``f(t)``.  The models need an expression they can
evaluate exactly, so ``f(t)`` is represented by the harmonic force ``F0 cos(Omega t)`` (two
parameters, ``F0`` and ``Omega``): every step of the source's derivation is linear in
``f``, so nothing in it depends on that choice.

Frames and bodies.  One inertial frame ``O`` (``i`` along the guide).  The block translates:
a particle ``m`` at ``x i``.

Free-body diagram (along ``i``; the guide's normal force and the weight act across ``i``
and are not asked for)::

      spring  -k x i,     dashpot  -b x' i,     drive  f(t) i

      m x'' = -k x - b x' + f(t)

Lagrangian (written independently, as the source does)::

      T = m x'^2/2,    U = k x^2/2,    R = b x'^2/2,    Q = f(t)
      dR/dx' = b x',   dU/dx = k x
      m x'' + b x' + k x = f(t)

Steady state (hand derivation, used in the tests): with ``Delta = (k - m Omega^2)^2 +
(b Omega)^2`` the particular solution is
``x_p = F0 ((k - m Omega^2) cos(Omega t) + b Omega sin(Omega t)) / Delta``.

Errata: none -- every printed line is right.  Nothing was garbled beyond use.

Example
-------
>>> p = SpringMassDamper(); p.validate()
>>> p.model("lagrange").equations[0]
-F0*cos(Omega*t) + b*Derivative(x(t), t) + k*x(t) + m*Derivative(x(t), (t, 2))
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Published, coordinate, rate, t, DAMPING, FORCE, FREQUENCY,
                      LENGTH, MASS, STIFFNESS)

__all__ = ["SpringMassDamper", "PROBLEMS", "forcing", "steady_state", "m", "k", "b", "F0",
           "Omega", "x"]

m, k, b, F0, Omega = sp.symbols("m k b F0 Omega", positive=True)
x = coordinate("x")


def forcing() -> sp.Expr:
    """The force ``f(t)`` of the source, represented by ``F0 cos(Omega t)``."""
    return F0 * sp.cos(Omega * t)


def steady_state() -> sp.Expr:
    """The particular (steady-state) solution ``x_p(t)``, derived by hand (module docstring)."""
    delta = (k - m * Omega**2)**2 + (b * Omega)**2
    return F0 * ((k - m * Omega**2) * sp.cos(Omega * t) + b * Omega * sp.sin(Omega * t)) / delta


def _scene() -> SimpleNamespace:
    O = Frame.ground("O")
    P = Point.origin(O).locate("P", x * O.x)
    return SimpleNamespace(O=O, P=P, block=Particle("block", m, P))


def _loads(sc: SimpleNamespace) -> dict:
    """The forces on the block as vectors: spring, dashpot, drive."""
    i = sc.O.x
    return {"spring": -k * x * i, "dashpot": -b * rate(x) * i, "drive": forcing() * i}


class SpringMassDamper(Problem):
    """Block on a spring and a dashpot, driven by ``f(t) = F0 cos(Omega t)``."""

    name = "spring_mass_damper"
    title = "Spring-mass-damper driven by a force f(t)"
    source = "000_203248afac9714e6.txt: Example 11"
    summary = ("One coordinate, a spring, a dashpot (Rayleigh dissipation) and a generalised "
               "force; f(t) represented by F0 cos(Omega t). Every printed line is right.")
    parameters = (
        Parameter(m, MASS, 2.0, (0.1, 10.0), "mass of the block"),
        Parameter(k, STIFFNESS, 50.0, (1.0, 500.0), "spring constant"),
        Parameter(b, DAMPING, 3.0, (0.1, 50.0), "dashpot constant"),
        Parameter(F0, FORCE, 5.0, (0.1, 50.0), "amplitude of f(t)"),
        Parameter(Omega, FREQUENCY, 4.0, (0.5, 20.0), "angular frequency of f(t)"),
    )
    coordinates = (
        Coordinate(x, LENGTH, (-0.5, 0.5), (-2.0, 2.0), "displacement from the unstretched "
                   "spring"),
    )

    def newton_euler(self) -> EquationSet:
        """``sum F = m a`` on the block along ``i``."""
        sc = _scene()
        ne = NewtonEuler("newton_euler", coordinates=[x], ground=sc.O,
                         description="sum F = m a on the block, along the guide")
        for key, f in _loads(sc).items():
            ne.force(key, sc.block, f)
        ne.linear_momentum(sc.block, sc.O.x)
        return ne.equations()

    def lagrange(self) -> EquationSet:
        """``T``, ``U``, ``R`` and ``Q`` exactly as the source writes them."""
        lg = Lagrangian("lagrange", coordinates=[x],
                        description="T, U, R and Q of Example 11")
        lg.kinetic("T of block", m * rate(x)**2 / 2)
        lg.spring("spring", k, x)
        lg.damper("dashpot", b, rate(x))
        lg.generalized_force("drive", [forcing()])
        return lg.equations()

    def published(self) -> list[Published]:
        sc = _scene()
        loads = _loads(sc)
        i = sc.O.x
        v = sp.Symbol("v", real=True)
        # references from the direct form's objects: energy of the block, potential of the
        # spring force (minus its work from x = 0), Rayleigh function of the dashpot force
        # (minus its power integrated over the rate), virtual work of the drive
        spring_f = loads["spring"].dot(i)
        damper_f = loads["dashpot"].dot(i)
        U_ref = -sp.integrate(spring_f.subs(x, v), (v, 0, x))
        R_ref = -sp.integrate(damper_f.subs(rate(x), v), (v, 0, rate(x)))
        Q_ref = loads["drive"].dot(sc.P.vel(sc.O).diff(rate(x), sc.O))
        where = "Example 11 (f(t) represented by F0 cos(Omega t))"
        return [
            Published("T", "expression", (m * rate(x)**2 / 2,),
                      (sc.block.kinetic_energy(sc.O),), where=where),
            Published("U", "expression", (k * x**2 / 2,), (U_ref,), where=where),
            Published("R", "expression", (b * rate(x)**2 / 2,), (R_ref,), where=where),
            Published("Q", "expression", (forcing(),), (Q_ref,), where=where),
            Published("dR/dx', dU/dx", "expression", (b * rate(x), k * x),
                      (-damper_f, -spring_f), where=where),
            Published("equation of motion", "motion",
                      (m * rate(x, 2) + b * rate(x) + k * x - forcing(),), where=where),
        ]


PROBLEMS = (SpringMassDamper,)
