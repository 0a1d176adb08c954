r"""Student mistakes injected into the double Atwood machine with massive pulleys
(tests/corpus/teacher_problems/double_atwood.py, whose docstring derives both models).

Correct, by hand: ``T = m1 x'^2/2 + (M a^2/2)(x'/a)^2/2 + M_B x'^2/2 + (M_B b^2/2)(y'/b)^2/2
+ m2 (x' - y')^2/2 + m3 (x' + y')^2/2``; the direct form balances m1, A (vertically and about
its axle), B (vertically and about its centre), m2 and m3.

``REACTION_ONLY`` lists mistakes that leave the motion as it is and change a reaction only:
two models (the direct one alone derives the reactions) cannot see them; the toolkit's Kane
referee, derived from the direct model's declarations, must.
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


_p = _problem("double_atwood")
m1, m2, m3, M, MB, a, b, g, x, y = (_p.m1, _p.m2, _p.m3, _p.M, _p.MB, _p.a, _p.b, _p.g, _p.x,
                                     _p.y)
T1, T2, T3, T4, R_A = sp.symbols("T1 T2 T3 T4 R_A", real=True)


class DoubleAtwood(_p.DoubleAtwood):
    name = "teacher_double_atwood"


class MassivePulleyIgnored(DoubleAtwood):
    """Pulley A's kinetic energy left out: ``(M a^2/2)(x'/a)^2/2 = M x'^2/4`` missing."""

    def kinetic(self, lg):
        xd, yd = rate(x), rate(y)
        lg.kinetic("T of m1", m1 * xd**2 / 2)
        lg.kinetic("T of pulley B", MB * xd**2 / 2 + MB * b**2 / 2 * (yd / b)**2 / 2)
        lg.kinetic("T of m2", m2 * (xd - yd)**2 / 2)
        lg.kinetic("T of m3", m3 * (xd + yd)**2 / 2)


class PulleyBAsARing(DoubleAtwood):
    """Pulley B's spin with a ring's inertia ``M_B b^2``: ``M_B y'^2/2`` where ``M_B y'^2/4``
    belongs, ``M_B y'^2/4`` too much in T of pulley B."""

    def kinetic(self, lg):
        xd, yd = rate(x), rate(y)
        lg.kinetic("T of m1", m1 * xd**2 / 2)
        lg.kinetic("T of pulley A", M * a**2 / 2 * (xd / a)**2 / 2)
        lg.kinetic("T of pulley B", MB * xd**2 / 2 + MB * b**2 * (yd / b)**2 / 2)
        lg.kinetic("T of m2", m2 * (xd - yd)**2 / 2)
        lg.kinetic("T of m3", m3 * (xd + yd)**2 / 2)


class RelativeVelocitySign(DoubleAtwood):
    """m3's speed written ``x' - y'`` (it rises relative to B, so ``x' + y'``):
    ``m3 (x' - y')^2/2`` has ``-m3 x' y'`` where ``m3 x' y'`` belongs, ``2 m3 x' y'`` apart."""

    def kinetic(self, lg):
        xd, yd = rate(x), rate(y)
        lg.kinetic("T of m1", m1 * xd**2 / 2)
        lg.kinetic("T of pulley A", M * a**2 / 2 * (xd / a)**2 / 2)
        lg.kinetic("T of pulley B", MB * xd**2 / 2 + MB * b**2 / 2 * (yd / b)**2 / 2)
        lg.kinetic("T of m2", m2 * (xd - yd)**2 / 2)
        lg.kinetic("T of m3", m3 * (xd - yd)**2 / 2)


class WeightOfBSign(DoubleAtwood):
    """B's weight counted as pulling m1's side: ``V = -g x (m1 + M_B - m2 - m3) - ...``,
    ``-g M_B x`` where ``g M_B x`` belongs (``2 g M_B x`` apart)."""

    def potential(self, lg):
        lg.potential("gravity", -g * x * (m1 + MB - m2 - m3) - g * y * (m2 - m3))


class PulleyAsIfMassless(DoubleAtwood):
    """Pulley A's moment balance written as if it were massless, ``(T1 - T2) a = 0``:
    ``-I_A x''/a = -M a x''/2`` is missing."""

    def balances(self, ne, sc):
        ne.linear_momentum(sc.m1, sc.O.y)
        ne.linear_momentum(sc.A, sc.O.y)
        ne.equation("sum tau_O . O.z (pulley A), taken as massless",
                    {"reaction T1": T1 * a, "reaction T2": -T2 * a})
        ne.linear_momentum(sc.B, sc.O.y)
        ne.angular_momentum(sc.B, sc.O.z)
        ne.linear_momentum(sc.m2, sc.O.y)
        ne.linear_momentum(sc.m3, sc.O.y)


class PulleyWeightDropped(DoubleAtwood):
    """The axle's balance written without pulley A's weight, ``R_A - T1 - T2 = 0``: ``-M g``
    is missing.  The motion is unchanged (R_A appears nowhere else); R_A is ``M g`` too
    small."""

    def balances(self, ne, sc):
        ne.linear_momentum(sc.m1, sc.O.y)
        ne.equation("sum F . O.y (pulley A), weight left out",
                    {"reaction R_A": R_A, "reaction T1": -T1, "reaction T2": -T2})
        ne.angular_momentum(sc.A, sc.O.z)
        ne.linear_momentum(sc.B, sc.O.y)
        ne.angular_momentum(sc.B, sc.O.z)
        ne.linear_momentum(sc.m2, sc.O.y)
        ne.linear_momentum(sc.m3, sc.O.y)


#: (variant, the quantity named, a term of the edit (either side), hand-derived)
MISTAKES = [
    (MassivePulleyIgnored, "T of pulley A", M * rate(x)**2 / 4),
    (PulleyBAsARing, "T of pulley B", MB * rate(y)**2 / 4),
    (RelativeVelocitySign, "T of m3", 2 * m3 * rate(x) * rate(y)),
    (WeightOfBSign, "V of gravity", 2 * g * MB * x),
    (PulleyAsIfMassless, "taken as massless", M * a * rate(x, 2) / 2),
]
#: (variant, the reaction it changes, by how much: hand-derived)
REACTION_ONLY = [(PulleyWeightDropped, "R_A", -M * g)]
