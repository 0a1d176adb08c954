r"""Student mistakes injected into the block on a rough incline
(tests/corpus/teacher_problems/rough_incline.py, whose docstring derives both models).

Correct, by hand: ``T = m s'^2/2``, ``V = k s^2/2 - m g s sin alpha``, dissipation
``c s'^2/2``, the friction's virtual work ``-mu m g cos alpha ds``; the direct form balances
the block along n.x (down the slope) and n.y, friction ``-mu N n.x``.
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


_p = _problem("rough_incline")
m, k, c, mu, alpha, g, s = _p.m, _p.k, _p.c, _p.mu, _p.alpha, _p.g, _p.s
ds = sp.Symbol("δs", real=True)


class RoughIncline(_p.RoughIncline):
    name = "teacher_rough_incline"


class GravityCosineForSine(RoughIncline):
    """The height lost taken as ``s cos alpha``: ``V`` has ``-m g s cos alpha`` where
    ``-m g s sin alpha`` belongs."""

    def potential(self, lg):
        lg.potential("spring", k * s**2 / 2)
        lg.potential("gravity", -m * g * s * sp.cos(alpha))


class SpringSign(RoughIncline):
    """The spring drawn pushing the block further down: ``+k s n.x``; its virtual work
    ``k s ds`` where ``-k s ds`` belongs (``V = -k s^2/2``)."""

    def loads(self, ne, sc):
        ne.gravity(-g * sc.O.y)
        ne.force("spring", sc.block, k * s * sc.n.x)
        ne.linear_damper("damper", sc.block, c, rate(s), sc.n.x)
        N = ne.reaction("N", sc.block, sc.n.y)
        ne.force("friction", sc.block, -mu * N * sc.n.x)


class DamperSign(RoughIncline):
    """Rayleigh's function with the wrong sign, ``-c s'^2/2``: the damper's virtual work
    ``c s' ds`` where ``-c s' ds`` belongs."""

    def lagrange(self):
        lg = _p.Lagrangian("lagrange", coordinates=[s])
        lg.kinetic("T of block", m * rate(s)**2 / 2)
        self.potential(lg)
        lg.dissipation("damper", -c * rate(s)**2 / 2)
        lg.generalized_force("friction", [-mu * m * g * sp.cos(alpha)])
        return lg.equations()


class FrictionWithoutCosine(RoughIncline):
    """The normal force taken as the whole weight, ``N = m g``: the friction's virtual work
    ``-mu m g ds`` where ``-mu m g cos alpha ds`` belongs."""

    def lagrange(self):
        lg = _p.Lagrangian("lagrange", coordinates=[s])
        lg.kinetic("T of block", m * rate(s)**2 / 2)
        self.potential(lg)
        lg.dissipation("damper", c * rate(s)**2 / 2)
        lg.generalized_force("friction", [-mu * m * g])
        return lg.equations()


class NormalBalanceByHandWithoutWeight(RoughIncline):
    """The n.y row written by hand as ``N = 0`` (the weight's ``-m g cos alpha`` left out):
    the friction then vanishes and the motion changes."""

    def newton_euler(self):
        sc = _p._Scene()
        ne = _p.NewtonEuler("newton_euler", coordinates=[s], ground=sc.O)
        self.loads(ne, sc)
        ne.linear_momentum(sc.block, sc.n.x)
        ne.equation("sum F . n.y (block), weight left out",
                    {"reaction N": sp.Symbol("N", real=True)})
        return ne.equations()


#: (variant, the quantity named, a term of the edit (either side), hand-derived)
MISTAKES = [
    (GravityCosineForSine, "V of gravity", m * g * s * sp.cos(alpha)),
    (SpringSign, "spring", k * s**2 / 2),
    (DamperSign, "damper", c * rate(s) * ds),
    (FrictionWithoutCosine, "friction", mu * m * g * ds),
    (NormalBalanceByHandWithoutWeight, "weight left out", m * g * sp.cos(alpha)),
]
