r"""Three masses on a chain of springs: mass and stiffness matrices (Cambridge 3C5).

Source: ``sources/002_df41972c66c4514e.txt``, section 4 ("Analysis of Small Amplitude
Vibrations"), "Example: Three mass system".

The system, as the printed equations describe it (the figure is garbled in the extraction): a
chain ceiling -- ``k1`` -- ``m1`` -- ``k2`` -- ``m2`` -- ``k3`` -- ``m3``, the last mass free.
"Neglect gravity (ie assume displacements are about the static equilibrium position)": the
chain hangs, and ``x_i`` is the displacement of ``m_i`` from its static position, taken
downwards.

Sign convention::

        ///////////  ceiling
            /
            \ k1             j (up), gravity -g j
            /
        +------+
        |  m1  |  | x1 (down, from the static position)
        +------+  v
            \ k2
        +------+
        |  m2  |  | x2
        +------+  v
            / k3
        +------+
        |  m3  |  | x3
        +------+  v

Frames and bodies.  ``O`` inertial; three particles, ``m_i`` at ``-x_i j`` from its static
position (the static depths are constants and drop out).

Free-body diagrams (Newton--Euler), written *with* gravity.  Spring ``i`` is stretched by its
static extension ``delta_i`` plus ``x_i - x_{i-1}`` (``x_0 = 0``); in the static position it
carries the weight below it, ``k1 delta1 = (m1 + m2 + m3) g``, ``k2 delta2 = (m2 + m3) g``,
``k3 delta3 = m3 g``.  Forces along ``j``::

        m1:  k1 (delta1 + x1) - k2 (delta2 + x2 - x1) - m1 g = -m1 x1''
        m2:  k2 (delta2 + x2 - x1) - k3 (delta3 + x3 - x2) - m2 g = -m2 x2''
        m3:  k3 (delta3 + x3 - x2) - m3 g = -m3 x3''

The static parts cancel exactly, so the source's "neglect gravity" is no approximation for
linear springs: the comparator proves the direct form *with* gravity equivalent to the
Lagrangian *without* it.

Lagrangian (written independently, as the source does)::

        T = (m1 x1'^2 + m2 x2'^2 + m3 x3'^2) / 2
        U = k1 x1^2/2 + k2 (x2 - x1)^2/2 + k3 (x3 - x2)^2/2

        M = diag(m1, m2, m3),   K = [[k1 + k2, -k2, 0], [-k2, k2 + k3, -k3], [0, -k3, k3]]

Natural frequencies and modes (not printed for this example; the source states the method,
``|-w^2 M + K| = 0``): computed with the library in the tests and compared with the roots of
the printed matrices' determinant, and for equal masses and springs with the hand result
``w_j = 2 sqrt(k/m) sin((2j - 1) pi / 14)``, mode ``j`` proportional to
``sin((2j - 1) n pi / 7)`` at mass ``n`` (a fixed-free chain of three).

Reading the extraction.  The printed equations name the masses ``M`` and ``m`` while the
matrix form names them ``m1, m2, m3``; they are transcribed with ``m1, m2, m3``.  Labels such
as ``dT/dx1 = m x2'`` and ``dx3/dy3`` are garbled (``dT/dx2' = m2 x2'``, ``dU/dx3``).  The
matrix equation is printed ``... + K x + 0`` for ``... + K x = 0``.  No errata.

Example
-------
>>> p = ThreeMassChain(); p.validate()
>>> p.model("lagrange").linearize()[2]
Matrix([
[k1 + k2,     -k2,   0],
[    -k2, k2 + k3, -k3],
[      0,     -k3,  k3]])
"""
from __future__ import annotations

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Published, coordinate, rate, ACCELERATION, LENGTH, MASS,
                      STIFFNESS)

__all__ = ["ThreeMassChain", "PROBLEMS", "m1", "m2", "m3", "k1", "k2", "k3", "g",
           "x1", "x2", "x3", "printed_matrices"]

m1, m2, m3, k1, k2, k3, g = sp.symbols("m1 m2 m3 k1 k2 k3 g", positive=True)
x1, x2, x3 = coordinate("x1"), coordinate("x2"), coordinate("x3")
XS = (x1, x2, x3)


def printed_matrices() -> tuple[sp.Matrix, sp.Matrix]:
    """The source's mass and stiffness matrices."""
    M = sp.diag(m1, m2, m3)
    K = sp.Matrix([[k1 + k2, -k2, 0], [-k2, k2 + k3, -k3], [0, -k3, k3]])
    return M, K


class _Scene:
    """Frame, points and particles of the direct form (also used for published references)."""

    def __init__(self):
        self.O = Frame.ground("O")
        self.ceiling = Point.origin(self.O, "ceiling")
        self.P = [self.ceiling.locate(f"P{i + 1}", -q * self.O.y) for i, q in enumerate(XS)]
        self.masses = [Particle(f"mass {i + 1}", mi, p)
                       for i, (mi, p) in enumerate(zip((m1, m2, m3), self.P))]

    def stretch(self, i: int) -> sp.Expr:
        """How much spring ``i`` (1, 2, 3) is stretched beyond its static extension."""
        upper = self.ceiling if i == 1 else self.P[i - 2]
        return (upper.pos_from() - self.P[i - 1].pos_from()).dot(self.O.y)


