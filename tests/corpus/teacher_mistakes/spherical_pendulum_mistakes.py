r"""Student mistakes injected into the spherical pendulum
(tests/corpus/teacher_problems/spherical_pendulum.py, whose docstring derives both models).

Correct, by hand: ``T = m l^2 (th'^2 + sin^2 th phi'^2)/2``, ``V = -m g l cos th``; the bob's
``m a`` along arm.x, h.y and arm.z, the rod's pull ``T`` along arm.z.
"""
from __future__ import annotations

import importlib.util
from pathlib import Path

import sympy as sp

from dualmech import rate


def _problem(name: str):
    path = Path(__file__).parents[1] / "teacher_problems" / f"{name}.py"
    spec = importlib.util.spec_from_file_location(f"teacher_problem_{name}", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod



_p = _problem("spherical_pendulum")
m, l, g, theta, phi = _p.m, _p.l, _p.g, _p.theta, _p.phi
T = sp.Symbol("T", real=True)


class SphericalPendulum(_p.SphericalPendulum):
    name = "teacher_spherical_pendulum"


class SinSquaredMissed(SphericalPendulum):
    """The azimuthal speed taken as ``l phi'`` (the bob's distance from the axis is
    ``l sin th``): ``m l^2 phi'^2/2`` where ``m l^2 sin^2 th phi'^2/2`` belongs."""

    def kinetic(self, lg):
        lg.kinetic("T of bob", m * l**2 * (rate(theta)**2 + rate(phi)**2) / 2)


class GravitySign(SphericalPendulum):
    """``V = m g l cos th`` (height measured downwards)."""

    def potential(self, lg):
        lg.potential("gravity", m * g * l * sp.cos(theta))


class CoriolisDropped(SphericalPendulum):
    """The h.y row written by hand without the Coriolis term: ``-m l sin th phi'' = 0``;
    ``-2 m l cos th th' phi'`` is missing."""

    def newton_euler(self):
        sc = _p._Scene()
        ne = _p.NewtonEuler("newton_euler", coordinates=[theta, phi], ground=sc.O)
        self.loads(ne, sc)
        ne.linear_momentum(sc.bob, sc.arm.x)
        ne.equation("sum F . h.y (bob), Coriolis left out",
                    {"inertia of bob": -m * l * sp.sin(theta) * rate(phi, 2)})
        ne.linear_momentum(sc.bob, sc.arm.z)
        return ne.equations()


class CentripetalSign(SphericalPendulum):
    """The arm.x row written by hand with the centripetal part's sign wrong:
    ``-m g sin th - m l th'' - m l sin th cos th phi'^2 = 0``; ``+m l sin th cos th phi'^2``
    belongs."""

    def newton_euler(self):
        sc = _p._Scene()
        ne = _p.NewtonEuler("newton_euler", coordinates=[theta, phi], ground=sc.O)
        self.loads(ne, sc)
        ne.equation("sum F . arm.x (bob), by hand",
                    {"gravity on bob": -m * g * sp.sin(theta),
                     "inertia of bob": -m * l * rate(theta, 2)
                     - m * l * sp.sin(theta) * sp.cos(theta) * rate(phi)**2})
        ne.linear_momentum(sc.bob, sc.h.y)
        ne.linear_momentum(sc.bob, sc.arm.z)
        return ne.equations()


class TensionVertical(SphericalPendulum):
    """The rod's pull drawn straight up (O.z) instead of along the rod: the bob rises by
    ``l sin th dth``, so it does the virtual work ``T l sin th dth``."""

    def loads(self, ne, sc):
        ne.gravity(-g * sc.O.z)
        ne.reaction("T", sc.bob, sc.O.z)


#: (variant, the quantity named, a term of the edit (either side), hand-derived)
MISTAKES = [
    (SinSquaredMissed, "T of bob", m * l**2 * rate(phi)**2 / 2),
    (GravitySign, "V of gravity", m * g * l * sp.cos(theta)),
    (CoriolisDropped, "Coriolis left out", 2 * m * l * sp.cos(theta) * rate(theta) * rate(phi)),
    (CentripetalSign, "by hand", m * l * sp.sin(theta) * sp.cos(theta) * rate(phi)**2),
    (TensionVertical, "reaction T", T * l * sp.sin(theta) * sp.Symbol("δθ", real=True)),
]
