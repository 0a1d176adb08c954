"""Helicopter blade flapping (problems/helicopter_blade.py): lift, flapping frequency, coning."""
import pytest
import sympy as sp

from dualmech import t
from dualmech.problems.helicopter_blade import (A, L, M, HelicopterBlade, HelicopterBladeWeighted,
                                                Omega, alpha0, beta, first_order, frames, g,
                                                lift_per_length, x)

problem = HelicopterBlade()
D = lambda q, n=1: q.diff(t, n)  # noqa: E731


@pytest.fixture
def comparison(compared):
    return compared("helicopter_blade")


def _zero(expr) -> bool:
    return sp.simplify(sp.expand(expr)) == 0


def test_station_velocity_from_the_frames():
    # hand: a station at x moves Omega x cos(beta) along its travel y_b and x beta' across, z_b
    f = frames()
    v = f.station.vel(f.O).express(f.b).components
    assert [sp.simplify(c) for c in v] == [0, Omega * x * sp.cos(beta), x * D(beta)]


@pytest.mark.parametrize("p, weight", [(problem, 0), (HelicopterBladeWeighted(), 1)],
                         ids=["source", "weighted"])
def test_equation_of_motion_by_hand(p, weight):
    # (M L^3/3)(beta'' + Omega^2 sin cos) [+ (M g L^2/2) cos(beta) with the weight]
    #     = A L^4 (alpha0 Omega^2 - Omega beta')/4
    hand = (M * L**3 / 3 * (D(beta, 2) + Omega**2 * sp.sin(beta) * sp.cos(beta))
            + weight * M * g * L**2 / 2 * sp.cos(beta)
            - A * L**4 * (alpha0 * Omega**2 - Omega * D(beta)) / 4)
    (lag,) = p.model("lagrange").equations
    (direct,) = p.model("newton_euler").equations
    assert _zero(lag - hand) and _zero(direct + hand)


def test_source_model_has_no_weight():
    assert g not in problem.parameter_symbols
    assert g in HelicopterBladeWeighted().parameter_symbols


def test_lift_acts_at_three_quarters_of_the_span():
    w = lift_per_length()
    resultant = sp.integrate(w, (x, 0, L))
    assert _zero(sp.integrate(x * w, (x, 0, L)) / resultant - 3 * L / 4)


def test_printed_lift_at_every_station():
    # first order in beta, beta' of A (alpha0 - atan(v_n / v_t)) |v|^2, v from the frames
    f = frames()
    v = f.station.vel(f.O)
    lift = A * (alpha0 - sp.atan(sp.cancel(v.dot(f.b.z) / v.dot(f.b.y)))) * v.dot(v)
    model = first_order(lift)
    expanded = A * (alpha0 * x**2 * Omega**2 - x * D(beta) * x * Omega)
    factored = A * (alpha0 + x * D(beta) / (x * Omega)) * (x * Omega)**2
    assert _zero(expanded - model) and _zero(lift_per_length() - model)
    # the factored form's + sign: too much lift by 2 A Omega x^2 beta' at every station
    assert _zero(factored - model - 2 * A * Omega * x**2 * D(beta))


def test_small_flapping_frequency_is_the_rotor_speed_and_damping_the_lock_number_over_16():
    # no pitch, weight neglected: beta = 0 is an equilibrium; (M L^3/3) beta'' + (A Omega L^4/4)
    # beta' + (M L^3 Omega^2/3) beta = 0.  Lock number gamma = rho a c L^4 / I = 6 A L / M
    # (A = rho a c / 2, I = M L^3/3), damping ratio gamma/16 (textbook rotor result)
    eqs = problem.model("lagrange").substitute({g: 0, alpha0: 0})
    Mm, Cm, Km = eqs.linearize()
    assert (Mm[0], Cm[0], Km[0]) == (M * L**3 / 3, A * Omega * L**4 / 4, M * L**3 * Omega**2 / 3)
    assert eqs.natural_frequencies() == [Omega]
    zeta = Cm[0] / (2 * sp.sqrt(Km[0] * Mm[0]))
    assert _zero(zeta - (6 * A * L / M) / 16)


def test_weightless_blade_cones_at_the_textbook_angle():
    # g = 0, pitch alpha0: sin(2 beta0) = 3 A alpha0 L / (2 M), so beta0 = asin(k)/2 ~ gamma
    # alpha0 / 8 for the blade near the hub plane; the library's equilibria, at exact values
    values = {M: 10, L: 5, A: sp.Rational(3, 10), alpha0: sp.Rational(1, 10), Omega: 30, g: 0}
    k = (3 * A * alpha0 * L / (2 * M)).subs(values)
    found = [e[beta] for e in problem.model("lagrange").equilibria(values)]
    assert len(found) == 4
    for b0 in found:            # every one balances centrifugal stiffening against lift
        assert abs(sp.N(sp.sin(2 * b0) - k, 60)) < sp.Float(10)**-50
    near_hub = [b0 for b0 in found if abs(sp.N(b0)) < 0.1]
    assert len(near_hub) == 1
    assert abs(sp.N(near_hub[0] - sp.asin(k) / 2, 60)) < sp.Float(10)**-50
    gamma = (6 * A * L / M).subs(values)
    assert abs(sp.N(near_hub[0] - gamma * alpha0.subs(values) / 8)) < k**3 / 12 * 1.01


def test_comparator_names_the_wrong_sign_of_the_angle_of_attack(comparison):
    # a rising blade meets the air from above: alpha0 - beta'/Omega, not + (module doc)
    verdicts = {v.label: v for v in comparison.published}
    assert "2*beta'/Omega" in verdicts["angle of attack"].detail