class ThreeMassChain(Problem):
    """Masses ``m1, m2, m3`` hanging on springs ``k1, k2, k3`` (see module doc)."""

    name = "three_mass_chain"
    title = "Three masses on a chain of springs"
    source = "002_df41972c66c4514e.txt: section 4, example: three mass system"
    summary = ("Mass and stiffness matrices, natural frequencies and modes by the library; "
               "gravity cancels exactly against the springs' static extension.")
    parameters = (
        Parameter(m1, MASS, 1.0, (0.1, 10.0), "upper mass"),
        Parameter(m2, MASS, 2.0, (0.1, 10.0), "middle mass"),
        Parameter(m3, MASS, 1.5, (0.1, 10.0), "lower mass"),
        Parameter(k1, STIFFNESS, 400.0, (10.0, 2000.0), "spring from the ceiling to m1"),
        Parameter(k2, STIFFNESS, 300.0, (10.0, 2000.0), "spring from m1 to m2"),
        Parameter(k3, STIFFNESS, 200.0, (10.0, 2000.0), "spring from m2 to m3"),
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
    )
    coordinates = (
        Coordinate(x1, LENGTH, (-0.05, 0.05), (-0.5, 0.5), "m1 below its static position"),
        Coordinate(x2, LENGTH, (-0.05, 0.05), (-0.5, 0.5), "m2 below its static position"),
        Coordinate(x3, LENGTH, (-0.05, 0.05), (-0.5, 0.5), "m3 below its static position"),
    )

    def newton_euler(self) -> EquationSet:
        """Each mass along ``j``, with gravity and the springs' static extension."""
        sc = _Scene()
        ne = NewtonEuler("newton_euler", coordinates=list(XS), ground=sc.O,
                         description="sum F = m a on each mass along j, gravity included")
        ne.gravity(-g * sc.O.y)
        static = ((m1 + m2 + m3) * g / k1, (m2 + m3) * g / k2, m3 * g / k3)
        for i, (k, delta) in enumerate(zip((k1, k2, k3), static), start=1):
            # stretched by delta + x_i - x_{i-1}; the lower end moves down (-j) as it grows
            ne.linear_spring(f"spring {i}", sc.masses[i - 1], k, delta + sc.stretch(i),
                             -sc.O.y, against=sc.masses[i - 2] if i > 1 else None)
        for mass in sc.masses:
            ne.linear_momentum(mass, sc.O.y)
        return ne.equations()

    def lagrange(self) -> EquationSet:
        """``T`` and ``U`` as the source writes them, gravity neglected."""
        lg = Lagrangian("lagrange", coordinates=list(XS),
                        description="about the static equilibrium, gravity neglected")
        for i, (mi, q) in enumerate(zip((m1, m2, m3), XS), start=1):
            lg.kinetic(f"T of mass {i}", mi * rate(q)**2 / 2)
        lg.spring("spring 1", k1, x1)
        lg.spring("spring 2", k2, x2 - x1)
        lg.spring("spring 3", k3, x3 - x2)
        return lg.equations()

    def published(self) -> list[Published]:
        sc = _Scene()
        T_ref = sum(mass.kinetic_energy(sc.O) for mass in sc.masses)
        U_ref = sum(k * sc.stretch(i)**2 / 2 for i, k in enumerate((k1, k2, k3), start=1))
        M_ne, _, K_ne = self.model("newton_euler").linearize()
        M, K = printed_matrices()
        q, qd, qdd = sp.Matrix(XS), sp.Matrix([rate(x) for x in XS]), sp.Matrix([rate(x, 2) for x in XS])
        where = "section 4, three mass system"
        return [
            Published("dT/dx_i'", "expression", (m1 * rate(x1), m2 * rate(x2), m3 * rate(x3)),
                      tuple(T_ref.diff(rate(x)) for x in XS), where=where),
            Published("dU/dx_i", "expression",
                      (k1 * x1 - k2 * (x2 - x1), k2 * (x2 - x1) - k3 * (x3 - x2),
                       k3 * (x3 - x2)), tuple(U_ref.diff(x) for x in XS), where=where),
            Published("(1)", "equation", (m1 * rate(x1, 2) + (k1 + k2) * x1 - k2 * x2,),
                      where=where + ", equation (1)"),
            Published("(2)", "equation",
                      (m2 * rate(x2, 2) + (k2 + k3) * x2 - k2 * x1 - k3 * x3,),
                      where=where + ", equation (2)"),
            Published("(3)", "equation", (m3 * rate(x3, 2) + k3 * (x3 - x2),),
                      where=where + ", equation (3)"),
            Published("matrix form", "motion", tuple(M * qdd + K * q), where=where),
            # Right: the direct form (with gravity) linearised about x = 0 has these matrices.
            Published("mass and stiffness matrices", "expression", tuple(M) + tuple(K),
                      tuple(M_ne) + tuple(K_ne), where=where),
            Published("M_ij is d^2 T / dx_i' dx_j'", "expression", tuple(M),
                      tuple(sp.hessian(T_ref, list(qd))), where=where),
            # Section 4: T = q'^T M q'/2, V = q^T K q/2, with the printed matrices.
            Published("T = q'^T M q'/2, V = q^T K q/2", "expression",
                      ((qd.T * M * qd)[0] / 2, (q.T * K * q)[0] / 2), (T_ref, U_ref),
                      where="section 4, applied to the three mass system"),
        ]


PROBLEMS = (ThreeMassChain,)
