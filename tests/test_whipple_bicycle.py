"""The benchmark bicycle (problems/whipple_bicycle.py) against independent references:

* Meijaard, Papadopoulos, Ruina & Schwab (2007), Table 2 and section 5 (the printed claims,
  judged by the toolkit like every printed answer);
* sympy's own test of the same benchmark (sympy/physics/mechanics/tests/test_kane3.py,
  ``test_bicycle``): Kane's method on Moore's parametrisation, linearised, its state matrix
  in (roll, steer, roll rate, steer rate) transcribed below as ``SYMPY_RES``.  Its eigenvalues
  must be ours; the matrices differ by the choice of state and sign conventions.
"""
import numpy as np
import pytest

from dualmech.problems import get
from dualmech.verify.stability_claims import _Spectra, judge_stability_claims


def sympy_res(v: float) -> np.ndarray:
    """sympy test_kane3.py, ``Res`` (precomputed there for comparison), at speed ``v``."""
    return np.array([
        [0, 0, 1.0, 0],
        [0, 0, 0, 1.0],
        [9.48977444677355, -0.891197738059089 * v**2 - 0.571523173729245,
         -0.105522449805691 * v, -0.330515398992311 * v],
        [11.7194768719633, -1.97171508499972 * v**2 + 30.9087533932407,
         3.67680523332152 * v, -3.08486552743311 * v]])


@pytest.fixture(scope="module")
def problem():
    return get("whipple_bicycle")


@pytest.fixture(scope="module")
def spectra(problem):
    return _Spectra(problem)


def _sorted(values) -> np.ndarray:
    return np.array(sorted((complex(z) for z in values), key=lambda z: (round(z.real, 8),
                                                                       round(z.imag, 8))))


@pytest.mark.slow
@pytest.mark.parametrize("speed", [0, 1, 2, 3, 4, 5])
def test_lagrange_linearisation_has_sympys_eigenvalues(spectra, speed):
    ours = _sorted(spectra.nontrivial(speed))
    theirs = _sorted(np.linalg.eigvals(sympy_res(speed)))
    assert len(ours) == 4
    assert np.max(np.abs(ours - theirs)) < 1e-9


@pytest.mark.slow
def test_the_structural_zeros_are_the_yaw_and_the_speed(spectra):
    # the reduced state keeps the yaw (a heading: no restoring) and one forward speed (a
    # neighbouring steady motion); both eigenvalues vanish at every speed, roll and steer
    # remain
    assert spectra.zeros == 2
    assert {"phi", "delta"} <= set(spectra.lin.states)


@pytest.mark.slow
def test_table_2_and_the_weave_and_capsize_speeds_are_judged_right(problem):
    verdicts = judge_stability_claims(problem)
    assert len(verdicts) == 13
    assert {v.label: v.verdict for v in verdicts} == {v.label: "correct" for v in verdicts}


@pytest.mark.slow
def test_a_misprinted_weave_speed_is_wrong_and_the_true_one_is_named(problem):
    from dualmech import Published
    claims = [Published("weave", "critical", (4.30,), tolerance=1e-3),
              Published("v = 5 with a slipped digit", "eigenvalues",
                        (-14.07838969279822, -0.32286642900409,
                         -0.77534188219585 + 4.46486771378823j,
                         -0.77534188219585 - 4.46486771378823j + 1e-6), at=5,
                        tolerance=1e-9)]
    weave, five = judge_stability_claims(problem, claims)
    assert weave.verdict == "wrong"
    found = [float(x) for x in weave.detail.split("changes at v = ")[1].split(", ")]
    # the paper's weave and capsize speeds, section 5, to the bisection's 1e-9
    assert min(abs(f - 4.29238253634111) for f in found) < 1e-9
    assert min(abs(f - 6.02426201538837) for f in found) < 1e-9
    assert five.verdict == "wrong"
