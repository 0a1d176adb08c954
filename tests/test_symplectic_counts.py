"""The midpoint rule's honest bookkeeping: every model evaluation counted, energy on its steps.

References: the implicit midpoint rule conserves every quadratic invariant exactly (Hairer,
Lubich & Wanner, Geometric Numerical Integration, theorem IV.2.1), so on the harmonic
oscillator ``x'' + x = 0`` its steps keep ``E = (x^2 + x'^2)/2`` to round-off, while a cubic
interpolation between steps errs by ``O(h^4)``; the evaluation count is checked against a
counter wrapped around the model (independent of the integrator's own bookkeeping).
"""
import numpy as np

from dualmech import EquationSet, coordinate, t
from dualmech.numeric.energy import EnergyFunction
from dualmech.numeric.formulations import formulations
from dualmech.numeric.symplectic import energy_drift, midpoint
from dualmech.problems import get


class _Counting:
    """An energy function that counts the evaluations the midpoint rule asks of it."""

    def __init__(self, energy):
        self.energy, self.count = energy, 0

    def step_terms(self, q, qd):
        self.count += 1
        return self.energy.step_terms(q, qd)


def test_midpoint_counts_every_evaluation_of_the_model():
    # regression: the first residual of each step (two evaluations) was not counted
    f = formulations(get("compound_double_pendulum"), models=["lagrange"])[0][0]
    counted = _Counting(f.energy)
    run = midpoint(counted, (0.0, 1.0), f.y0, np.array([0.0, 1.0]), h=0.05)
    assert run.steps == 20
    assert run.calls == counted.count


def _oscillator():
    x = coordinate("x")
    return EnergyFunction(EquationSet("spring", (x,), (x.diff(t, 2) + x,)), {})


def test_midpoint_energy_drift_is_measured_on_its_steps():
    E = _oscillator()
    te = np.linspace(0.0, 10.0, 1001)
    run = midpoint(E, (0.0, 10.0), [1.0, 0.0], te, h=0.25)
    T, Y = run.nodes
    assert T.size == run.steps + 1 == 41
    energy = 0.5 * (Y**2).sum(axis=0)
    assert np.abs(energy - 0.5).max() <= 1e-14           # quadratic invariant: exact
    change = lambda y: E.along(y[:1], y[1:])               # noqa: E731 -- a one-liner
    assert energy_drift(change, run) <= 1e-14
    # the interpolated samples are not the method: their energy errs by O(h^4) ~ 1e-4
    assert np.abs(change(run.y)).max() > 1e-6
