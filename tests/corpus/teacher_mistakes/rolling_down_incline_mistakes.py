r"""Student mistakes injected into the disk rolling down an incline
(tests/corpus/teacher_problems/rolling_down_incline.py, whose docstring derives both models).

Correct, by hand: ``T = m x'^2/2 + (m r^2/2) phi'^2/2``, ``V = -m g x sin alpha``, the rolling
``-x' + r phi' = 0`` closed by the multiplier ``F`` (the friction up the slope); the direct
form draws ``F`` along -n.x at the contact P and declares the rolling with ``ne.rolling``.
Two of these change the friction's sign only (the motion is the same): the multiplier model
derives ``F`` a second time, so two models see them.
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


_p = _problem("rolling_down_incline")
m, r, g, alpha, x, phi = _p.m, _p.r, _p.g, _p.alpha, _p.x, _p.phi


class RollingDownIncline(_p.RollingDownIncline):
    name = "teacher_rolling_down_incline"


class MultiplierSignReversed(RollingDownIncline):
    """The constraint written ``x' - r phi' = 0`` with the multiplier named F: its force on x
    is ``+F``, so the multiplier is the friction with the opposite sign, ``-m g sin alpha/3``
    where the free-body diagram's ``F`` is ``m g sin alpha/3``."""

    def constraint(self, lg):
        lg.velocity_constraint("F", [1, -r])


class FrictionDrawnDownTheSlope(RollingDownIncline):
    """The friction's arrow drawn down the slope (+n.x): the direct form's F is
    ``-m g sin alpha/3`` where the multiplier (the friction up the slope) is
    ``m g sin alpha/3``."""

    def loads(self, ne, sc):
        ne.gravity(-g * sc.O.y)
        ne.reaction("N", sc.disk, sc.n.y, at=sc.P)
        ne.reaction("F", sc.disk, sc.n.x, at=sc.P)


class SphereInertia(RollingDownIncline):
    """The disk's spin given a sphere's inertia, ``(2/5) m r^2``: ``m r^2 phi'^2/5`` where
    ``m r^2 phi'^2/4`` belongs."""

    def lagrange(self):
        lg = _p.Lagrangian("lagrange", coordinates=[x, phi])
        lg.kinetic("T of disk", m * rate(x)**2 / 2 + m * r**2 / 5 * rate(phi)**2)
        lg.potential("gravity", -m * g * x * sp.sin(alpha))
        self.constraint(lg)
        return lg.equations()


class HeightSign(RollingDownIncline):
    """The height taken as rising with x: ``V = m g x sin alpha``."""

    def lagrange(self):
        lg = _p.Lagrangian("lagrange", coordinates=[x, phi])
        lg.kinetic("T of disk", m * rate(x)**2 / 2 + m * r**2 / 4 * rate(phi)**2)
        lg.potential("gravity", m * g * x * sp.sin(alpha))
        self.constraint(lg)
        return lg.equations()


#: (variant, the quantity named, a term of the edit (either side), hand-derived)
MISTAKES = [
    (MultiplierSignReversed, "reaction F", m * g * sp.sin(alpha) / 3),
    (FrictionDrawnDownTheSlope, "reaction F", m * g * sp.sin(alpha) / 3),
    (SphereInertia, "T of disk", m * r**2 * rate(phi)**2 / 5),
    (HeightSign, "V of gravity", m * g * x * sp.sin(alpha)),
]
