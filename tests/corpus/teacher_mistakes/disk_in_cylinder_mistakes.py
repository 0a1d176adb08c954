r"""Student mistakes injected into the disk rolling inside a cylinder
(tests/corpus/teacher_problems/disk_in_cylinder.py, whose docstring derives both models).

Correct, by hand: ``T = m (R - r)^2 th'^2/2 + (m r^2/2) phi'^2/2`` with ``phi' = -(R - r) th'/r``,
``V = -m g (R - r) cos th``; the direct form balances the disk along e.x, e.y and about its
centre C, the friction ``F`` and the normal push ``N`` acting at the contact point P.
"""
from __future__ import annotations

import importlib.util
from pathlib import Path

import sympy as sp

from dualmech import RigidBody, rate


def _problem(name: str):
    path = Path(__file__).parents[1] / "teacher_problems" / f"{name}.py"
    spec = importlib.util.spec_from_file_location(f"teacher_problem_{name}", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


_p = _problem("disk_in_cylinder")
m, R, r, g, theta = _p.m, _p.R, _p.r, _p.g, _p.theta


class DiskInCylinder(_p.DiskInCylinder):
    name = "teacher_disk_in_cylinder"


class SpinForgotten(DiskInCylinder):
    """Only the centre's motion counted: ``T = m (R - r)^2 th'^2/2``; the spin's
    ``(m r^2/4) ((R - r) th'/r)^2 = m (R - r)^2 th'^2/4`` is missing."""

    def kinetic(self, lg):
        lg.kinetic("T of disk", m * (R - r)**2 * rate(theta)**2 / 2)


class RollingAsOnAFlat(DiskInCylinder):
    """The rolling taken as on a flat floor of the wall's length, ``phi' = R th'/r``: the spin
    energy is ``m R^2 th'^2/4`` where ``m (R - r)^2 th'^2/4`` belongs, ``m r (2 R - r) th'^2/4``
    too much."""

    def kinetic(self, lg):
        lg.kinetic("T of disk", m * (R - r)**2 * rate(theta)**2 / 2
                   + m * r**2 / 4 * (R * rate(theta) / r)**2)


class GravitySign(DiskInCylinder):
    """Height measured downwards: ``V = m g (R - r) cos th``."""

    def potential(self, lg):
        lg.potential("gravity", m * g * (R - r) * sp.cos(theta))


class FrictionAtTheCentre(DiskInCylinder):
    """The friction drawn at the centre C instead of the contact point P: its moment about C,
    ``(-r e.y) x (F e.x) . O.z = r F``, is missing from the disk's moment balance.  Seen as
    virtual work: at P (which does not slip) F does none; at C, which moves by
    ``(R - r) dth`` along e.x, it does ``F (R - r) dth``."""

    def loads(self, ne, sc):
        ne.gravity(-g * sc.O.y)
        ne.reaction("N", sc.disk, sc.e.y, at=sc.P)
        ne.reaction("F", sc.disk, sc.e.x)


class RingInertia(DiskInCylinder):
    """The disk given a ring's inertia, ``I_C = m r^2`` (a declaration the direct model and the
    referee share): the disk's kinetic energy from that declaration is
    ``m (R - r)^2 th'^2/2 + (m r^2) phi'^2/2 = m (R - r)^2 th'^2`` where
    ``3 m (R - r)^2 th'^2/4`` belongs: ``m (R - r)^2 th'^2/4`` too much in T of disk."""

    def newton_euler(self):
        sc = _p._Scene()
        sc.disk = RigidBody("disk", m, sc.C, sc.disk_frame, sp.diag(m * r**2 / 2,
                                                                       m * r**2 / 2, m * r**2))
        ne = _p.NewtonEuler("newton_euler", coordinates=[theta], ground=sc.O)
        self.loads(ne, sc)
        self.balances(ne, sc)
        return ne.equations()


#: (variant, the quantity named, a term of the edit (either side), hand-derived)
MISTAKES = [
    (SpinForgotten, "T of disk", m * (R - r)**2 * rate(theta)**2 / 4),
    (RollingAsOnAFlat, "T of disk", m * r * (2 * R - r) * rate(theta)**2 / 4),
    (GravitySign, "V of gravity", m * g * (R - r) * sp.cos(theta)),
    (FrictionAtTheCentre, "reaction F",
     sp.Symbol("F", real=True) * (R - r) * sp.Symbol("δθ", real=True)),
    (RingInertia, "T of disk", m * (R - r)**2 * rate(theta)**2 / 4),
]
