r"""Example 13: a bead on a wire hoop spun about its vertical diameter at a prescribed rate.

Source: ``sources/000_203248afac9714e6.txt``, "Example 13: Bead on a Spinning Wire Hoop".  A
bead ``m`` slides without friction on a circular hoop of radius ``R``; the hoop is driven
about its vertical diameter at the constant rate ``omega`` (its angle ``psi = omega t`` is
prescribed: the problem is rheonomic).  One coordinate: ``theta``, the bead's angle from the
bottom of the hoop.

Sign convention::

            K (up, spin axis)                   hoop plane (i_H, K), seen from -j_H
            |  psi = omega t                             K
            |  about K                                   |
       .----+----.                                  .----+----.
      /     |     \                                /     O     \
     |      O      |  the hoop turns;             |      |\     |
      \     |   o  /  i_H = hoop frame x          |      | \ R  |
       '----+--/--'                                \     |th\  /
            |                                       '----+---o   bead:
                                                         |       R (sin th i_H - cos th K)

Frames (rotation matrices)::

    O                              ground, gravity -g K
    H = O.child(rot_z(omega t))    hoop: i_H, j_H (normal to the hoop plane), K
    B = H.child(rot_y(-theta))     bead: i_B = ( cos th, 0, sin th) (direction of increasing th)
                                         j_B = j_H
                                         k_B = (-sin th, 0, cos th) (from the bead to O)
    r_bead = -R k_B

Body and free-body diagram: one particle ``m``; weight ``-m g K``; the hoop's force, which has
no component along the wire (no friction) but two across it: ``N k_B`` (in the hoop plane,
towards O) and ``N_b j_H`` (normal to the hoop plane, the push that turns the bead with the
hoop).

Acceleration by hand (relative motion in H, ``w = omega K``)::

    a = R (th'' - omega^2 sin th cos th) i_B + 2 R omega th' cos th j_B
        + R (th'^2 + omega^2 sin^2 th) k_B

Direct form, ``sum F = m a`` on B::

    i_B:  -m g sin th     = m R (th'' - omega^2 sin th cos th)
    j_B:   N_b            = 2 m R omega th' cos th                (Coriolis)
    k_B:   N - m g cos th = m R (th'^2 + omega^2 sin^2 th)

Lagrangian (written independently, as the source does; ``psi`` prescribed as ``omega t``)::

    T = m ((R th')^2 + (R psi' sin th)^2) / 2,     U = m g R (1 - cos th)
    m R^2 th'' - m R^2 omega^2 sin th cos th + m g R sin th = 0

Both reactions a second time (multiplier model): free the bead from the wire in both normal
directions -- ``r`` its distance from O in the hoop plane, ``w`` its offset along ``j_H`` --
so ``r_bead = r (sin th i_H - cos th K) + w j_H``, and close with ``R - r = 0`` (multiplier
``N``: ``N k_B`` does the virtual work ``-N dr``) and ``w = 0`` (multiplier ``N_b``, work
``N_b dw``); ``psi = omega t`` is prescribed there too.

Equilibria (relative to the hoop) and stability, ``omega_c^2 = g / R``::

    th = 0      stable when omega^2 < g/R   (stiffness m R (g - R omega^2))
    th = pi     always unstable             (stiffness -m R (g + R omega^2))
    cos th0 = g/(R omega^2), when omega^2 > g/R: stable (stiffness m R^2 omega^2 sin^2 th0),
                and there the hoop's in-plane force is N = m R omega^2, whatever g.

Errata: none.  The source's ``th'' = (omega^2 cos th - g/R) sin th`` is right (it is the
Lagrange equation divided by ``m R^2``).  Readable throughout ("Velocity of hoop: rho omega
= R sin th omega" is the speed of the hoop's point under the bead).

Example
-------
>>> p = BeadOnHoop(); p.validate()
>>> p.model("lagrange").equations[0]
-R**2*m*omega**2*sin(theta(t))*cos(theta(t)) + R**2*m*Derivative(theta(t), (t, 2)) + R*g*m*sin(theta(t))
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Published, Reaction, coordinate, rate, rot_y, rot_z, t,
                      ACCELERATION, ANGLE, FORCE, FREQUENCY, LENGTH, MASS)

__all__ = ["BeadOnHoop", "PROBLEMS", "hand_reactions", "m", "R", "g", "omega", "theta", "psi",
           "r", "w"]

m, R, g, omega = sp.symbols("m R g omega", positive=True)
theta = coordinate("theta")
psi = coordinate("psi")            # hoop angle, prescribed as omega t
r, w = coordinate("r"), coordinate("w")  # bead off the wire, multiplier model only


def hand_reactions() -> dict:
    """``{"N": ..., "N_b": ...}`` from the free-body diagram (module docstring)."""
    s, co, thd = sp.sin(theta), sp.cos(theta), rate(theta)
    return {"N": m * g * co + m * R * (thd**2 + omega**2 * s**2),
            "N_b": 2 * m * R * omega * thd * co}


def _scene() -> SimpleNamespace:
    O = Frame.ground("O")
    H = O.child("H", rot_z(omega * t))
    B = H.child("B", rot_y(-theta))
    o = Point.origin(O, "O")
    bead = o.locate("bead", -R * B.z)
    return SimpleNamespace(O=O, H=H, B=B, o=o, P=bead, bead=Particle("bead", m, bead))


class BeadOnHoop(Problem):
    """Bead on a hoop turning at the prescribed rate ``omega`` (see module doc)."""

    name = "bead_on_hoop"
    title = "Bead on a spinning wire hoop"
    source = "000_203248afac9714e6.txt: Example 13"
    summary = ("Rheonomic: the hoop's angle omega t is prescribed. The hoop's force in two "
               "directions from the free-body diagram and from multipliers; equilibria "
               "0, pi and arccos(g/(R omega^2)) with their stability.")
    parameters = (
        Parameter(m, MASS, 0.1, (0.01, 5.0), "mass of the bead"),
        Parameter(R, LENGTH, 0.5, (0.05, 3.0), "radius of the hoop"),
        Parameter(g, ACCELERATION, 9.81, (9.0, 10.0), "gravitational acceleration"),
        Parameter(omega, FREQUENCY, 6.0, (0.5, 20.0), "spin rate of the hoop"),
    )
    coordinates = (
        Coordinate(theta, ANGLE, (-3.0, 3.0), (-4.0, 4.0), "bead angle from the bottom"),
    )
    extra_coordinates = (
        Coordinate(r, LENGTH, (0.05, 3.0), (-0.5, 0.5), "distance of the bead from O"),
        Coordinate(w, LENGTH, (-0.05, 0.05), (-0.5, 0.5), "offset of the bead along j_H"),
    )
    reactions = (
        Reaction("N", FORCE, "hoop on bead, in the hoop plane, along k_B (towards O)"),
        Reaction("N_b", FORCE, "hoop on bead, normal to the hoop plane, along j_H"),
    )
    extra_models = ("multiplier",)

    def coordinate_maps(self) -> dict:
        return {"multiplier": {theta: theta, r: R, w: 0}}

    # -- direct form ----------------------------------------------------------------------
    def newton_euler(self) -> EquationSet:
        """``sum F = m a`` on the bead, projected on ``i_B``, ``j_B``, ``k_B``."""
        sc = _scene()
        ne = NewtonEuler("newton_euler", coordinates=[theta], ground=sc.O,
                         description="sum F = m a on the bead, hoop turning at omega")
        ne.gravity(-g * sc.O.z)
        ne.reaction("N", sc.bead, sc.B.z)
        ne.reaction("N_b", sc.bead, sc.H.y)
        for axis in (sc.B.x, sc.B.y, sc.B.z):
            ne.linear_momentum(sc.bead, axis)
        return ne.equations()

    # -- indirect form --------------------------------------------------------------------
    def lagrange(self) -> EquationSet:
        """``T`` and ``U`` as the source writes them, the hoop angle prescribed."""
        lg = Lagrangian("lagrange", coordinates=[theta, psi],
                        description="T and U of Example 13, psi = omega t prescribed")
        lg.kinetic("T of bead", m * ((R * rate(theta))**2 + (R * rate(psi) * sp.sin(theta))**2) / 2)
        lg.potential("gravity", m * g * R * (1 - sp.cos(theta)))
        lg.prescribe(psi, omega * t)
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """The bead freed from the wire (``r``, ``w``), held on it by ``N`` and ``N_b``."""
        lg = Lagrangian("multiplier", coordinates=[theta, r, w, psi],
                        description="bead off the wire, closed by two multipliers")
        in_hoop = sp.Matrix([r * sp.sin(theta), w, -r * sp.cos(theta)])
        pos = sp.Matrix(rot_z(psi)) * in_hoop
        lg.kinetic("T of bead", m * (rate(pos).T * rate(pos))[0, 0] / 2)
        lg.potential("gravity", m * g * pos[2])
        lg.constraint("N", R - r)
        lg.constraint("N_b", w)
        lg.prescribe(psi, omega * t)
        return lg.equations()

    # -- the source's answers -------------------------------------------------------------
    def published(self) -> list[Published]:
        sc = _scene()
        O, H, B = sc.O, sc.H, sc.B
        v = sc.P.vel(O)
        v_rel = sc.P.pos_from(sc.o).dt(H)             # seen from the hoop
        v_hoop = v - v_rel                              # the hoop's point under the bead
        height = sc.P.pos_from(sc.o).dot(O.z) + R       # above the bottom of the hoop
        s, co = sp.sin(theta), sp.cos(theta)
        where = "Example 13"
        return [
            Published("velocity of bead, velocity of hoop", "expression",
                      (R * rate(theta), R * s * omega),
                      (v_rel.dot(B.x), v_hoop.dot(H.y)),
                      where=where + ": R th' along the wire; rho omega = R sin(th) omega "
                      "normal to the hoop plane"),
            Published("T", "expression",
                      (m * ((R * rate(theta))**2 + (R * omega * s)**2) / 2,),
                      (sc.bead.kinetic_energy(O),), where=where),
            Published("U", "expression", (m * g * R - m * g * R * co,), (m * g * height,),
                      where=where + ", relative to the bottom of the hoop"),
            Published("equation of motion", "motion",
                      (m * R**2 * rate(theta, 2) - m * R**2 * omega**2 * s * co
                       + m * g * R * s,), where=where),
            Published("angular acceleration", "expression",
                      ((omega**2 * co - g / R) * s,), (rate(theta, 2),),
                      where=where + ", 'Solving for the angular acceleration'"),
        ]


PROBLEMS = (BeadOnHoop,)
