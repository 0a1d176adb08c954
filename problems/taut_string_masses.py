r"""Two masses on a taut string: small transverse vibration (Cambridge 3C5, Lagrangian mechanics).

Source: ``sources/002_df41972c66c4514e.txt``, section 4, "Example: Two masses on a taut
string".

Two equal masses ``m`` sit on a string stretched between two fixed points ``3a`` apart, at
``a`` and ``2a``; the string carries the pre-load (tension) ``P``.  The masses move
transversely by ``x1``, ``x2``.

Sign convention::

        anchor                                          anchor
          O----------- m ----------- m -----------o      i along the string, j transverse
          0     a     a+x1 j    2a  2a+x2 j   3a           (x1, x2 along j)

             string segments: O--m1, m1--m2, m2--anchor, each of length a at rest

The model the source writes, and the approximations it makes.  The string's potential energy
is the work of its tension through the stretch ``Delta = L - 3a`` of the deformed length
``L``; with the tension taken as the pre-load, ``V = P Delta``.  That is

* the tension stays ``P``: the extra tension of an elastic string, ``EA Delta / L0``, is of
  second order in the displacements, so its work (``EA Delta^2 / (2 L0)``) is of fourth order
  and drops out of a quadratic ``V``;
* small slopes: each segment's length ``sqrt(a^2 + d^2)`` is expanded to
  ``a (1 + d^2 / (2 a^2))`` -- in the free-body diagram, the tension's direction is taken with
  the segment's length ``a`` (``sin alpha ~ tan alpha = d / a``);
* the masses move only transversely (their motion along the string is of second order and
  neglected); gravity is not considered.

Frames and bodies.  ``O`` inertial, ``i`` along the string, ``j`` transverse.  Particles
``m`` at ``a i + x1 j`` and ``2a i + x2 j``; anchors at ``0`` and ``3a i``.

Free-body diagrams (Newton--Euler, the small-vibration model).  Each segment pulls each of its
ends towards the other with the tension ``P`` along the segment, length taken as ``a``::

        on m1:  P (r0 - r1)/a + P (r2 - r1)/a,     on m2:  P (r1 - r2)/a + P (r3 - r2)/a
        j:  m x1'' = -(P/a) x1 + (P/a)(x2 - x1),   m x2'' = -(P/a)(x2 - x1) - (P/a) x2

(the ``i`` components, ``-P + P``, cancel exactly).

Lagrangian (written independently, as the source does)::

        L ~ 3a + (x1^2 + (x2 - x1)^2 + x2^2) / (2a),       V = P Delta
        T = m (x1'^2 + x2'^2) / 2
        m x1'' + (P/a)(x1 - (x2 - x1)) = 0,      m x2'' + (P/a)(x2 + (x2 - x1)) = 0

        M = [[m, 0], [0, m]],   K = [[2P/a, -P/a], [-P/a, 2P/a]]
        w^2 = P/(a m): x1 = x2;      w^2 = 3P/(a m): x1 = -x2

:func:`exact_geometry` writes the same string without the small-slope expansion (``V = P (L -
3a)`` with the exact lengths); the tests check that the library's linearisation of it is the
source's ``M`` and ``K``, and that it departs from the quadratic model at third order.

Reading the extraction.  The derivation of ``V = P Delta`` (the lines with ``L0``, ``L1 = 3a``,
``L = L1 + Delta``) is garbled beyond the definitions and the conclusion ``V ~ P Delta``; the
integral over the tension cannot be read.  ``y2^2`` in ``Delta`` is ``x2^2``; ``U`` and ``V``
are both used for the potential; ``P`` appears as ``rho``/``l`` in places.  No errata.

Example
-------
>>> p = TautStringMasses(); p.validate()
>>> p.model("lagrange").linearize()[2]
Matrix([
[2*P/a,  -P/a],
[ -P/a, 2*P/a]])
"""
from __future__ import annotations

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Published, coordinate, rate, FORCE, LENGTH, MASS)

__all__ = ["TautStringMasses", "PROBLEMS", "m", "P", "a", "x1", "x2", "exact_geometry",
           "segment_lengths", "string_pulls"]

m, P, a = sp.symbols("m P a", positive=True)
x1, x2 = coordinate("x1"), coordinate("x2")


class _Scene:
    """Frame, anchors and masses (also used for published references)."""

    def __init__(self):
        self.O = Frame.ground("O")
        o = Point.origin(self.O, "left anchor")
        self.ends = [o, o.locate("P1", a * self.O.x + x1 * self.O.y),
                     o.locate("P2", 2 * a * self.O.x + x2 * self.O.y),
                     o.locate("right anchor", 3 * a * self.O.x)]
        self.masses = [Particle("mass 1", m, self.ends[1]), Particle("mass 2", m, self.ends[2])]

    def segment(self, i: int):
        """Vector from the left end to the right end of segment ``i`` (0, 1, 2)."""
        return self.ends[i + 1].pos_from(self.ends[i])

    def pulls(self) -> list[tuple]:
        """``(key, mass, force)``: each segment pulls each mass at its ends towards the other
        end with the tension ``P``, its length taken as ``a`` (small slopes)."""
        out = []
        for i in range(3):
            pull = P * self.segment(i) / a   # on the segment's left end, towards the right
            if i > 0:
                out.append((f"string {i + 1}", self.masses[i - 1], pull))
            if i < 2:
                out.append((f"string {i + 1}", self.masses[i], -pull))
        return out


def segment_lengths() -> list[sp.Expr]:
    """Exact lengths of the three segments, ``sqrt(a^2 + d^2)``."""
    sc = _Scene()
    return [sp.sqrt(sc.segment(i).dot(sc.segment(i))) for i in range(3)]


