r"""Student mistakes injected into the rod sliding in a motor-driven tube
(tests/corpus/teacher_problems/rod_in_rotating_tube.py, whose docstring derives both models).

Correct, by hand: ``T = m (r'^2 + r^2 phi'^2)/2 + (m b^2/12) phi'^2/2 + (M L^2/3) phi'^2/2``,
``V = m g r sin phi + M g (L/2) sin phi``, ``phi = Omega t``; the direct form balances the rod
along u.x and u.y and the tube about its pivot O (the motor's couple ``tau``).
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


_p = _problem("rod_in_rotating_tube")
m, M, b, L, g, Omega, r, phi = _p.m, _p.M, _p.b, _p.L, _p.g, _p.Omega, _p.r, _p.phi
t = _p.t
N, tau = sp.symbols("N tau", real=True)


class RodInRotatingTube(_p.RodInRotatingTube):
    name = "teacher_rod_in_rotating_tube"


class TurningForgotten(RodInRotatingTube):
    """The rod's speed taken as ``r'`` alone (the tube's turning forgotten): the term
    ``m r^2 phi'^2/2 = m r^2 Omega^2/2`` of T of rod is missing."""

    def kinetic(self, lg):
        lg.kinetic("T of rod", m * rate(r)**2 / 2 + m * b**2 / 12 * rate(phi)**2 / 2)
        lg.kinetic("T of tube", M * L**2 / 3 * rate(phi)**2 / 2)


class GravityCosine(RodInRotatingTube):
    """The rod's height taken as ``r cos phi`` (the angle read from the vertical): ``V`` has
    ``m g r cos(Omega t)`` where ``m g r sin(Omega t)`` belongs."""

    def potential(self, lg):
        lg.potential("gravity", m * g * r * sp.cos(phi) + M * g * L / 2 * sp.sin(phi))


class RadialRowAsIfFixed(RodInRotatingTube):
    """The rod's u.x row written as in a tube at rest, ``-m g sin(Omega t) - m r'' = 0``: the
    centripetal ``m r Omega^2`` is missing."""

    def balances(self, ne, sc):
        ne.equation("sum F . u.x (rod), tube taken at rest",
                    {"gravity on rod": -m * g * sp.sin(Omega * t),
                     "inertia of rod": -m * rate(r, 2)})
        ne.linear_momentum(sc.rod, sc.u.y)
        ne.angular_momentum(sc.tube, sc.O.z, about=sc.pivot)


class TubeWeightDropped(RodInRotatingTube):
    """The tube's moment balance written without its weight, ``tau - N r = 0``:
    ``-M g (L/2) cos(Omega t)`` is missing.  The motion is unchanged (tau appears nowhere
    else); tau is ``M g (L/2) cos(Omega t)`` too small."""

    def balances(self, ne, sc):
        ne.linear_momentum(sc.rod, sc.u.x)
        ne.linear_momentum(sc.rod, sc.u.y)
        ne.equation("sum tau_O . O.z (tube), weight left out",
                    {"reaction tau": tau, "reaction N": -N * r})


#: (variant, the quantity named, a term of the edit (either side), hand-derived)
MISTAKES = [
    (TurningForgotten, "T of rod", m * r**2 * Omega**2 / 2),
    (GravityCosine, "V of gravity", m * g * r * sp.cos(Omega * t)),
    (RadialRowAsIfFixed, "tube taken at rest", m * r * Omega**2),
]
#: (variant, the reaction it changes, by how much: hand-derived)
REACTION_ONLY = [(TubeWeightDropped, "tau", -M * g * L / 2 * sp.cos(Omega * t))]
