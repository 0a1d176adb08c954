"""Symplectic integrators (dualmech.numeric.symplectic): order, bounded energy, constraints kept.

References: each run against DOP853 at rtol 1e-12 (its own error far below the methods'
second-order error at the steps used); the order of the implicit midpoint rule, Stormer--Verlet
and RATTLE is 2 (Hairer, Lubich & Wanner, Geometric Numerical Integration, chapters II.1,
VI.3 and VII.1); a symplectic method's energy error stays bounded over exponentially long
times (ibid. chapter IX), an error-controlled Runge--Kutta run's grows linearly.
"""
import numpy as np
import pytest

from dualmech.numeric.formulations import formulations
from dualmech.numeric.integrators import IntegrationError, integrate
from dualmech.numeric.studies.regimes import growth_exponent
from dualmech.numeric.simulation import problem_parameters
from dualmech.numeric.symplectic import constraint_functions
from dualmech.problems import get


def _order(f, method, span, hs, **kw):
    """Slope of log(error at the end) against log(h), against a DOP853 run at rtol 1e-12."""
    te = np.array([0.0, span])
    ref = f.run("DOP853", (0.0, span), te, rtol=1e-12).y[:, -1]
    errs = [np.abs(integrate(f.rhs, (0.0, span), f.y0, method, t_eval=te, step=h,
                             hamiltonian=f.energy, **kw).y[:, -1] - ref).max() for h in hs]
    return np.polyfit(np.log(hs), np.log(errs), 1)[0], errs


def test_newton_midpoint_converges_where_the_fixed_point_iteration_failed():
    # regression: the work-precision sweep's coarsest step on the compound double pendulum,
    # 5 s / 32 = 0.156 s, stopped the fixed-point iteration at t = 0
    f = formulations(get("compound_double_pendulum"), models=["lagrange"])[0][0]
    te = np.linspace(0.0, 5.0, 101)
    coarse = f.run("midpoint", (0.0, 5.0), te, step=5.0 / 32)
    fine = f.run("midpoint", (0.0, 5.0), te, step=5.0 / 64)
    assert coarse.success and coarse.steps == 32
    e1, e2 = (np.abs(f.energy_change(r.y)).max() for r in (coarse, fine))
    # second order: halving the step divides the energy error by about 4 (not 1, not 2)
    assert 2.5 <= e1 / e2 <= 8


def test_midpoint_is_second_order_with_a_configuration_dependent_mass_matrix():
    f = formulations(get("compound_double_pendulum"), models=["lagrange"])[0][0]
    order, _ = _order(f, "midpoint", 2.0, [0.02, 0.01, 0.005])
    assert order == pytest.approx(2.0, abs=0.1)


def test_verlet_is_second_order_and_refuses_a_varying_mass_matrix():
    f = formulations(get("coupled_pendulums"), models=["lagrange"])[0][0]
    assert f.energy.constant_mass
    order, _ = _order(f, "verlet", 2.0, [0.01, 0.005, 0.0025])
    assert order == pytest.approx(2.0, abs=0.1)
    dp = formulations(get("compound_double_pendulum"), models=["lagrange"])[0][0]
    with pytest.raises(ValueError, match="constant mass matrix.*use `midpoint`"):
        dp.run("verlet", (0.0, 1.0), np.array([0.0, 1.0]), step=0.01)


@pytest.fixture(scope="module")
def cartesian():
    p = get("pendulum_particle")
    forms = formulations(p, y0=[1.0, 0.0], stabilisations=("none",))[0]
    f = next(f for f in forms if f.name.startswith("cartesian"))
    return f, constraint_functions(f.constrained, problem_parameters(p))


def test_rattle_is_second_order_and_keeps_both_constraint_levels(cartesian):
    f, gG = cartesian
    order, _ = _order(f, "rattle", 2.0, [0.02, 0.01, 0.005], constraint=gG)
    assert order == pytest.approx(2.0, abs=0.1)
    run = integrate(f.rhs, (0.0, 2.0), f.y0, "rattle", t_eval=np.linspace(0, 2.0, 401),
                    step=0.01, hamiltonian=f.energy, constraint=gG)
    # at the steps (every other sample) the constraints hold to round-off: |g| within a few
    # ulps of l^2 = 1, G M^-1 p = 0 to the rounding of the solve
    g, gd = f.drift(run.y[:, ::2])
    assert np.abs(g).max() <= 8 * np.finfo(float).eps
    assert np.abs(gd).max() <= 64 * np.finfo(float).eps * np.abs(run.y[2:]).max()


def test_rattle_energy_stays_bounded_over_200_periods_where_rk45_drifts(cartesian):
    """The energy error's envelope grows like t^p: p = 0 (bounded) for RATTLE, about 1 or
    more for RK45 (here on the same index-1 DAE, which also drifts off the constraint)."""
    f, gG = cartesian
    period = 2 * np.pi * np.sqrt(1.0 / 9.81)      # small-angle period, l = 1 m
    end = 200 * period
    te = np.linspace(0.0, end, 2001)
    rattle = integrate(f.rhs, (0.0, end), f.y0, "rattle", t_eval=te, step=period / 40,
                       hamiltonian=f.energy, constraint=gG)
    rk = f.run("RK45", (0.0, end), te, rtol=1e-6)
    e_rattle, e_rk = np.abs(f.energy_change(rattle.y)), np.abs(f.energy_change(rk.y))
    assert growth_exponent(te, e_rattle) == pytest.approx(0.0, abs=0.05)
    assert growth_exponent(te, e_rk) >= 0.9
    # bounded means: the last 50 periods' worst error is no larger than the first 50's
    quarter = te.size // 4
    assert e_rattle[-quarter:].max() <= 1.05 * e_rattle[:quarter].max()


def test_symplectic_methods_say_what_they_need():
    f = formulations(get("simple_pendulum"), models=["lagrange"])[0][0]
    with pytest.raises(ValueError, match="`rattle` needs `constraint`"):
        f.run("rattle", (0.0, 1.0), np.array([0.0, 1.0]), step=0.01)
    with pytest.raises(ValueError, match="`verlet` needs `hamiltonian`"):
        integrate(f.rhs, (0.0, 1.0), f.y0, "verlet", t_eval=np.array([0.0, 1.0]), step=0.1)
    with pytest.raises(IntegrationError, match="halve `step`"):
        # a step of three periods: the midpoint equations have no nearby solution
        g = formulations(get("compound_double_pendulum"), y0=[2.0, 2.5, 0.0, 0.0],
                         models=["lagrange"])[0][0]
        g.run("midpoint", (0.0, 20.0), np.array([0.0, 20.0]), step=2.0)