def string_pulls() -> list[tuple]:
    """The free-body diagrams' loads ``(key, mass, force)`` of the small-vibration model."""
    return _Scene().pulls()


def exact_geometry() -> EquationSet:
    """The string without the small-slope expansion: ``V = P (L - 3a)``, exact lengths.

    Not a model of the problem (it is not equivalent to the small-vibration model); its
    linearisation about ``x = 0`` is.
    """
    lg = Lagrangian("exact_geometry", coordinates=[x1, x2],
                    description="constant tension P, exact segment lengths")
    lg.kinetic("T of masses", m * (rate(x1)**2 + rate(x2)**2) / 2)
    lg.potential("string", P * (sum(segment_lengths()) - 3 * a))
    return lg.equations()


class TautStringMasses(Problem):
    """Two masses ``m`` on a string of tension ``P``, spacing ``a`` (see module doc)."""

    name = "taut_string_masses"
    title = "Two masses on a taut string"
    source = "002_df41972c66c4514e.txt: section 4, example: two masses on a taut string"
    summary = ("Small transverse vibration with V = P Delta; frequencies P/(a m), 3P/(a m) "
               "and the modes x1 = +-x2 by the library.")
    parameters = (
        Parameter(m, MASS, 0.2, (0.01, 5.0), "mass of each bead"),
        Parameter(P, FORCE, 50.0, (1.0, 500.0), "tension (pre-load) of the string"),
        Parameter(a, LENGTH, 0.3, (0.05, 2.0), "spacing of anchors and masses"),
    )
    coordinates = (
        Coordinate(x1, LENGTH, (-0.01, 0.01), (-0.5, 0.5), "transverse displacement of mass 1"),
        Coordinate(x2, LENGTH, (-0.01, 0.01), (-0.5, 0.5), "transverse displacement of mass 2"),
    )

    def newton_euler(self) -> EquationSet:
        """Each mass along ``j``: the tension ``P`` along each segment, length taken as ``a``."""
        sc = _Scene()
        ne = NewtonEuler("newton_euler", coordinates=[x1, x2], ground=sc.O,
                         description="tension P along each segment, small slopes")
        for key, body, force in sc.pulls():
            ne.force(key, body, force)
        for mass in sc.masses:
            ne.linear_momentum(mass, sc.O.y)
        return ne.equations()

    def lagrange(self) -> EquationSet:
        """``T`` and ``V = P Delta`` as the source writes them."""
        lg = Lagrangian("lagrange", coordinates=[x1, x2], description="V = P Delta, by hand")
        lg.kinetic("T of masses", m * rate(x1)**2 / 2 + m * rate(x2)**2 / 2)
        lg.potential("string", P / (2 * a) * (x1**2 + (x2 - x1)**2 + x2**2))
        return lg.equations()

    def published(self) -> list[Published]:
        sc = _Scene()
        eps = sp.Symbol("epsilon")
        small = {x1: eps * x1, x2: eps * x2}
        # each exact length to second order in the displacements
        L2 = [sp.series(Li.xreplace(small), eps, 0, 3).removeO().subs(eps, 1)
              for Li in segment_lengths()]
        Delta = sum(L2) - 3 * a
        T_ref = sum(mass.kinetic_energy(sc.O) for mass in sc.masses)
        Mn, _, Kn = self.model("newton_euler").linearize()
        Mn, Kn = -Mn, -Kn   # the direct form reads sum F - m a = 0: M q'' + K q = 0 negated
        w2 = sp.Symbol("omega2")
        roots = sorted(sp.solve((Kn - w2 * Mn).det(), w2), key=lambda r: float(
            r.subs(self.defaults())))
        shapes = []
        for r in roots:   # x2 / x1 of the null vector of K - w^2 M
            (vec,) = (Kn - r * Mn).nullspace()
            shapes.append(sp.simplify(vec[1] / vec[0]))
        printed_L = (a * (1 + x1**2 / (2 * a**2)) + a * (1 + (x2 - x1)**2 / (2 * a**2))
                     + a * (1 + x2**2 / (2 * a**2)))
        printed_Delta = (x1**2 + (x2 - x1)**2 + x2**2) / (2 * a)
        where = "section 4, two masses on a taut string"
        return [
            Published("L, expanded", "expression", (printed_L,), (sum(L2),), where=where),
            Published("Delta = L - 3a", "expression", (printed_Delta,), (Delta,),
                      where=where + " (printed y2^2 for x2^2)"),
            Published("U = P Delta", "expression",
                      (P / (2 * a) * (x1**2 + (x2 - x1)**2 + x2**2),), (P * Delta,),
                      where=where),
            Published("T", "expression", (m * rate(x1)**2 / 2 + m * rate(x2)**2 / 2,), (T_ref,),
                      where=where),
            Published("equations of motion", "motion",
                      (m * rate(x1, 2) + P / a * (x1 - (x2 - x1)),
                       m * rate(x2, 2) + P / a * (x2 + (x2 - x1))), where=where),
            # Right: the free-body diagram's equations, linearised, have these matrices.
            Published("mass and stiffness matrices", "expression",
                      (m, 0, 0, m, 2 * P / a, -P / a, -P / a, 2 * P / a),
                      tuple(Mn) + tuple(Kn), where=where + ", matrix form"),
            Published("natural frequencies w^2", "expression", (P / (a * m), 3 * P / (a * m)),
                      tuple(roots), where=where + ": w^2 = 3P/(am) or P/(am)"),
            Published("mode shapes x2/x1", "expression", (1, -1), tuple(shapes),
                      where=where + ": mode 1 x1 = x2, mode 2 x1 = -x2"),
        ]


PROBLEMS = (TautStringMasses,)
