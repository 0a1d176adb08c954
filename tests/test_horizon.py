"""Chaotic horizons against a reference more accurate than the run (dualmech.numeric.studies.horizon).

The property checked: an error that starts at the tolerance and grows like e^(lambda t) passes
a threshold at t = (ln threshold - ln tol) / lambda, so the horizons' slope against -ln(tol)
is 1/lambda -- with lambda estimated independently by Benettin's method.  The consistency is
judged by the slope's own standard error (least squares over the tolerances).
"""
import numpy as np
import pytest

from dualmech.numeric.studies.horizon import horizons, lyapunov, state_sizes
from dualmech.numeric.studies.regimes import chaos
from dualmech.problems import get

Y0 = [2.0, 2.5, 0.0, 0.0]   # the atlas's chaotic state of the compound double pendulum


@pytest.fixture(scope="module")
def hz():
    return horizons(get("compound_double_pendulum"), y0=Y0, duration=7.0,
                    tolerances=(1e-4, 1e-5, 1e-6, 1e-7, 1e-8), lyapunov_time=40.0)


@pytest.mark.slow
def test_horizons_grow_with_minus_log_tol_at_the_rate_benettins_exponent_gives(hz):
    assert all(not r["bound"] for r in hz.rows)          # every horizon inside the reference
    assert hz.reference_valid > max(r["horizon"] for r in hz.rows)
    # slope 1/lambda of the fit against 1/lambda from Benettin: within two standard errors
    assert 1 / hz.fitted == pytest.approx(1 / hz.lyapunov, abs=2 * hz.slope_error)
    assert hz.lyapunov > 0


@pytest.mark.slow
def test_two_formulations_agree_longer_than_either_is_right(hz):
    # the old measure (agreement of two formulations) overstates how long a run is right
    c = chaos(get("compound_double_pendulum"), y0=Y0, duration=7.0, tolerances=(1e-4, 1e-6))
    truth = {r["rtol"]: r["horizon"] for r in hz.rows}
    for r in c.rows:
        assert r["horizon"] > truth[r["rtol"]]


def test_lyapunov_exponent_of_an_unstable_linear_system_is_its_eigenvalue():
    # y'' = y: the separation grows like e^t exactly, so lambda = 1 (the renormalisation
    # keeps the companion in the linear regime; the integration error is ~1e-12 per leg)
    rhs = lambda t, y: np.array([y[1], y[0]])  # noqa: E731
    assert lyapunov(rhs, np.array([1e-3, -1e-3]), 10.0, transient=2.0) == pytest.approx(
        1.0, abs=1e-6)


def test_state_sizes_measure_coordinates_and_rates_each_as_a_block():
    # q = (3, 0) then (-4, 0): rms of the coordinates sqrt((9 + 16) / 4); the rates all zero
    # fall back to 1 (no division by zero)
    y = np.array([[3.0, -4.0], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0]])
    assert state_sizes(y).tolist() == pytest.approx([2.5, 2.5, 1.0, 1.0])


@pytest.mark.parametrize("noise", [0.0, 0.05, 0.4], ids=["on a line", "scatter", "wide"])
def test_the_slope_error_comes_from_the_fits_residuals(noise):
    # regression: the '+-' was (X^T X)^-1 alone for three horizons -- a number fixed by the
    # tolerances, the same however the horizons scattered.  Reference: scipy's linregress
    # (standard error on N - 2 degrees of freedom), floored by the horizons' grid rounding.
    from scipy.stats import linregress
    from dualmech.numeric.studies.horizon import fit_slope
    x = -np.log([1e-4, 1e-5, 1e-6, 1e-7])
    y = 0.8 * x + noise * np.array([1.0, -1.0, -0.5, 0.7])
    slope, err = fit_slope(x, y, 0.005)
    ref = linregress(x, y)
    floor = 0.005 / np.sqrt(12 * ((x - x.mean()) ** 2).sum())
    assert slope == pytest.approx(ref.slope, rel=1e-12)
    assert err == pytest.approx(max(ref.stderr, floor), rel=1e-9)
    if noise:
        assert err > 10 * floor          # the scatter, not the grid, sets it
