r"""Student mistakes injected into the disk rolling on a cart held by a spring
(tests/corpus/teacher_problems/disk_on_cart.py, whose docstring derives both models).

Correct, by hand: ``T = M x'^2/2 + m (x' + s')^2/2 + (m r^2/2)(s'/r)^2/2``, ``V = k x^2/2``;
the direct form balances the disk along O.x, O.y and about its centre C, the cart along O.x
and O.y; the deck's ``N`` and ``F`` act at the contact P, the floor's ``N_f`` on the cart.
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


_p = _problem("disk_on_cart")
M, m, r, k, g, x, s = _p.M, _p.m, _p.r, _p.k, _p.g, _p.x, _p.s
F, N, N_f = sp.symbols("F N N_f", real=True)


class DiskOnCart(_p.DiskOnCart):
    name = "teacher_disk_on_cart"


class SpinForgotten(DiskOnCart):
    """The disk's spin left out of T: ``(m r^2/2)(s'/r)^2/2 = m s'^2/4`` missing."""

    def kinetic(self, lg):
        lg.kinetic("T of cart", M * rate(x)**2 / 2)
        lg.kinetic("T of disk", m * (rate(x) + rate(s))**2 / 2)


class VelocityRelativeToTheCart(DiskOnCart):
    """The disk's speed taken relative to the cart, ``s'`` (the cart's ``x'`` forgotten):
    ``m (x' + s')^2/2`` written ``m s'^2/2``, the terms ``m x'^2/2`` and ``m x' s'`` (the
    transport terms) missing."""

    def kinetic(self, lg):
        lg.kinetic("T of cart", M * rate(x)**2 / 2)
        lg.kinetic("T of disk", m * rate(s)**2 / 2 + m * r**2 / 4 * (rate(s) / r)**2)


class SpringPullsTheWrongWay(DiskOnCart):
    """The spring drawn pushing the cart away from the wall, ``+k x O.x``: its virtual work
    ``k x dx`` where ``-k x dx`` belongs (``V = -k x^2/2``)."""

    def loads(self, ne, sc):
        ne.gravity(-g * sc.O.y)
        ne.force("spring", sc.cart, k * x * sc.O.x)
        ne.reaction("N", sc.disk, sc.O.y, at=sc.P, against=sc.cart)
        ne.reaction("F", sc.disk, sc.O.x, at=sc.P, against=sc.cart)
        ne.reaction("N_f", sc.cart, sc.O.y)


class FrictionOnTheCartForgotten(DiskOnCart):
    """The friction drawn on the disk only (its reaction on the cart, ``-F``, forgotten): the
    pair no longer cancels; on the disk at P, whose material point moves with the cart, it
    does the virtual work ``F dx``."""

    def loads(self, ne, sc):
        ne.gravity(-g * sc.O.y)
        ne.linear_spring("spring", sc.cart, k, x, sc.O.x)
        ne.reaction("N", sc.disk, sc.O.y, at=sc.P, against=sc.cart)
        ne.reaction("F", sc.disk, sc.O.x, at=sc.P)
        ne.reaction("N_f", sc.cart, sc.O.y)


class MomentsAboutTheContact(DiskOnCart):
    """Moments about the contact point P, which moves with the cart, taken as if P were fixed:
    ``-(3 m r^2/2) phi'' = (3 m r/2) s''`` for the disk alone (N and F pass through P); about
    the accelerating P the term ``-m (r_PC x a_P) . O.z = -m r x''`` is missing."""

    def balances(self, ne, sc):
        ne.linear_momentum(sc.disk, sc.O.x)
        ne.linear_momentum(sc.disk, sc.O.y)
        ne.equation("sum tau_P . O.z (disk), P taken as fixed",
                    {"inertia of disk": -3 * m * r / 2 * rate(s, 2)})
        ne.linear_momentum(sc.cart, sc.O.x)
        ne.linear_momentum(sc.cart, sc.O.y)


class CartWeightDropped(DiskOnCart):
    """The cart's vertical balance written without its weight, ``N_f - N = 0``: ``-M g`` is
    missing.  The motion is unchanged; N_f is ``M g`` too small."""

    def balances(self, ne, sc):
        ne.linear_momentum(sc.disk, sc.O.x)
        ne.linear_momentum(sc.disk, sc.O.y)
        ne.angular_momentum(sc.disk, sc.O.z)
        ne.linear_momentum(sc.cart, sc.O.x)
        ne.equation("sum F . O.y (cart), weight left out",
                    {"reaction N_f": N_f, "reaction N": -N})


#: (variant, the quantity named, a term of the edit (either side), hand-derived)
MISTAKES = [
    (SpinForgotten, "T of disk", m * rate(s)**2 / 4),
    (VelocityRelativeToTheCart, "T of disk", m * rate(x) * rate(s)),
    (SpringPullsTheWrongWay, "spring", k * x**2 / 2),
    (FrictionOnTheCartForgotten, "reaction F", F * sp.Symbol("δx", real=True)),
    (MomentsAboutTheContact, "P taken as fixed", m * r * rate(x, 2)),
]
#: (variant, the reaction it changes, by how much: hand-derived)
REACTION_ONLY = [(CartWeightDropped, "N_f", -M * g)]
