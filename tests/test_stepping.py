"""Projection after every accepted step (dualmech.numeric.stepping) writes into scipy's
steppers: these tests pin the scipy releases that was checked on and catch a release whose
steppers no longer go on from the state written.

Reference: the harmonic oscillator y'' = -y, whose flow from any state over a time h is the
rotation by h (exact), so the step after a restart can be checked against it.
"""
import numpy as np
import pytest
import scipy

from dualmech.numeric.stepping import _STEPPERS, CHECKED_SCIPY, PROJECTABLE, _restart_from

RTOL, ATOL = 1e-8, 1e-10


def _oscillator(t, y):
    return np.vstack([y[1], -y[0]]) if np.ndim(y) == 2 else np.array([y[1], -y[0]])


def _flow(t0, y0, t):
    c, s = np.cos(t - t0), np.sin(t - t0)
    return np.array([c * y0[0] + s * y0[1], -s * y0[0] + c * y0[1]])


def test_scipy_is_a_release_the_projection_was_checked_on():
    release = ".".join(scipy.__version__.split(".")[:2])
    assert release in CHECKED_SCIPY, (
        f"scipy {scipy.__version__}: projected_run writes its steppers' y, f and BDF's D "
        f"(see stepping._restart_from), checked on scipy {', '.join(CHECKED_SCIPY)}. Run "
        "tests/test_stepping.py and tests/test_dae.py on this release; if they pass, add it "
        "to CHECKED_SCIPY")


@pytest.mark.parametrize("method", PROJECTABLE)
def test_the_step_after_a_restart_starts_from_the_state_written(method):
    """Moved off its path by 1e-3 (as a projection moves it), the stepper's next step starts
    there (its interpolant passes through it) and lands where the exact flow from there
    goes, within the step's own tolerance.  Writing only ``y`` misses by 2.6e-7 (RK45) and
    1e-7 (DOP853), without ``D`` BDF by the whole 1e-3."""
    kw = {"vectorized": True} if method in ("Radau", "BDF") else {}
    solver = _STEPPERS[method](_oscillator, 0.0, np.array([0.0, 1.0]), 10.0, rtol=RTOL,
                               atol=ATOL, **kw)
    for _ in range(5):
        solver.step()
    moved = 0.999 * solver.y + np.array([1e-3, 0.0])
    t0 = solver.t
    _restart_from(solver, moved)
    solver.step()
    assert solver.t_old == t0
    assert np.array_equal(solver.dense_output()(t0), moved)
    err = np.abs(solver.y - _flow(t0, moved, solver.t)).max()
    assert err <= RTOL * np.abs(moved).max() + ATOL
