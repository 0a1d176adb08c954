r"""Euler's equations of a rigid body from Lagrange's equation in z-y-z Euler angles.

Source: ``sources/002_df41972c66c4514e.txt``, Cambridge 3C5 notes, section 5 "Euler's
Equations for the Rotation of a Rigid Body".

A rigid body turns about its mass centre G (or about a fixed point; the equations are the
same with A, B, C taken about that point).  Body axes x, y, z are principal axes with moments
of inertia ``A, B, C``; the applied torque has constant body-axis components
``Q1, Q2, Q3`` (the source's ``Q_i``, "torques about these axes").  The attitude is given by
the Euler angles ``phi, theta, psi``: turn by ``phi`` about Z, then by ``theta`` about the new
y axis, then by ``psi`` about the new z axis::

            Z = z_1                       z_2 = z
            |   phi                        |  .  theta (about y_1 = y_2)
            |  /                           | .
            | /                            |.
            +----- Y                       G-------- y  psi about z_2
           / \
          X   x_1  (phi about Z)

    (X, Y, Z) fixed in space; (x, y, z) fixed in the body; theta is the angle between Z and z.

Frames (the library's rotation matrices have the child's unit vectors as *columns*; the source
prints their transposes, whose rows are the child's unit vectors)::

    O  = ground (X, Y, Z)
    F1 = O.child(rot_z(phi))        source's R1 = rot_z(phi)^T
    F2 = F1.child(rot_y(theta))     source's R2 = rot_y(theta)^T
    b  = F2.child(rot_z(psi))       source's R3 = rot_z(psi)^T,  (x, y, z) = R3 R2 R1 (X, Y, Z)

Angular velocity (from the matrices; equal to the sum of the relative rates
``phi' Z + theta' y_1 + psi' z``), body components::

    w1 = theta' sin(psi) - phi' sin(theta) cos(psi)
    w2 = theta' cos(psi) + phi' sin(theta) sin(psi)
    w3 = psi' + phi' cos(theta)

Body and free-body diagram: one rigid body, inertia ``diag(A, B, C)`` about G in body axes;
the applied couple ``Q1 x + Q2 y + Q3 z``.  Any force through G (a support at G, its weight
when G is the support) has no moment about G and is left out.

Direct form: ``sum tau_G = d/dt H_G`` with ``H_G = A w1 x + B w2 y + C w3 z``, differentiated
in the ground frame by the transport theorem and projected on x, y, z -- Euler's equations::

    A w1' - (B - C) w2 w3 = Q1
    B w2' - (C - A) w3 w1 = Q2
    C w3' - (A - B) w1 w2 = Q3

Lagrangian, written independently from the printed angular velocities::

    T = (A w1^2 + B w2^2 + C w3^2) / 2,    V = 0
    delta W = Q . delta(rotation) = Q1 (sin(psi) d theta - sin(theta) cos(psi) d phi)
              + Q2 (cos(psi) d theta + sin(theta) sin(psi) d phi) + Q3 (d psi + cos(theta) d phi)
    Q_phi = -Q1 sin(theta) cos(psi) + Q2 sin(theta) sin(psi) + Q3 cos(theta)
    Q_theta = Q1 sin(psi) + Q2 cos(psi),     Q_psi = Q3

The psi equation is the third Euler equation itself (``dT/dpsi' = C w3``,
``dT/dpsi = A w1 dw1/dpsi + B w2 dw2/dpsi = (A - B) w1 w2`` because ``dw1/dpsi = w2`` and
``dw2/dpsi = -w1``); the phi and theta equations are combinations of all three: with
``J = d(w1, w2, w3)/d(phi', theta', psi')``, (Lagrange) = ``J^T`` (Euler).

Singular set (gimbal lock): the mass matrix is ``J^T diag(A, B, C) J`` with
``det J = -sin(theta)``, so ``det M = A B C sin^2(theta)``: at ``theta = 0`` or ``pi`` the
angles phi and psi turn about the same axis and the coordinates cannot tell them apart.

Errata and unreadable formulas (see :meth:`RigidBodyEulerAngles.published`):

* Everything printed in section 5 that can be read is right: the Euler equations, the three
  rotation matrices, the spin-rate formula, ``w1, w2, w3``, ``T`` and ``dT/dpsi' = C w3``.
  The spin-rate formula carries redundant factors (``R3 (0, 0, psi')`` equals
  ``(0, 0, psi')`` and ``R1 (0, 0, phi')`` equals ``(0, 0, phi')``) but is right.
* The extracted text drops every dot in the psi derivation: it prints ``d/dt[dT/dpsi] -
  dT/dpsi`` and "dT/dpsi ... = C w3"; the latter is read as ``dT/dpsi' = C w3`` (the chain
  rule written beside it only gives ``C w3`` for the rate).  The following lines (``dT/dpsi``
  and the resulting third Euler equation) are too garbled to read; the psi equation is
  checked instead in the tests.
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Point,
                      Probe, Problem, Published, RigidBody, coordinate, rate, rot_y, rot_z, ANGLE,
                      INERTIA, TORQUE)

__all__ = ["RigidBodyEulerAngles", "PROBLEMS", "frames", "body_rates", "A", "B", "C", "Q1",
           "Q2", "Q3", "phi", "theta", "psi"]

A, B, C = sp.symbols("A B C", positive=True)
Q1, Q2, Q3 = sp.symbols("Q1 Q2 Q3", real=True)
phi, theta, psi = coordinate("phi"), coordinate("theta"), coordinate("psi")
_mass = sp.Symbol("m", positive=True)  # never enters: moments about the mass centre


def frames() -> SimpleNamespace:
    """The z-y-z chain ``O -> F1 -> F2 -> b`` and the mass centre ``G`` at the ground origin."""
    O = Frame.ground("O")
    F1 = O.child("F1", rot_z(phi))
    F2 = F1.child("F2", rot_y(theta))
    b = F2.child("b", rot_z(psi))
    return SimpleNamespace(O=O, F1=F1, F2=F2, b=b, G=Point.origin(O, "G"))


def body_rates() -> tuple:
    """``(w1, w2, w3)`` written by hand from the z-y-z angles (source, section 5)."""
    return (rate(theta) * sp.sin(psi) - rate(phi) * sp.sin(theta) * sp.cos(psi),
            rate(theta) * sp.cos(psi) + rate(phi) * sp.sin(theta) * sp.sin(psi),
            rate(psi) + rate(phi) * sp.cos(theta))


class RigidBodyEulerAngles(Problem):
    """Torqued rigid body about its mass centre in z-y-z Euler angles (see module doc)."""

    name = "rigid_body_euler_angles"
    title = "Rigid body in z-y-z Euler angles"
    source = "002_df41972c66c4514e.txt: section 5, Euler's equations via Euler angles"
    summary = ("Euler's equations from the angular-momentum balance in body axes against "
               "Lagrange's equations of the z-y-z angles; gimbal lock at sin(theta) = 0.")
    parameters = (
        Parameter(A, INERTIA, 0.6, (0.05, 5.0), "principal moment of inertia about x"),
        Parameter(B, INERTIA, 0.9, (0.05, 5.0), "principal moment of inertia about y"),
        Parameter(C, INERTIA, 1.3, (0.05, 5.0), "principal moment of inertia about z"),
        Parameter(Q1, TORQUE, 0.0, (-2.0, 2.0), "applied torque about body x"),
        Parameter(Q2, TORQUE, 0.0, (-2.0, 2.0), "applied torque about body y"),
        Parameter(Q3, TORQUE, 0.0, (-2.0, 2.0), "applied torque about body z"),
    )
    coordinates = (
        Coordinate(phi, ANGLE, (-3.0, 3.0), (-3.0, 3.0), "first turn, about Z"),
        Coordinate(theta, ANGLE, (0.3, 2.8), (-3.0, 3.0), "second turn, about y_1 (nutation)"),
        Coordinate(psi, ANGLE, (-3.0, 3.0), (-3.0, 3.0), "third turn, about z (spin)"),
    )
    reactions = ()
    singular = (sp.sin(theta),)
    probes = (Probe((0.0, 0.3, 0.0, 1e-2, -0.3, 1e-2), "lagrange", 1.5,
                    "the nutation angle heads for 0: gimbal lock of the z-y-z angles"),)

    # -- direct form: Euler's equations, sum tau_G = dH_G/dt in body axes --------------------
    def newton_euler(self) -> EquationSet:
        f = frames()
        body = RigidBody("body", _mass, f.G, f.b, sp.diag(A, B, C))
        ne = NewtonEuler(coordinates=[phi, theta, psi], ground=f.O,
                         description="sum tau_G = dH_G/dt projected on the body axes x, y, z")
        ne.torque("applied torque", body, f.b.vector(Q1, Q2, Q3))
        for axis in (f.b.x, f.b.y, f.b.z):
            ne.angular_momentum(body, axis)
        return ne.equations()

    # -- indirect form ---------------------------------------------------------------------
    def lagrange(self) -> EquationSet:
        """``T`` from the printed body rates; ``Q_j`` from the virtual work of the couple."""
        w1, w2, w3 = body_rates()
        st, ct, sps, cps = sp.sin(theta), sp.cos(theta), sp.sin(psi), sp.cos(psi)
        lg = Lagrangian(coordinates=[phi, theta, psi],
                        description="T = (A w1^2 + B w2^2 + C w3^2)/2 by hand; Q by virtual work")
        lg.kinetic("T of body", (A * w1**2 + B * w2**2 + C * w3**2) / 2)
        lg.generalized_force("applied torque", [-Q1 * st * cps + Q2 * st * sps + Q3 * ct,
                                                Q1 * sps + Q2 * cps, Q3])
        return lg.equations()

    # -- the source's answers --------------------------------------------------------------
    def published(self) -> list[Published]:
        f = frames()
        st, ct = sp.sin(theta), sp.cos(theta)
        R1 = sp.Matrix([[sp.cos(phi), sp.sin(phi), 0], [-sp.sin(phi), sp.cos(phi), 0],
                        [0, 0, 1]])
        R2 = sp.Matrix([[ct, 0, -st], [0, 1, 0], [st, 0, ct]])
        R3 = sp.Matrix([[sp.cos(psi), sp.sin(psi), 0], [-sp.sin(psi), sp.cos(psi), 0],
                        [0, 0, 1]])
        w = tuple(f.b.ang_vel_in(f.O).express(f.b).components)
        spin = (R3 * sp.Matrix([0, 0, rate(psi)]) + R3 * R2 * sp.Matrix([0, rate(theta), 0])
                + R3 * R2 * R1 * sp.Matrix([0, 0, rate(phi)]))
        w1, w2, w3 = (rate(theta) * sp.sin(psi) - rate(phi) * st * sp.cos(psi),
                      rate(theta) * sp.cos(psi) + rate(phi) * st * sp.sin(psi),
                      rate(psi) + rate(phi) * ct)
        body = RigidBody("body", _mass, f.G, f.b, sp.diag(A, B, C))
        T_ref = body.kinetic_energy(f.O)
        euler = (A * rate(w1) - (B - C) * w2 * w3 - Q1,
                 B * rate(w2) - (C - A) * w3 * w1 - Q2,
                 C * rate(w3) - (A - B) * w1 * w2 - Q3)
        return [
            Published("(5) Euler's equations", "motion", euler,
                      where="section 5, first display: A w1' - (B - C) w2 w3 = Q1 and cyclic, "
                      "with w1, w2, w3 as printed further on"),
            Published("(5) R1", "expression", tuple(R1), tuple(f.O.dcm(f.F1)),
                      where="section 5, step 1: (x1, y1, z1) = R1 (X, Y, Z)"),
            Published("(5) R2", "expression", tuple(R2), tuple(f.F1.dcm(f.F2)),
                      where="section 5: (x2, y2, z2) = R2 (x1, y1, z1)"),
            Published("(5) R3", "expression", tuple(R3), tuple(f.F2.dcm(f.b)),
                      where="section 5: (x, y, z) = R3 (x2, y2, z2)"),
            Published("(5) full transformation", "expression", tuple(R3 * R2 * R1),
                      tuple(f.O.dcm(f.b)), where="section 5: (x, y, z) = R3 R2 R1 (X, Y, Z)"),
            Published("(5) spin rates from the matrices", "expression", tuple(spin), w,
                      where="section 5: (w1, w2, w3) = R3 (0, 0, psi') + R3 R2 (0, theta', 0)"
                      " + R3 R2 R1 (0, 0, phi')"),
            Published("(5) w1, w2, w3", "expression", (w1, w2, w3), w,
                      where="section 5, 'and hence'"),
            Published("(5) kinetic energy", "expression",
                      ((A * w1**2 + B * w2**2 + C * w3**2) / 2,), (T_ref,),
                      where="section 5: T = (A w1^2 + B w2^2 + C w3^2)/2"),
            Published("(5) dT/dpsi'", "expression", (C * w3,), (T_ref.diff(rate(psi)),),
                      where="section 5, psi derivation: '= C w3' (the extraction drops the dot)"),
        ]


PROBLEMS = (RigidBodyEulerAngles,)
