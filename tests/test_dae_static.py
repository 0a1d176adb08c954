"""A massless part's static rows as constraints of the DAE forms (dualmech.numeric.formulations).

The model case is the copying machine (problems/copying_machine.py, Example 14): the bar is
massless, so ``theta`` has no inertia and its rows are static.  The reference is independent
of the DAE machinery: the problem's ``reduced`` model (``theta`` eliminated by hand, ``m2 y''
+ b y' + k_e y = F``, an ODE) at DOP853's ``rtol = 1e-12``, lifted to ``(y, theta)`` by the
source's static equation ``theta = k2 L y / (k2 L^2 + k1 a^2)``; the pivot force is the hand
``R_O = k1 k2 a (L - a) y / (k2 L^2 + k1 a^2)`` of the module docstring.
"""
import numpy as np
import pytest

from dualmech.numeric.formulations import formulations
from dualmech.numeric.simulation import problem_parameters
from dualmech.problems import get

SPAN = (0.0, 2.0)
TE = np.linspace(*SPAN, 41)
STABS = ("none", "baumgarte", "projection")


@pytest.fixture(scope="module")
def machine():
    p = get("copying_machine")
    forms, skipped = formulations(p, stabilisations=STABS)
    values = {s.name: v for s, v in problem_parameters(p).items()}
    return {f.name: f for f in forms}, skipped, values


@pytest.fixture(scope="module")
def lifted(machine):
    forms, _, v = machine
    run = forms["reduced"].run("DOP853", SPAN, TE, rtol=1e-12)
    assert run.success
    ratio = v["k2"] * v["L"] / (v["k2"] * v["L"]**2 + v["k1"] * v["a"]**2)
    y, yd = run.y
    return np.vstack([y, ratio * y]), np.vstack([yd, ratio * yd])


def test_every_model_starts_on_its_static_balance_with_m2_where_the_problem_put_it(machine):
    forms, _, v = machine
    ratio = v["k2"] * v["L"] / (v["k2"] * v["L"]**2 + v["k1"] * v["a"]**2)
    for name, f in forms.items():
        if f.kind == "dae":
            y, theta = f.y0[0], f.y0[1]
            assert y == pytest.approx(0.01, abs=1e-15), name    # the default state's y
            assert theta == pytest.approx(ratio * y, rel=1e-13), name


@pytest.mark.parametrize("model", ["lagrange", "newton_euler", "multiplier"])
@pytest.mark.parametrize("stab", ["index 1", "Baumgarte", "projection"])
def test_each_form_follows_the_hand_reduced_motion(machine, lifted, model, stab):
    forms, _, v = machine
    f = forms[f"{model} (DAE, {stab})"]
    run = f.run("DOP853", SPAN, TE, rtol=1e-10)
    assert run.success, run.message
    want = f.from_reference(TE, *lifted)
    err = np.abs(run.y - want) / f.scales[:, None]
    assert err.max() <= 1e-8, err.max()
    g, _ = f.drift(run.y)
    assert np.abs(g).max() <= 1e-9          # the static balance holds (N m, forces ~ 10 N)
    if model != "lagrange":                 # the pivot force against the hand formula
        y = lifted[0][0]
        hand = v["k1"] * v["k2"] * v["a"] * (v["L"] - v["a"]) * y / \
            (v["k2"] * v["L"]**2 + v["k1"] * v["a"]**2)
        R = f.reactions(TE, run.y)["R_O"]
        assert np.abs(R - hand).max() <= 1e-7 * np.abs(hand).max()
