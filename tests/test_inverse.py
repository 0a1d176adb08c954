"""Inverse dynamics (dualmech/model/inverse.py): inputs and reactions along a prescribed motion."""
import math
import sys

import pytest
import sympy as sp

from dualmech import EquationSet, ModelError, coordinate, t
from dualmech.model.inverse import peak, required_inputs

x, th = coordinate("x"), coordinate("theta")
m, l, g, k = sp.symbols("m l g k", positive=True)
F, tau, N = sp.symbols("F tau N", real=True)


def _pendulum_with_normal_force() -> EquationSet:
    """Bob on a rod driven by a torque; N the rod's pull (by hand)."""
    return EquationSet("pendulum", (th,), (
        m * l**2 * th.diff(t, 2) + m * g * l * sp.sin(th) - tau,
        N - m * g * sp.cos(th) - m * l * th.diff(t)**2), (N,))


def test_torque_and_reaction_along_a_uniform_rotation():
    # theta = w t: the torque balances gravity, the rod pulls m g cos + m l w^2 (by hand)
    w = sp.Symbol("w", positive=True)
    need = required_inputs(_pendulum_with_normal_force(), [tau], {th: w * t})
    assert sp.simplify(need[tau] - m * g * l * sp.sin(w * t)) == 0
    assert sp.simplify(need[N] - (m * g * sp.cos(w * t) + m * l * w**2)) == 0


def test_two_inputs_on_two_coordinates():
    eqs = EquationSet("two", (x, th), (m * x.diff(t, 2) + k * x - F,
                                        m * l**2 * th.diff(t, 2) - tau))
    need = required_inputs(eqs, [F, tau], {x: t**2, th: t**3})
    assert need == {F: 2 * m + k * t**2, tau: 6 * m * l**2 * t}


@pytest.mark.parametrize("inputs, motion, message", [
    ([tau], {}, "must prescribe every coordinate"),
    ([F], {th: t}, "do not appear"),
])
def test_bad_input_is_refused_with_a_message(inputs, motion, message):
    with pytest.raises(ModelError, match=message):
        required_inputs(_pendulum_with_normal_force(), inputs, motion)


def test_inputs_must_enter_linearly_and_be_as_many_as_the_equations():
    eqs = EquationSet("nonlinear", (x,), (m * x.diff(t, 2) - F**2 / m,))
    with pytest.raises(ModelError, match="not linear"):
        required_inputs(eqs, [F], {x: t})
    eqs = EquationSet("one", (x,), (m * x.diff(t, 2) - F - tau,))
    with pytest.raises(ModelError, match="1 equations but 2 inputs"):
        required_inputs(eqs, [F, tau], {x: t})


def test_inputs_that_act_alike_are_not_determined():
    eqs = EquationSet("alike", (x, th), (m * x.diff(t, 2) - F - tau,
                                          m * th.diff(t, 2) - F - tau))
    with pytest.raises(ModelError, match="do not determine"):
        required_inputs(eqs, [F, tau], {x: t**2, th: t**2})


def test_peak_finds_an_interior_maximum_and_an_end():
    when, value = peak(sp.sin(t) * sp.exp(-t / 5), (0, 4))
    # d/dt (sin t e^{-t/5}) = 0 at tan t = 5; a maximum is flat, so its time is found only
    # to about sqrt(eps) (value error ~ f'' dt^2 / 2 must stay at rounding level)
    assert math.isclose(when, math.atan(5), abs_tol=4 * math.sqrt(sys.float_info.epsilon))
    assert math.isclose(value, math.sin(math.atan(5)) * math.exp(-math.atan(5) / 5),
                        rel_tol=1e-12)
    assert peak(3 - t, (0, 4)) == (0.0, 3.0)


def test_peak_needs_every_parameter():
    with pytest.raises(ModelError, match="lacks values"):
        peak(m * t, (0, 1))
    assert peak(m * t, (0, 1), {m: 2.0}) == (1.0, 2.0)
