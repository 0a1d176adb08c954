"""A derivation written in other coordinates than the reference is explained in its own.

Issue 6, point 2: "show the residual in each model's own coordinates, labels and terms".
The verdict is reached in the reference coordinates; the explanation carries the state over
by the problem's declared coordinate map (``Problem.coordinate_maps``) and writes the
symbolic residual through its inverse.

Reference values are hand derivations from the problems' docstrings, written in each test:
the maps ``y1 = x1``, ``y2 = x2 - x1 - l0`` (falling container, Example 15), ``X = x + a
sin(theta)`` (trolley pendulum), ``r = a`` (simple pendulum's multiplier model), and the
equations of motion printed there.  Tolerances: the states carry 30 digits and are shown as
doubles, so values agree to ~1e-15 relative; 1e-9 leaves room only for rounding.
"""
from __future__ import annotations

import dataclasses
import math
import re

import pytest
import sympy as sp

from dualmech import EquationSet, coordinate, t
from dualmech.verify.check import compare
from dualmech.model.equations import state_symbols
from dualmech.verify.coordinates import OwnCoordinates
from dualmech.verify.display import dotted
from dualmech.verify.explain import explain_model
from dualmech.verify.sampling import Context
from dualmech.problems import falling_container as fc
from dualmech.problems import trolley_pendulum as tp
from dualmech.problems.simple_pendulum import SimplePendulum

D = lambda q, n=1: q.diff(t, n)  # noqa: E731
REFERENCE_NAMES = re.compile(r"\bx[12]\b")


class FallingContainerDashpotFlipped(fc.FallingContainer):
    """The direct model in ``(y1, y2)`` with the dashpot's force on both bodies reversed."""

    def newton_euler_y(self):
        wrong = super().newton_euler_y().flipped("dashpot")
        return dataclasses.replace(wrong, name="newton_euler_y")


class TrolleyBobWithoutTrolley(tp.TrolleyPendulum):
    """The ``(X, theta)`` Lagrangian without the trolley's kinetic energy."""

    def bob_coordinates(self):
        wrong = super().bob_coordinates().without("T of trolley")
        return dataclasses.replace(wrong, name="bob_coordinates")


class PendulumMultiplierWeightReversed(SimplePendulum):
    """The ``(theta, r)`` multiplier model with gravity reversed."""

    def multiplier(self):
        return dataclasses.replace(super().multiplier().flipped("gravity"), name="multiplier")


def explained(cls, name: str) -> dict:
    """``{label: Mismatch}`` of model ``name``, explained as ``compare`` explains it, with the
    problem (and so its coordinate maps) handed to the explanation."""
    problem = cls()
    j = compare(problem).judgement
    assert j.odd == [name]
    ctx = Context(problem.model(problem.reference).coordinates, problem.parameter_symbols,
                  problem)
    against = tuple(a for a in j.majority if a != name)
    return {mm.equation: mm for mm in explain_model(name, j, against, ctx, problem=problem)}


@pytest.fixture(scope="module")
def container():
    return explained(FallingContainerDashpotFlipped, "newton_euler_y")


# -- the falling container: y1 = x1, y2 = x2 - x1 - l0 ------------------------------------------
def test_state_terms_and_residual_are_in_y(container):
    assert set(container) == {"sum F . O.y (container)", "sum F . O.y (m2)"}
    for mm in container.values():
        assert {"y1", "y2", "y1'", "y2'"} <= set(mm.state)
        text = str(mm) + repr(mm.to_dict())
        assert not REFERENCE_NAMES.search(text), text
        assert "shown in the reference coordinates" not in mm.reason


def test_residual_is_the_reversed_dashpot(container):
    """By hand (docstring's free-body diagrams in y): the container's row
    ``-m1 y1'' - m1 g + k y2 + c y2'`` with the dashpot reversed leaves ``-2 c y2'`` on the
    true motion, m2's row ``-m2 (y1'' + y2'') - m2 g - k y2 - c y2'`` leaves ``+2 c y2'``."""
    c, y2 = fc.c, fc.y2
    assert container["sum F . O.y (container)"].residual == dotted(-2 * c * D(y2))
    assert container["sum F . O.y (m2)"].residual == dotted(2 * c * D(y2))


def test_terms_hold_the_dashpot_with_the_wrong_sign(container):
    """The dashpot's term is ``-c y2'`` in the container's row and ``+c y2'`` in m2's (the
    free-body diagrams have ``+c y2'`` on the container, ``-c y2'`` on m2); with it reversed
    the row holds, and the row's value is twice the term."""
    for label, sign in (("sum F . O.y (container)", -1), ("sum F . O.y (m2)", 1)):
        mm = container[label]
        s = mm.state
        terms = dict(mm.terms)
        dashpot = terms[dotted(sign * fc.c * D(fc.y2))]
        assert dashpot == pytest.approx(sign * s["c"] * s["y2'"], rel=1e-12)
        scale = sum(abs(v) for v in terms.values())
        assert mm.value - 2 * dashpot == pytest.approx(0, abs=1e-12 * scale)
        assert mm.value == pytest.approx(2 * sign * s["c"] * s["y2'"], rel=1e-9)


