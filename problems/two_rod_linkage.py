r"""Mass on a spring and dashpot carrying a two-rod linkage (MIT 2.003J, spring 2011, quiz 2, problem 2).

A mass ``M`` slides without friction in a horizontal shaft (along ``I``), tied to the left wall
by a spring ``k`` and to the right wall by a dashpot ``c``.  A point mass ``m`` at A is joined
to the fixed pivot O and to M (at B) by two massless rigid rods of length ``l``; every pivot is
frictionless.  ``l0 < 2l`` is the distance OB at which the spring is unstretched; ``m`` stays
above the line OB.  One degree of freedom, written twice: in ``theta`` and in ``x``.

Sign convention (plane I-J, K out of the page, gravity ``-g J``)::

                         A  (m)
                        / \
                   l   /   \   l           O r_A = l (cos(theta) I + sin(theta) J)
                      /     \              O r_B = (l0 + x) I = 2 l cos(theta) I
                     /theta  \
    |/|---/\/\/\----O----------B[ M ]----[ c |---|/|
      spring k (wall to M)     '-> x grows to the right (x = 0: spring unstretched)

Frames (rotation matrices about K)::

    O = (O, I, J, K)             ground
    A = O.child(rot_z(theta))    rod OA:  i_A = cos(theta) I + sin(theta) J
    R = O.child(rot_z(-theta))   rod AB:  i_R = cos(theta) I - sin(theta) J   (from A to B)

Bodies: two particles, ``m`` at ``A = l i_A`` and ``M`` at ``B = A + l i_R = 2 l cos(theta) I``.

Free-body diagrams (the rods are massless two-force members: with no torque at their pins
their forces lie along them)::

    m:  weight -m g J,   rod OA  F_L i_A (F_L > 0: OA pushes m out),   rod AB  -F_R i_R
    M:  weight -M g J,   shaft N J,   spring -k x I,   dashpot -c x' I,   rod AB  F_R i_R

``F_R`` is the force the right bar exerts on M along ``i_R`` (compression positive), as the
source defines it.  ``sum F = m a`` on I and J for each particle (``x = 2 l cos(theta) - l0``)::

    M, I:  F_R cos(theta) - k x - c x' = M x''
    M, J:  N - M g - F_R sin(theta) = 0
    m:     F_L i_A - F_R i_R - m g J = m l (theta'' j_A - theta'^2 i_A)

The ``j_A`` part of m's balance, with ``i_R . j_A = -sin(2 theta)``, and ``F_R`` from M's
``I`` balance, give the equation of motion.

Lagrangian in ``theta`` (written independently; ``x' = -2 l theta' sin(theta)``)::

    T = m l^2 theta'^2/2 + 2 M l^2 theta'^2 sin^2(theta)
    V = m g l sin(theta) + k (2 l cos(theta) - l0)^2/2,     R = 2 c l^2 theta'^2 sin^2(theta)

    m l^2 theta'' + 4 M l^2 (theta'' sin^2 + theta'^2 sin cos) + 4 c l^2 theta' sin^2
        + m g l cos(theta) - 2 k l (2 l cos(theta) - l0) sin(theta) = 0

Lagrangian in ``x``: with ``D = 4 l^2 - (l0 + x)^2``, ``theta' = -x'/sqrt(D)`` and the height
of m ``l sin(theta) = sqrt(D)/2``::

    T = M x'^2/2 + m l^2 x'^2/(2 D),     V = k x^2/2 + m g sqrt(D)/2,     R = c x'^2/2

    M x'' + m l^2 (x''/D + (l0 + x) x'^2/D^2) + c x' + k x = m g (l0 + x)/(2 sqrt(D))

Branch: ``sqrt(D) = 2 l sin(theta)`` holds only for ``sin(theta) > 0`` -- m above the line of
the spring, as the source assumes.  The ``x`` form is a model of that branch only (below the
line the height of m is ``-sqrt(D)/2``); its map to the reference, ``x = 2 l cos(theta) - l0``,
is valid everywhere.  ``theta`` therefore declares the domain ``(0, pi)``: the comparator
decides identities over that domain, where ``sqrt(4 l^2 sin^2(theta)) = 2 l sin(theta)``
holds, instead of over every real ``theta``.  At ``sin(theta) = 0`` (the rods folded flat, ``x = +-2l - l0``) the map
``theta -> x`` has zero derivative and the ``x`` form's mass ``M + m l^2/D`` is infinite: that is
the singular set declared.  Near it the ``x`` form also loses digits in floating point
(``D = 4 l^2 - (l0 + x)^2`` cancels, relative error ~ ``eps/sin^2(theta)``), so the working
range of ``theta`` stays at least 0.4 rad away from the fold.

Every bar force once more, as a multiplier: free m from the bar OA (polar coordinates
``(r, theta)`` of A, ``r`` independent), B from the bar AB (``x`` independent of ``theta``) and
lift M off the shaft (height ``y``); close all three with constraints written as distances
with unit gradient along the forces::

    T = m (r'^2 + r^2 theta'^2)/2 + M (x'^2 + y'^2)/2,   V = m g r sin(theta) + k x^2/2 + M g y
    F_L:  r - l                                      (gradient i_A at A: OA pushes m out)
    F_R:  (|AB|^2 - l^2)/(2 l) = (x_B (x_B - 2 r cos(theta)) + y (y - 2 r sin(theta)) + r^2 - l^2)/(2 l)
    N:    y                                          (B = x_B I + y J,  x_B = l0 + x)

(``|AB|^2 = x_B^2 + y^2 - 2 r (x_B cos(theta) + y sin(theta)) + r^2``; the gradient of the
``F_R`` constraint with respect to B is ``(B - A)/l``, the unit vector ``i_R`` on the
constraint, so its multiplier is ``F_R``; the virtual work of the pair ``+-F_R i_R`` on M and
m is ``F_R d|AB|``.  The ``F_L`` constraint's gradient with respect to A is ``i_A``: its
multiplier is the force of OA on m along ``i_A``, the direct form's ``F_L``.)

Errata found in the printed solution (see :meth:`TwoRodLinkage.published`):

* (b) the ``x`` equation prints the gravity term ``m g (l0 - x)/sqrt(D)``; it is
  ``m g (l0 + x)/(2 sqrt(D))`` (``d/dx`` of ``m g sqrt(D)/2``): both the sign of ``x`` and a
  factor 1/2 are off.  Hand check: times ``dx/dtheta = -2 l sin(theta)`` it must give the
  ``theta`` equation's ``m g l cos(theta)``; ``(l0 + x)/(2 sqrt(D)) * 2 l sin(theta) =
  l cos(theta)`` does, the printed term does not.
* (B) ``F_R`` "for ``q1 = theta``" prints the spring term ``k (2 l cos(theta))``; with
  ``x = 2 l cos(theta) - l0`` it is ``k (2 l cos(theta) - l0)``.
* (b) the potential is printed ``V = m g (r_A . J) + k (r_B . r_B)/2`` before the (right) result
  ``m g l sin(theta) + k x^2/2``: the spring's energy is ``k (|r_B| - l0)^2/2``, not
  ``k |r_B|^2/2``.

Garbled in the PDF extraction: the Lagrange operator of the ``x`` equation is printed
``d/d (dL/dx)``, read as ``d/dt (dL/dx')``.

Example
-------
>>> p = TwoRodLinkage(); p.validate()
>>> sp.factor(p.model("lagrange").mass_matrix()[0])
l**2*(4*M*sin(theta(t))**2 + m)
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Probe, Problem, Published, Reaction, coordinate, rate, rot_z, t,
                      ACCELERATION, ANGLE, DAMPING, FORCE, LENGTH, MASS, STIFFNESS)

__all__ = ["TwoRodLinkage", "PROBLEMS", "scene", "M", "m", "k", "c", "l", "l0", "g", "theta",
           "x", "y", "r"]

M, m, k, c, l, l0, g = sp.symbols("M m k c l l0 g", positive=True)
theta = coordinate("theta")
x = coordinate("x")   # the x form's coordinate (and B's freed position in the multiplier model)
y = coordinate("y")   # height of M off the shaft, multiplier model only
r = coordinate("r")   # distance of m from O (rod OA freed), multiplier model only
F_R = sp.Symbol("F_R", real=True)


def scene() -> SimpleNamespace:
    """Frames, points and particles of the direct form in ``theta`` (see the module doc)."""
    O = Frame.ground("O")
    A = O.child("A", rot_z(theta))
    R = O.child("R", rot_z(-theta))
    o = Point.origin(O, "O")
    pA = o.locate("A", l * A.x)
    pB = pA.locate("B", l * R.x)
    x_of_theta = pB.pos_from(o).dot(O.x) - l0
    return SimpleNamespace(O=O, A=A, R=R, o=o, pA=pA, pB=pB, x=x_of_theta,
                           bob=Particle("m", m, pA), slider=Particle("M", M, pB))


def _branch_height():
    """Height of m in the ``x`` form, ``sqrt(D)/2`` (branch ``sin(theta) > 0``)."""
    return sp.sqrt(4 * l**2 - (l0 + x)**2) / 2


class TwoRodLinkage(Problem):
    """Spring-and-dashpot slider M carrying a two-rod linkage with a point mass m."""

    name = "two_rod_linkage"
    title = "Mass on spring and dashpot carrying a two-rod linkage"
    source = "001_9d08622cf8d659c2.txt: 2.003J spring 2011, quiz 2, problem 2"
    summary = ("One degree of freedom in theta and in x (x-form valid above the line, "
               "singular where the rods fold flat); bar force F_R twice; two errata.")
    parameters = (
        Parameter(M, MASS, 2.0, (0.2, 10.0), "mass of the slider"),
        Parameter(m, MASS, 0.5, (0.05, 5.0), "point mass of the linkage"),
        Parameter(k, STIFFNESS, 40.0, (1.0, 500.0), "spring constant"),
        Parameter(c, DAMPING, 1.5, (0.1, 20.0), "dashpot constant"),
        Parameter(l, LENGTH, 1.0, (0.5, 2.0), "length of each rod"),
        Parameter(l0, LENGTH, 0.6, (0.1, 0.9), "OB with the spring unstretched (< 2l)"),
        Parameter(g, ACCELERATION, 9.81, (9.0, 10.0), "gravitational acceleration"),
    )
    coordinates = (
        Coordinate(theta, ANGLE, (0.4, 2.7), (-3.0, 3.0), "angle of OA above OB",
                   domain=(0.0, 3.141592653589793)),   # (0, pi): m above the line
    )
    extra_coordinates = (
        Coordinate(x, LENGTH, (-2.5, 1.5), (-4.0, 4.0),
                   "displacement of M from the unstretched spring"),
        Coordinate(y, LENGTH, (-0.1, 0.1), (-0.5, 0.5), "height of M off the shaft"),
        Coordinate(r, LENGTH, (0.5, 2.0), (0.1, 4.0), "distance of m from O (rod OA freed)"),
    )
    reactions = (
        Reaction("F_R", FORCE, "right bar on M, along i_R = cos(theta) I - sin(theta) J"),
        Reaction("F_L", FORCE, "left bar on m, along i_A (from O to A)"),
        Reaction("N", FORCE, "shaft on M, along J"),
    )
    singular = (sp.sin(theta),)
    extra_models = ("lagrange_x", "multiplier")
    probes = (Probe((2.7, 3.0), "lagrange_x", 1.0,
                    "the spring throws the rods flat (sin(theta) = 0, at 0.68 s), where the x "
                    "form's mass is infinite and m passes below the line"),)

    def coordinate_maps(self) -> dict:
        x_of_theta = 2 * l * sp.cos(theta) - l0
        return {"lagrange_x": {x: x_of_theta},
                "multiplier": {theta: theta, x: x_of_theta, y: 0, r: l}}

    # -- direct form -----------------------------------------------------------------------
    def newton_euler(self) -> EquationSet:
        """``sum F = m a`` on I and J for m and for M."""
        s = scene()
        O = s.O
        ne = NewtonEuler(coordinates=[theta], ground=O,
                         description="sum F = m a on m and on M, along I and J")
        ne.gravity(-g * O.y)
        ne.linear_spring("spring", s.slider, k, s.x, O.x)
        ne.linear_damper("dashpot", s.slider, c, s.x.diff(t), O.x)
        ne.reaction("N", s.slider, O.y)
        ne.reaction("F_R", s.slider, s.R.x, against=s.bob)
        ne.reaction("F_L", s.bob, s.A.x)
        for body in (s.bob, s.slider):
            ne.linear_momentum(body, O.x)
            ne.linear_momentum(body, O.y)
        return ne.equations()

    # -- indirect forms --------------------------------------------------------------------
    def lagrange(self) -> EquationSet:
        """``T``, ``V``, ``R`` in ``theta``, by hand (``x' = -2 l theta' sin(theta)``)."""
        lg = Lagrangian(coordinates=[theta], description="T, V, R in theta, by hand")
        lg.kinetic("T of m", m * l**2 * rate(theta)**2 / 2)
        lg.kinetic("T of M", 2 * M * l**2 * rate(theta)**2 * sp.sin(theta)**2)
        lg.potential("gravity", m * g * l * sp.sin(theta))
        lg.spring("spring", k, 2 * l * sp.cos(theta) - l0)
        lg.dissipation("dashpot", 2 * c * l**2 * rate(theta)**2 * sp.sin(theta)**2)
        return lg.equations()

    def lagrange_x(self) -> EquationSet:
        """``T``, ``V``, ``R`` in ``x`` (branch ``sin(theta) > 0``, m above the line)."""
        lg = Lagrangian("lagrange_x", coordinates=[x],
                        description="T, V, R in x; m's height sqrt(D)/2 (m above the line)")
        lg.kinetic("T of M", M * rate(x)**2 / 2)
        lg.kinetic("T of m", m * l**2 * rate(x)**2 / (2 * (4 * l**2 - (l0 + x)**2)))
        lg.potential("gravity", m * g * _branch_height())
        lg.spring("spring", k, x)
        lg.damper("dashpot", c, rate(x))
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """Both bars and the shaft as constraints: ``F_L``, ``F_R`` and ``N`` as multipliers."""
        lg = Lagrangian("multiplier", coordinates=[theta, r, x, y],
                        description="bars OA, AB and the shaft as constraints with multipliers")
        lg.kinetic("T of m", m * (rate(r)**2 + r**2 * rate(theta)**2) / 2)
        lg.kinetic("T of M", M * (rate(x)**2 + rate(y)**2) / 2)
        lg.potential("gravity", m * g * r * sp.sin(theta) + M * g * y)
        lg.spring("spring", k, x)
        lg.damper("dashpot", c, rate(x))
        xB = l0 + x
        lg.constraint("F_L", r - l)
        lg.constraint("F_R", (xB * (xB - 2 * r * sp.cos(theta)) + y * (y - 2 * r * sp.sin(theta))
                              + r**2 - l**2) / (2 * l))
        lg.constraint("N", y)
        return lg.equations()

    # -- the source's answers --------------------------------------------------------------
    def published(self) -> list[Published]:
        s = scene()
        O = s.O
        I, J = O.x, O.y
        st, ct = sp.sin(theta), sp.cos(theta)
        th1, th2, x1, x2 = rate(theta), rate(theta, 2), rate(x), rate(x, 2)
        Dx = 4 * l**2 - (l0 + x)**2
        T = s.bob.kinetic_energy(O) + s.slider.kinetic_energy(O)
        V = m * g * s.pA.pos_from(s.o).dot(J) + k * s.x**2 / 2
        # generalised forces of the dashpot, from the points placed by x and by theta
        B_x = s.o.locate("B_x", (l0 + x) * I)
        Xi_x = (-c * B_x.vel(O)).dot(B_x.vel(O).diff(x1, O))
        Xi_th = (-c * s.x.diff(t) * I).dot(s.pB.vel(O).diff(th1, O))
        bar = (F_R * s.R.x.dot(I), F_R * s.R.x.dot(J))
        rest = M * x2 + c * x1 + k * x
        rest_th = M * (-2 * l * th2 * st - 2 * l * th1**2 * ct) + c * (-2 * l * th1 * st) \
            + k * (2 * l * ct)
        q = "quiz 2, problem 2"
        return [
            Published("(a) x(theta)", "expression", (2 * l * ct - l0,), (s.x,),
                      where=f"{q} (a)"),
            Published("(a) x'(theta, theta')", "expression", (-2 * l * th1 * st,),
                      (s.pB.vel(O).dot(I),), where=f"{q} (a), boxed"),
            Published("(a) theta'(x, x')", "expression", (-x1 / sp.sqrt(Dx),), (th1,),
                      where=f"{q} (a), boxed (branch sin(theta) > 0)", coordinates="lagrange_x"),
            Published("(a) x''", "expression", (-2 * l * th2 * st - 2 * l * th1**2 * ct,),
                      (s.pB.acc(O).dot(I),), where=f"{q} (a), 'not asked'"),
            Published("(a) theta''", "expression",
                      (-x2 / sp.sqrt(Dx) - (l0 + x) * x1**2 * sp.sqrt(Dx) / Dx**2,), (th2,),
                      where=f"{q} (a), 'not asked' (branch sin(theta) > 0)",
                      coordinates="lagrange_x"),
            Published("(b) T", "expression", (m * l**2 * th1**2 / 2 + M * x1**2 / 2,), (T,),
                      where=f"{q} (b)", coordinates="lagrange_x"),
            Published("(b) V, middle form", "expression",
                      (m * g * s.pA.pos_from(s.o).dot(J)
                       + k * s.pB.pos_from(s.o).dot(s.pB.pos_from(s.o)) / 2,), (V,),
                      where=f"{q} (b): WRONG, k (r_B . r_B)/2; the spring's energy is "
                      "k (|r_B| - l0)^2/2"),
            Published("(b) V", "expression", (m * g * l * st + k * x**2 / 2,), (V,),
                      where=f"{q} (b)", coordinates="lagrange_x"),
            Published("(b) Xi_x", "expression", (-c * x1,), (Xi_x,),
                      where=f"{q} (b), q1 = x", coordinates="lagrange_x"),
            Published("(b) L in x", "expression",
                      (m * l**2 * x1**2 / (2 * Dx) + M * x1**2 / 2
                       - m * g * l * sp.sqrt(Dx) / (2 * l) - k * x**2 / 2,), (T - V,),
                      where=f"{q} (b), q1 = x (branch sin(theta) > 0)",
                      coordinates="lagrange_x"),
            Published("(b) x equation", "equation",
                      (M * x2 + m * l**2 * (x2 / Dx + (l0 + x) * x1**2 / Dx**2) + c * x1 + k * x
                       - m * g * (l0 - x) / sp.sqrt(Dx),),
                      where=f"{q} (b), q1 = x: WRONG, gravity term m g (l0 - x)/sqrt(D); it is "
                      "m g (l0 + x)/(2 sqrt(D))", coordinates="lagrange_x"),
            Published("(b) Xi_theta", "expression", (-4 * c * l**2 * th1 * st**2,), (Xi_th,),
                      where=f"{q} (b), q1 = theta"),
            Published("(b) L in theta", "expression",
                      (m * l**2 * th1**2 / 2 + 2 * M * l**2 * th1**2 * st**2 - m * g * l * st
                       - k * (2 * l * ct - l0)**2 / 2,), (T - V,),
                      where=f"{q} (b), q1 = theta"),
            Published("(b) theta equation", "motion",
                      (m * l**2 * th2 + 4 * M * l**2 * (th2 * st**2 + th1**2 * st * ct)
                       + 4 * c * l**2 * th1 * st**2 + m * g * l * ct
                       - 2 * k * l * (2 * l * ct - l0) * st,),
                      where=f"{q} (b), q1 = theta, boxed"),
            Published("(B) I projection", "equation", (F_R * ct - rest,),
                      where=f"{q} (B): F_R cos(theta) = M x'' + c x' + k x",
                      coordinates="lagrange_x"),
            Published("(B) F_R", "expression", (rest, -rest * sp.tan(theta)), bar,
                      where=f"{q} (B): (M x'' + c x' + k x)(I - tan(theta) J)",
                      coordinates="lagrange_x"),
            Published("(B) F_R in x", "expression",
                      (rest, -rest * sp.sqrt(Dx) / (l0 + x)), bar,
                      where=f"{q} (B), q1 = x (branch sin(theta) > 0)",
                      coordinates="lagrange_x"),
            Published("(B) F_R in theta", "expression", (rest_th, -rest_th * sp.tan(theta)), bar,
                      where=f"{q} (B), q1 = theta: WRONG, spring term k (2 l cos(theta)); it "
                      "is k (2 l cos(theta) - l0)"),
        ]


PROBLEMS = (TwoRodLinkage,)
