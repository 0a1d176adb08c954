"""Steady motions (dualmech.model.steady): conditions and rates from the equations, clear refusals."""
import pytest
import sympy as sp

from dualmech import Lagrangian, coordinate, t
from dualmech.model.equations import EquationSet, ModelError
from dualmech.model.steady import steady_conditions, steady_rates

r, th, z = coordinate("r"), coordinate("theta"), coordinate("z")
m, mu, k, g = sp.symbols("m mu k g", positive=True)
D = lambda q, n=1: q.diff(t, n)  # noqa: E731


def _orbit() -> EquationSet:
    lg = Lagrangian(coordinates=[r, th])
    lg.kinetic("T", m * (D(r)**2 + r**2 * D(th)**2) / 2)
    lg.potential("V", -m * mu / r)
    return lg.equations()


def _conical_pendulum() -> EquationSet:
    # bob on a massless rod of length l from a fixed point: theta from the downward vertical,
    # z the azimuth; steady circling needs z'^2 = g / (l cos(theta)) (hand)
    l = sp.Symbol("l", positive=True)
    lg = Lagrangian(coordinates=[th, z])
    lg.kinetic("T", m * l**2 * (D(th)**2 + sp.sin(th)**2 * D(z)**2) / 2)
    lg.potential("V", -m * g * l * sp.cos(th))
    return lg.equations(), l


def test_circular_orbit_speed_squared_is_mu_over_r():
    # hand: m r theta'^2 = m mu / r^2 on a circle
    rates = steady_rates(_orbit(), [r], D(th))
    assert len(rates) == 2
    for w in rates:
        assert sp.simplify(r * w**2 - mu / r**2) == 0


def test_conditions_drop_the_equations_a_steady_motion_satisfies_identically():
    # the theta equation is d/dt(m r^2 theta') = 0: identically zero once r' = r'' = theta'' = 0
    (cond,) = steady_conditions(_orbit(), [r])
    assert sp.simplify(cond - (m * mu / r**2 - m * r * D(th)**2)) == 0


def test_conical_pendulum_with_a_parameter_fixed_first():
    eqs, l = _conical_pendulum()
    rates = steady_rates(eqs, [th], D(z), values={g: 0})
    assert rates == [0]   # weightless: only the bob at rest (sin(theta) != 0)
    for w in steady_rates(eqs, [th], D(z)):
        assert sp.simplify(w**2 - g / (l * sp.cos(th))) == 0


def test_refusals_say_what_to_fix():
    eqs = _orbit()
    with pytest.raises(ModelError, match="not coordinates"):
        steady_conditions(eqs, [z])
    with pytest.raises(ModelError, match="rate q'"):
        steady_rates(eqs, [r], th)
    with pytest.raises(ModelError, match="holds at rest"):
        steady_rates(eqs, [r], D(r))
    lam = sp.Symbol("N", real=True)
    with_reaction = EquationSet("direct", (r,), (m * D(r, 2) - lam,), (lam,))
    with pytest.raises(ModelError, match="reaction-free"):
        steady_conditions(with_reaction, [r])


def test_conditions_not_involving_the_rate_are_reported():
    # a spring on r alone: r fixed needs k r = 0, which no rate z' can change
    lg = Lagrangian(coordinates=[r, z])
    lg.kinetic("T", m * (D(r)**2 + D(z)**2) / 2)
    lg.potential("spring", k * r**2 / 2)
    with pytest.raises(ModelError, match="involves"):
        steady_rates(lg.equations(), [r], D(z))
    # orbit plus a sprung z: r fixed ties theta', z fixed needs k z = 0 besides
    lg = Lagrangian(coordinates=[r, th, z])
    lg.kinetic("T", m * (D(r)**2 + r**2 * D(th)**2 + D(z)**2) / 2)
    lg.potential("V", -m * mu / r + k * z**2 / 2)
    with pytest.raises(ModelError, match="do not involve"):
        steady_rates(lg.equations(), [r, z], D(th))