def test_accelerations_in_y_follow_the_true_motion(container):
    """The shown ``y`` state is the true motion's: the docstring's y equations
    ``(m1 + m2) y1'' + m2 y2'' + (m1 + m2) g = 0``, ``m2 (y1'' + y2'') + c y2' + k y2 + m2 g
    = 0`` give ``m1 y1'' = c y2' + k y2 - m1 g`` at the shown ``y2, y2'``; the term
    ``-m1 y1''`` must have that value (a ``y2`` off by ``l0`` would not)."""
    for mm in container.values():
        s = mm.state
        y1dd = (s["c"] * s["y2'"] + s["k"] * s["y2"]) / s["m1"] - s["g"]
        y2dd = -(s["c"] * s["y2'"] + s["k"] * s["y2"]) / s["m2"] - s["g"] - y1dd
        terms = dict(mm.terms)
        if "-m1*y1''" in terms:
            assert terms["-m1*y1''"] == pytest.approx(-s["m1"] * y1dd, rel=1e-9)
        else:
            assert terms["-m2*y2''"] == pytest.approx(-s["m2"] * y2dd, rel=1e-9)


def test_the_map_carries_a_state_over_by_hand():
    """``y1 = x1``, ``y2 = x2 - x1 - l0`` and their rates, at a state chosen here."""
    problem = fc.FallingContainer()
    own = OwnCoordinates(problem.model("lagrange_y"), problem.coordinate_maps()["lagrange_y"],
                         (fc.x1, fc.x2))
    X1, X2 = state_symbols(fc.x1), state_symbols(fc.x2)
    Y1, Y2 = state_symbols(fc.y1), state_symbols(fc.y2)
    at = {fc.l0: 0.3, t: 1.0, X1.q: 2.0, X2.q: 2.45, X1.qd: -1.5, X2.qd: 0.5,
          X1.qdd: -9.0, X2.qdd: 3.0}
    y = {k: float(v) for k, v in own.state(at).items()}
    assert (y[Y1.q], y[Y1.qd], y[Y1.qdd]) == (2.0, -1.5, -9.0)
    assert y[Y2.q] == pytest.approx(2.45 - 2.0 - 0.3, rel=1e-15)
    assert (y[Y2.qd], y[Y2.qdd]) == (2.0, 12.0)
    assert own.inverse(at) == {fc.x1: fc.y1, fc.x2: fc.y1 + fc.y2 + fc.l0}


# -- other maps: a nonlinear one with a shared coordinate, one with more coordinates -------------
def test_trolley_in_bob_coordinates_is_explained_in_x_big_and_theta():
    """By hand (docstring): without ``M (X' - a theta' cos)^2/2`` the X row loses
    ``d/dt (M (X' - a theta' cos theta)) = M x''``, so it leaves ``-M x''`` on the true motion,
    with ``x''`` from ``(M + m) x'' + m a cos th th'' = F + P + m a th'^2 sin th`` and
    ``m a cos th x'' + m a^2 th'' = P a cos th - m g a sin th``."""
    mm = explained(TrolleyBobWithoutTrolley, "bob_coordinates")["Lagrange, X"]
    s = mm.state
    assert {"X", "X'", "theta", "theta'"} <= set(s) and "x" not in s and "x'" not in s
    assert not re.search(r"\bx\b", str(mm)), str(mm)
    M, m, a, g, F, P = (s[k] for k in ("M", "m", "a", "g", "F", "P"))
    th, th1 = s["theta"], s["theta'"]
    A = [[M + m, m * a * math.cos(th)], [m * a * math.cos(th), m * a**2]]
    b = [F + P + m * a * th1**2 * math.sin(th),
         P * a * math.cos(th) - m * g * a * math.sin(th)]
    det = A[0][0] * A[1][1] - A[0][1] * A[1][0]
    xdd = (b[0] * A[1][1] - A[0][1] * b[1]) / det
    assert mm.value == pytest.approx(-M * xdd, rel=1e-9)
    assert "X" not in mm.residual   # x'' does not depend on where the trolley is
    assert mm.residual.startswith("-M*") and "theta" in mm.residual


def test_multiplier_model_with_an_extra_coordinate():
    """``r = a`` fixed by the map: the state shows ``r = a``, ``r' = 0``; the theta row
    ``M r^2 th'' + M g r sin th`` with gravity reversed leaves ``-2 M g a sin th`` on the
    true motion (``th'' = -g sin th / a``)."""
    mm = explained(PendulumMultiplierWeightReversed, "multiplier")["Lagrange, theta"]
    s = mm.state
    assert s["r"] == pytest.approx(s["a"], rel=1e-15) and s["r'"] == 0
    expect = -2 * s["M"] * s["g"] * s["a"] * math.sin(s["theta"])
    assert mm.value == pytest.approx(expect, rel=1e-9)
    M, a, g = sp.symbols("M a g", positive=True)
    assert mm.residual == dotted(-2 * M * a * g * sp.sin(coordinate("theta")))


def test_an_inverse_branch_goes_through_the_state_or_none_is_given():
    """``x = l sin th``, ``y = l cos th``: at ``th = 2.5`` the inverse is ``pi - asin(x/l)``
    (``asin`` alone gives 0.64); at ``th = -2.5`` neither ``asin`` nor ``acos`` branch
    returns it, so no formula is offered (the residual then says so) rather than a wrong one."""
    th, x, y = coordinate("theta"), coordinate("x"), coordinate("y")
    l, m, g = sp.symbols("l m g", positive=True)
    own = OwnCoordinates(EquationSet("cartesian", (x, y), (m * D(x, 2), m * D(y, 2) - m * g)),
                         {x: l * sp.sin(th), y: l * sp.cos(th)}, (th,))
    S = state_symbols(th)
    at = {l: 1.3, m: 1.0, g: 9.8, t: 0.0, S.qd: 0.4, S.qdd: -1.0}
    inv = own.inverse({**at, S.q: 2.5})
    back = inv[th].xreplace({x: 1.3 * math.sin(2.5), l: 1.3})
    assert float(back) == pytest.approx(2.5, rel=1e-14)
    assert own.inverse({**at, S.q: -2.5}) is None
